// Entry length and main time (paper 002, the Vitebsk calculator): one form drives
// POST /v1/entry-length (one pass, with its scheme for the drawings) and POST /v1/main-time
// (every lateral and depth pass).

import { RawNumber } from '../core/api.js';
import { onCalculate } from '../core/calculation.js';
import { csvButton } from '../core/export.js';
import {
  at,
  h,
  iso,
  lengthText,
  noDiagram,
  readBody,
  showFailure,
  sym,
  value,
  valueList,
  warningList,
  wireContourFields,
} from '../core/form.js';
import {
  arrowHead,
  Bounds,
  diagram,
  figure,
  horizontalDimension,
  mapped,
  points,
  s,
  subText,
  unitsPerPixel,
} from '../core/svg.js';
import { programSource, wireProgramDownload } from '../core/program_section.js';
import { t, tn } from '../core/i18n.js';
import { machineTimeLine, markTimed, postWithMachine } from '../core/machine.js';
import { csvUnit, unitText } from '../core/units.js';

// " = 12.5 mm" for a dimension line: the length in the page's units.

const LENGTH = 'entry-length';
const TIME = 'main-time';
const PROGRAM = 'program';
const PROGRAM_PATH = '/v1/main-time/program';

export function init() {
  const form = document.getElementById('entry-form');
  const result = document.getElementById('entry-result');
  const download = document.getElementById('entry-download');
  let programRequest = null; // the body of the last program that was written
  form.dataset.machine = 'mill'; // the pass program is timed on the page's machine profile (a mill)
  wireContourFields(form);
  const calculator = onCalculate(form, async (api) => {
    // The pass program takes the main-time request plus the `program` options.
    const programBody = { ...readBody(form, TIME), ...readBody(form, PROGRAM) };
    // A program needs a straight path: with an extra path L1 the page does not ask for one.
    const extra = programBody.extra_path_mm;
    const straight = extra === undefined || (extra instanceof RawNumber && Number(extra.text) === 0);
    const [length, time, timed] = await Promise.all([
      api.postJson('/v1/entry-length', { ...readBody(form, LENGTH), include_scheme: true }),
      api.postJson('/v1/main-time', readBody(form, TIME)),
      straight ? postWithMachine(api, PROGRAM_PATH, programBody, 'mill', ['x', 'y', 'z']) : Promise.resolve(null),
    ]);
    const program = timed?.answer ?? null;
    markTimed(form, timed?.sent);
    if (!length.ok) showFailure(form, length, t('result.entry_length'));
    if (!time.ok) showFailure(form, time, t('result.main_time'));
    // The program repeats main-time's own errors: only its own are shown.
    if (time.ok && program && !program.ok) showFailure(form, program, t('result.program'));
    programRequest = program?.ok ? timed.sent : null;
    download.disabled = programRequest === null;
    result.replaceChildren();
    if (length.ok) result.append(...lengthResults(length, result));
    if (time.ok) result.append(...timeResults(time.json));
    if (program?.ok) result.append(...programResults(program.json, timed.note));
    if (time.ok && !straight) {
      result.append(
        h('p', { class: 'source-note' }, tn('result.no_program_extra_path')),
      );
    }
    if (!length.ok && !time.ok) {
      result.append(h('p', { class: 'placeholder' }, t('result.no_results')));
    }
  });

  wireProgramDownload(download, form, PROGRAM_PATH, () => programRequest, 'CUTCALC.ngc');
  return calculator;
}

// ------------------------------------------------------------------ the program (main-time/program)

function programResults(body, machineNote) {
  return [
    h('h3', {}, t('result.program')),
    programSource(body, PROGRAM_PATH, 'result.program_from'),
    valueList(
      body,
      [
        [[t('result.passes_lateral_depth')], '/passes', ''],
        [[t('result.feed_time')], '/working_time_min', 'min'],
        [[t('result.plunges')], '/plunge_time_min', 'min'],
        [[t('result.rapids')], '/rapid_time_min', 'min'],
        [[t('result.cycle_time')], '/cycle_time_min', 'min'],
      ],
      PROGRAM,
    ),
    machineTimeLine(body, machineNote, PROGRAM),
    h(
      'p',
      { class: 'source-note' },
      t('result.not_in_times', {
        list: (body.not_modelled ?? []).map((code) => t(`not_modelled.${code}`)).join(', '),
      }),
    ),
    warningList(body),
    h(
      'pre',
      {
        id: 'entry-program',
        tabindex: '0',
        'aria-label': t('result.g_code_program'),
        'data-file-name': body.file_name,
      },
      body.program,
    ),
  ];
}

