// SVG drawing: diagrams with a viewBox computed from the data, plots with axes, ticks and labels,
// legends. Styling comes from classes in app.css (no inline style: the page's CSP forbids it);
// stroke widths and dashes are in screen pixels (vector-effect: non-scaling-stroke) and the text
// keeps a readable pixel size at any width (fitText below).

import { h } from './form.js';

const NS = 'http://www.w3.org/2000/svg';

// Diagrams side by side where there is room (print), else one under the other.
export function diagramRow(...views) {
  return h('div', { class: 'diagram-row' }, ...views);
}

// SVG text with a subscript: subText('X', 'n', ' = 5 mm') reads X with subscript n, then ' = 5 mm'.
export function subText(base, sub, rest = '') {
  return [
    base,
    s('tspan', { 'baseline-shift': 'sub', 'font-size': '0.75em' }, sub),
    s('tspan', {}, rest),
  ];
}

export function s(tag, attrs = {}, ...children) {
  const element = document.createElementNS(NS, tag);
  for (const [name, value] of Object.entries(attrs)) {
    if (value === undefined || value === null || value === false) continue;
    element.setAttribute(name, String(value));
  }
  for (const child of children.flat(Infinity)) {
    if (child === undefined || child === null || child === false) continue;
    element.append(child instanceof Node ? child : document.createTextNode(String(child)));
  }
  return element;
}

// Rounds a coordinate for the SVG text (keeps files small, far below a pixel).
const r6 = (v) => Number(v.toPrecision(7));

export function points(list) {
  return list.map(([x, y]) => `${r6(x)},${r6(y)}`).join(' ');
}

// ------------------------------------------------------------------ text size

const TEXT_PX = 12.5;
let observer = null;

function fit(svg) {
  const width = svg.getBoundingClientRect().width;
  const box = svg.viewBox.baseVal;
  if (width > 0 && box && box.width > 0) {
    svg.setAttribute('font-size', String(r6((TEXT_PX * box.width) / width)));
  }
}

// Keeps the diagram's text at TEXT_PX screen pixels whatever width the SVG is drawn at.
function fitText(svg) {
  if (!observer && 'ResizeObserver' in window) {
    observer = new ResizeObserver((entries) =>
      entries.forEach((e) => (e.target.isConnected ? fit(e.target) : observer.unobserve(e.target))),
    );
  }
  observer?.observe(svg);
}

// Printed, a diagram is as wide as its --print-width (app.css), whatever its width on screen: its
// text is sized for that width while the page prints, and for the screen again afterwards.
const PRINT_TEXT_PX = 11;
const CSS_PX_PER_CM = 96 / 2.54;
window.addEventListener('beforeprint', () => {
  for (const svg of document.querySelectorAll('svg.diagram')) {
    const cm = parseFloat(getComputedStyle(svg).getPropertyValue('--print-width'));
    const box = svg.viewBox.baseVal;
    if (cm > 0 && box && box.width > 0) {
      svg.setAttribute('font-size', String(r6((PRINT_TEXT_PX * box.width) / (cm * CSS_PX_PER_CM))));
    }
  }
});
window.addEventListener('afterprint', () => document.querySelectorAll('svg.diagram').forEach(fit));

// User units per screen pixel for a diagram of `viewBoxWidth` drawn in `container` (estimate
// used for arrowheads and label offsets at drawing time).
export function unitsPerPixel(viewBoxWidth, container) {
  const width = Math.min(container?.clientWidth || 360, 720);
  return viewBoxWidth / Math.max(width, 200);
}

// ------------------------------------------------------------------ diagrams

// An empty diagram: <svg role="img" data-diagram=kind> with a <title> (and <desc>).
export function diagram(kind, title, viewBox, description = '') {
  const [x, y, w, hgt] = viewBox;
  const svg = s(
    'svg',
    {
      class: 'diagram',
      role: 'img',
      'data-diagram': kind,
      viewBox: `${r6(x)} ${r6(y)} ${r6(w)} ${r6(hgt)}`,
      preserveAspectRatio: 'xMidYMid meet',
      'font-size': String(r6((TEXT_PX * w) / 360)),
      'aria-labelledby': `${kind}-svg-title`,
    },
    s('title', { id: `${kind}-svg-title` }, title),
    description ? s('desc', {}, description) : null,
  );
  fitText(svg);
  return svg;
}

// The diagram in a <figure> with a legend: items = [{cls, label, shape: 'line'|'area'|'dot'}].
export function figure(svg, legendItems = [], caption = '') {
  const legend = legendItems.length
    ? h(
        'ul',
        { class: 'legend' },
        legendItems.map((item) => h('li', {}, swatch(item), h('span', {}, item.label))),
      )
    : null;
  return h(
    'figure',
    { class: 'diagram' },
    svg,
    legend,
    caption ? h('figcaption', {}, caption) : null,
  );
}

