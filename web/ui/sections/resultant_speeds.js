// Resultant cutting speeds in turn-milling (paper 000): the points the user asked for, and
// |v_e| along the whole engagement arc for up- and down-milling (two requests with arc_samples).

import { onCalculate } from '../core/calculation.js';
import { csvButton } from '../core/export.js';
import { h, iso, noDiagram, readBody, showFailure, sym, value, valueList } from '../core/form.js';
import { t, tn } from '../core/i18n.js';
import { csvUnit, unitText } from '../core/units.js';
import { domain, figure, plot, points, s, subText } from '../core/svg.js';

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
      result.append(h('p', { class: 'placeholder' }, t('result.no_results')));
      return;
    }
    result.append(...pointResults(main.json));
    const [up, down] = await Promise.all([
      api.postJson(PATH, { ...arcBody, milling: 'up', arc_samples: ARC_SAMPLES }),
      api.postJson(PATH, { ...arcBody, milling: 'down', arc_samples: ARC_SAMPLES }),
    ]);
    if (up.ok && down.ok) {
      result.append(speedPlot(up.json.points, down.json.points, main.json));
    } else {
      result.append(noDiagram(t('result.no_arc')));
    }
  });
}

// Column key, header label (built per table: DOM nodes cannot be shared), unit.
const columns = () => [
  ['contact_angle_deg', sym('\u03c1'), 'deg'],
  ['contact_radius_mm', sym('R', '2\u2032'), 'mm'],
  ['contact_polar_angle_deg', sym('\u03c3'), 'deg'],
  ['tool_speed_m_per_min', [...sym('v', 'T'), ...iso('v', 'c')], 'm_per_min'],
  ['workpiece_speed_m_per_min', sym('v', 'S2'), 'm_per_min'],
  ['resultant_feed_mm_per_min', ['|', ...sym('u', 's'), '|'], 'mm_per_min'],
  ['resultant_speed_m_per_min', ['|', ...sym('v', 'e'), '|'], 'm_per_min'],
  [
    'resultant_angle_deg',
    [t('result.angle'), ' ', ...sym('v', 'T'), '\u2192', ...sym('v', 'e')],
    'deg',
  ],
  ['sense', [t('result.sense')], ''],
  ['kinematic_ratio', sym('i', 'k'), ''],
  ['normal_speed_m_per_min', sym('v', 'N'), 'm_per_min'],
  ['along_edge_speed_m_per_min', [t('result.along_edge')], 'm_per_min'],
];

// The milling sense at a point (the API's code) in words.
const describeSense = (code) => t(`milling.${code}`);

function pointResults(body) {
  const list = Array.isArray(body.points) ? body.points : [];
  const table = h(
    'table',
    {},
    h(
      'caption',
      { class: 'source-note' },
      tn('result.at_each_contact_point'),
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
            unit ? [h('br'), h('span', { class: 'unit' }, unitText(unit))] : null,
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
          columns().map(([key, , unit]) =>
            h(
              'td',
              { class: key === 'sense' ? 'text' : undefined },
              value(body, `/points/${i}/${key}`, unit, undefined, describeSense, true),
            ),
          ),
        ),
      ),
    ),
  );
  return [
    h('h3', {}, t('result.engagement_arc')),
    valueList(body, [
      [
        [t('result.engagement_half_angle'), ' ', ...sym('\u03c1', 'e')],
        '/engagement_half_angle_deg',
        'deg',
      ],
    ]),
    h('div', { class: 'table-wrap' }, table),
    csvButton(
      'speeds-points-csv',
      'resultant-speeds-points.csv',
      columns().map(([key, , unit]) => [key, csvUnit(unit)]),
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
    title: t('diagram.speed_plot_title'),
    xLabel: t('diagram.contact_angle_axis', { unit: unitText('deg') }),
    yLabel: subText('|v', 'e', `|, ${unitText('m_per_min')}`),
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
      { cls: 's-curve-up', label: t('legend.up_milling') },
      { cls: 's-curve-down', label: t('legend.down_milling') },
      { cls: 's-marker', label: t('legend.requested_points'), shape: 'dot' },
    ],
    t('diagram.speed_plot_caption'),
  );
}
