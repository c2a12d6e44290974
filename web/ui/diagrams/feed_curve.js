// A height against the feed (groove wall Rz(S), roughness.md R8; bore cusp Delta(S), B13): the
// answer's curve, the requested feed marked and, with a target, the target line and the largest
// feed. The feed axis reads in the page's units; the height stays in micrometres.

import { fmt } from '../core/form.js';
import { t } from '../core/i18n.js';
import { domain, figure, plot, points, s } from '../core/svg.js';
import { unitText } from '../core/units.js';

// `curve`: [feed, height] pairs and `feed` in the page's units (`feedUnit`); `height` the answer at
// `feed`; `target`: {height, maxFeed} (maxFeed in the page's units) or null.
export function feedCurvePlot({ kind, title, xLabel, yLabel, curveLabel, feedUnit, curve, feed, height, target }) {
  const ys = curve
    .map((p) => p[1])
    .concat(target ? [target.height] : [])
    .concat([height]);
  const xs = curve.map((p) => p[0]).concat([feed]);
  const chart = plot({
    kind,
    title,
    xLabel,
    yLabel,
    xDomain: domain(xs, 0.02, true),
    yDomain: domain(ys, 0.08, true),
  });
  const { x, y, area } = chart;
  chart.layer.append(
    s('polyline', {
      'data-role': 'curve',
      class: 's-curve',
      points: points(curve.map(([f, value]) => [x(f), y(value)])),
    }),
  );
  const legend = [{ cls: 's-curve', label: curveLabel }];
  if (target) {
    chart.layer.append(
      s(
        'g',
        { 'data-role': 'target-line' },
        s('line', {
          class: 's-target',
          x1: area.left,
          y1: y(target.height),
          x2: area.right,
          y2: y(target.height),
        }),
        s(
          'text',
          { x: area.left + 4, y: y(target.height), dy: '-0.4em' },
          `T = ${fmt(target.height)} ${unitText('um')}`,
        ),
      ),
      s(
        'g',
        { 'data-role': 'max-feed-line' },
        s('line', {
          class: 's-max-feed',
          x1: x(target.maxFeed),
          y1: area.top,
          x2: x(target.maxFeed),
          y2: area.bottom,
        }),
        s(
          'text',
          { x: x(target.maxFeed), y: area.top, dx: '-0.3em', dy: '1em', 'text-anchor': 'end' },
          `S max = ${fmt(target.maxFeed)} ${unitText(feedUnit)}`,
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
      s('circle', { class: 's-marker', cx: x(feed), cy: y(height), r: 5 }),
    ),
  );
  legend.push({ cls: 's-marker', label: t('legend.this_feed'), shape: 'dot' });
  return figure(chart.svg, legend);
}
