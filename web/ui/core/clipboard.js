// Copying text for the user, with a message saying what happened (role="status", read out).

// The Clipboard API exists only in secure contexts (https, localhost): a shop's http://host:8080
// has none, so the old copy command on a selected, off-screen text area is the fallback.
async function writeText(text) {
  if (navigator.clipboard?.writeText) {
    try {
      await navigator.clipboard.writeText(text);
      return true;
    } catch {
      // Permission refused: try the fallback.
    }
  }
  const area = document.createElement('textarea');
  area.value = text;
  area.readOnly = true;
  area.className = 'offscreen';
  document.body.append(area);
  area.select();
  let copied = false;
  try {
    copied = document.execCommand('copy');
  } catch {
    copied = false;
  }
  area.remove();
  return copied;
}

// Copies `text`, then says so in `status` (messages: {copied, failed, name} in the page's
// language); when nothing could copy it, the text is shown there, selected, to copy by hand.
export async function copyText(text, messages, status) {
  const copied = await writeText(text);
  if (copied) {
    status.replaceChildren(messages.copied);
    return;
  }
  const area = document.createElement('textarea');
  area.value = text;
  area.readOnly = true;
  area.rows = 3;
  area.setAttribute('aria-label', messages.name);
  status.replaceChildren(messages.failed, area);
  area.select();
}
