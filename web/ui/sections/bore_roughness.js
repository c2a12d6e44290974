// Bore milling roughness (paper 001): the cusp between adjacent tooth paths and, with a target,
// the largest feed; the plot of the cusp against the feed comes from the same request
// (curve_points).

import { boreDiagrams } from '../diagrams/bore_roughness_diagram.js';
import { feedCurvePlot } from '../diagrams/feed_curve.js';
import { onCalculate } from '../core/calculation.js';
import { csvButton } from '../core/export.js';
import { at, h, iso, noDiagram, readBody, showFailure, sym, valueList } from '../core/form.js';
import { t } from '../core/i18n.js';
import { s } from '../core/svg.js';
import { csvUnit, fromApi, unitText } from '../core/units.js';

const PATH = '/v1/roughness/bore-milling';
const CURVE_POINTS = 200;
// The curve's fields (the answer's curve[] items) and API units, for its CSV.
const CURVE_COLUMNS = [
  ['feed_per_rev_mm', 'mm_per_rev'],
  ['cusp_height_um', 'um'],
];
const DELTA = '\u0394';

export function init() {
  const form = document.getElementById('bore-form');
  const result = document.getElementById('bore-result');
  return onCalculate(form, async (api) => {
    const body = readBody(form);
    const answer = await api.postJson(PATH, { ...body, curve_points: CURVE_POINTS });
    result.replaceChildren();
    if (!answer.ok) {
      showFailure(form, answer);
      result.append(h('p', { class: 'placeholder' }, t('result.no_results')));
      return;
    }
    result.append(
      h('h3', {}, t('result.cusp_title')),
      valueList(answer.json, [
        [
          [t('result.cusp_height'), ' ', ...sym('\u0394'), ' ', t('result.exact')],
          '/cusp_height_um',
          'um',
        ],
        [
          [
            t('result.approximation'),
            ' ',
            ...sym('f', 'zb'),
            h('var', { class: 'sym' }, '\u00b2/8 (1/r \u2212 1/R)'),
          ],
          '/approximate_cusp_height_um',
          'um',
        ],
        [
          [t('result.feed_per_tooth'), ' ', ...sym('f', 'z'), ' ', t('result.centre_path')],
          '/feed_per_tooth_mm',
          'mm_per_tooth',
        ],
        [
          [t('result.feed_per_tooth'), ' ', ...sym('f', 'zb'), ' ', t('result.on_bore')],
          '/feed_per_tooth_on_bore_mm',
          'mm_per_tooth',
        ],
        [[t('result.pitch_angle'), ' ', ...sym('\u03b1')], '/pitch_angle_deg', 'deg'],
        [
          [t('result.bore_largest_feed'), ' ', ...sym('S', 'max'), ...iso('f', 'max')],
          '/max_feed_per_rev_mm',
          'mm_per_rev',
        ],
      ]),
      h(
        'p',
        { class: 'source-note' },
        t('result.cusp_note'),
      ),
      boreDiagrams(
        {
          boreRadius: Number(body.bore_radius_mm?.text),
          cutterRadius: Number(body.cutter_radius_mm?.text),
          teeth: Number(body.teeth?.text),
          milling: body.milling,
        },
        answer.json,
        result,
      ),
    );
    const response = answer.json;
    if (Array.isArray(response.curve) && response.curve.length >= 2) {
      result.append(
        cuspPlot(response, Number(body.feed_per_rev_mm?.text), Number(body.target_cusp_um?.text)),
        csvButton(
          'bore-curve-csv',
          'bore-milling-cusp-curve.csv',
          CURVE_COLUMNS.map(([key, unit]) => [key, csvUnit(unit)]),
          response.curve.map((point) => CURVE_COLUMNS.map(([key]) => point[key])),
        ),
      );
    } else {
      result.append(noDiagram(t('result.no_curve')));
    }
  });
}

// The cusp against the feed (B13), with a target the target line and the largest feed (B12).
function cuspPlot(response, feedMm, target) {
  const hasTarget = at(response, '/max_feed_per_rev_mm') !== undefined && Number.isFinite(target);
  return feedCurvePlot({
    kind: 'cusp-vs-feed',
    title: t('diagram.bore_curve_title'),
    xLabel: t('diagram.bore_feed_axis', { unit: unitText('mm_per_rev') }),
    yLabel: [DELTA, s('tspan', {}, `, ${unitText('um')}`)],
    curveLabel: `${DELTA}(S)`,
    feedUnit: 'mm_per_rev',
    curve: response.curve.map((p) => [fromApi(p.feed_per_rev_mm, 'mm_per_rev'), p.cusp_height_um]),
    feed: fromApi(feedMm, 'mm_per_rev'),
    height: response.cusp_height_um,
    target: hasTarget
      ? { height: target, maxFeed: fromApi(response.max_feed_per_rev_mm, 'mm_per_rev') }
      : null,
  });
}
