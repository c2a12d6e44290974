// What a printed setup sheet adds to a section's results (see print_sheet.js): the inputs of the
// calculation as a table (form controls print poorly), a link that reproduces it, and, for a
// program, its file name and header. Built from the form and the shown program, so the labels,
// symbols and units are the page's own, whatever language or units it shows them in.

import { h } from './form.js';
import { t } from './i18n.js';
import { unitText } from './units.js';
import { sectionLink } from './url_state.js';

// Lines of a program shown on the sheet when it has no safe-height rapid to end its header on.
const FALLBACK_HEADER_LINES = 12;

// The inputs of `form` as a table: one group per fieldset, a row per applicable field
// (label with its symbol | value | unit); a field hidden because it does not apply is left out.
export function inputsTable(form) {
  return fieldsetTable([...form.querySelectorAll('fieldset')], t('sheet.inputs'), 'sheet-inputs');
}

// The machine profile a program section was timed on (machine.js): its own table, after the
// section's inputs.
export function machineTable() {
  const profile = document.getElementById('program-time-machine');
  return profile ? fieldsetTable([profile], t('sheet.machine'), 'sheet-machine', false) : null;
}

// A table of the fields of `fieldsets`, a group per fieldset headed by its legend (`legends`).
function fieldsetTable(fieldsets, caption, className, legends = true) {
  const table = h('table', { class: className }, h('caption', {}, caption));
  for (const fieldset of fieldsets) {
    const rows = [...fieldset.querySelectorAll('.field')]
      .filter((field) => !field.hidden)
      .map(inputRow)
      .filter(Boolean);
    if (rows.length === 0) continue;
    const legend = fieldset.querySelector('legend')?.textContent ?? '';
    const heading = legends ? h('tr', {}, h('th', { colspan: 3, scope: 'colgroup' }, legend)) : null;
    table.append(h('tbody', {}, heading, rows));
  }
  return table;
}

function inputRow(field) {
  const control = field.querySelector('input[name^="/"], select[name^="/"]');
  const label = field.querySelector('label');
  if (!control || !label) return null;
  const { quantity, unit } = labelParts(label);
  const shown =
    control.tagName === 'SELECT'
      ? (control.selectedOptions[0]?.textContent ?? control.value)
      : control.value.trim() || '\u2014';
  return h(
    'tr',
    { 'data-input': control.name },
    h('th', { scope: 'row' }, quantity),
    h('td', { class: 'num' }, shown),
    h('td', { class: 'unit' }, unit),
  );
}

// A label is built of parts (index.html): the quantity's text (data-i18n), its paper symbol
// (.sym), its ISO symbol (var.iso) and its unit (.unit, data-unit, the API's unit id). The sheet
// shows the parts before the unit, one space apart, and the unit in the page's units apart. The
// ISO symbol's mark, drawn by the page's CSS, is text on the sheet (print loses the colour).
function labelParts(label) {
  const quantity = [];
  for (const part of label.children) {
    if (part.matches('[data-unit]')) continue;
    if (quantity.length) quantity.push(' ');
    if (part.matches('var.iso')) {
      quantity.push(h('span', { class: 'iso-mark' }, t('sheet.iso')), ' ');
    }
    quantity.push(part.cloneNode(true));
  }
  const unit = label.querySelector('[data-unit]')?.dataset.unit ?? '';
  return { quantity, unit: unitText(unit) };
}

export function linkLine(id, form) {
  return h('p', { class: 'sheet-link' }, t('sheet.calculation'), ' ', sectionLink(id, form));
}

// The program's file name and header (its blocks up to the first rapid to the safe height, where
// the passes begin, spec programs.md), from the shown program `pre` (data-file-name).
export function programHeader(pre) {
  if (!pre || pre.hidden || !pre.textContent) return [];
  return programHeaderOf(pre.textContent, pre.dataset.fileName ?? '');
}

// The same from a program's text (only its first lines are read: a program to time may be
// megabytes) and its file name ('' when it has none: a pasted program).
export function programHeaderOf(text, fileName) {
  if (!text) return [];
  const lines = firstLines(text, 200);
  const safe = lines.findIndex((line) => /^G0?0\b.*Z/.test(line.trim()));
  const header = lines.slice(0, safe >= 0 ? safe + 1 : FALLBACK_HEADER_LINES);
  return [
    h('h3', {}, t('sheet.program_header')),
    fileName
      ? h('p', {}, t('sheet.file'), ' ', h('span', { class: 'sheet-file-name' }, fileName))
      : null,
    h('pre', { class: 'sheet-program-header' }, header.join('\n')),
  ].filter(Boolean);
}

function firstLines(text, count) {
  const lines = [];
  let start = 0;
  while (lines.length < count && start <= text.length) {
    const end = text.indexOf('\n', start);
    lines.push(text.slice(start, end < 0 ? text.length : end).replace(/\r$/, ''));
    if (end < 0) break;
    start = end + 1;
  }
  return lines;
}
