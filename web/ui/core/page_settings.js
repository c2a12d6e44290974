// The page-wide settings, language (lang) and units: links at the top of the page. A setting is
// kept in the URL (url_state.js), so choosing one opens the page's URL with it changed: the page
// starts again in the new language or units with the same inputs (typed lengths converted).

import { numberLiteral } from './api.js';
import { language } from './i18n.js';
import { convertTyped, inputUnit, units } from './units.js';
import { pageUrlWith } from './url_state.js';

const CURRENT = { lang: language, units };
// The value a setting has when the URL does not name it: left out of the URL.
const DEFAULT = { lang: 'en', units: 'mm' };

// A typed input as it reads in the `target` unit system (text that is not a number stays). A
// program written in the page's units follows them, so that it downloads in the new units.
function convertedText(control, target) {
  if (control.name === '/program/units') return control.value === units ? target : control.value;
  if (control.tagName === 'SELECT') return control.value;
  const literal = numberLiteral(control.value);
  if (literal === null) return control.value;
  return String(convertTyped(Number(literal), inputUnit(control), units, target));
}

function urlFor(calculators, setting, choice) {
  const value = choice === DEFAULT[setting] ? null : choice;
  const text = setting === 'units' ? (c) => convertedText(c, choice) : (c) => c.value;
  return pageUrlWith(calculators, { [setting]: value }, text);
}

export function wirePageSettings(calculators) {
  for (const link of document.querySelectorAll('a[data-setting]')) {
    const { setting, choice } = link.dataset;
    if (CURRENT[setting] === choice) link.setAttribute('aria-current', 'true');
    // The href is for people (hover, open in a new tab); a click takes the inputs as they are now.
    const refresh = () => {
      link.href = urlFor(calculators, setting, choice);
    };
    refresh();
    link.addEventListener('focus', refresh);
    link.addEventListener('pointerenter', refresh);
    link.addEventListener('click', (event) => {
      event.preventDefault();
      window.location.assign(urlFor(calculators, setting, choice));
    });
  }
}