function swatch({ cls, shape = 'line' }) {
  const sw = s('svg', { viewBox: '0 0 36 14', 'aria-hidden': 'true', focusable: 'false' });
  if (shape === 'area') sw.append(s('rect', { x: 2, y: 2, width: 32, height: 10, class: cls }));
  else if (shape === 'dot') sw.append(s('circle', { cx: 18, cy: 7, r: 5, class: cls }));
  else sw.append(s('line', { x1: 1, y1: 7, x2: 35, y2: 7, class: cls }));
  return sw;
}

// Bounding box of screen-space points (SVG y grows downwards).
export class Bounds {
  constructor() {
    this.minX = Infinity;
    this.minY = Infinity;
    this.maxX = -Infinity;
    this.maxY = -Infinity;
  }
  add(x, y) {
    if (!Number.isFinite(x) || !Number.isFinite(y)) return this;
    this.minX = Math.min(this.minX, x);
    this.maxX = Math.max(this.maxX, x);
    this.minY = Math.min(this.minY, y);
    this.maxY = Math.max(this.maxY, y);
    return this;
  }
  addAll(list) {
    list.forEach(([x, y]) => this.add(x, y));
    return this;
  }
  addCircle(x, y, radius) {
    return this.add(x - radius, y - radius).add(x + radius, y + radius);
  }
  get width() {
    return this.maxX - this.minX;
  }
  get height() {
    return this.maxY - this.minY;
  }
  // [x, y, w, h] with `fraction` of the larger side as margin (equal units on both axes).
  viewBox(fraction = 0.06) {
    const size = Math.max(this.width, this.height, 1e-9);
    const m = size * fraction;
    return [
      this.minX - m,
      this.minY - m,
      Math.max(this.width, 1e-9) + 2 * m,
      Math.max(this.height, 1e-9) + 2 * m,
    ];
  }
}

// A closed polygon from Point objects ({x_mm, y_mm}), mapped to screen by `map`.
export function mapped(list, map) {
  return list.map((p) => map(p.x_mm, p.y_mm));
}

// Arrowhead at (x, y) pointing along (dx, dy), `size` user units long.
export function arrowHead(x, y, dx, dy, size, cls = 's-arrow') {
  const len = Math.hypot(dx, dy) || 1;
  const ux = dx / len;
  const uy = dy / len;
  const bx = x - ux * size;
  const by = y - uy * size;
  const w = size * 0.35;
  return s('polygon', {
    class: cls,
    points: points([
      [x, y],
      [bx - uy * w, by + ux * w],
      [bx + uy * w, by - ux * w],
    ]),
  });
}

// A dimension line between (x1, y) and (x2, y) (screen space) with arrowheads, extension lines
// down to the measured points and the text above it.
export function horizontalDimension({ role, x1, x2, y, from1, from2, text, arrow }) {
  const g = s('g', { 'data-role': role });
  const ext = (x, y0) =>
    y0 === undefined
      ? null
      : s('line', { class: 's-dimension-extension', x1: x, y1: y0, x2: x, y2: y });
  // An extension line only where a measured point is given (append(null) would add "null").
  g.append(...[ext(x1, from1), ext(x2, from2)].filter(Boolean));
  g.append(s('line', { class: 's-dimension', x1, y1: y, x2, y2: y }));
  if (Math.abs(x2 - x1) > arrow * 2.2) {
    g.append(arrowHead(x1, y, x1 - x2, 0, arrow), arrowHead(x2, y, x2 - x1, 0, arrow));
  }
  g.append(s('text', { x: (x1 + x2) / 2, y, dy: '-0.45em', 'text-anchor': 'middle' }, text));
  return g;
}

// A dimension line between (x, y1) and (x, y2) (screen space) with arrowheads, extension lines
// across from the measured points (at x from1 and from2) and the text beside it, on the right.
export function verticalDimension({ role, x, y1, y2, from1, from2, text, arrow }) {
  const g = s('g', { 'data-role': role });
  const ext = (y, x0) =>
    x0 === undefined
      ? null
      : s('line', { class: 's-dimension-extension', x1: x0, y1: y, x2: x, y2: y });
  g.append(...[ext(y1, from1), ext(y2, from2)].filter(Boolean));
  g.append(s('line', { class: 's-dimension', x1: x, y1, x2: x, y2 }));
  if (Math.abs(y2 - y1) > arrow * 2.2) {
    g.append(arrowHead(x, y1, 0, y1 - y2, arrow), arrowHead(x, y2, 0, y2 - y1, arrow));
  }
  g.append(s('text', { x, y: (y1 + y2) / 2, dx: '0.4em', dy: '0.35em' }, text));
  return g;
}

// ------------------------------------------------------------------ plots

