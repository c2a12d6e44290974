// The page's state in its URL, so that a link reproduces a calculation (format in README.md):
//
//   /?groove.feed_mm=0.2&groove.nose_radius_mm=0.3&groove.minor_edge_angle_deg=2
//     &groove.target_rz_um=#groove      (one line)
//
// A key with a dot is one input of one section: the section's id, then the input's name (its
// JSON Pointer) with '.' for '/' (entry.allowance.width_mm is /allowance/width_mm of #entry-form).
// The value is the text as typed ("1,5" stays "1,5"); an empty value is an empty input. A section
// in the URL lists every input of its request, so the link keeps its meaning when the page's
// defaults change; a section not in the URL shows its defaults. Keys without a dot are page-wide
// settings (lang, units: i18n.js, units.js); the page keeps them, and ignores keys it does
// not know. The inputs of the page's machine profile (data-page-wide, machine.js) are page-wide
// too: keyed by their name alone (machine.axes.x.max_velocity_mm_per_min), written into every
// URL the page writes once they differ from their defaults. A <textarea> (a program to time) is
// never in the URL.

import { controls } from './form.js';
import { pageWideControls, profileSignature } from './machine.js';

const isPageWide = (control) => control.hasAttribute('data-page-wide');
const keyOf = (sectionId, control) =>
  isPageWide(control)
    ? control.name.slice(1).replaceAll('/', '.')
    : `${sectionId}${control.name.replaceAll('/', '.')}`;
const isPageSetting = (key) => !key.includes('.');
// A section's own inputs (not those of the page-wide profile it may hold).
const sectionControls = (form) => controls(form).filter((c) => !isPageWide(c));

// The inputs of the form's request (its enabled named controls) as [name, text] pairs: the list
// of a section's fields comes from the form itself.
export function fieldValues(form) {
  return controls(form).map((c) => [c.name, c.value]);
}

// A key for "the same inputs": a calculation is repeated only when this changes. Besides the
// form's inputs: its text areas (a program) and what of the machine profile the section uses.
export function signature(form) {
  const texts = [...form.querySelectorAll('textarea[name^="/"]')].map((area) => area.value);
  return JSON.stringify([fieldValues(form), texts, profileSignature(form)]);
}

function defaultValue(control) {
  if (control.tagName !== 'SELECT') return control.defaultValue;
  const option = [...control.options].find((o) => o.defaultSelected) ?? control.options[0];
  return option?.value ?? '';
}

export function differsFromDefaults(form) {
  return sectionControls(form).some((c) => c.value !== defaultValue(c));
}

// `text` gives the text of a control to write (the value as typed, or as converted when the
// units change).
function appendSection(params, sectionId, form, text = (control) => control.value) {
  for (const control of sectionControls(form)) {
    params.append(keyOf(sectionId, control), text(control));
  }
}

// The machine profile, every input of it, once it differs from its defaults.
function appendPageWide(params, text = (control) => control.value) {
  const profile = pageWideControls();
  if (!profile.some((c) => c.value !== defaultValue(c))) return;
  for (const control of profile) params.append(keyOf('', control), text(control));
}

// The page-wide settings of the current URL, to carry into every URL the page writes.
function pageSettings() {
  const params = new URLSearchParams();
  for (const [key, text] of new URLSearchParams(window.location.search)) {
    if (isPageSetting(key)) params.append(key, text);
  }
  return params;
}

function urlWith(params, sectionId) {
  const url = new URL(window.location.href);
  url.search = params.toString();
  url.hash = sectionId;
  return url.href;
}

// The link to one section's calculation (with the page-wide settings).
export function sectionLink(sectionId, form) {
  const params = pageSettings();
  appendPageWide(params);
  appendSection(params, sectionId, form);
  return urlWith(params, sectionId);
}

// The URL of the whole page: every section whose inputs differ from its defaults, scrolled to
// `sectionId`. sections = [{id, form}, ...].
export function pageUrl(sections, sectionId) {
  const params = pageSettings();
  appendPageWide(params);
  for (const { id, form } of sections) {
    if (differsFromDefaults(form)) appendSection(params, id, form);
  }
  return urlWith(params, sectionId);
}

// The URL of the whole page with page-wide settings changed (settings = {lang: 'ru'}; null drops
// a setting), the inputs written by `text(control)`, at the same place in the page.
export function pageUrlWith(sections, settings, text) {
  const params = pageSettings();
  for (const [key, value] of Object.entries(settings)) {
    params.delete(key);
    if (value !== null) params.append(key, value);
  }
  appendPageWide(params, text);
  for (const { id, form } of sections) {
    if (differsFromDefaults(form)) appendSection(params, id, form, text);
  }
  return urlWith(params, window.location.hash.slice(1));
}

// Sets the form to the section's inputs in `search` (a URL's query), its defaults where the URL
// has none. A select keeps its default when the URL names no option of it. The selects are
// announced (change events) so that the fields that depend on them are shown or hidden. A text
// area keeps its text (a program is not in the URL: back and forward do not lose it).
export function applyToForm(form, sectionId, search) {
  const params = new URLSearchParams(search);
  const texts = [...form.querySelectorAll('textarea')].map((area) => [area, area.value]);
  form.reset();
  for (const [area, text] of texts) area.value = text;
  const selects = [...form.querySelectorAll('select[name^="/"]')];
  for (const control of form.querySelectorAll('input[name^="/"], select[name^="/"]')) {
    const text = params.get(keyOf(sectionId, control));
    if (text === null) continue;
    const known = control.tagName !== 'SELECT' || [...control.options].some((o) => o.value === text);
    if (!known) continue;
    control.value = text;
  }
  for (const select of selects) select.dispatchEvent(new Event('change', { bubbles: true }));
}
