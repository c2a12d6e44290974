// Bore milling diagrams (spec roughness.md, part B): the bore with the cutter at the contacts of
// two successive teeth, and the cusp between their marks magnified. The bore, the cutter and the
// centre path are to scale; the pitch angle alpha is drawn as it is unless it is too small to
// see, and the cusp is magnified (its caption says by how much).

import { fmt, h } from '../core/form.js';
import { t } from '../core/i18n.js';
import { arrowHead, diagram, diagramRow, figure, points, s, unitsPerPixel } from '../core/svg.js';
import { fromApi, unitText } from '../core/units.js';

// Below this the two cutter positions would lie on top of each other: the angle is opened up.
const MIN_DRAWN_ANGLE_DEG = 24;

// Screen direction of a contact at `angle` (rad) from the lowest point of the bore, turning
// counter-clockwise on screen (y grows downwards).
const towards = (angle) => [Math.sin(angle), Math.cos(angle)];

// Both views side by side where there is room (print), else one under the other.
export function boreDiagrams(inputs, answer, container) {
  return diagramRow(boreView(inputs, answer, container), cuspView(inputs, answer));
}

// Delta to 4 significant digits: the cusp is often far below a micrometre.
const significant = (v) => String(Number(v.toPrecision(4)));

// A length of the API (mm) as the page shows it: its number in the page's units, and the unit.
const length = (mm) => ({ value: fmt(fromApi(mm, 'mm')), unit: unitText('mm') });

// ------------------------------------------------------------------ the bore and two cutters

function boreView({ boreRadius: R, cutterRadius: r, teeth, milling }, answer, container) {
  const Rc = R - r;
  const alpha = answer.pitch_angle_deg;
  const drawnDeg = Math.max(alpha, MIN_DRAWN_ANGLE_DEG);
  const half = (drawnDeg * Math.PI) / 360;
  const margin = R * 0.08;
  const svg = diagram(
    'bore-milling',
    t('diagram.bore_title', {
      bore: length(R).value,
      cutter: length(r).value,
      unit: unitText('mm'),
    }),
    [-R - margin, -R - margin, 2 * (R + margin), 2 * (R + margin)],
    t('diagram.bore_description'),
  );
  const unit = unitsPerPixel(2 * (R + margin), container);

  svg.append(
    s('circle', { 'data-role': 'bore', class: 's-bore', cx: 0, cy: 0, r: R }),
    s('circle', { 'data-role': 'centre-path', class: 's-centre-path', cx: 0, cy: 0, r: Rc }),
    s('circle', { class: 's-bore-axis', cx: 0, cy: 0, r: 3 * unit }),
  );

  // The first tooth touches the bore at -half, the next one at +half (the orbit runs that way).
  [-half, half].forEach((contact, index) => {
    const [dx, dy] = towards(contact);
    const cx = Rc * dx;
    const cy = Rc * dy;
    const cutter = s('g', { 'data-role': 'cutter-position', 'data-tooth': index + 1 });
    cutter.append(
      s('circle', {
        'data-role': 'cutter',
        class: `s-cutter s-bore-cutter-${index + 1}`,
        cx,
        cy,
        r,
      }),
      s('circle', { class: `s-axis-dot s-bore-cutter-${index + 1}`, cx, cy, r: 2.5 * unit }),
    );
    // The teeth, evenly spaced; the one in contact points at the bore.
    for (let j = 0; j < teeth && j < 64; j += 1) {
      const [tx, ty] = towards(contact + (2 * Math.PI * j) / teeth);
      cutter.append(
        s('line', {
          class: j === 0 ? 's-tooth s-tooth-contact' : 's-tooth',
          x1: cx + 0.82 * r * tx,
          y1: cy + 0.82 * r * ty,
          x2: cx + r * tx,
          y2: cy + r * ty,
        }),
      );
    }
    svg.append(cutter);
  });

  // The orbit: an arrow along the centre path from the first position to the second; the pitch
  // angle between the two contacts, at the bore axis.
  const orbit = [];
  for (let i = 0; i <= 24; i += 1) orbit.push(towards(-half + (2 * half * i) / 24));
  const onPath = orbit.map(([x, y]) => [Rc * x, Rc * y]);
  const [ex, ey] = onPath.at(-1);
  const [px, py] = onPath.at(-2);
  const [ax, ay] = towards(-half);
  const [bx, by] = towards(half);
  svg.append(
    s(
      'g',
      { 'data-role': 'orbit' },
      s('polyline', { class: 's-feed', fill: 'none', points: points(onPath) }),
      arrowHead(ex, ey, ex - px, ey - py, 9 * unit),
    ),
    s(
      'g',
      { 'data-role': 'pitch-angle' },
      s('line', { class: 's-dimension-extension', x1: 0, y1: 0, x2: R * ax, y2: R * ay }),
      s('line', { class: 's-dimension-extension', x1: 0, y1: 0, x2: R * bx, y2: R * by }),
      s(
        'text',
        { x: 0, y: -6 * unit, 'text-anchor': 'middle' },
        `\u03b1 = ${fmt(alpha)}\u00b0`,
        alpha < MIN_DRAWN_ANGLE_DEG ? ` ${t('diagram.drawn_larger')}` : null,
      ),
    ),
  );

  // The magnified region: the bore between the two contacts.
  const box = 14 * unit;
  svg.append(
    s('rect', {
      'data-role': 'detail-mark',
      class: 's-detail-mark',
      x: -box,
      y: R - box,
      width: 2 * box,
      height: 2 * box,
    }),
  );
  return figure(
    svg,
    [
      { cls: 's-bore', label: t('diagram.bore_radius', length(R)) },
      { cls: 's-centre-path', label: t('legend.cutter_centre_path', length(Rc)) },
      { cls: 's-cutter s-bore-cutter-1', label: t('legend.cutter_tooth_1') },
      { cls: 's-cutter s-bore-cutter-2', label: t('legend.cutter_next_tooth') },
    ],
    t('diagram.bore_caption', { milling: t(`milling.${milling}`), teeth }),
  );
}

