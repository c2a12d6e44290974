// The grooving cycle "v razvod" (spec grooving-cycle.md): the revolutions, shifts and times of the
// cycle, the wall roughness and chip, the diagrams of the groove and of the shift pattern, and the
// lathe program with its download.

import { h, iso, sym, value, valueList, warningList, wireContourFields } from '../core/form.js';
import { groovingDiagrams } from '../diagrams/grooving_cycle_diagram.js';
import { programSection, programSource } from '../core/program_section.js';
import { t, tn } from '../core/i18n.js';
import { machineTimeLine } from '../core/machine.js';

const PATH = '/v1/grooving/cycle';

// Codes of the answer in words: where the final shift ends, the crest's branch.
const describeSide = (code) => t(`grooving.side.${code}`);
const describeBranch = (code) => t(`branch.${code}`);

export function init() {
  wireContourFields(document.getElementById('grooving-form'));
  return programSection({
    id: 'grooving',
    path: PATH,
    machine: 'lathe',
    axes: () => ['x', 'z'],
    fileName: 'CUTCALC.ngc',
    results: (json, { body, note, result, program }) => [
      ...cycleResults(json, note),
      groovingDiagrams(
        {
          grooveWidth: Number(body.groove_width_mm?.text),
          startDiameter: Number(body.start_diameter_mm?.text),
          leftZ: Number(body.groove_left_z_mm?.text),
        },
        json,
        result,
      ),
      h('h3', {}, t('result.g_code')),
      programSource(json, PATH, 'result.grooving_program_from'),
      program,
    ],
  });
}

// Spec section 3.7, in the order a setter reads them: the cycle, its times, the wall and chip.
function cycleResults(body, machineNote) {
  return [
    h('h3', {}, t('result.grooving_cycle')),
    valueList(body, [
      [[t('result.tool_width'), ' ', ...sym('B')], '/tool_width_mm', 'mm'],
      [[t('result.shift'), ' ', ...sym('X', '2')], '/shift_mm', 'mm'],
      [[t('result.groove_depth'), ' ', ...sym('h')], '/groove_depth_mm', 'mm'],
      [[t('result.bottom_diameter'), ' ', ...sym('D', 'b')], '/bottom_diameter_mm', 'mm'],
      [[t('result.approach_diameter'), ' ', ...sym('D', 'a')], '/approach_diameter_mm', 'mm'],
      [[t('result.revolutions'), ' ', ...sym('N')], '/revolutions', ''],
      [[t('result.radial_revolutions')], '/radial_revolutions', ''],
      [[t('result.shift_revolutions')], '/shift_revolutions', ''],
      [[t('result.shifts')], '/shifts', ''],
      [
        [t('result.infeed_per_revolution'), ' ', ...sym('s'), ...iso('f')],
        '/infeed_per_revolution_mm',
        'mm_per_rev',
      ],
      [
        [t('result.shift_feed'), ' ', ...sym('f', 'sh')],
        '/shift_feed_mm_per_rev',
        'mm_per_rev',
      ],
      [[t('result.final_shift_revolutions'), ' ', ...sym('X', '2'), '/', ...sym('s')], '/final_shift_revolutions', ''],
      [[t('result.spindle_revolutions')], '/spindle_revolutions', ''],
      [[t('result.end_side')], '/end_side', '', describeSide],
      [[t('result.spindle_speed_at_start'), ' ', ...sym('n', '0')], '/spindle_speed_at_start_rpm', 'rpm'],
      [[t('result.spindle_speed_at_bottom'), ' ', ...sym('n', 'b')], '/spindle_speed_at_bottom_rpm', 'rpm'],
    ]),
    h('h3', {}, t('result.machining_time')),
    valueList(body, [
      [[t('result.approach_time')], '/approach_time_min', 'min'],
      [[t('result.plunge_time_radial')], '/plunge_time_min', 'min'],
      [[t('result.shift_time')], '/shift_time_min', 'min'],
      [[t('result.dwell_time')], '/dwell_time_min', 'min'],
      [[t('result.final_shift_time')], '/final_shift_time_min', 'min'],
      [[t('result.retract_time')], '/retract_time_min', 'min'],
      [[t('result.cycle_time')], '/cycle_time_min', 'min'],
    ]),
    machineTimeLine(body, machineNote),
    // The dwell as the program prints it: seconds, 3 decimals (spec 3.5).
    h(
      'p',
      { class: 'source-note', 'data-role': 'dwell-seconds' },
      t('result.dwell_in_program', { value: (body.dwell_time_min * 60).toFixed(3) }),
    ),
    h('h3', {}, t('result.wall_and_chip')),
    valueList(body, [
      [[t('result.chip_thickness'), ' ', ...sym('a')], '/chip_thickness_mm', 'mm'],
      [[t('result.side_chip_thickness'), ' ', ...sym('a', '1')], '/side_chip_thickness_mm', 'mm'],
      [[t('result.wall_pitch'), ' ', ...sym('4s')], '/wall_pitch_mm', 'mm'],
      [[t('result.wall_rz'), ' ', ...sym('Rz', 'p')], '/wall_rz_um', 'um'],
      [[t('result.plain_plunge_rz'), ' ', ...sym('Rz', 'p')], '/plain_plunge_rz_um', 'um'],
    ]),
    // A sentence, not a list row: the words of the branch stay on one line on a printed sheet.
    h(
      'p',
      { 'data-role': 'wall-rz-branch' },
      t('result.crest_formed_by'),
      ': ',
      value(body, '/wall_rz_branch', '', undefined, describeBranch),
    ),
    h('p', { class: 'source-note' }, tn('result.grooving_rz_note')),
    warningList(body),
  ];
}
