// A flat milled on a lathe by C-axis steps and X motion (spec lathe-flat.md): the flat's geometry,
// the flatness error of N steps, layers, blocks, the block-rate limit and the time, the step table
// with its CSV, the diagrams and the G93 lathe program with its download.

import { csvButton } from '../core/export.js';
import { at, fmt, h, sym, value, valueList, warningList } from '../core/form.js';
import { flatDiagrams } from '../diagrams/lathe_flat_diagram.js';
import { programSection, programSource } from '../core/program_section.js';
import { t, tn } from '../core/i18n.js';
import { machineTimeLine } from '../core/machine.js';
import { csvUnit, unitText } from '../core/units.js';

const PATH = '/v1/lathe-flat';

// The step table's columns (spec section 8): field of steps_table[], label, API unit.
const STEP_COLUMNS = [
  ['c_deg', () => [...sym('C')], 'deg'],
  ['x_mm', () => [...sym('X'), ' ', t('result.flat_radius')], 'mm'],
  ['dx_mm', () => [...sym('dX')], 'mm'],
  ['chord_mm', () => [t('result.flat_chord')], 'mm'],
];

const describeCorners = (sharp) => t(sharp === true ? 'flat.corners.sharp' : 'flat.corners.lands');

export function init() {
  return programSection({
    id: 'flat',
    path: PATH,
    machine: 'lathe',
    axes: () => ['x', 'z', 'c'],
    fileName: 'CUTCALC.ngc',
    results: (json, { body, note, result, program }) => [
      ...flatResults(json, note),
      flatDiagrams(
        {
          partDiameter: Number(body.part_diameter_mm?.text),
          toolRadius: body.tool_radius_mm === undefined ? 0 : Number(body.tool_radius_mm.text),
          flats: body.flats === undefined ? 1 : Number(body.flats.text),
        },
        json,
        result,
      ),
      ...stepTable(json),
      h('h3', {}, t('result.g_code')),
      programSource(json, PATH, 'result.flat_program_from'),
      program,
    ],
  });
}

// Spec section 8, in the order a setter reads them: the flat, its steps and flatness, the blocks
// and the time.
function flatResults(body, machineNote) {
  const depths = Array.isArray(body.layer_depths_mm) ? body.layer_depths_mm : [];
  const error = body.flatness_error_mm;
  return [
    h('h3', {}, t('result.flat_geometry')),
    valueList(body, [
      [[t('result.axis_distance'), ' ', ...sym('d')], '/axis_distance_mm', 'mm'],
      [[t('result.flat_depth'), ' ', ...sym('t')], '/flat_depth_mm', 'mm'],
      [[t('result.flat_width'), ' ', ...sym('b')], '/flat_width_mm', 'mm'],
      [[t('result.face_width'), ' ', ...sym('w')], '/face_width_mm', 'mm'],
      [[t('result.across_flats'), ' ', ...sym('s')], '/across_flats_mm', 'mm'],
      [[t('result.engagement_half_angle'), ' ', ...sym('\u03b1', 'e')], '/engagement_half_angle_deg', 'deg'],
      [[t('result.x_travel')], '/x_travel_mm', 'mm'],
    ]),
    // A sentence, not a list row: the words stay together on a narrow column and a printed sheet.
    h(
      'p',
      { 'data-role': 'corners' },
      t('result.sharp_corners'),
      ': ',
      // Words, not a data-result: the shown results are numbers and codes.
      h('strong', { 'data-value': String(body.sharp_corners) }, describeCorners(body.sharp_corners)),
    ),
    h('h3', {}, t('result.flat_steps_and_flatness')),
    valueList(body, [
      [[t('result.c_steps'), ' ', ...sym('N')], '/steps', ''],
      [[t('result.steps_for_tolerance')], '/steps_for_tolerance', ''],
      [[t('result.flatness_error')], '/flatness_error_mm', 'mm'],
      [[t('result.flatness_error_estimate')], '/flatness_error_estimate_mm', 'mm'],
      [[t('result.layers'), ' ', ...sym('L')], '/layers', ''],
    ]),
    // The flatness error in µm: at 3 µm the page's 4 decimals of mm would show 0.003.
    typeof error === 'number'
      ? h(
          'p',
          { class: 'source-note', 'data-role': 'flatness-um' },
          t('result.flatness_in_um', { value: fmt(error * 1000) }),
        )
      : null,
    depths.length
      ? h(
          'p',
          { 'data-role': 'layer-depths' },
          t('result.layer_depths'),
          ': ',
          depths.map((_, i) => [i ? ', ' : '', value(body, `/layer_depths_mm/${i}`, 'mm')]),
        )
      : null,
    h('h3', {}, t('result.flat_blocks_and_time')),
    valueList(body, [
      [[t('result.cut_blocks')], '/cut_blocks', ''],
      [[t('result.shortest_block')], '/shortest_block_mm', 'mm'],
      [[t('result.max_feed_by_block_rate')], '/max_feed_by_block_rate_mm_per_min', 'mm_per_min'],
      [[t('result.clear_x'), ' ', ...sym('X', 'c')], '/clear_x_mm', 'mm'],
      [[t('result.flat_cut_time')], '/cut_time_min', 'min'],
      [[t('result.flat_approach_time')], '/approach_time_min', 'min'],
      [[t('result.machining_time')], '/machining_time_min', 'min'],
    ]),
    machineTimeLine(body, machineNote),
    h('p', { class: 'source-note' }, tn('result.flat_time_note')),
    warningList(body),
  ];
}

// The step table of the final layer of flat 1 (i, C, X radius, dX, chord) and its CSV.
function stepTable(body) {
  const rows = Array.isArray(body.steps_table) ? body.steps_table : [];
  if (!rows.length) return [];
  const table = h(
    'table',
    { 'data-role': 'steps-table' },
    h('caption', { class: 'source-note' }, t('result.flat_steps_table')),
    h(
      'thead',
      {},
      h(
        'tr',
        {},
        h('th', { scope: 'col' }, ...sym('i')),
        STEP_COLUMNS.map(([, label, unit]) =>
          h('th', { scope: 'col' }, ...label(), h('br'), h('span', { class: 'unit' }, unitText(unit))),
        ),
      ),
    ),
    h(
      'tbody',
      {},
      rows.map((row, k) =>
        h(
          'tr',
          {},
          h('th', { scope: 'row' }, String(row.i)),
          STEP_COLUMNS.map(([key, , unit]) =>
            h('td', {}, value(body, `/steps_table/${k}/${key}`, unit, undefined, undefined, true)),
          ),
        ),
      ),
    ),
  );
  return [
    h('h3', {}, t('result.flat_step_table_title')),
    h('div', { class: 'table-wrap' }, table),
    csvButton(
      'flat-steps-csv',
      'lathe-flat-steps.csv',
      [['i', ''], ...STEP_COLUMNS.map(([key, , unit]) => [key, csvUnit(unit)])],
      rows.map((_, k) => [
        at(body, `/steps_table/${k}/i`),
        ...STEP_COLUMNS.map(([key]) => at(body, `/steps_table/${k}/${key}`)),
      ]),
    ),
  ];
}
