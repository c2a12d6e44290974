// Flat-on-a-lathe diagrams (spec lathe-flat.md, sections 3-4): the cross-section to scale in the
// part frame (the part, its m flats, the tool at a few steps of the final layer of flat 1) and the
// path between two step points magnified, with the flatness error (F10-F14) labelled.

import { fmt, lengthText, noDiagram } from '../core/form.js';
import { t } from '../core/i18n.js';
import {
  Bounds,
  diagram,
  diagramRow,
  figure,
  horizontalDimension,
  points,
  s,
  unitsPerPixel,
  verticalDimension,
} from '../core/svg.js';

const DEG = Math.PI / 180;
// Tool positions drawn: about this many, evenly over the step table (first and last included).
const SHOWN_TOOLS = 5;
// Points per segment for the spiral (F10) and its offset (F12).
const SAMPLES = 64;


// Both views side by side where there is room (print), else one under the other.
export function flatDiagrams(inputs, answer, container) {
  return diagramRow(sectionView(inputs, answer, container), spiralView(inputs, answer));
}

// The tool reference point at block parameter u in [0, 1] of segment i of the step table, in the
// part frame of flat 1 (outward normal +x): c = r (cos a, -sin a), r and a linear in u (F10).
function spiralPoint(rows, i, u) {
  const a = (rows[i].c_deg + u * (rows[i + 1].c_deg - rows[i].c_deg)) * DEG;
  const r = rows[i].x_mm + u * (rows[i + 1].x_mm - rows[i].x_mm);
  return [r * Math.cos(a), -r * Math.sin(a)];
}

// The machined point for the tool reference point at u (F12): the spiral offset by R towards the
// axis along the normal of its tangent (R = 0: the spiral itself).
function surfacePoint(rows, i, u, R) {
  const [x, y] = spiralPoint(rows, i, u);
  if (!(R > 0)) return [x, y];
  const du = 1e-6;
  const [x1, y1] = spiralPoint(rows, i, Math.max(0, u - du));
  const [x2, y2] = spiralPoint(rows, i, Math.min(1, u + du));
  let [nx, ny] = [-(y2 - y1), x2 - x1];
  if (nx > 0) [nx, ny] = [-nx, -ny];
  const n = Math.hypot(nx, ny) || 1;
  return [x + (R * nx) / n, y + (R * ny) / n];
}

// ------------------------------------------------------------------ the cross-section, to scale

// Part frame (x right, y up, seen from +Z) to screen (y grows downwards).
const toScreen = ([x, y]) => [x, -y];

// The finished cross-section: the circle cut by the m half-planes x . n_k <= d (n_k at k 360/m),
// as the radius in each direction (the shape is convex, so star-shaped from the axis).
function finishedOutline(R2, d, m) {
  const outline = [];
  const count = 1440;
  for (let j = 0; j < count; j += 1) {
    const phi = (j * 2 * Math.PI) / count;
    let r = R2;
    for (let k = 0; k < m; k += 1) {
      const c = Math.cos(phi - (k * 2 * Math.PI) / m);
      if (c > 0) r = Math.min(r, d / c);
    }
    outline.push([r * Math.cos(phi), r * Math.sin(phi)]);
  }
  return outline;
}

