// Polygon-hole G-code (paper 004): the program, its figures, the predicted hole and its corner,
// and the program as a .ngc download (the same request with Accept: text/plain).

import { onCalculate } from './calculation.js';
import {
  fmt,
  h,
  noDiagram,
  readBody,
  downloadProgram,
  showFailure,
  sym,
  valueList,
  warningList,
} from './form.js';
import { Bounds, diagram, figure, mapped, points, s, unitsPerPixel } from './svg.js';
import { t } from './i18n.js';
import { fromApi, unitText } from './units.js';

const PATH = '/v1/polygon-hole/gcode';

export function init() {
  const form = document.getElementById('polygon-form');
  const result = document.getElementById('polygon-result');
  const download = document.getElementById('polygon-download');
  // The program's <pre> is part of the page from the start (hidden until there is a program).
  const program = document.getElementById('polygon-program');
  let calculated = null; // the body of the last successful calculation

  const calculator = onCalculate(form, async (api) => {
    const body = withoutDefaultProgram(readBody(form));
    const answer = await api.postJson(PATH, { ...body, include_geometry: true });
    result.replaceChildren();
    if (!answer.ok) {
      calculated = null;
      download.disabled = true;
      showFailure(form, answer);
      program.textContent = '';
      delete program.dataset.fileName;
      program.hidden = true;
      result.append(
        h('p', { class: 'placeholder' }, t('result.no_results')),
        program,
      );
      return;
    }
    calculated = body;
    download.disabled = false;
    program.textContent = answer.json.program;
    program.dataset.fileName = answer.json.file_name;
    program.hidden = false;
    result.append(...programResults(answer, result), h('h3', {}, t('result.g_code')), program);
  });

  download.addEventListener('click', async () => {
    if (!calculated) return;
    download.disabled = true;
    try {
      await downloadProgram(form, PATH, calculated, 'polygon-hole.ngc');
    } finally {
      download.disabled = calculated === null;
    }
  });
  return calculator;
}

function programResults(answer, container) {
  const body = answer.json;
  const parts = [
    h('h3', {}, t('result.program_and_hole')),
    valueList(body, [
      [[t('result.eccentricity'), ' ', ...sym('e')], '/eccentricity_mm', 'mm'],
      [[t('result.loop_length'), ' ', ...sym('L', 'p')], '/loop_length_mm', 'mm'],
      [[t('result.feed_per_revolution'), ' ', ...sym('f')], '/feed_per_rev_mm', 'mm_per_rev'],
      [[t('result.arc_blocks_per_loop')], '/blocks_per_loop', ''],
      [[t('result.largest_path_deviation')], '/max_path_deviation_mm', 'mm'],
      [[t('result.predicted_overcut')], '/predicted_overcut_mm', 'mm'],
      [[t('result.corner_gap'), ' ', ...sym('g')], '/corner_gap_mm', 'mm'],
      [[t('result.uncut_corner_area')], '/uncut_corner_area_mm2', 'mm2'],
      [
        [t('result.block_rate_feed_limit'), ' ', ...sym('v', 'f')],
        '/max_feed_by_block_rate_mm_per_min',
        'mm_per_min',
      ],
    ]),
  ];
  parts.push(warningList(body));
  const geometry = body.geometry;
  if (geometry && Array.isArray(geometry.polygon) && Array.isArray(geometry.predicted_hole)) {
    parts.push(holeDiagram(geometry, container), cornerDiagram(geometry, body));
  } else {
    parts.push(noDiagram(t('result.no_geometry')));
  }
  return parts;
}

// Program coordinates (Y up) to screen.
const toScreen = (x, y) => [x, -y];

// The corner detail frames the material side of the vertex: the window's centre sits half a view
// radius from the vertex towards the hole centre, so the corner wall fills it instead of a quarter.
function cornerWindow(corner) {
  const [vx, vy] = toScreen(corner.vertex.x_mm, corner.vertex.y_mm);
  const radius = corner.view_radius_mm;
  const length = Math.hypot(vx, vy);
  const [ux, uy] = length > 0 ? [-vx / length, -vy / length] : [0, 0];
  const half = 0.75 * radius;
  return { vx, vy, radius, half, cx: vx + 0.5 * radius * ux, cy: vy + 0.5 * radius * uy };
}

