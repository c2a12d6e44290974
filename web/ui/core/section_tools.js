// The buttons every section has beside Calculate: "Copy link" (the section's inputs in a URL,
// see url_state.js) and "Copy as curl" (the requests of the section's last calculation, exactly
// as the page sent them), with one status line saying what was copied.

import { copyText } from './clipboard.js';
import { curlScript } from './export.js';
import { h } from './form.js';
import { t } from './i18n.js';
import { sectionLink } from './url_state.js';

const messages = (what) => ({
  copied: t(`copy.${what}.copied`),
  failed: t(`copy.${what}.failed`),
  name: t(`copy.${what}.name`),
});

export function wireSectionTools(calculators) {
  for (const { id, form } of calculators) {
    const link = h('button', { type: 'button', id: `${id}-copy-link` }, t('button.copy_link'));
    // Nothing to copy before the first calculation has been sent.
    const curl = h(
      'button',
      { type: 'button', id: `${id}-copy-curl`, disabled: true },
      t('button.copy_curl'),
    );
    const status = h('p', { class: 'copy-status', id: `${id}-copy-status`, role: 'status' });
    form.querySelector('.actions').append(link, curl);
    form.append(status);

    let sent = [];
    form.addEventListener('calculated', (event) => {
      sent = event.detail.requests;
      curl.disabled = sent.length === 0;
    });
    link.addEventListener('click', () => copyText(sectionLink(id, form), messages('link'), status));
    curl.addEventListener('click', () => copyText(curlScript(sent), messages('curl'), status));
  }
}
