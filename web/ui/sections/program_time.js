// Program time (machine-time.md, POST /v1/program-time): a G-code program, pasted or opened from a
// file, timed on the page's machine profile (machine.js, the Machine fieldset of this form): the
// estimate beside the nominal time, the estimate's split, counts and lengths, the path velocity
// against time (plot and CSV), the blocks that lose the most time (table and CSV) and the
// warnings. A refused program's message stands under the text area, naming its line and column.
// The program is not in the page's link (a program may be megabytes): the link keeps the machine
// profile and the control only.

import { onCalculate } from '../core/calculation.js';
import { csvButton } from '../core/export.js';
import { h, readBody, showFailure, showMessage, sym, value, valueList, warningList } from '../core/form.js';
import { t, tn } from '../core/i18n.js';
import { axisNames, wirePresets } from '../core/machine.js';
import { programHeaderOf } from '../core/sheet_content.js';
import { domain, figure, plot, points, s } from '../core/svg.js';
import { csvUnit, fromApi, unitText } from '../core/units.js';

const PATH = '/v1/program-time';
// Samples of the velocity profile: enough for a smooth line at the plot's width.
const PROFILE_POINTS = 400;
// What holds a slow block back (the API's limited_by code) in words.
const describeLimit = (code) => t(`limit.${code}`);

export function init() {
  const form = document.getElementById('program-time-form');
  const result = document.getElementById('program-time-result');
  const area = document.getElementById('program-time-program');
  let fileName = ''; // the file the program was opened from, '' for a pasted program
  wirePresets(form);

  const calculator = onCalculate(form, async (api) => {
    const body = { program: area.value, ...readBody(form), profile_points: PROFILE_POINTS };
    const answer = await api.postJson(PATH, body);
    result.replaceChildren();
    if (!answer.ok) {
      showFailure(form, atAxisInputs(answer));
      offerLine(answer, area);
      result.append(h('p', { class: 'placeholder' }, t('result.no_results')));
      return;
    }
    result.append(...timeResults(answer.json, body.program));
  });

  wireFileInput(form, area, (name) => {
    fileName = name;
    calculator.calculate('input');
  });
  // Typed or pasted text is no longer the opened file's.
  area.addEventListener('input', () => {
    fileName = '';
    document.getElementById('program-time-file-name').textContent = '';
  });
  // The printed sheet's program header: the program's first blocks (print_sheet.js).
  calculator.sheetProgram = () => programHeaderOf(area.value, fileName);
  return calculator;
}

// "Open a file": the file's text goes into the text area (FileReader, UTF-8), its name and length
// under the button; then `opened(name)`.
function wireFileInput(form, area, opened) {
  const input = document.getElementById('program-time-file');
  const note = document.getElementById('program-time-file-name');
  input.addEventListener('change', () => {
    const file = input.files?.[0];
    if (!file) return;
    const reader = new FileReader();
    reader.addEventListener('load', () => {
      area.value = String(reader.result);
      const lines = area.value.split('\n').length - (area.value.endsWith('\n') ? 1 : 0);
      note.textContent = t('result.file_opened', { name: file.name, lines });
      opened(file.name);
    });
    reader.addEventListener('error', () => {
      showMessage(form, t('error.file_read', { reason: reader.error?.message ?? file.name }));
    });
    reader.readAsText(file);
    // The same file may be opened again (after edits): it is a new choice then.
    input.value = '';
  });
}

// An axis the program moves and the profile lacks (422 at /machine/axes with `axis`): its
// message goes under that axis's velocity input, the empty one to fill in.
function atAxisInputs(answer) {
  const errors = answer.json?.errors;
  if (!Array.isArray(errors)) return answer;
  const placed = errors.map((e) =>
    e.pointer === '/machine/axes' && typeof e.axis === 'string' ? { ...e, pointer: axisNames(e.axis)[0] } : e,
  );
  return { ...answer, json: { ...answer.json, errors: placed } };
}

