// Groove-wall roughness (paper 003): Rz of the feed marks, the branch of the model and, with a
// target, the largest feed; the plot Rz(feed) comes from the same request (curve_points).

import { onCalculate } from './calculation.js';
import { csvButton } from './export.js';
import {
  at,
  fmt,
  h,
  noDiagram,
  readBody,
  showFailure,
  sym,
  valueList,
} from './form.js';
import { domain, figure, plot, points, s } from './svg.js';

const PATH = '/v1/roughness/groove-wall';
const CURVE_POINTS = 200;
// The curve's fields (the answer's curve[] items) and units, for its CSV.
const CURVE_COLUMNS = [
  ['feed_mm', 'mm'],
  ['rz_um', '\u00b5m'],
];

const BRANCHES = {
  nose_arc: 'between two nose arcs',
  nose_arc_and_minor_edge: 'nose arc and minor edge',
  minor_edge_and_main_edge: 'minor edge and main edge',
};

export function init() {
  const form = document.getElementById('groove-form');
  const result = document.getElementById('groove-result');
  return onCalculate(form, async (api) => {
    const body = readBody(form);
    const answer = await api.postWithOptIn(PATH, body, 'curve_points', CURVE_POINTS);
    result.replaceChildren();
    if (!answer.ok) {
      showFailure(form, answer);
      result.append(h('p', { class: 'placeholder' }, 'No results: see the messages in the form.'));
      return;
    }
    const response = answer.json;
    result.append(
      h('h3', {}, 'Theoretical roughness'),
      valueList(response, [
        [['Crest height ', ...sym('Rz', 'p')], '/rz_um', '\u00b5m'],
        [['Largest feed for the target'], '/max_feed_mm', 'mm'],
        [['Crest formed by'], '/branch', '', (code) => BRANCHES[code]],
      ]),
      h(
        'p',
        { class: 'source-note' },
        'Rz\u209a is a geometric lower bound: measured Rz is larger.',
      ),
    );
    if (Array.isArray(response.curve) && response.curve.length >= 2) {
      result.append(
        rzPlot(response, Number(body.feed_mm?.text), Number(body.target_rz_um?.text)),
        csvButton(
          'groove-curve-csv',
          'groove-wall-rz-curve.csv',
          CURVE_COLUMNS,
          response.curve.map((point) => CURVE_COLUMNS.map(([key]) => point[key])),
        ),
      );
    } else {
      result.append(
        noDiagram(
          answer.optInRefused
            ? 'this service does not return the Rz(feed) curve yet.'
            : 'the answer has no curve.',
        ),
      );
    }
  });
}

function rzPlot(response, feed, target) {
  const curve = response.curve.map((p) => [p.feed_mm, p.rz_um]);
  const hasTarget = at(response, '/max_feed_mm') !== undefined && Number.isFinite(target);
  const ys = curve
    .map((p) => p[1])
    .concat(hasTarget ? [target] : [])
    .concat([response.rz_um]);
  const xs = curve.map((p) => p[0]).concat([feed]);
  const chart = plot({
    kind: 'rz-vs-feed',
    title: 'Theoretical crest height Rz against the feed, with the target and the largest feed',
    xLabel: 'feed S, mm',
    yLabel: [
      'Rz',
      s('tspan', { 'baseline-shift': 'sub', 'font-size': '0.75em' }, 'p'),
      s('tspan', {}, ', \u00b5m'),
    ],
    xDomain: domain(xs, 0.02, true),
    yDomain: domain(ys, 0.08, true),
  });
  const { x, y, area } = chart;
  chart.layer.append(
    s('polyline', {
      'data-role': 'curve',
      class: 's-curve',
      points: points(curve.map(([f, rz]) => [x(f), y(rz)])),
    }),
  );
  const legend = [{ cls: 's-curve', label: 'Rz(S)' }];
  if (hasTarget) {
    chart.layer.append(
      s(
        'g',
        { 'data-role': 'target-line' },
        s('line', {
          class: 's-target',
          x1: area.left,
          y1: y(target),
          x2: area.right,
          y2: y(target),
        }),
        s('text', { x: area.left + 4, y: y(target), dy: '-0.4em' }, `T = ${fmt(target)} \u00b5m`),
      ),
    );
    const maxFeed = response.max_feed_mm;
    chart.layer.append(
      s(
        'g',
        { 'data-role': 'max-feed-line' },
        s('line', {
          class: 's-max-feed',
          x1: x(maxFeed),
          y1: area.top,
          x2: x(maxFeed),
          y2: area.bottom,
        }),
        s(
          'text',
          { x: x(maxFeed), y: area.top, dx: '-0.3em', dy: '1em', 'text-anchor': 'end' },
          `S max = ${fmt(maxFeed)} mm`,
        ),
      ),
    );
    legend.push(
      { cls: 's-target', label: 'target T' },
      { cls: 's-max-feed', label: 'largest feed' },
    );
  }
  chart.svg.append(
    s(
      'g',
      { 'data-role': 'feed-marker' },
      s('circle', { class: 's-marker', cx: x(feed), cy: y(response.rz_um), r: 5 }),
    ),
  );
  legend.push({ cls: 's-marker', label: 'this feed', shape: 'dot' });
  return figure(chart.svg, legend);
}