// ------------------------------------------------------------------ one pass (entry-length)

function lengthResults(answer, container) {
  const body = answer.json;
  const parts = [
    h('h3', {}, t('result.one_pass')),
    h('p', { class: 'source-note' }, t('result.from_entry_length')),
    valueList(
      body,
      [
        [[t('result.start'), ' ', ...sym('X', 'n')], '/start/x_mm', 'mm'],
        [[t('result.start'), ' ', ...sym('Y', 'n')], '/start/y_mm', 'mm'],
        [[t('result.end'), ' ', ...sym('X', 'k')], '/end/x_mm', 'mm'],
        [[t('result.end'), ' ', ...sym('Y', 'k')], '/end/y_mm', 'mm'],
        [[t('result.engagement_length'), ' ', ...sym('L', 'vr1')], '/engagement_length_mm', 'mm'],
        [[t('result.entry_length'), ' ', ...sym('L', 'vr')], '/entry_length_mm', 'mm'],
        [[t('result.steady_width'), ' ', ...sym('W')], '/steady_width_mm', 'mm'],
        [[t('result.working_stroke'), ' ', ...sym('L', 'rx')], '/working_stroke_mm', 'mm'],
      ],
      LENGTH,
    ),
  ];
  const scheme = body.scheme;
  if (!scheme || !scheme.entry) {
    parts.push(noDiagram(t('result.no_scheme')));
    return parts;
  }
  parts.push(entryScheme(scheme, body, container));
  if (scheme.exit) parts.push(exitScheme(scheme, body, container));
  return parts;
}

// Frame coordinates (X against the feed, Y lateral) to screen: the feed runs left to right and
// Y points up, so screen = (-X, -Y) (a half turn, no mirror).
const toScreen = (x, y) => [-x, -y];

function positionsByName(frame) {
  const byName = {};
  for (const p of frame.positions ?? []) byName[p.name] = p;
  return byName;
}

// Geometry common to both schemes: workpiece, band, strip edges, contour, cutters.
function drawFrame(svg, frame, radius, names, box) {
  const outline = mapped(frame.workpiece_outline ?? [], toScreen);
  svg.append(
    s('polygon', { 'data-role': 'workpiece', class: 's-workpiece', points: points(outline) }),
  );

  const [bandTop, bandBottom] = [-frame.band.y_max_mm, -frame.band.y_min_mm];
  svg.append(
    s(
      'g',
      { 'data-role': 'band' },
      s('rect', {
        class: 's-band',
        x: box.minX,
        y: bandTop,
        width: box.width,
        height: bandBottom - bandTop,
      }),
      s('line', { class: 's-band-edge', x1: box.minX, y1: bandTop, x2: box.maxX, y2: bandTop }),
      s('line', {
        class: 's-band-edge',
        x1: box.minX,
        y1: bandBottom,
        x2: box.maxX,
        y2: bandBottom,
      }),
    ),
  );
  const strip = s('g', { 'data-role': 'strip', 'aria-hidden': 'true' });
  for (const yv of [frame.strip.y_min_mm, frame.strip.y_max_mm]) {
    strip.append(
      s('line', { class: 's-strip-edge', x1: box.minX, y1: -yv, x2: box.maxX, y2: -yv }),
    );
  }
  svg.append(strip);
  svg.append(
    s('polyline', {
      'data-role': 'contour',
      class: 's-contour',
      points: points(mapped(frame.contour, toScreen)),
    }),
  );
  const byName = positionsByName(frame);
  for (const [name, role] of names) {
    const p = byName[name];
    if (!p) continue;
    const [cx, cy] = toScreen(p.x_mm, p.y_mm);
    svg.append(
      s(
        'g',
        { 'data-role': role },
        s('circle', { class: `s-cutter s-${role}`, cx, cy, r: radius }),
        s('circle', { class: `s-axis-dot s-${role}`, cx, cy, r: radius * 0.06 }),
      ),
    );
  }
}

