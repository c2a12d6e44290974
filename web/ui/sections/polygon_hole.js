// Polygon-hole G-code (paper 004): the program, its figures, the predicted hole and its corner,
// the rotor dimensioned for grinding it, the machining time, and the program as a .ngc download
// (the same request with Accept: text/plain).

import { fmt, h, noDiagram, sym, value, valueList, warningList } from '../core/form.js';
import {
  Bounds,
  diagram,
  figure,
  horizontalDimension,
  mapped,
  points,
  s,
  unitsPerPixel,
} from '../core/svg.js';
import { programSection } from '../core/program_section.js';
import { t } from '../core/i18n.js';
import { machineTimeLine } from '../core/machine.js';
import { fromApi, unitText } from '../core/units.js';

const PATH = '/v1/polygon-hole/gcode';

export function init() {
  return programSection({
    id: 'polygon',
    path: PATH,
    machine: 'mill',
    axes: (body) => (body.synchronization === 'c_axis' ? ['x', 'y', 'z', 'c'] : ['x', 'y', 'z']),
    fileName: 'polygon-hole.ngc',
    request: (body) => ({ ...withoutDefaultProgram(body), include_geometry: true }),
    // The download asks for the same program (and machine time) without the geometry.
    downloaded: (sent) => {
      const request = { ...sent };
      delete request.include_geometry;
      return request;
    },
    results: (json, { note, result, program }) => [
      ...programResults(json, result, note),
      h('h3', {}, t('result.g_code')),
      program,
    ],
  });
}

function programResults(body, container, machineNote) {
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
  parts.push(
    h('h3', {}, t('result.machining_time')),
    valueList(body, [
      [[t('result.working_time')], '/working_time_min', 'min'],
      [[t('result.plunge_time')], '/plunge_time_min', 'min'],
      [[t('result.rapid_time')], '/rapid_time_min', 'min'],
      [[t('result.cycle_time')], '/cycle_time_min', 'min'],
    ]),
    machineTimeLine(body, machineNote),
  );
  parts.push(warningList(body));
  const geometry = body.geometry;
  if (geometry && Array.isArray(geometry.polygon) && Array.isArray(geometry.predicted_hole)) {
    parts.push(holeDiagram(geometry, container), cornerDiagram(geometry, body));
  } else {
    parts.push(noDiagram(t('result.no_geometry')));
  }
  parts.push(...rotorResults(body, container));
  return parts;
}

// ------------------------------------------------------------------ the rotor (P28-P31)

function rotorResults(body, container) {
  const rotor = body.rotor;
  if (!rotor || !Array.isArray(rotor.flank_arcs)) return [];
  return [
    h('h3', {}, t('result.rotor_tool')),
    valueList(body, [
      [[t('result.rotor_corners'), ' ', ...sym('M')], '/rotor/corners', ''],
      [
        [t('result.corner_circle_diameter'), ' ', ...sym('2r')],
        '/rotor/corner_circle_diameter_mm',
        'mm',
      ],
      [[t('result.rotor_corner_angle')], '/rotor/corner_angle_deg', 'deg'],
      [[t('result.width_min')], '/rotor/width_min_mm', 'mm'],
      [[t('result.width_max')], '/rotor/width_max_mm', 'mm'],
      [[t('result.largest_neck')], '/rotor/neck_diameter_max_mm', 'mm'],
      [[t('result.hole_corner_radius'), ' ', ...sym('\u03c1', 'c')], '/corner_radius_mm', 'mm'],
    ]),
    flankTable(body),
    rotorDiagram(rotor, container),
  ];
}

// The flank arcs between corner 0 and corner 1, rotor frame (the other flanks are it turned).
function flankTable(body) {
  const columns = [
    ['radius_mm', [t('result.flank_radius'), ' ', ...sym('R', 'm')], 'mm'],
    ['centre/x_mm', [t('result.flank_centre'), ' ', ...sym('X')], 'mm'],
    ['centre/y_mm', [t('result.flank_centre'), ' ', ...sym('Y')], 'mm'],
    ['start_angle_deg', [t('result.normal_from')], 'deg'],
    ['end_angle_deg', [t('result.normal_to')], 'deg'],
  ];
  return h(
    'div',
    { class: 'table-wrap' },
    h(
      'table',
      { 'data-role': 'rotor-flank-arcs' },
      h('caption', { class: 'source-note' }, t('result.flank_arcs_caption')),
      h(
        'thead',
        {},
        h(
          'tr',
          {},
          h('th', { scope: 'col' }, ...sym('m')),
          columns.map(([, label, unit]) =>
            h('th', { scope: 'col' }, label, h('br'), h('span', { class: 'unit' }, unitText(unit))),
          ),
        ),
      ),
      h(
        'tbody',
        {},
        body.rotor.flank_arcs.map((_, i) =>
          h(
            'tr',
            {},
            h('th', { scope: 'row' }, String(i + 1)),
            columns.map(([key, , unit]) =>
              h('td', {}, value(body, `/rotor/flank_arcs/${i}/${key}`, unit, undefined, undefined, true)),
            ),
          ),
        ),
      ),
    ),
  );
}

