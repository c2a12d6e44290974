// The bore-milling cusp against the feed (spec roughness.md B13): the answer's curve, with a target
// also the target line and the largest feed (B12), and the requested feed marked. The feed axis
// reads in the page's units; the cusp stays in micrometres.

import { at, fmt } from './form.js';
import { t } from './i18n.js';
import { domain, figure, plot, points, s } from './svg.js';
import { fromApi, unitText } from './units.js';

// The curve's fields (the answer's curve[] items) and API units, for its CSV.
export const CURVE_COLUMNS = [
  ['feed_per_rev_mm', 'mm_per_rev'],
  ['cusp_height_um', 'um'],
];

const DELTA = '\u0394';

export function cuspPlot(answer, feedMm, target) {
  const feed = fromApi(feedMm, 'mm_per_rev');
  const curve = answer.curve.map((p) => [
    fromApi(p.feed_per_rev_mm, 'mm_per_rev'),
    p.cusp_height_um,
  ]);
  const hasTarget = at(answer, '/max_feed_per_rev_mm') !== undefined && Number.isFinite(target);
  const ys = curve
    .map((p) => p[1])
    .concat(hasTarget ? [target] : [])
    .concat([answer.cusp_height_um]);
  const xs = curve.map((p) => p[0]).concat([feed]);
  const chart = plot({
    kind: 'cusp-vs-feed',
    title: t('diagram.bore_curve_title'),
    xLabel: t('diagram.bore_feed_axis', { unit: unitText('mm_per_rev') }),
    yLabel: [DELTA, s('tspan', {}, `, ${unitText('um')}`)],
    xDomain: domain(xs, 0.02, true),
    yDomain: domain(ys, 0.08, true),
  });
  const { x, y, area } = chart;
  chart.layer.append(
    s('polyline', {
      'data-role': 'curve',
      class: 's-curve',
      points: points(curve.map(([f, cusp]) => [x(f), y(cusp)])),
    }),
  );
  const legend = [{ cls: 's-curve', label: `${DELTA}(S)` }];
  if (hasTarget) {
    const maxFeed = fromApi(answer.max_feed_per_rev_mm, 'mm_per_rev');
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
        s(
          'text',
          { x: area.left + 4, y: y(target), dy: '-0.4em' },
          `T = ${fmt(target)} ${unitText('um')}`,
        ),
      ),
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
          `S max = ${fmt(maxFeed)} ${unitText('mm_per_rev')}`,
        ),
      ),
    );
    legend.push(
      { cls: 's-target', label: t('legend.target') },
      { cls: 's-max-feed', label: t('legend.largest_feed') },
    );
  }
  chart.svg.append(
    s(
      'g',
      { 'data-role': 'feed-marker' },
      s('circle', { class: 's-marker', cx: x(feed), cy: y(answer.cusp_height_um), r: 5 }),
    ),
  );
  legend.push({ cls: 's-marker', label: t('legend.this_feed'), shape: 'dot' });
  return figure(chart.svg, legend);
}
