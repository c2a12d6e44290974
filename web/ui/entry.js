// Entry length and main time (paper 002, the Vitebsk calculator): one form drives
// POST /v1/entry-length (one pass, with its scheme for the drawings) and POST /v1/main-time
// (every lateral and depth pass).

import { RawNumber } from './api.js';
import { onCalculate } from './calculation.js';
import { csvButton } from './export.js';
import {
  h,
  noDiagram,
  readBody,
  downloadProgram,
  showFailure,
  sym,
  value,
  valueList,
  wireContourFields,
  fmt,
} from './form.js';
import {
  arrowHead,
  Bounds,
  diagram,
  figure,
  horizontalDimension,
  mapped,
  points,
  s,
  unitsPerPixel,
} from './svg.js';

const LENGTH = 'entry-length';
const TIME = 'main-time';
const PROGRAM = 'program';
const PROGRAM_PATH = '/v1/main-time/program';

export function init() {
  const form = document.getElementById('entry-form');
  const result = document.getElementById('entry-result');
  const download = document.getElementById('entry-download');
  let programRequest = null; // the body of the last program that was written
  wireContourFields(form);
  const calculator = onCalculate(form, async (api) => {
    // The pass program takes the main-time request plus the `program` options.
    const programBody = { ...readBody(form, TIME), ...readBody(form, PROGRAM) };
    // A program needs a straight path: with an extra path L1 the page does not ask for one.
    const extra = programBody.extra_path_mm;
    const straight = extra === undefined || (extra instanceof RawNumber && Number(extra.text) === 0);
    const [length, time, program] = await Promise.all([
      api.postWithOptIn('/v1/entry-length', readBody(form, LENGTH), 'include_scheme', true),
      api.postJson('/v1/main-time', readBody(form, TIME)),
      straight ? api.postJson(PROGRAM_PATH, programBody) : Promise.resolve(null),
    ]);
    if (!length.ok) showFailure(form, length, 'Entry length');
    if (!time.ok) showFailure(form, time, 'Main time');
    // The program repeats main-time's own errors: only its own are shown.
    if (time.ok && program && !program.ok) showFailure(form, program, 'Program');
    programRequest = program?.ok ? programBody : null;
    download.disabled = programRequest === null;
    result.replaceChildren();
    if (length.ok) result.append(...lengthResults(length, result));
    if (time.ok) result.append(...timeResults(time.json));
    if (program?.ok) result.append(...programResults(program.json));
    if (time.ok && !straight) {
      result.append(
        h('p', { class: 'source-note' }, 'No program: a program needs a straight path (L1 = 0).'),
      );
    }
    if (!length.ok && !time.ok) {
      result.append(h('p', { class: 'placeholder' }, 'No results: see the messages in the form.'));
    }
  });

  download.addEventListener('click', async () => {
    if (!programRequest) return;
    download.disabled = true;
    try {
      await downloadProgram(form, PROGRAM_PATH, programRequest, 'CUTCALC.ngc');
    } finally {
      download.disabled = programRequest === null;
    }
  });
  return calculator;
}

// ------------------------------------------------------------------ the program (main-time/program)

function programResults(body) {
  const warnings = Array.isArray(body.warnings) ? body.warnings : [];
  return [
    h('h3', {}, 'Program'),
    h(
      'p',
      { class: 'source-note' },
      `From ${PROGRAM_PATH}: ${body.dialect}, ${body.units}, file ${body.file_name}. `,
      'The feed switches from the entry feed to the steady feed at the end of each entry section, ',
      'so the feed time is the main time.',
    ),
    valueList(
      body,
      [
        [['Passes (lateral \u00d7 depth)'], '/passes', ''],
        [['Feed time (= main time)'], '/working_time_min', 'min'],
        [['Plunges'], '/plunge_time_min', 'min'],
        [['Rapids'], '/rapid_time_min', 'min'],
        [['Cycle time'], '/cycle_time_min', 'min'],
      ],
      PROGRAM,
    ),
    h(
      'p',
      { class: 'source-note' },
      `Not in the times: ${(body.not_modelled ?? []).join(', ').replaceAll('_', ' ')}.`,
    ),
    warnings.length
      ? h(
          'ul',
          { class: 'warnings' },
          warnings.map((w, i) => h('li', {}, value(body, `/warnings/${i}/code`), ': ', w.detail)),
        )
      : [],
    h(
      'pre',
      {
        id: 'entry-program',
        tabindex: '0',
        'aria-label': 'G-code program',
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
    h('h3', {}, 'One pass: coordinates and entry length'),
    h('p', { class: 'source-note' }, 'From /v1/entry-length (offset K, the whole strip).'),
    valueList(
      body,
      [
        [['Start ', ...sym('X', 'n')], '/start/x_mm', 'mm'],
        [['Start ', ...sym('Y', 'n')], '/start/y_mm', 'mm'],
        [['End ', ...sym('X', 'k')], '/end/x_mm', 'mm'],
        [['End ', ...sym('Y', 'k')], '/end/y_mm', 'mm'],
        [['Engagement length ', ...sym('L', 'vr1')], '/engagement_length_mm', 'mm'],
        [['Entry length ', ...sym('L', 'vr')], '/entry_length_mm', 'mm'],
        [['Steady width W'], '/steady_width_mm', 'mm'],
        [['Working stroke ', ...sym('L', 'rx')], '/working_stroke_mm', 'mm'],
      ],
      LENGTH,
    ),
  ];
  const scheme = body.scheme;
  if (!scheme || !scheme.entry) {
    parts.push(
      noDiagram(
        answer.optInRefused
          ? 'this service does not return the entry scheme yet.'
          : 'the answer has no scheme.',
      ),
    );
    return parts;
  }
  parts.push(entryScheme(scheme, body, container));
  if (scheme.exit) parts.push(exitScheme(scheme, body, container));
  return parts;
}

// Frame coordinates (X against the feed, Y lateral) to screen: the feed runs left to right and
// Y points up, so screen = (-X, -Y) (a half turn, no mirror).
const toScreen = (x, y) => [-x, -y];

function subText(base, sub, rest) {
  return [
    base,
    s('tspan', { 'baseline-shift': 'sub', 'font-size': '0.75em' }, sub),
    s('tspan', {}, rest),
  ];
}

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
      s('text', { x: fx + size * 1.6, y: fy, dx: '0.3em', dy: '0.35em' }, 'feed'),
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
    'Entry scheme to scale: workpiece, contour, steady band and the cutter at start, first contact and saturation',
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
        text: subText('L', 'vr', ` = ${fmt(body.entry_length_mm)} mm`),
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
        text: subText('X', 'n', ` = ${fmt(start.x_mm)} mm`),
        arrow: 8 * upp,
      }),
    );
  }
  drawAxesHint(svg, axisSize, feedAt);
  return figure(
    svg,
    [
      { cls: 's-workpiece', label: 'workpiece', shape: 'area' },
      { cls: 's-contour', label: 'entry contour' },
      { cls: 's-band', label: 'steady band', shape: 'area' },
      { cls: 's-cutter s-cutter-start', label: 'cutter at start' },
      { cls: 's-cutter s-cutter-first-contact', label: 'first contact' },
      { cls: 's-cutter s-cutter-saturation', label: 'saturation' },
    ],
    'Entry frame: X against the feed from the entry origin, Y across the strip; to scale.',
  );
}

