// The button every section has beside Calculate: "Copy link" (the section's inputs in a URL,
// see url_state.js), with a status line saying what was copied.

import { copyText } from './clipboard.js';
import { h } from './form.js';
import { sectionLink } from './url_state.js';

export function wireSectionTools(calculators) {
  for (const { id, form } of calculators) {
    const link = h('button', { type: 'button', id: `${id}-copy-link` }, 'Copy link');
    const status = h('p', { class: 'copy-status', id: `${id}-copy-status`, role: 'status' });
    form.querySelector('.actions').append(link);
    form.append(status);
    link.addEventListener('click', () => copyText(sectionLink(id, form), 'Link', status));
  }
}
