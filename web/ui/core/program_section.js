// The program part of a section that writes a machine program (the lathe flat, the grooving
// cycle, the polygon hole, and the pass program's download): the request timed on the page's
// machine profile, the program's <pre> and its download (the same request, Accept: text/plain),
// and the line that says where the program came from.

import { fileNameOf, postJson } from './api.js';
import { onCalculate } from './calculation.js';
import { saveFile } from './export.js';
import { h, readBody, showFailure, showMessage } from './form.js';
import { t } from './i18n.js';
import { markTimed, postWithMachine } from './machine.js';

// Asks `path` for the plain-text program of `body` (Accept: text/plain) and saves it under the
// file name the service gives (Content-Disposition), or `fallback`. Failures are shown on `form`.
export async function downloadProgram(form, path, body, fallback) {
  try {
    const answer = await postJson(path, body, 'text/plain');
    if (!answer.ok) {
      showFailure(form, answer, t('result.download'));
      return;
    }
    const name = fileNameOf(answer.headers.get('Content-Disposition'), fallback);
    saveFile(name, answer.text, 'text/plain');
  } catch (error) {
    showMessage(form, t('error.download_failed', { reason: error?.message ?? error }));
  }
}

// A section's program <pre>: the answer's program under its file name, or empty and hidden.
export function showProgram(pre, answerJson) {
  pre.textContent = answerJson.program;
  pre.dataset.fileName = answerJson.file_name;
  pre.hidden = false;
}
export function hideProgram(pre) {
  pre.textContent = '';
  delete pre.dataset.fileName;
  pre.hidden = true;
}

// A "Download program" button: a click downloads the program of the request `currentBody()`
// returns (nothing while there is none), the button disabled while it is fetched.
export function wireProgramDownload(button, form, path, currentBody, fallback) {
  button.addEventListener('click', async () => {
    const body = currentBody();
    if (!body) return;
    button.disabled = true;
    try {
      await downloadProgram(form, path, body, fallback);
    } finally {
      button.disabled = currentBody() === null;
    }
  });
}

// Wires the section `id` (its elements #id-form, #id-result, #id-download, #id-program) to `path`:
// each calculation posts request(body) timed on the machine of kind `machine` over axes(body),
// then shows results(json, {body, note, result, program}) or the failure, the program hidden.
// downloaded(sent) is the request the download repeats (by default the one sent). Returns the
// calculator (calculation.js).
export function programSection({
  id,
  path,
  machine,
  axes,
  fileName,
  results,
  request = (body) => body,
  downloaded = (sent) => sent,
}) {
  const form = document.getElementById(`${id}-form`);
  const result = document.getElementById(`${id}-result`);
  const download = document.getElementById(`${id}-download`);
  // The program's <pre> is part of the page from the start (hidden until there is a program).
  const program = document.getElementById(`${id}-program`);
  let calculated = null; // the request of the last program written, for its download
  form.dataset.machine = machine; // timed on the page's machine profile when it is this kind

  const calculator = onCalculate(form, async (api) => {
    const body = readBody(form);
    const { answer, sent, note } = await postWithMachine(api, path, request(body), machine, axes(body));
    markTimed(form, sent);
    result.replaceChildren();
    if (!answer.ok) {
      calculated = null;
      download.disabled = true;
      showFailure(form, answer);
      hideProgram(program);
      result.append(h('p', { class: 'placeholder' }, t('result.no_results')), program);
      return;
    }
    calculated = downloaded(sent);
    download.disabled = false;
    showProgram(program, answer.json);
    result.append(...results(answer.json, { body, note, result, program }));
  });

  wireProgramDownload(download, form, path, () => calculated, fileName);
  return calculator;
}

// Where a program came from (`key`: a catalogue sentence with {path, dialect, units, decimals,
// file}); the text itself is in the <pre> after it.
export function programSource(body, path, key) {
  return h(
    'p',
    { class: 'source-note' },
    t(key, {
      path,
      dialect: body.dialect,
      units: t(`program_units.${body.units}`),
      decimals: body.decimals,
      file: body.file_name,
    }),
  );
}
