// Groove-wall roughness (paper 003): Rz and Ra of the feed marks, the branch of the model and,
// with a target, the largest feed; the plot Rz(feed) and the bearing curve of the wall profile come
// from the same request (curve_points, bearing_points).

import { onCalculate } from '../core/calculation.js';
import { csvButton } from '../core/export.js';
import { feedCurvePlot } from '../diagrams/feed_curve.js';
import {
  at,
  h,
  noDiagram,
  readBody,
  showFailure,
  iso,
  sym,
  valueList,
} from '../core/form.js';
import { t, tn } from '../core/i18n.js';
import { csvUnit, fromApi, unitText } from '../core/units.js';
import { domain, figure, plot, points, s, subText } from '../core/svg.js';

const PATH = '/v1/roughness/groove-wall';
const CURVE_POINTS = 200;
const BEARING_POINTS = 100;
// The curve's fields (the answer's curve[] items) and units, for its CSV.
const CURVE_COLUMNS = [
  ['feed_mm', 'mm'],
  ['rz_um', 'um'],
];

// The branch of the model (the API's code) in words.
const describeBranch = (code) => t(`branch.${code}`);

export function init() {
  const form = document.getElementById('groove-form');
  const result = document.getElementById('groove-result');
  return onCalculate(form, async (api) => {
    const body = readBody(form);
    const answer = await api.postJson(PATH, {
      ...body,
      curve_points: CURVE_POINTS,
      bearing_points: BEARING_POINTS,
    });
    result.replaceChildren();
    if (!answer.ok) {
      showFailure(form, answer);
      result.append(h('p', { class: 'placeholder' }, t('result.no_results')));
      return;
    }
    const response = answer.json;
    result.append(
      h('h3', {}, t('result.theoretical_roughness')),
      valueList(response, [
        [[t('result.crest_height'), ' ', ...sym('Rz', 'p')], '/rz_um', 'um'],
        [[t('result.groove_mean_roughness'), ' ', ...sym('Ra', 'p')], '/ra_um', 'um'],
        [
          [t('result.largest_feed'), ' ', ...sym('S', 'max'), ...iso('f', 'max')],
          '/max_feed_mm',
          'mm',
        ],
        [[t('result.crest_formed_by')], '/branch', '', describeBranch],
      ]),
      h(
        'p',
        { class: 'source-note' },
        tn('result.rz_lower_bound'),
      ),
      h(
        'p',
        { class: 'source-note', 'data-role': 'ra-caveat' },
        tn('result.groove_ra_lower_bound'),
      ),
    );
    if (Array.isArray(response.curve) && response.curve.length >= 2) {
      result.append(
        rzPlot(response, Number(body.feed_mm?.text), Number(body.target_rz_um?.text)),
        csvButton(
          'groove-curve-csv',
          'groove-wall-rz-curve.csv',
          CURVE_COLUMNS.map(([key, unit]) => [key, csvUnit(unit)]),
          response.curve.map((point) => CURVE_COLUMNS.map(([key]) => point[key])),
        ),
      );
    } else {
      result.append(noDiagram(t('result.no_curve')));
    }
    if (Array.isArray(response.bearing_curve) && response.bearing_curve.length >= 2) {
      result.append(bearingPlot(response));
    } else {
      result.append(noDiagram(t('result.groove_no_bearing_curve')));
    }
  });
}

// The bearing (Abbott-Firestone) curve as ISO 4287 draws it: the material ratio across, the
// level of the cut down from the crest (height above the valleys, so the crest is on top).
function bearingPlot(response) {
  const rz = response.rz_um;
  const curve = [[0, rz]].concat(
    response.bearing_curve.map((p) => [100 * p.material_ratio, rz - p.depth_um]),
  );
  const chart = plot({
    kind: 'bearing-curve',
    title: t('diagram.groove_bearing_title'),
    xLabel: t('diagram.groove_material_ratio_axis'),
    yLabel: t('diagram.groove_height_axis', { unit: unitText('um') }),
    xDomain: [0, 100],
    yDomain: domain([0, rz > 0 ? rz : 1], 0.08, true),
  });
  const { x, y } = chart;
  chart.layer.append(
    s('polyline', {
      'data-role': 'bearing-curve',
      class: 's-curve',
      points: points(curve.map(([ratio, level]) => [x(ratio), y(level)])),
    }),
  );
  return figure(chart.svg, [{ cls: 's-curve', label: t('legend.groove_bearing_curve') }]);
}

// The feed (x) in the page's units: the curve keeps its shape, its axis reads in mm or inches.
function rzPlot(response, feedMm, target) {
  const hasTarget = at(response, '/max_feed_mm') !== undefined && Number.isFinite(target);
  return feedCurvePlot({
    kind: 'rz-vs-feed',
    title: t('diagram.rz_plot_title'),
    xLabel: t('diagram.feed_axis', { unit: unitText('mm') }),
    yLabel: subText('Rz', 'p', `, ${unitText('um')}`),
    curveLabel: 'Rz(S)',
    feedUnit: 'mm',
    curve: response.curve.map((p) => [fromApi(p.feed_mm, 'mm'), p.rz_um]),
    feed: fromApi(feedMm, 'mm'),
    height: response.rz_um,
    target: hasTarget ? { height: target, maxFeed: fromApi(response.max_feed_mm, 'mm') } : null,
  });
}
