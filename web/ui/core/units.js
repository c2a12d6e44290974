// The page's units: the `units` page setting of the URL, mm by default, inch on request. The API
// speaks mm only, so the page converts at its edge: inputs typed in inches are sent in mm
// (form.js), the mm answers are shown in inches (form.js value(), the diagrams' dimension texts).
// Only lengths and feeds convert; speeds (m/min, rpm), angles, times and Rz (µm) stay.

import en from './catalogue_en.js';
import { t } from './i18n.js';

export const MM_PER_INCH = 25.4;

// Each unit (its catalogue key unit.<id>) that is a length to some power, with its inch
// counterpart: the one conversion table of the page.
const INCH = {
  mm: { unit: 'in', power: 1 },
  mm_per_tooth: { unit: 'in_per_tooth', power: 1 },
  mm_per_rev: { unit: 'in_per_rev', power: 1 },
  mm_per_min: { unit: 'in_per_min', power: 1 },
  mm2: { unit: 'in2', power: 2 },
};

export const UNIT_SYSTEMS = ['mm', 'inch'];
const asked = new URLSearchParams(window.location.search).get('units');
export const units = UNIT_SYSTEMS.includes(asked) ? asked : 'mm';

const inchOf = (unit) => (units === 'inch' ? INCH[unit] : undefined);
const factor = (conversion) => MM_PER_INCH ** conversion.power;

// Whether a quantity in `unit` is shown in other units on this page.
export const converts = (unit) => inchOf(unit) !== undefined;

// The unit id a quantity in the API's `unit` is shown in.
export const shownUnit = (unit) => inchOf(unit)?.unit ?? unit;

// An API value (mm) in the page's units, and back.
export function fromApi(value, unit) {
  const conversion = inchOf(unit);
  return conversion && typeof value === 'number' ? value / factor(conversion) : value;
}
export function toApi(value, unit) {
  const conversion = inchOf(unit);
  return conversion ? value * factor(conversion) : value;
}

// The shown unit's name in the page's language ('' for none).
export const unitText = (unit) => (unit ? t(`unit.${shownUnit(unit)}`) : '');

// Rounds a converted input so that it reads as typed (5 significant digits: 0.0001 in, 1 µm).
export function roundInput(value) {
  return Number(value.toPrecision(5));
}

// A value typed in `system` (mm or inch) for a field in `unit`, as the same length in `target`.
export function convertTyped(value, unit, system, target) {
  if (!INCH[unit] || system === target) return value;
  const f = factor(INCH[unit]);
  return roundInput(target === 'inch' ? value / f : value * f);
}

// The unit of an input: its label's [data-unit] (the label says it once).
export function inputUnit(control) {
  const label = control.id ? document.querySelector(`label[for="${control.id}"]`) : null;
  return label?.querySelector('[data-unit]')?.dataset.unit ?? '';
}

// Puts the static page into its units: every label's unit name, the inputs' defaults in inches
// (so a section not in the URL shows its defaults in the page's units) and the programs' default
// units, so that a program downloads in the units the page is in.
export function applyUnitsToPage() {
  for (const element of document.querySelectorAll('[data-unit]')) {
    element.textContent = unitText(element.dataset.unit);
  }
  if (units === 'mm') return;
  for (const input of document.querySelectorAll('input[name^="/"]')) {
    const unit = inputUnit(input);
    const typed = Number(input.defaultValue);
    if (converts(unit) && input.defaultValue.trim() !== '' && Number.isFinite(typed)) {
      input.defaultValue = String(convertTyped(typed, unit, 'mm', units));
    }
  }
  for (const option of document.querySelectorAll('select[name="/program/units"] option')) {
    option.defaultSelected = option.value === units;
  }
}

// A CSV column's unit: the API's (mm), named in English like the API's field names, whatever
// the page shows (the file is data for programs, the same in every language and unit system).
export const csvUnit = (unit) => (unit ? en[`unit.${unit}`] : '');