function sectionView({ partDiameter: D, toolRadius: R, flats: m }, answer, container) {
  const rows = Array.isArray(answer.steps_table) ? answer.steps_table : [];
  const d = answer.axis_distance_mm;
  const R2 = D / 2;
  if (
    ![D, R, m, d].every(Number.isFinite) ||
    !(R2 > 0) ||
    !(d > 0) ||
    rows.length < 2 ||
    !Number.isInteger(m) ||
    m < 1
  ) {
    return noDiagram(t('result.no_geometry'));
  }
  const last = rows.length - 1;
  const shown = [...new Set(Array.from({ length: SHOWN_TOOLS }, (_, k) => Math.round((k * last) / (SHOWN_TOOLS - 1))))];
  // Tool centres in the part frame: the step's X on the tool ray turned back by the step's C.
  const centre = (row) => [row.x_mm * Math.cos(row.c_deg * DEG), -row.x_mm * Math.sin(row.c_deg * DEG)];
  const box = new Bounds().addAll([toScreen([-R2, -R2]), toScreen([R2, R2])]);
  for (const k of shown) {
    const [x, y] = centre(rows[k]);
    box.addAll([toScreen([x - R, y - R]), toScreen([x + R, y + R])]);
  }
  box.add(...toScreen([R2 + 0.12 * D, 0]));
  const viewBox = box.viewBox(0.06);
  const upp = unitsPerPixel(viewBox[2], container);
  const arrow = 8 * upp;
  const svg = diagram('flat-section', t('diagram.flat_section_title'), viewBox);

  // The reference point's path over the whole final layer of flat 1 (the spirals between steps).
  const path = [];
  for (let i = 0; i < last; i += 1) {
    for (let j = 0; j < 8; j += 1) path.push(spiralPoint(rows, i, j / 8));
  }
  path.push(centre(rows[last]));

  const outline = finishedOutline(R2, d, m);
  const halfWidth = (answer.face_width_mm ?? answer.flat_width_mm) / 2;
  svg.append(
    s('circle', { 'data-role': 'part', class: 's-flat-stock', cx: 0, cy: 0, r: R2 }),
    s('polygon', { 'data-role': 'flats', class: 's-flat-part', points: points(outline.map(toScreen)) }),
    s('line', {
      'data-role': 'flat-1',
      class: 's-flat-face',
      ...lineAttrs(toScreen([d, -halfWidth]), toScreen([d, halfWidth])),
    }),
    s('circle', { 'data-role': 'axis', class: 's-axis-dot', cx: 0, cy: 0, r: 3 * upp }),
    s('polyline', { 'data-role': 'tool-path', class: 's-centre-path', points: points(path.map(toScreen)) }),
  );
  for (const k of shown) {
    const [cx, cy] = toScreen(centre(rows[k]));
    svg.append(
      s(
        'g',
        { 'data-role': 'tool', 'data-i': rows[k].i },
        R > 0 ? s('circle', { class: 's-cutter s-cutter-end', cx, cy, r: R }) : null,
        s('circle', { class: 's-cutter-end s-axis-dot', cx, cy, r: 3 * upp }),
      ),
    );
  }
  svg.append(
    horizontalDimension({
      role: 'dimension-axis-distance',
      x1: 0,
      x2: d,
      y: 0.55 * R2,
      from2: halfWidth,
      text: t('diagram.flat_axis_distance', { value: lengthText(d) }),
      arrow,
    }),
    verticalDimension({
      role: 'dimension-width',
      x: d - 0.25 * (R2 - d) - 0.04 * D,
      y1: -halfWidth,
      y2: halfWidth,
      text: t('diagram.flat_width', { value: lengthText(2 * halfWidth) }),
      arrow,
    }),
    s(
      'text',
      { 'data-role': 'part-diameter', x: -R2 * 0.7, y: -R2 * 0.75, 'text-anchor': 'end' },
      t('diagram.flat_part_diameter', { value: lengthText(D) }),
    ),
  );
  // Text on a dimension drawn inside the flat's own line reads better left of it.
  svg.querySelector('[data-role="dimension-width"] text')?.setAttribute('text-anchor', 'end');
  svg.querySelector('[data-role="dimension-width"] text')?.setAttribute('dx', '-0.4em');
  return figure(
    svg,
    [
      { cls: 's-flat-stock', label: t('legend.flat_stock') },
      { cls: 's-flat-part', label: t('legend.flat_finished'), shape: 'area' },
      { cls: 's-cutter s-cutter-end', label: t('legend.flat_tool') },
      { cls: 's-centre-path', label: t('legend.flat_tool_path') },
    ],
    t('diagram.flat_section_caption', { steps: answer.steps, shown: shown.length, m }),
  );
}

const lineAttrs = ([x1, y1], [x2, y2]) => ({ x1, y1, x2, y2 });

// ------------------------------------------------------------------ between two steps, magnified

