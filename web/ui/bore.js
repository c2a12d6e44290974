// Bore milling roughness (paper 001): the cusp between adjacent tooth paths.

import { boreDiagrams } from './bore_diagram.js';
import { onCalculate } from './calculation.js';
import { h, readBody, showFailure, sym, valueList } from './form.js';

export function init() {
  const form = document.getElementById('bore-form');
  const result = document.getElementById('bore-result');
  return onCalculate(form, async (api) => {
    const body = readBody(form);
    const answer = await api.postJson('/v1/roughness/bore-milling', body);
    result.replaceChildren();
    if (!answer.ok) {
      showFailure(form, answer);
      result.append(h('p', { class: 'placeholder' }, 'No results: see the messages in the form.'));
      return;
    }
    result.append(
      h('h3', {}, 'Cusp between adjacent tooth paths'),
      valueList(answer.json, [
        [['Cusp height \u0394 (exact)'], '/cusp_height_um', '\u00b5m'],
        [
          ['Approximation ', ...sym('f', 'zb'), '\u00b2/8 (1/r \u2212 1/R)'],
          '/approximate_cusp_height_um',
          '\u00b5m',
        ],
        [['Feed per tooth ', ...sym('f', 'z'), ' (centre path)'], '/feed_per_tooth_mm', 'mm'],
        [['Feed per tooth ', ...sym('f', 'zb'), ' (bore)'], '/feed_per_tooth_on_bore_mm', 'mm'],
        [['Pitch angle \u03b1'], '/pitch_angle_deg', 'deg'],
      ]),
      h(
        'p',
        { class: 'source-note' },
        'The kinematic cusp between ideal tooth paths: a lower bound of the profile height.',
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
  });
}