function exitScheme(scheme, body, container) {
  const frame = scheme.exit;
  const radius = scheme.cutter_radius_mm;
  const end = positionsByName(frame).end;
  const { box, upp, bottomRow, axisSize, feedAt } = schemeLayout(frame, radius, container, false);

  const svg = diagram(
    'exit-scheme',
    'Exit scheme to scale: workpiece, exit contour, steady band and the cutter at the end position',
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
        text: subText('X', 'k', ` = ${fmt(end.x_mm)} mm`),
        arrow: 8 * upp,
      }),
    );
  }
  drawAxesHint(svg, axisSize, feedAt);
  return figure(
    svg,
    [
      { cls: 's-workpiece', label: 'workpiece', shape: 'area' },
      { cls: 's-contour', label: 'exit contour' },
      { cls: 's-band', label: 'steady band', shape: 'area' },
      { cls: 's-cutter s-cutter-end', label: 'cutter at the end' },
    ],
    'Exit frame: X against the feed from the exit origin; to scale.',
  );
}

// ------------------------------------------------------------------ the setup (main-time)

function timeResults(body) {
  const passes = Array.isArray(body.lateral_passes) ? body.lateral_passes : [];
  const depths = Array.isArray(body.depth_passes_mm) ? body.depth_passes_mm : [];
  const columns = [
    ['width_mm', ['Width ', ...sym('W', 'i')], 'mm'],
    ['axis_y_mm', ['Axis Y'], 'mm'],
    ['offset_mm', ['Offset ', ...sym('K', 'i')], 'mm'],
    ['entry_length_mm', ['Entry length ', ...sym('L', 'vr')], 'mm'],
    ['working_stroke_mm', ['Stroke ', ...sym('L', 'rx')], 'mm'],
    ['entry_time_min', ['Entry time'], 'min'],
    ['steady_time_min', ['Steady time'], 'min'],
    ['time_min', ['Time'], 'min'],
  ];
  const table = h(
    'table',
    {},
    h(
      'caption',
      { class: 'source-note' },
      'Lateral passes, one traverse each (repeated at every depth level)',
    ),
    h(
      'thead',
      {},
      h(
        'tr',
        {},
        h('th', { scope: 'col' }, 'Pass'),
        columns.map(([, label, unit]) =>
          h('th', { scope: 'col' }, label, h('br'), h('span', { class: 'unit' }, unit)),
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
          columns.map(([key]) => h('td', {}, value(body, `/lateral_passes/${i}/${key}`, '', TIME))),
        ),
      ),
    ),
  );
  return [
    h('h3', {}, 'Main time of the setup'),
    h(
      'p',
      { class: 'source-note' },
      'From /v1/main-time (every lateral pass at every depth level).',
    ),
    valueList(
      body,
      [
        [['Main time ', ...sym('T', 'o')], '/main_time_min', 'min'],
        [['at the entry feed'], '/entry_time_min', 'min'],
        [['at the steady feed'], '/steady_time_min', 'min'],
        [['Spindle speed n'], '/spindle_speed_rpm', 'rev/min'],
        [['Feed per rev ', ...sym('S', 'o')], '/feed_per_rev_mm', 'mm/rev'],
        [['Feed ', ...sym('S', 'm2')], '/feed_mm_per_min', 'mm/min'],
        [['Entry feed ', ...sym('S', 'm1')], '/entry_feed_mm_per_min', 'mm/min'],
      ],
      TIME,
    ),
    h(
      'p',
      {},
      'Depth passes: ',
      depths.map((_, i) => [i ? ', ' : '', value(body, `/depth_passes_mm/${i}`, 'mm', TIME)]),
    ),
    h('div', { class: 'table-wrap' }, table),
    csvButton(
      'entry-passes-csv',
      'main-time-passes.csv',
      [['pass', ''], ...columns.map(([key, , unit]) => [key, unit])],
      passes.map((pass, i) => [i + 1, ...columns.map(([key]) => pass[key])]),
    ),
  ];
}
