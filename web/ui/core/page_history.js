// The page's URL follows its calculations (format: url_state.js): opening a URL fills the forms
// from it and calculates every section once; each calculation the user asks for becomes a history
// entry; back and forward put the forms back as they were and recalculate what changed.

import { applyToForm, pageUrl } from './url_state.js';

const BY_USER = new Set(['input', 'submit']);
let shown = null; // the query the forms show

function applyUrl(calculators) {
  shown = window.location.search;
  for (const { id, form, quietly } of calculators) {
    quietly(() => applyToForm(form, id, window.location.search));
  }
}

export function wirePageHistory(calculators) {
  applyUrl(calculators);
  for (const calculator of calculators) {
    calculator.form.addEventListener('calculation-start', (event) => {
      if (!BY_USER.has(event.detail.cause)) return;
      const url = pageUrl(calculators, calculator.id);
      // The same inputs again (Enter twice) are no new history entry.
      if (new URL(url).search === window.location.search) return;
      window.history.pushState(null, '', url);
      shown = window.location.search;
    });
    calculator.calculate('load');
  }
  window.addEventListener('popstate', () => {
    // A link within the page (#speeds) moves in history too, but changes no input.
    if (window.location.search === shown) return;
    applyUrl(calculators);
    for (const calculator of calculators) calculator.calculate('history');
  });
}