function holeDiagram(geometry, container) {
  const polygon = mapped(geometry.polygon, toScreen);
  const hole = mapped(geometry.predicted_hole, toScreen);
  const path = mapped(geometry.centre_path ?? [], toScreen);
  const rotors = Array.isArray(geometry.rotor_positions) ? geometry.rotor_positions : [];
  const box = new Bounds().addAll(polygon).addAll(hole).addAll(path);
  rotors.forEach((r) => box.addAll(mapped(r.outline ?? [], toScreen)));
  const detail = geometry.corner?.vertex && geometry.corner.view_radius_mm > 0
    ? cornerWindow(geometry.corner)
    : null;
  if (detail) box.addCircle(detail.cx, detail.cy, Math.SQRT2 * detail.half);
  const viewBox = box.viewBox(0.05);
  const upp = unitsPerPixel(viewBox[2], container);
  const svg = diagram(
    'polygon-hole',
    t('diagram.hole_title'),
    viewBox,
  );
  svg.append(
    s('polygon', {
      'data-role': 'predicted-hole',
      class: 's-predicted-hole',
      points: points(hole),
    }),
  );
  svg.append(s('polygon', { 'data-role': 'polygon', class: 's-polygon', points: points(polygon) }));
  rotors.forEach((rotor) => {
    const [ax, ay] = toScreen(rotor.axis.x_mm, rotor.axis.y_mm);
    svg.append(
      s(
        'g',
        { 'data-role': 'rotor', 'data-phase-deg': rotor.phase_deg },
        s('polygon', { class: 's-rotor', points: points(mapped(rotor.outline ?? [], toScreen)) }),
        s('circle', { class: 's-rotor s-axis-dot', cx: ax, cy: ay, r: 3 * upp }),
      ),
    );
  });
  svg.append(
    s('polygon', { 'data-role': 'centre-path', class: 's-centre-path', points: points(path) }),
  );
  svg.append(
    s(
      'g',
      { 'data-role': 'hole-centre', 'aria-hidden': 'true' },
      s('line', { class: 's-frame', x1: -6 * upp, y1: 0, x2: 6 * upp, y2: 0 }),
      s('line', { class: 's-frame', x1: 0, y1: -6 * upp, x2: 0, y2: 6 * upp }),
    ),
  );
  if (detail) {
    svg.append(
      s('rect', {
        'data-role': 'corner-detail',
        class: 's-dimension-extension',
        x: detail.cx - detail.half,
        y: detail.cy - detail.half,
        width: 2 * detail.half,
        height: 2 * detail.half,
        fill: 'none',
      }),
    );
  }
  return figure(
    svg,
    [
      { cls: 's-polygon', label: t('legend.ideal_polygon') },
      { cls: 's-predicted-hole', label: t('legend.predicted_hole'), shape: 'area' },
      { cls: 's-centre-path', label: t('legend.tool_axis_path') },
      { cls: 's-rotor', label: t('legend.rotor', { count: rotors.length }) },
    ],
    t('diagram.hole_caption'),
  );
}

function cornerDiagram(geometry, body) {
  const corner = geometry.corner;
  if (!corner?.vertex || !(corner.view_radius_mm > 0))
    return noDiagram(t('result.no_corner'));
  const { vx, vy, radius, half, cx, cy } = cornerWindow(corner);
  const viewBox = [cx - half, cy - half, 2 * half, 2 * half];
  const svg = diagram(
    'polygon-corner',
    t('diagram.corner_title'),
    viewBox,
  );
  svg.append(
    s('polygon', {
      'data-role': 'predicted-hole',
      class: 's-predicted-hole',
      points: points(mapped(geometry.predicted_hole, toScreen)),
    }),
    s('polygon', {
      'data-role': 'polygon',
      class: 's-polygon',
      points: points(mapped(geometry.polygon, toScreen)),
    }),
    s('circle', { class: 's-vertex', cx: vx, cy: vy, r: radius * 0.015 }),
    s(
      'text',
      { x: cx - half, y: cy - half, dx: '0.5em', dy: '1.3em' },
      t('diagram.corner_gap', {
        value: fmt(fromApi(body.corner_gap_mm, 'mm')),
        unit: unitText('mm'),
      }),
    ),
  );
  return figure(svg, [
    { cls: 's-polygon', label: t('legend.ideal_polygon') },
    { cls: 's-predicted-hole', label: t('legend.predicted_hole'), shape: 'area' },
  ]);
}

// The `program` object only when it asks for something: without it the service writes today's
// LinuxCNC mm program, byte for byte.
function withoutDefaultProgram(body) {
  const p = body.program ?? {};
  const plain =
    (p.dialect ?? 'linuxcnc') === 'linuxcnc' &&
    (p.units ?? 'mm') === 'mm' &&
    p.tool_number === undefined &&
    !p.tool_length_offset;
  if (plain) delete body.program;
  return body;
}