// Origin of the frame with the X (against the feed) and Y directions, and the feed direction.
function drawAxesHint(svg, size, feedAt) {
  const g = s('g', { 'data-role': 'frame-axes' });
  g.append(
    s('line', { class: 's-frame', x1: 0, y1: 0, x2: -size, y2: 0 }),
    arrowHead(-size, 0, -1, 0, size * 0.25),
  );
  g.append(
    s('line', { class: 's-frame', x1: 0, y1: 0, x2: 0, y2: -size }),
    arrowHead(0, -size, 0, -1, size * 0.25),
  );
  g.append(s('text', { x: -size, y: 0, dy: '1.1em', 'text-anchor': 'middle' }, 'X'));
  g.append(s('text', { x: 0, y: -size, dx: '0.4em', dy: '0.3em' }, 'Y'));
  g.append(s('circle', { class: 's-vertex', cx: 0, cy: 0, r: size * 0.07 }));
  svg.append(g);
  const [fx, fy] = feedAt;
  svg.append(
    s(
      'g',
      { 'data-role': 'feed' },
      s('line', { class: 's-feed', x1: fx, y1: fy, x2: fx + size * 1.6, y2: fy }),
      arrowHead(fx + size * 1.6, fy, 1, 0, size * 0.3),
      s('text', { x: fx + size * 1.6, y: fy, dx: '0.3em', dy: '0.35em' }, t('diagram.feed')),
    ),
  );
}

function geometryBounds(frame, radius) {
  const box = new Bounds();
  box.addAll(mapped(frame.workpiece_outline ?? [], toScreen));
  box.addAll(mapped(frame.contour ?? [], toScreen));
  for (const p of frame.positions ?? []) box.addCircle(...toScreen(p.x_mm, p.y_mm), radius);
  box.add(...toScreen(0, frame.strip.y_min_mm)).add(...toScreen(0, frame.strip.y_max_mm));
  box.add(0, 0);
  return box;
}

// The drawing area of one scheme: the geometry with room for a dimension row below it (and above
// it with `withTopRow`), the feed arrow above, and the frame's axes hint at its origin.
function schemeLayout(frame, radius, container, withTopRow) {
  const box = geometryBounds(frame, radius);
  const upp = unitsPerPixel(box.width * 1.12, container);
  const em = 12.5 * upp;
  const gap = 2.6 * em;
  const topRow = box.minY - gap;
  const bottomRow = box.maxY + gap;
  const axisSize = 3 * em;
  const feedAt = [box.minX, (withTopRow ? topRow : box.minY) - 2 * em];
  box.add(box.minX, feedAt[1] - em).add(box.minX, bottomRow + 0.5 * em);
  box.add(feedAt[0] + axisSize * 1.6 + 4 * em, feedAt[1]);
  box.add(-axisSize - em, 0).add(0, -axisSize - em);
  return { box, upp, topRow, bottomRow, axisSize, feedAt };
}