// The segment of the first half whose machined surface stands highest above the flat (F14,
// sampled: the exact value is the answer's), with that surface's samples [u along the flat, height].
function highestSegment(rows, answer, R, R2) {
  const d = answer.axis_distance_mm;
  const halfWidth = (answer.face_width_mm ?? answer.flat_width_mm) / 2;
  const half = (rows.length - 1) / 2;
  let best = null;
  for (let i = 0; i < half; i += 1) {
    const samples = [];
    let top = -Infinity;
    let topAt = 0;
    for (let j = 0; j <= SAMPLES; j += 1) {
      const [x, y] = surfacePoint(rows, i, j / SAMPLES, R);
      const e = x - d;
      samples.push([y, e]);
      const material = Math.abs(y) <= halfWidth ? Math.min(e, Math.sqrt(Math.max(R2 * R2 - y * y, 0)) - d) : -Infinity;
      if (material > top) [top, topAt] = [material, j];
    }
    if (best === null || top > best.top) best = { i, samples, top, topAt };
  }
  return best;
}

function spiralView({ partDiameter: D, toolRadius: R }, answer) {
  const rows = Array.isArray(answer.steps_table) ? answer.steps_table : [];
  const error = answer.flatness_error_mm;
  if (rows.length < 3 || !(D > 0) || !Number.isFinite(R) || !(error >= 0)) {
    return noDiagram(t('result.no_geometry'));
  }
  const segment = highestSegment(rows, answer, R, D / 2);
  if (segment === null) return noDiagram(t('result.no_geometry'));
  const { i, samples, topAt } = segment;
  const us = samples.map(([u]) => u);
  const uMin = Math.min(...us);
  const uMax = Math.max(...us);
  const heights = samples.map(([, e]) => e);
  const eMax = Math.max(error, ...heights.map((e) => Math.max(e, 0)));
  if (!(uMax > uMin) || !(eMax > 0)) return noDiagram(t('result.no_geometry'));

  const W = 420;
  const left = 40;
  const plotWidth = 340;
  const top = 40;
  const plotHeight = 150;
  const H = top + plotHeight + 60;
  // u grows downwards on the part's flat 1 seen from +Z; drawn left to right from the step i.
  const x = (u) => left + ((u - samples[0][0]) / (samples[samples.length - 1][0] - samples[0][0])) * plotWidth;
  const y = (e) => top + plotHeight - (Math.max(e, 0) / eMax) * plotHeight;
  const exaggeration = ((plotHeight / eMax) / (plotWidth / (uMax - uMin)));
  const svg = diagram('flat-spiral', t('diagram.flat_spiral_title'), [0, 0, W, H]);
  const [peakU, peakE] = samples[topAt];
  svg.append(
    s('line', { 'data-role': 'flat-line', class: 's-flat-face', x1: x(samples[0][0]), y1: y(0), x2: x(samples[samples.length - 1][0]), y2: y(0) }),
    s('polyline', { 'data-role': 'hump', class: 's-curve', points: points(samples.map(([u, e]) => [x(u), y(e)])) }),
    s('circle', { 'data-role': 'step-start', class: 's-pattern-point', cx: x(samples[0][0]), cy: y(0), r: 3.5 }),
    s('circle', { 'data-role': 'step-end', class: 's-pattern-point', cx: x(samples[samples.length - 1][0]), cy: y(0), r: 3.5 }),
    s('text', { x: x(samples[0][0]), y: y(0), dy: '1.4em', 'text-anchor': 'middle' }, t('diagram.flat_step', { i: rows[i].i })),
    s('text', { x: x(samples[samples.length - 1][0]), y: y(0), dy: '1.4em', 'text-anchor': 'middle' }, t('diagram.flat_step', { i: rows[i + 1].i })),
    verticalDimension({
      role: 'dimension-flatness',
      x: x(peakU),
      y1: y(0),
      y2: y(peakE),
      text: t('diagram.flat_flatness_error', { value: `${fmt(error * 1000)} ${t('unit.um')}` }),
      arrow: 7,
    }),
    s(
      'text',
      { 'data-role': 'exaggeration', x: left, y: top - 18 },
      t('diagram.flat_exaggeration', { factor: fmt(Number(exaggeration.toPrecision(2))) }),
    ),
  );
  return figure(
    svg,
    [
      { cls: 's-flat-face', label: t('legend.flat_plane') },
      { cls: 's-curve', label: R > 0 ? t('legend.flat_offset_spiral') : t('legend.flat_spiral') },
    ],
    t('diagram.flat_spiral_caption', {
      from: rows[i].i,
      to: rows[i + 1].i,
      chord: lengthText(rows[i].chord_mm),
    }),
  );
}