// A refused block: under the message, the block as written and a button that selects it in the
// text area (the API's 1-based line and column).
function offerLine(answer, area) {
  const item = answer.json?.errors?.find((e) => e.pointer === '/program' && Number.isInteger(e.line));
  const message = document.getElementById(`${area.id}-error`);
  if (!item || !message) return;
  const block = linesAt(area.value, [item.line]).get(item.line) ?? '';
  const show = h('button', { type: 'button', class: 'show-line', 'data-role': 'show-line' }, t('button.show_line', { line: item.line }));
  show.addEventListener('click', () => selectLine(area, item.line, item.column));
  if (block) message.append(' ', h('code', { class: 'error-block', 'data-role': 'error-block' }, block));
  message.append(' ', show);
}

// Selects line `line` of the text area from `column` (1-based) to its end and scrolls to it.
function selectLine(area, line, column = 1) {
  const text = area.value;
  let start = 0;
  for (let n = 1; n < line; n += 1) {
    const next = text.indexOf('\n', start);
    if (next < 0) break;
    start = next + 1;
  }
  const end = text.indexOf('\n', start);
  const stop = end < 0 ? text.length : end;
  area.focus();
  area.setSelectionRange(Math.min(start + Math.max(column - 1, 0), stop), stop);
  const lineHeight = parseFloat(getComputedStyle(area).lineHeight) || 18;
  area.scrollTop = Math.max(0, (line - 3) * lineHeight);
}

// The text of the lines `numbers` (1-based, as the API counts: LF ends a line, a CR before it is
// not part of it), read from the start of the program up to the last one only.
function linesAt(text, numbers) {
  const wanted = new Set(numbers);
  const last = Math.max(...numbers);
  const found = new Map();
  let start = 0;
  for (let line = 1; line <= last; line += 1) {
    const end = text.indexOf('\n', start);
    const stop = end < 0 ? text.length : end;
    if (wanted.has(line)) found.set(line, text.slice(start, stop).replace(/\r$/, '').trim());
    if (end < 0) break;
    start = end + 1;
  }
  return found;
}

// ------------------------------------------------------------------ results

function timeResults(body, program) {
  return [
    h('h3', {}, t('result.time_on_this_machine')),
    valueList(body, [
      [[t('result.estimated_time'), ' ', ...sym('T', 'e')], '/estimated_time_min', 'min'],
      [[t('result.nominal_time'), ' ', ...sym('T', 'n')], '/nominal_time_min', 'min'],
    ]),
    h(
      'p',
      { class: 'source-note', 'data-role': 'seconds' },
      tn('result.times_in_seconds', {
        estimated: (body.estimated_time_min * 60).toFixed(3),
        nominal: (body.nominal_time_min * 60).toFixed(3),
      }),
    ),
    h('h3', {}, t('result.time_split')),
    valueList(body, [
      [[t('result.feed_moves_time')], '/feed_time_min', 'min'],
      [[t('result.rapids_time')], '/rapid_time_min', 'min'],
      [[t('result.dwells_time')], '/dwell_time_min', 'min'],
      [[t('result.dynamics_time'), ' ', ...sym('T', 'e'), '\u00a0\u2212\u00a0', ...sym('T', 'n')], '/dynamics_time_min', 'min'],
    ]),
    h('h3', {}, t('result.program_counts')),
    valueList(body, [
      [[t('result.blocks')], '/blocks', ''],
      [[t('result.moves')], '/moves', ''],
      [[t('result.feed_length')], '/feed_length_mm', 'mm'],
      [[t('result.rapid_length')], '/rapid_length_mm', 'mm'],
      [[t('result.rotary_travel')], '/rotary_deg', 'deg'],
    ]),
    h('p', { class: 'source-note' }, tn('result.program_time_note')),
    warningList(body),
    ...profileResults(body),
    ...slowestBlocks(body, program),
  ];
}

