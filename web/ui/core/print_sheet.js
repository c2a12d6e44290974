// Setup sheets: a "Print sheet" button per section prints that section alone; the browser's own
// Print (Ctrl+P) prints every section, one per page. The print rules in app.css (@media print)
// hide the page's header, navigation, forms and buttons and show each section's sheet parts:
// its inputs as a table before the results and, for a program, its header after them. The sheet
// parts are rebuilt after each calculation, so they are the inputs of the results shown. A section
// whose program is not in a <pre> gives its header itself (controller.sheetProgram()).

import { h } from './form.js';
import { t } from './i18n.js';
import { inputsTable, linkLine, machineTable, programHeader } from './sheet_content.js';

// The section being printed alone carries this attribute until the print dialog closes.
const TARGET = 'data-print-target';

export function wirePrintSheets(calculators) {
  for (const controller of calculators) {
    const { id, form } = controller;
    const section = form.closest('section');
    const inputs = h('div', { class: 'sheet-part', id: `${id}-sheet-inputs` });
    const program = h('div', { class: 'sheet-part', id: `${id}-sheet-program` });
    section.querySelector('.calc').before(inputs);
    section.append(program);
    form.addEventListener('calculated', () => {
      // A program timed on the page's machine profile (data-timed, machine.js) lists it too,
      // unless the profile is part of the section's own inputs.
      const profile = document.getElementById('program-time-machine');
      const timed = form.hasAttribute('data-timed') && !form.contains(profile);
      inputs.replaceChildren(
        ...[inputsTable(form), timed ? machineTable() : null, linkLine(id, form)].filter(Boolean),
      );
      program.replaceChildren(
        ...(controller.sheetProgram?.() ?? programHeader(section.querySelector('pre[data-file-name]'))),
      );
    });

    const button = h('button', { type: 'button', id: `${id}-print` }, t('button.print_sheet'));
    form.querySelector('.actions').append(button);
    button.addEventListener('click', async () => {
      // Edits not yet calculated are calculated first: the sheet shows the inputs as they are.
      await controller.calculate('input');
      for (const other of document.querySelectorAll(`[${TARGET}]`)) other.removeAttribute(TARGET);
      section.setAttribute(TARGET, '');
      window.print();
    });
  }
  window.addEventListener('afterprint', () => {
    for (const section of document.querySelectorAll(`[${TARGET}]`)) section.removeAttribute(TARGET);
  });
}