// "Nice" tick values covering [min, max], about `count` of them.
export function niceTicks(min, max, count = 5) {
  if (!(max > min)) return { ticks: [min], step: 1 };
  const raw = (max - min) / count;
  const power = 10 ** Math.floor(Math.log10(raw));
  const step = [1, 2, 2.5, 5, 10].map((m) => m * power).find((v) => v >= raw) ?? 10 * power;
  const ticks = [];
  for (let v = Math.ceil(min / step - 1e-9) * step; v <= max + step * 1e-9; v += step) {
    ticks.push(Math.abs(v) < step * 1e-9 ? 0 : v);
  }
  return { ticks, step };
}

function tickText(v, step) {
  const exponent = Math.floor(Math.log10(step) + 1e-9);
  const mantissa = step / 10 ** exponent;
  const decimals = Math.max(0, -exponent + (Math.abs(mantissa - 2.5) < 1e-9 ? 1 : 0));
  return v.toFixed(Math.min(decimals, 10));
}

// Domain [min, max] of values with a margin, never empty.
export function domain(values, fraction = 0.06, includeZero = false) {
  let min = Math.min(...values);
  let max = Math.max(...values);
  if (includeZero) {
    min = Math.min(min, 0);
    max = Math.max(max, 0);
  }
  if (!(max > min)) {
    const pad = Math.abs(min) * 0.01 || 1;
    return [min - pad, max + pad];
  }
  const pad = (max - min) * fraction;
  return [includeZero && min === 0 ? 0 : min - pad, max + pad];
}

// A plot frame: axes with ticks and labels (groups data-role axis-x / axis-y), grid, a clipped
// group for the series. Returns {svg, x, y, layer} with x(), y() mapping data to user units.
export function plot({ kind, title, description, xLabel, yLabel, xDomain, yDomain }) {
  const W = 420;
  const H = 280;
  const left = 78;
  const right = 14;
  const top = 14;
  const bottom = 52;
  const svg = diagram(kind, title, [0, 0, W, H], description);
  const [x0, x1] = xDomain;
  const [y0, y1] = yDomain;
  const x = (v) => left + ((v - x0) / (x1 - x0)) * (W - left - right);
  const y = (v) => H - bottom - ((v - y0) / (y1 - y0)) * (H - top - bottom);
  const xt = niceTicks(x0, x1, 5);
  const yt = niceTicks(y0, y1, 5);

  const grid = s('g', { 'aria-hidden': 'true' });
  xt.ticks.forEach((v) =>
    grid.append(s('line', { class: 's-grid', x1: x(v), y1: top, x2: x(v), y2: H - bottom })),
  );
  yt.ticks.forEach((v) =>
    grid.append(s('line', { class: 's-grid', x1: left, y1: y(v), x2: W - right, y2: y(v) })),
  );
  svg.append(grid);

  const axisX = s('g', { 'data-role': 'axis-x' });
  axisX.append(
    s('line', { class: 's-axis', x1: left, y1: H - bottom, x2: W - right, y2: H - bottom }),
  );
  for (const v of xt.ticks) {
    axisX.append(
      s('line', { class: 's-axis', x1: x(v), y1: H - bottom, x2: x(v), y2: H - bottom + 5 }),
    );
    axisX.append(
      s(
        'text',
        { x: x(v), y: H - bottom + 6, dy: '1em', 'text-anchor': 'middle' },
        tickText(v, xt.step),
      ),
    );
  }
  axisX.append(s('text', { x: (left + W - right) / 2, y: H - 4, 'text-anchor': 'middle' }, xLabel));
  svg.append(axisX);

  const axisY = s('g', { 'data-role': 'axis-y' });
  axisY.append(s('line', { class: 's-axis', x1: left, y1: top, x2: left, y2: H - bottom }));
  for (const v of yt.ticks) {
    axisY.append(s('line', { class: 's-axis', x1: left - 5, y1: y(v), x2: left, y2: y(v) }));
    axisY.append(
      s('text', { x: left - 7, y: y(v), dy: '0.35em', 'text-anchor': 'end' }, tickText(v, yt.step)),
    );
  }
  const cy = (top + H - bottom) / 2;
  axisY.append(
    s(
      'text',
      { x: 4, y: cy, dy: '0.8em', 'text-anchor': 'middle', transform: `rotate(-90 4 ${cy})` },
      yLabel,
    ),
  );
  svg.append(axisY);

  const clipId = `${kind}-clip`;
  svg.append(
    s(
      'defs',
      {},
      s(
        'clipPath',
        { id: clipId },
        s('rect', { x: left, y: top - 2, width: W - left - right, height: H - top - bottom + 4 }),
      ),
    ),
  );
  const layer = s('g', { 'clip-path': `url(#${clipId})` });
  svg.append(layer);
  return { svg, x, y, layer, area: { left, right: W - right, top, bottom: H - bottom } };
}