// ------------------------------------------------------------------ the cusp magnified

// The surface near the cusp: the marks of the two teeth meet Delta inside the bore, halfway
// between their contacts, which lie R alpha apart along the bore. Each mark is drawn as the
// parabola through its contact and the cusp (the paths' curvature difference, B8, in the form
// that gives the exact Delta of B5).
function cuspView({ boreRadius: R }, answer) {
  const delta = answer.cusp_height_um;
  const spacing = R * ((answer.pitch_angle_deg * Math.PI) / 180);
  if (!(delta > 0) || !(spacing > 0)) {
    return h('p', { class: 'no-diagram' }, t('diagram.no_cusp'));
  }
  const W = 400;
  const H = 230;
  const x = (u) => W / 2 + (u / spacing) * 150; // mm along the bore
  const y = (w) => 150 - (w / delta) * 80; // um inwards from the bore, up on screen
  const mark = (u, centre) => delta * ((u - centre) / (spacing / 2)) ** 2;
  const contacts = [-1.5, -0.5, 0.5, 1.5].map((k) => k * spacing);
  const surface = [];
  for (let i = 0; i <= 160; i += 1) {
    const u = -spacing * 1.2 + (2.4 * spacing * i) / 160;
    surface.push([x(u), y(Math.min(...contacts.map((c) => mark(u, c))))]);
  }
  const svg = diagram(
    'bore-cusp',
    t('diagram.cusp_title', { value: significant(delta), unit: unitText('um') }),
    [0, 0, W, H],
  );
  const toothPath = (centre, index) => {
    const list = [];
    for (let i = 0; i <= 40; i += 1) {
      const u = centre - 0.6 * spacing + (1.2 * spacing * i) / 40;
      list.push([x(u), y(mark(u, centre))]);
    }
    return s('polyline', { class: `s-tooth-path s-bore-cutter-${index}`, points: points(list) });
  };
  svg.append(
    s('polygon', {
      class: 's-workpiece',
      points: points([...surface, [surface.at(-1)[0], H], [surface[0][0], H]]),
    }),
    s('line', { class: 's-strip-edge', x1: 0, y1: y(0), x2: W, y2: y(0) }),
    toothPath(-spacing / 2, 1),
    toothPath(spacing / 2, 2),
    s('polyline', { 'data-role': 'surface', class: 's-contour', points: points(surface) }),
    s('text', { x: 8, y: y(0), dy: '1.2em' }, t('diagram.bore_radius', length(R))),
    s('text', { x: 8, y: 18 }, t('diagram.towards_bore_axis')),
  );
  // Delta: from the bore line up to the cusp, labelled with the computed value.
  const top = y(delta);
  const base = y(0);
  svg.append(
    s(
      'g',
      { 'data-role': 'cusp-height' },
      s('line', { class: 's-dimension', x1: x(0), y1: base, x2: x(0), y2: top }),
      arrowHead(x(0), top, 0, -1, 8),
      arrowHead(x(0), base, 0, 1, 8),
      s(
        'text',
        {
          'data-role': 'cusp-label',
          'data-value': String(delta),
          x: x(0),
          y: (top + base) / 2,
          dx: '0.6em',
          dy: '0.35em',
        },
        `\u0394 = ${significant(delta)} ${unitText('um')}`,
      ),
    ),
  );
  // The spacing of the contacts along the bore.
  const yDim = base + 48;
  svg.append(
    s(
      'g',
      { 'data-role': 'contact-spacing' },
      s('line', {
        class: 's-dimension',
        x1: x(-spacing / 2),
        y1: yDim,
        x2: x(spacing / 2),
        y2: yDim,
      }),
      arrowHead(x(-spacing / 2), yDim, -1, 0, 8),
      arrowHead(x(spacing / 2), yDim, 1, 0, 8),
      s(
        'text',
        { x: W / 2, y: yDim, dy: '-0.45em', 'text-anchor': 'middle' },
        `R\u03b1 = ${significant(fromApi(spacing, 'mm'))} ${unitText('mm')}`,
      ),
    ),
  );
  // Screen units per mm across the bore over those along it.
  const exaggeration = fmt(Number((80 / (delta / 1000) / (150 / spacing)).toPrecision(3)));
  return figure(
    svg,
    [
      { cls: 's-contour', label: t('legend.machined_surface') },
      { cls: 's-tooth-path s-bore-cutter-1', label: t('legend.mark_of_tooth_1') },
      { cls: 's-tooth-path s-bore-cutter-2', label: t('legend.mark_of_next_tooth') },
    ],
    t('diagram.cusp_caption', { factor: exaggeration }),
  );
}
