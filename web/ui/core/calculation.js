// When a section calculates: on Enter or Calculate at once, after a pause in typing (debounced,
// so a number typed digit by digit is one request, not one per keystroke), on first load and
// when the browser goes back or forward. One calculation at a time per form: one asked for
// meanwhile runs after it (several such become one), so the result shown is always that of the
// latest inputs and never overwritten by an older answer arriving late.

import { apiClient } from './api.js';
import { clearErrors, showMessage } from './form.js';
import { t } from './i18n.js';
import { signature } from './url_state.js';

// Long enough for a few keystrokes (and for a test to fill several fields) to count as one edit.
export const PAUSE_MS = 600;

// Causes of a calculation. 'input' (a pause after an edit) and 'history' (back/forward) repeat a
// calculation only when the inputs changed; 'submit' (Enter, Calculate) and 'load' always run.
const ALWAYS = new Set(['submit', 'load']);

// Wires `calculate(api)` to the form and returns its controller. `api` is the client to send the
// calculation's requests with: they are kept (controller.requests) for "Copy as curl". The form
// announces each calculation with a 'calculation-start' event and its end with 'calculated'
// (detail: {cause, requests}).
export function onCalculate(form, calculate) {
  let timer = 0;
  let running = null; // the loop below, while it runs
  let pending = null; // the cause of a calculation asked for while one runs
  let calculated = null; // the signature of the inputs last calculated
  let quiet = false; // set while the page itself changes the inputs

  const controller = {
    id: form.closest('section').id,
    form,
    requests: [],
    // Runs a calculation now (or right after the one running); resolves when the form is idle.
    calculate(cause) {
      clearTimeout(timer);
      if (pending === null || !ALWAYS.has(pending)) pending = cause;
      running ??= drain();
      return running;
    },
    // Changes the inputs without that counting as an edit (`change` runs synchronously).
    quietly(change) {
      quiet = true;
      try {
        change();
      } finally {
        quiet = false;
      }
    },
  };

  async function drain() {
    // Never finishes synchronously: `running` is set before it is cleared below.
    await null;
    while (pending !== null) {
      const next = pending;
      pending = null;
      if (ALWAYS.has(next) || signature(form) !== calculated) await once(next);
    }
    running = null;
  }

  async function once(cause) {
    calculated = signature(form);
    form.dispatchEvent(new CustomEvent('calculation-start', { detail: { cause } }));
    clearErrors(form);
    form.setAttribute('aria-busy', 'true');
    const requests = [];
    try {
      await calculate(apiClient((request) => requests.push(request)));
    } catch (error) {
      showMessage(form, t('error.page_failed', { reason: error?.message ?? error }));
      console.error(error);
    } finally {
      form.removeAttribute('aria-busy');
    }
    controller.requests = requests;
    form.dispatchEvent(new CustomEvent('calculated', { detail: { cause, requests } }));
  }

  const afterPause = () => {
    if (quiet) return;
    clearTimeout(timer);
    timer = setTimeout(() => controller.calculate('input'), PAUSE_MS);
  };
  form.addEventListener('input', afterPause);
  form.addEventListener('change', afterPause);
  form.addEventListener('submit', (event) => {
    event.preventDefault();
    controller.calculate('submit');
  });
  return controller;
}