function entryScheme(scheme, body, container) {
  const frame = scheme.entry;
  const radius = scheme.cutter_radius_mm;
  const byName = positionsByName(frame);
  const start = byName.start;
  const saturation = byName.saturation;
  const { box, upp, topRow, bottomRow, axisSize, feedAt } = schemeLayout(
    frame,
    radius,
    container,
    true,
  );

  const svg = diagram(
    'entry-scheme',
    t('diagram.entry_scheme_title'),
    box.viewBox(0.03),
  );
  drawFrame(
    svg,
    frame,
    radius,
    [
      ['start', 'cutter-start'],
      ['first_contact', 'cutter-first-contact'],
      ['saturation', 'cutter-saturation'],
    ],
    box,
  );
  if (start && saturation) {
    const [x1, y1] = toScreen(start.x_mm, start.y_mm);
    const [x2, y2] = toScreen(saturation.x_mm, saturation.y_mm);
    svg.append(
      horizontalDimension({
        role: 'dimension-lvr',
        x1,
        x2,
        y: topRow,
        from1: y1,
        from2: y2,
        text: subText('L', 'vr', ` = ${lengthText(body.entry_length_mm)}`),
        arrow: 8 * upp,
      }),
    );
    svg.append(
      horizontalDimension({
        role: 'dimension-xn',
        x1: 0,
        x2: x1,
        y: bottomRow,
        from1: 0,
        from2: y1,
        text: subText('X', 'n', ` = ${lengthText(start.x_mm)}`),
        arrow: 8 * upp,
      }),
    );
  }
  drawAxesHint(svg, axisSize, feedAt);
  return figure(
    svg,
    [
      { cls: 's-workpiece', label: t('legend.workpiece'), shape: 'area' },
      { cls: 's-contour', label: t('legend.entry_contour') },
      { cls: 's-band', label: t('legend.steady_band'), shape: 'area' },
      { cls: 's-cutter s-cutter-start', label: t('legend.cutter_at_start') },
      { cls: 's-cutter s-cutter-first-contact', label: t('legend.first_contact') },
      { cls: 's-cutter s-cutter-saturation', label: t('legend.saturation') },
    ],
    t('diagram.entry_frame'),
  );
}

function exitScheme(scheme, body, container) {
  const frame = scheme.exit;
  const radius = scheme.cutter_radius_mm;
  const end = positionsByName(frame).end;
  const { box, upp, bottomRow, axisSize, feedAt } = schemeLayout(frame, radius, container, false);

  const svg = diagram(
    'exit-scheme',
    t('diagram.exit_scheme_title'),
    box.viewBox(0.03),
  );
  drawFrame(svg, frame, radius, [['end', 'cutter-end']], box);
  if (end) {
    const [x1, y1] = toScreen(end.x_mm, end.y_mm);
    svg.append(
      horizontalDimension({
        role: 'dimension-xk',
        x1: 0,
        x2: x1,
        y: bottomRow,
        from1: 0,
        from2: y1,
        text: subText('X', 'k', ` = ${lengthText(end.x_mm)}`),
        arrow: 8 * upp,
      }),
    );
  }
  drawAxesHint(svg, axisSize, feedAt);
  return figure(
    svg,
    [
      { cls: 's-workpiece', label: t('legend.workpiece'), shape: 'area' },
      { cls: 's-contour', label: t('legend.exit_contour') },
      { cls: 's-band', label: t('legend.steady_band'), shape: 'area' },
      { cls: 's-cutter s-cutter-end', label: t('legend.cutter_at_the_end') },
    ],
    t('diagram.exit_frame'),
  );
}

// ------------------------------------------------------------------ the setup (main-time)