// The path velocity against time, T_e and T_n marked, and its CSV.
function profileResults(body) {
  const profile = Array.isArray(body.profile) ? body.profile : [];
  if (profile.length < 2) return [];
  const samples = profile.map((p) => [p.t_min, fromApi(p.velocity_mm_per_min, 'mm_per_min')]);
  const estimated = body.estimated_time_min;
  const nominal = body.nominal_time_min;
  const end = Math.max(estimated, nominal, ...samples.map(([time]) => time));
  const chart = plot({
    kind: 'velocity-profile',
    title: t('diagram.velocity_profile_title'),
    xLabel: t('diagram.time_axis', { unit: unitText('min') }),
    yLabel: t('diagram.velocity_axis', { unit: unitText('mm_per_min') }),
    xDomain: [0, end > 0 ? end * 1.03 : 1],
    yDomain: domain([0, ...samples.map(([, v]) => v)], 0.1, true),
  });
  const { x, y, area } = chart;
  chart.layer.append(
    s('polyline', {
      'data-role': 'profile',
      class: 's-curve',
      points: points(samples.map(([time, v]) => [x(time), y(v)])),
    }),
  );
  // A vertical line at a time, labelled with its symbol on the side away from the other line.
  const mark = (time, role, cls, sub, right) =>
    s(
      'g',
      { 'data-role': role },
      s('line', { class: cls, x1: x(time), y1: area.top, x2: x(time), y2: area.bottom }),
      s(
        'text',
        { x: x(time), y: area.top, dx: right ? '0.3em' : '-0.3em', dy: '1em', 'text-anchor': right ? 'start' : 'end' },
        'T',
        s('tspan', { 'baseline-shift': 'sub', 'font-size': '0.75em' }, sub),
      ),
    );
  chart.svg.append(
    mark(nominal, 'nominal-time', 's-target', 'n', nominal > estimated),
    mark(estimated, 'estimated-time', 's-max-feed', 'e', estimated >= nominal),
  );
  return [
    h('h3', {}, t('result.velocity_profile')),
    figure(
      chart.svg,
      [
        { cls: 's-curve', label: t('legend.path_velocity') },
        { cls: 's-max-feed', label: t('legend.estimated_time') },
        { cls: 's-target', label: t('legend.nominal_time') },
      ],
      tn('diagram.velocity_caption', { points: profile.length }),
    ),
    csvButton(
      'program-time-profile-csv',
      'program-time-profile.csv',
      [
        ['t_min', csvUnit('min')],
        ['velocity_mm_per_min', csvUnit('mm_per_min')],
      ],
      profile.map((p) => [p.t_min, p.velocity_mm_per_min]),
    ),
  ];
}

// The blocks that lose the most time: line, the block as written, time lost, what limits it;
// and their CSV (the block's text and the API's codes).
function slowestBlocks(body, program) {
  const rows = Array.isArray(body.slowest_blocks) ? body.slowest_blocks : [];
  const heading = h('h3', {}, t('result.slowest_blocks'));
  if (!rows.length) return [heading, h('p', { class: 'source-note' }, t('result.no_slow_blocks'))];
  const blocks = linesAt(program, rows.map((r) => r.line));
  const head = (label, unit = '', cls = undefined) =>
    h('th', { scope: 'col', class: cls }, label, unit ? [h('br'), h('span', { class: 'unit' }, unitText(unit))] : null);
  const table = h(
    'table',
    { 'data-role': 'slowest-blocks' },
    h('caption', { class: 'source-note' }, t('result.slowest_caption')),
    h(
      'thead',
      {},
      h(
        'tr',
        {},
        head(t('result.line')),
        head(t('result.block'), '', 'text'),
        head(t('result.lost_time'), 'min'),
        head(t('result.limited_by'), '', 'text'),
      ),
    ),
    h(
      'tbody',
      {},
      rows.map((row, i) =>
        h(
          'tr',
          {},
          h('th', { scope: 'row' }, value(body, `/slowest_blocks/${i}/line`, '', undefined, undefined, true)),
          h('td', { class: 'text block' }, h('code', {}, blocks.get(row.line) ?? '')),
          h('td', {}, value(body, `/slowest_blocks/${i}/lost_min`, 'min', undefined, undefined, true)),
          h('td', { class: 'text' }, value(body, `/slowest_blocks/${i}/limited_by`, '', undefined, describeLimit, true)),
        ),
      ),
    ),
  );
  return [
    heading,
    h('div', { class: 'table-wrap' }, table),
    csvButton(
      'program-time-slowest-csv',
      'program-time-slowest-blocks.csv',
      [
        ['line', ''],
        ['block', ''],
        ['lost_min', csvUnit('min')],
        ['limited_by', ''],
      ],
      rows.map((row) => [row.line, blocks.get(row.line) ?? '', row.lost_min, row.limited_by]),
    ),
  ];
}
