// Grooving cycle diagrams (spec grooving-cycle.md, section 3): the groove as a half-section to scale
// with the tool at its start and after the final shift, and the shift pattern of the first
// revolutions (K10-K12) with the final shift at the bottom (K14) as a schematic strip.

import { fmt, h, lengthText, noDiagram } from '../core/form.js';
import { t } from '../core/i18n.js';
import {
  arrowHead,
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

// Revolutions the pattern strip shows before it skips to the bottom: two periods of the pattern.
const SHOWN_REVOLUTIONS = 8;

// A dimension's label: the paper's symbol (not a word: the same in every language) and its length.
const dimensionText = (symbol, mm) => `${symbol} = ${lengthText(mm)}`;

// Both views side by side where there is room (print), else one under the other.
export function groovingDiagrams(inputs, answer, container) {
  return diagramRow(sectionView(inputs, answer, container), patternView(answer));
}

// ------------------------------------------------------------------ the groove, to scale

// Program coordinates (Z to the right, radius up) to screen (y grows downwards).
const toScreen = (z, radius) => [z, -radius];

function sectionView({ grooveWidth: W, startDiameter: D0, leftZ: zL }, answer, container) {
  const B = answer.tool_width_mm;
  const X2 = answer.shift_mm;
  const depth = answer.groove_depth_mm;
  const R0 = D0 / 2;
  const Rb = answer.bottom_diameter_mm / 2;
  const Ra = answer.approach_diameter_mm / 2;
  if (![W, R0, zL, B, X2, depth, Rb, Ra].every(Number.isFinite) || !(W > 0) || !(depth > 0)) {
    return noDiagram(t('result.no_geometry'));
  }
  const size = Math.max(W, depth);
  const side = 0.7 * size; // workpiece shown beside the groove (room for the diameters' texts)
  const below = 0.45 * size; // and under its bottom
  const toolHeight = 0.9 * size;
  const zR = zL + W;
  const outline = [
    [zL - side, R0],
    [zL, R0],
    [zL, Rb],
    [zR, Rb],
    [zR, R0],
    [zR + side, R0],
  ].map(([z, r]) => toScreen(z, r));
  const material = [
    ...outline,
    toScreen(zR + side, Rb - below),
    toScreen(zL - side, Rb - below),
  ];
  const box = new Bounds().addAll(material);
  box.add(...toScreen(zL, Ra + toolHeight + 0.3 * size));
  box.add(...toScreen(zR + 0.6 * side + 0.9 * size, R0)); // room for the depth's text
  const viewBox = box.viewBox(0.04);
  const upp = unitsPerPixel(viewBox[2], container);
  const arrow = 8 * upp;
  const svg = diagram('grooving-section', t('diagram.grooving_section_title'), viewBox);

  // The end of the final shift: the other side of the pattern's end (K12, K14).
  const zEnd = answer.end_side === 'right' ? zL + X2 : zL;
  const [sx, sy] = toScreen(zL, Ra);
  svg.append(
    s('polygon', { 'data-role': 'workpiece', class: 's-workpiece', points: points(material) }),
    s('polyline', { 'data-role': 'groove', class: 's-contour', points: points(outline) }),
    s('rect', {
      'data-role': 'tool-start',
      class: 's-cutter s-cutter-start',
      x: zL,
      y: sy - toolHeight,
      width: B,
      height: toolHeight,
    }),
    s('rect', {
      'data-role': 'tool-end',
      class: 's-cutter s-cutter-end',
      x: zEnd,
      y: -Rb - toolHeight,
      width: B,
      height: toolHeight,
    }),
    s('circle', {
      'data-role': 'reference-point',
      class: 's-cutter-start s-axis-dot',
      cx: sx,
      cy: sy,
      r: 3.5 * upp,
    }),
    horizontalDimension({
      role: 'dimension-width',
      x1: zL,
      x2: zR,
      y: -(Rb - 0.25 * below),
      from1: -Rb,
      from2: -Rb,
      text: dimensionText('W', W),
      arrow,
    }),
    horizontalDimension({
      role: 'dimension-tool',
      x1: zL,
      x2: zL + B,
      y: sy - toolHeight - 0.12 * size,
      from1: sy - toolHeight,
      from2: sy - toolHeight,
      text: dimensionText('B', B),
      arrow,
    }),
    horizontalDimension({
      role: 'dimension-shift',
      x1: zL + B,
      x2: zR,
      y: sy - 0.5 * toolHeight,
      from2: -R0,
      text: dimensionText('X2', X2),
      arrow,
    }),
    verticalDimension({
      role: 'dimension-depth',
      x: zR + 0.6 * side,
      y1: -R0,
      y2: -Rb,
      from1: zR,
      from2: zR,
      text: dimensionText('h', depth),
      arrow,
    }),
    s(
      'text',
      { 'data-role': 'start-diameter', x: zL - side, y: -R0, dx: '0.3em', dy: '-0.4em' },
      dimensionText('D0', D0),
    ),
    s(
      'text',
      { 'data-role': 'bottom-diameter', x: zL - side, y: -Rb, dx: '0.3em', dy: '1.2em' },
      dimensionText('Db', answer.bottom_diameter_mm),
    ),
    s(
      'text',
      { 'data-role': 'start-point', x: sx, y: sy, dx: '0.4em', dy: '-0.5em' },
      t('diagram.grooving_start_point', { value: lengthText(answer.approach_diameter_mm) }),
    ),
  );
  return figure(
    svg,
    [
      { cls: 's-contour', label: t('legend.groove_contour') },
      { cls: 's-cutter s-cutter-start', label: t('legend.tool_at_start') },
      { cls: 's-cutter s-cutter-end', label: t('legend.tool_after_final_shift') },
    ],
    t('diagram.grooving_section_caption'),
  );
}

// ------------------------------------------------------------------ the shift pattern, schematic

// The tool's side after revolution k (K10-K12): 0 at z_L, 1 at z_L + X2. Shifts in revolutions
// 2, 6, 10, ... (+X2) and 4, 8, 12, ... (-X2).
const sideAfter = (k) => (k % 4 === 2 || k % 4 === 3 ? 1 : 0);

function patternView(answer) {
  const N = answer.revolutions;
  const infeed = answer.infeed_per_revolution_mm;
  if (!(N >= 1) || !(infeed > 0) || !(answer.shift_mm > 0)) {
    return noDiagram(t('result.no_geometry'));
  }
  const shown = Math.min(N, SHOWN_REVOLUTIONS);
  const skipped = N > shown;
  const W = 420;
  const left = 110;
  const strip = 170;
  const row = 24;
  const top = 44;
  const x = (side) => left + side * strip;
  const y = (k) => top + k * row;
  const yBottom = skipped ? y(shown) + 1.6 * row : y(N);
  const H = yBottom + 2.2 * row;
  const svg = diagram('grooving-pattern', t('diagram.grooving_pattern_title'), [0, 0, W, H]);

  svg.append(
    s(
      'g',
      { 'data-role': 'pattern-walls' },
      s('line', { class: 's-strip-edge', x1: x(0), y1: top - 10, x2: x(0), y2: yBottom + 8 }),
      s('line', { class: 's-strip-edge', x1: x(1), y1: top - 10, x2: x(1), y2: yBottom + 8 }),
      s('text', { x: x(0), y: top - 14, 'text-anchor': 'middle' }, t('diagram.grooving_at_left')),
      s('text', { x: x(1), y: top - 14, 'text-anchor': 'middle' }, t('diagram.grooving_at_right')),
    ),
    s('text', { x: left - 10, y: y(0), dy: '0.35em', 'text-anchor': 'end' }, t('diagram.grooving_start_row')),
    s('text', { x: x(1) + 14, y: y(0), dy: '0.35em' }, lengthText(0)),
  );

  const revolution = (k, from, to) =>
    s(
      'g',
      { 'data-role': 'revolution', 'data-k': k },
      s('line', {
        class: k % 2 === 0 ? 's-pattern-shift' : 's-pattern-radial',
        x1: x(sideAfter(k - 1)),
        y1: from,
        x2: x(sideAfter(k)),
        y2: to,
      }),
      s('circle', { class: 's-pattern-point', cx: x(sideAfter(k)), cy: to, r: 3 }),
      s(
        'text',
        { x: left - 10, y: to, dy: '0.35em', 'text-anchor': 'end' },
        t('diagram.grooving_revolution', { k }),
      ),
      s('text', { x: x(1) + 14, y: to, dy: '0.35em' }, lengthText(k * infeed)),
    );
  for (let k = 1; k <= shown; k += 1) svg.append(revolution(k, y(k - 1), y(k)));
  if (skipped) {
    svg.append(
      s('line', {
        class: 's-dimension-extension',
        x1: x(sideAfter(shown)),
        y1: y(shown),
        x2: x(sideAfter(N - 1)),
        y2: yBottom - row,
      }),
      s('text', { x: left - 10, y: y(shown) + 0.8 * row, dy: '0.35em', 'text-anchor': 'end' }, '\u2026'),
      revolution(N, yBottom - row, yBottom),
    );
  }

  // The dwell and the final shift at the bottom (K14): across to the other side at D_b.
  const from = sideAfter(N);
  const to = 1 - from;
  const final = s(
    'g',
    { 'data-role': 'final-shift' },
    s('line', { class: 's-final-shift', x1: x(from), y1: yBottom, x2: x(to), y2: yBottom }),
    arrowHead(x(to), yBottom, x(to) - x(from), 0, 9),
    s(
      'text',
      { x: (x(0) + x(1)) / 2, y: yBottom, dy: '1.6em', 'text-anchor': 'middle' },
      t('diagram.grooving_final_shift', {
        value: lengthText(answer.shift_mm),
        revolutions: fmt(answer.final_shift_revolutions),
      }),
    ),
  );
  if (answer.dwell_time_min > 0) {
    final.append(
      s('circle', { 'data-role': 'dwell', class: 's-dwell', cx: x(from), cy: yBottom, r: 7 }),
    );
  }
  svg.append(final);
  return figure(
    svg,
    [
      { cls: 's-pattern-radial', label: t('legend.radial_revolution') },
      { cls: 's-pattern-shift', label: t('legend.shift_revolution') },
      { cls: 's-final-shift', label: t('legend.final_shift') },
    ],
    t('diagram.grooving_pattern_caption', {
      infeed: lengthText(infeed),
      shift: lengthText(answer.shift_mm),
      pitch: lengthText(answer.wall_pitch_mm),
    }),
  );
}