function timeResults(body) {
  const passes = Array.isArray(body.lateral_passes) ? body.lateral_passes : [];
  const depths = Array.isArray(body.depth_passes_mm) ? body.depth_passes_mm : [];
  const finish = body.finish && typeof body.finish === 'object' ? body.finish : null;
  // [key, label, unit, pointer of pass i]: the pass's own member, or (with a finishing level) the
  // time of its finishing traverse.
  const columns = [
    ['width_mm', [t('result.width'), ' ', ...sym('W', 'i')], 'mm'],
    ['axis_y_mm', [t('result.axis'), ' ', ...sym('Y')], 'mm'],
    ['offset_mm', [t('result.offset'), ' ', ...sym('K', 'i')], 'mm'],
    ['entry_length_mm', [t('result.entry_length'), ' ', ...sym('L', 'vr')], 'mm'],
    ['working_stroke_mm', [t('result.stroke'), ' ', ...sym('L', 'rx')], 'mm'],
    ['entry_time_min', [t('result.entry_time')], 'min'],
    ['steady_time_min', [t('result.steady_time')], 'min'],
    ['time_min', [t('result.time')], 'min'],
  ].map(([key, label, unit]) => [key, label, unit, (i) => `/lateral_passes/${i}/${key}`]);
  if (finish) {
    columns.push([
      'finish_time_min',
      [t('result.finishing_time_of_pass'), ' ', ...sym('t', 'i,f')],
      'min',
      (i) => `/finish/lateral_passes/${i}/time_min`,
    ]);
  }
  const table = h(
    'table',
    {},
    h(
      'caption',
      { class: 'source-note' },
      t('result.lateral_passes'),
    ),
    h(
      'thead',
      {},
      h(
        'tr',
        {},
        h('th', { scope: 'col' }, t('result.pass')),
        columns.map(([, label, unit]) =>
          h('th', { scope: 'col' }, label, h('br'), h('span', { class: 'unit' }, unitText(unit))),
        ),
      ),
    ),
    h(
      'tbody',
      {},
      passes.map((_, i) =>
        h(
          'tr',
          {},
          h('th', { scope: 'row' }, String(i + 1)),
          columns.map(([, , unit, pointer]) =>
            h('td', {}, value(body, pointer(i), unit, TIME, undefined, true)),
          ),
        ),
      ),
    ),
  );
  return [
    h('h3', {}, t('result.main_time_of_setup')),
    h(
      'p',
      { class: 'source-note' },
      t('result.from_main_time'),
    ),
    valueList(
      body,
      [
        [[t('result.main_time'), ' ', ...sym('T', 'o')], '/main_time_min', 'min'],
        [[t('result.at_entry_feed')], '/entry_time_min', 'min'],
        [[t('result.at_steady_feed')], '/steady_time_min', 'min'],
        [[t('result.spindle_speed'), ' ', ...sym('n')], '/spindle_speed_rpm', 'rpm'],
        [
          [t('result.feed_per_rev'), ' ', ...sym('S', 'o'), ...iso('f')],
          '/feed_per_rev_mm',
          'mm_per_rev',
        ],
        [
          [t('result.feed'), ' ', ...sym('S', 'm2'), ...iso('v', 'f')],
          '/feed_mm_per_min',
          'mm_per_min',
        ],
        [
          [t('result.entry_feed'), ' ', ...sym('S', 'm1'), ...iso('v', 'f1')],
          '/entry_feed_mm_per_min',
          'mm_per_min',
        ],
      ],
      TIME,
    ),
    h(
      'p',
      {},
      t('result.depth_passes'),
      depths.map((_, i) => [i ? ', ' : '', value(body, `/depth_passes_mm/${i}`, 'mm', TIME)]),
      finish ? t('result.last_is_finishing') : null,
    ),
    ...(finish ? finishResults(body) : []),
    h('div', { class: 'table-wrap' }, table),
    csvButton(
      'entry-passes-csv',
      'main-time-passes.csv',
      [['pass', ''], ...columns.map(([key, , unit]) => [key, csvUnit(unit)])],
      passes.map((_, i) => [i + 1, ...columns.map(([, , , pointer]) => at(body, pointer(i)))]),
    ),
  ];
}

// The finishing level of section 15 (E39-E41): its depth, speed, feeds and times.
function finishResults(body) {
  return [
    h('h4', {}, t('result.finishing_level')),
    valueList(
      body,
      [
        [[t('result.finishing_depth'), ' ', ...sym('t', 'f')], '/finish/depth_mm', 'mm'],
        [[t('result.finishing_time')], '/finish/time_min', 'min'],
        [[t('result.at_entry_feed')], '/finish/entry_time_min', 'min'],
        [[t('result.at_steady_feed')], '/finish/steady_time_min', 'min'],
        [[t('result.spindle_speed'), ' ', ...sym('n', 'f')], '/finish/spindle_speed_rpm', 'rpm'],
        [
          [t('result.feed_per_rev'), ' ', ...sym('S', 'of'), ...iso('f')],
          '/finish/feed_per_rev_mm',
          'mm_per_rev',
        ],
        [
          [t('result.feed'), ' ', ...sym('S', 'm2f'), ...iso('v', 'f')],
          '/finish/feed_mm_per_min',
          'mm_per_min',
        ],
        [
          [t('result.entry_feed'), ' ', ...sym('S', 'm1f'), ...iso('v', 'f1')],
          '/finish/entry_feed_mm_per_min',
          'mm_per_min',
        ],
      ],
      TIME,
    ),
  ];
}
