// Resultant cutting speeds in turn-milling (paper 000): the points the user asked for, and
// |v_e| along the whole engagement arc for up- and down-milling (two requests with arc_samples).

import { onCalculate } from './calculation.js';
import { csvButton } from './export.js';
import { h, noDiagram, readBody, showFailure, sym, value, valueList } from './form.js';
import { domain, figure, plot, points, s } from './svg.js';

const PATH = '/v1/resultant-speeds';
const ARC_SAMPLES = 91;

export function init() {
  const form = document.getElementById('speeds-form');
  const result = document.getElementById('speeds-result');
  return onCalculate(form, async (api) => {
    const body = readBody(form);
    const arcBody = { ...body };
    delete arcBody.contact_angles_deg;
    // The requested points first (their answer is the section's result), then the two arcs.
    const main = await api.postJson(PATH, body);
    result.replaceChildren();
    if (!main.ok) {
      showFailure(form, main);
      result.append(h('p', { class: 'placeholder' }, 'No results: see the messages in the form.'));
      return;
    }
    result.append(...pointResults(main.json));
    const [up, down] = await Promise.all([
      api.postWithOptIn(PATH, { ...arcBody, milling: 'up' }, 'arc_samples', ARC_SAMPLES, false),
      api.postWithOptIn(PATH, { ...arcBody, milling: 'down' }, 'arc_samples', ARC_SAMPLES, false),
    ]);
    if (up.ok && down.ok && !up.optInRefused && !down.optInRefused) {
      result.append(speedPlot(up.json.points, down.json.points, main.json));
    } else {
      result.append(
        noDiagram(
          up.optInRefused || down.optInRefused
            ? 'this service does not sample the engagement arc (arc_samples) yet.'
            : 'the arc could not be sampled.',
        ),
      );
    }
  });
}

// Column key, header label (built per table: DOM nodes cannot be shared), unit.
const columns = () => [
  ['contact_angle_deg', sym('\u03c1'), 'deg'],
  ['contact_radius_mm', sym('R', '2\u2032'), 'mm'],
  ['contact_polar_angle_deg', sym('\u03c3'), 'deg'],
  ['tool_speed_m_per_min', sym('v', 'T'), 'm/min'],
  ['workpiece_speed_m_per_min', sym('v', 'S2'), 'm/min'],
  ['resultant_feed_mm_per_min', ['|', ...sym('u', 's'), '|'], 'mm/min'],
  ['resultant_speed_m_per_min', ['|', ...sym('v', 'e'), '|'], 'm/min'],
  ['resultant_angle_deg', ['angle ', ...sym('v', 'T'), '\u2192', ...sym('v', 'e')], 'deg'],
  ['sense', ['sense'], ''],
  ['kinematic_ratio', sym('i', 'k'), ''],
  ['normal_speed_m_per_min', sym('v', 'N'), 'm/min'],
  ['along_edge_speed_m_per_min', ['along edge'], 'm/min'],
];

function pointResults(body) {
  const list = Array.isArray(body.points) ? body.points : [];
  const table = h(
    'table',
    {},
    h(
      'caption',
      { class: 'source-note' },
      'At each contact point (entry +\u03c1e, middle 0, exit \u2212\u03c1e unless listed)',
    ),
    h(
      'thead',
      {},
      h(
        'tr',
        {},
        columns().map(([, label, unit]) =>
          h(
            'th',
            { scope: 'col' },
            label,
            unit ? [h('br'), h('span', { class: 'unit' }, unit)] : null,
          ),
        ),
      ),
    ),
    h(
      'tbody',
      {},
      list.map((_, i) =>
        h(
          'tr',
          {},
          columns().map(([key]) =>
            h(
              'td',
              { class: key === 'sense' ? 'text' : undefined },
              value(body, `/points/${i}/${key}`),
            ),
          ),
        ),
      ),
    ),
  );
  return [
    h('h3', {}, 'Engagement arc and contact points'),
    valueList(body, [
      [['Engagement half-angle ', ...sym('\u03c1', 'e')], '/engagement_half_angle_deg', 'deg'],
    ]),
    h('div', { class: 'table-wrap' }, table),
    csvButton(
      'speeds-points-csv',
      'resultant-speeds-points.csv',
      columns().map(([key, , unit]) => [key, unit]),
      list.map((point) => columns().map(([key]) => point[key])),
    ),
  ];
}

function speedPlot(upPoints, downPoints, main) {
  const xy = (list) =>
    list.map((p) => [p.contact_angle_deg, p.resultant_speed_m_per_min]).sort((a, b) => a[0] - b[0]);
  const up = xy(upPoints);
  const down = xy(downPoints);
  const own = xy(main.points ?? []);
  const all = [...up, ...down, ...own];
  const chart = plot({
    kind: 'speed-vs-angle',
    title: 'Resultant cutting speed |v_e| against the contact angle, up- and down-milling',
    xLabel: 'contact angle \u03c1, deg',
    yLabel: [
      '|v',
      s('tspan', { 'baseline-shift': 'sub', 'font-size': '0.75em' }, 'e'),
      s('tspan', {}, '|, m/min'),
    ],
    xDomain: domain(
      all.map((p) => p[0]),
      0.02,
    ),
    yDomain: domain(
      all.map((p) => p[1]),
      0.08,
    ),
  });
  const line = (list, role, cls) =>
    s('polyline', {
      'data-role': role,
      class: cls,
      points: points(list.map(([a, v]) => [chart.x(a), chart.y(v)])),
    });
  chart.layer.append(line(up, 'curve-up', 's-curve-up'), line(down, 'curve-down', 's-curve-down'));
  const marks = s('g', { 'data-role': 'requested-points' });
  for (const [a, v] of own)
    marks.append(s('circle', { class: 's-marker', cx: chart.x(a), cy: chart.y(v), r: 4 }));
  chart.svg.append(marks);
  return figure(
    chart.svg,
    [
      { cls: 's-curve-up', label: 'up-milling' },
      { cls: 's-curve-down', label: 'down-milling' },
      { cls: 's-marker', label: 'requested points', shape: 'dot' },
    ],
    'Entry at +\u03c1e (right), exit at \u2212\u03c1e (left); milling sense as at the middle of the arc.',
  );
}