const DEG = Math.PI / 180;

// The rotor's outline in the rotor frame (mm, Y up): corner v, then the flank arcs after it, each
// flank the first one turned by 360 v / M degrees.
function rotorOutline(rotor) {
  const M = rotor.corners;
  const r = rotor.corner_circle_diameter_mm / 2;
  const outline = [];
  for (let v = 0; v < M; v += 1) {
    const turn = (2 * Math.PI * v) / M;
    const [c, sn] = [Math.cos(turn), Math.sin(turn)];
    const rotate = ([x, y]) => [c * x - sn * y, sn * x + c * y];
    outline.push(rotate([0, -r]));
    for (const arc of rotor.flank_arcs) {
      const steps = 12;
      for (let k = 1; k < steps; k += 1) {
        const b = (arc.start_angle_deg + ((arc.end_angle_deg - arc.start_angle_deg) * k) / steps) * DEG;
        outline.push(
          rotate([arc.centre.x_mm + arc.radius_mm * Math.cos(b), arc.centre.y_mm + arc.radius_mm * Math.sin(b)]),
        );
      }
    }
  }
  return outline;
}

function rotorDiagram(rotor, container) {
  const r = rotor.corner_circle_diameter_mm / 2;
  const neck = rotor.neck_diameter_max_mm / 2;
  if (!(r > 0) || !(neck > 0)) return noDiagram(t('result.no_rotor'));
  const outline = rotorOutline(rotor).map(([x, y]) => toScreen(x, y));
  const gap = 0.25 * r;
  const box = new Bounds().addAll(outline);
  box.addCircle(0, 0, r);
  // Room for the dimension lines above and below and the radius labels on the right.
  box.addAll([
    [-r, -r - 1.6 * gap],
    [1.5 * r, r + 1.6 * gap],
  ]);
  const viewBox = box.viewBox(0.06);
  const upp = unitsPerPixel(viewBox[2], container);
  const mm = (v) => `${fmt(fromApi(v, 'mm'))} ${unitText('mm')}`;
  const svg = diagram('polygon-rotor', t('diagram.rotor_title'), viewBox);
  svg.append(
    s('polygon', { 'data-role': 'rotor', class: 's-rotor', points: points(outline) }),
    s('circle', {
      'data-role': 'corner-circle',
      class: 's-dimension-extension',
      cx: 0,
      cy: 0,
      r,
      fill: 'none',
    }),
    s('circle', {
      'data-role': 'neck-circle',
      class: 's-dimension-extension',
      cx: 0,
      cy: 0,
      r: neck,
      fill: 'none',
    }),
    s('circle', { class: 's-rotor s-axis-dot', cx: 0, cy: 0, r: 3 * upp }),
    horizontalDimension({
      role: 'corner-circle-diameter',
      x1: -r,
      x2: r,
      y: -r - gap,
      from1: 0,
      from2: 0,
      text: t('diagram.rotor_corner_circle', { value: mm(rotor.corner_circle_diameter_mm) }),
      arrow: 8 * upp,
    }),
    horizontalDimension({
      role: 'neck-diameter',
      x1: -neck,
      x2: neck,
      y: r + 1.4 * gap,
      from1: 0,
      from2: 0,
      text: t('diagram.rotor_neck', { value: mm(rotor.neck_diameter_max_mm) }),
      arrow: 8 * upp,
    }),
  );
  // A radius leader to the middle of each different flank arc (arcs m and N-1-m are alike).
  const distinct = rotor.flank_arcs.slice(0, Math.ceil(rotor.flank_arcs.length / 2));
  distinct.forEach((arc, i) => {
    const b = ((arc.start_angle_deg + arc.end_angle_deg) / 2) * DEG;
    const [ox, oy] = toScreen(arc.centre.x_mm, arc.centre.y_mm);
    const [px, py] = toScreen(
      arc.centre.x_mm + arc.radius_mm * Math.cos(b),
      arc.centre.y_mm + arc.radius_mm * Math.sin(b),
    );
    svg.append(
      s(
        'g',
        { 'data-role': 'flank-radius' },
        s('line', { class: 's-dimension', x1: ox, y1: oy, x2: px, y2: py }),
        s(
          'text',
          { x: px, y: py, dx: '0.3em', dy: `${1.2 * i + 1}em` },
          t('diagram.rotor_flank_radius', { m: i + 1, value: mm(arc.radius_mm) }),
        ),
      ),
    );
  });
  const [kx, ky] = toScreen(0, -r);
  svg.append(
    s(
      'text',
      { 'data-role': 'corner-angle', x: kx, y: ky, dy: '1.2em', 'text-anchor': 'middle' },
      t('diagram.rotor_corner_angle', { value: fmt(rotor.corner_angle_deg), unit: unitText('deg') }),
    ),
  );
  return figure(
    svg,
    [
      { cls: 's-rotor', label: t('legend.rotor_end_profile') },
      { cls: 's-dimension-extension', label: t('legend.rotor_circles') },
    ],
    t('diagram.rotor_caption'),
  );
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
