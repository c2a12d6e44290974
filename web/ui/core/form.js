// Forms: request bodies from the inputs (each input's name is its JSON Pointer), the service's
// problem messages next to the fields, and the result elements (data-result / data-value).

import { numberLiteral, RawNumber } from './api.js';
import { t } from './i18n.js';
import { converts, fromApi, inputUnit, shownUnit, toApi, unitText } from './units.js';

// Element builder: h('p', {class: 'x', 'data-a': 1}, 'text', child, ...). Attributes only: no
// inline style, no HTML strings (the page runs under a strict Content-Security-Policy).
export function h(tag, attrs = {}, ...children) {
  const element = document.createElement(tag);
  for (const [name, value] of Object.entries(attrs)) {
    if (value === undefined || value === null || value === false) continue;
    element.setAttribute(name, value === true ? '' : String(value));
  }
  for (const child of children.flat(Infinity)) {
    if (child === undefined || child === null || child === false) continue;
    element.append(child instanceof Node ? child : String(child));
  }
  return element;
}

function pointerTokens(pointer) {
  return pointer
    .split('/')
    .slice(1)
    .map((t) => t.replace(/~1/g, '/').replace(/~0/g, '~'));
}

function setAt(body, pointer, value) {
  const tokens = pointerTokens(pointer);
  let node = body;
  for (const token of tokens.slice(0, -1)) {
    if (typeof node[token] !== 'object' || node[token] === null) node[token] = {};
    node = node[token];
  }
  node[tokens[tokens.length - 1]] = value;
}

// The controls of a form that take part in requests: named, enabled, not in a hidden field.
export function controls(form) {
  return [...form.querySelectorAll('input[name^="/"], select[name^="/"]')].filter(
    (c) => !c.disabled,
  );
}

// A number typed in the page's units as the API's mm (other units pass as typed).
function apiNumber(control, literal) {
  const unit = inputUnit(control);
  if (!converts(unit)) return new RawNumber(literal);
  const mm = toApi(Number(literal), unit);
  // Too large to convert (1e400): sent as typed, so the service says why.
  return Number.isFinite(mm) ? new RawNumber(String(mm)) : new RawNumber(literal);
}

function controlValue(control) {
  if (control.tagName === 'SELECT') {
    // A yes/no choice is a JSON boolean.
    if (control.dataset.type === 'boolean') return control.value === 'true';
    return control.value;
  }
  const text = control.value.trim();
  if (control.dataset.type === 'number-list') {
    return text
      .split(/[\s;,]+/)
      .filter((t) => t !== '')
      .map((t) => {
        const literal = numberLiteral(t);
        return literal === null ? t : apiNumber(control, literal);
      });
  }
  if (control.dataset.type === 'number') {
    const literal = numberLiteral(text);
    // Not a number: sent as the text it is, so the service names the field and says why.
    return literal === null ? text : apiNumber(control, literal);
  }
  return text;
}

// The request body for `request` (an input without data-for belongs to every request of its
// form). An empty optional input is left out of the request.
export function readBody(form, request) {
  const body = {};
  for (const control of controls(form)) {
    const wanted = control.dataset.for;
    if (request && wanted && !wanted.split(/\s+/).includes(request)) continue;
    if (control.tagName !== 'SELECT' && control.value.trim() === '') continue;
    setAt(body, control.name, controlValue(control));
  }
  return body;
}

// Shows/hides the fields that apply to the selected contour: a field with
// data-contour-of="/entry/contour" data-contour="straight" is shown (and its input enabled) only
// while that select says "straight". Hidden inputs are disabled and so left out of the request.
export function wireContourFields(form) {
  const update = () => {
    for (const field of form.querySelectorAll('[data-contour-of]')) {
      const select = form.querySelector(`select[name="${field.dataset.contourOf}"]`);
      const applies = select !== null && field.dataset.contour.split(/\s+/).includes(select.value);
      field.hidden = !applies;
      for (const control of field.querySelectorAll('input, select')) control.disabled = !applies;
    }
  };
  form.addEventListener('change', (event) => {
    if (event.target instanceof HTMLSelectElement) update();
  });
  update();
}

// ------------------------------------------------------------------ errors

export function clearErrors(form) {
  for (const p of form.querySelectorAll('p.field-error')) p.remove();
  for (const control of form.querySelectorAll('[aria-invalid]')) {
    control.removeAttribute('aria-invalid');
    const original = control.dataset.describedby;
    if (original) control.setAttribute('aria-describedby', original);
    else control.removeAttribute('aria-describedby');
    delete control.dataset.describedby;
  }
  const box = form.querySelector('.form-error');
  box.replaceChildren();
  box.hidden = true;
}

// The enabled control whose name is `pointer` (a text area too: the program of Program time), or
// the one holding the list element it points into (/contact_angles_deg/1 belongs to the
// /contact_angles_deg list input).
function controlFor(form, pointer) {
  const areas = [...form.querySelectorAll('textarea[name^="/"]')].filter((a) => !a.disabled);
  const all = [...controls(form), ...areas];
  const exact = all.find((c) => c.name === pointer);
  if (exact) return exact;
  const m = /^(.*)\/\d+$/.exec(pointer);
  return m ? all.find((c) => c.name === m[1] && c.dataset.type === 'number-list') : undefined;
}

function fieldError(control, message) {
  const id = `${control.id}-error`;
  let p = document.getElementById(id);
  if (p) {
    const known = [...p.querySelectorAll('span')].map((s) => s.textContent);
    if (!known.includes(message)) p.append(h('span', {}, known.length ? ` ${message}` : message));
    return;
  }
  p = h('p', { class: 'field-error', id }, h('span', {}, message));
  control.after(p);
  if (!control.hasAttribute('aria-invalid')) {
    const original = control.getAttribute('aria-describedby');
    if (original) control.dataset.describedby = original;
    control.setAttribute('aria-invalid', 'true');
    control.setAttribute('aria-describedby', original ? `${id} ${original}` : id);
  }
}

function formError(form, message) {
  const box = form.querySelector('.form-error');
  const known = [...box.querySelectorAll('p')].map((p) => p.textContent);
  if (known.includes(message)) return;
  box.append(h('p', {}, message));
  box.hidden = false;
}

// Shows a failed answer: each errors[] item next to the input its pointer names, the rest and
// the detail at the top of the form. The messages are the service's own text. `label` names the
// calculation when a form drives several (then it prefixes the messages at the top).
export function showFailure(form, answer, label = '') {
  const prefix = label ? `${label}: ` : '';
  if (answer.status === 0) {
    const reason = answer.networkError?.message ?? t('error.network');
    formError(form, prefix + t('error.unreachable', { reason }));
    return;
  }
  const problem = answer.json;
  if (!problem || typeof problem !== 'object') {
    formError(form, `${prefix}HTTP ${answer.status}: ${answer.text.slice(0, 200)}`);
    return;
  }
  const unplaced = [];
  for (const item of Array.isArray(problem.errors) ? problem.errors : []) {
    const control = typeof item.pointer === 'string' ? controlFor(form, item.pointer) : undefined;
    if (control) fieldError(control, String(item.detail));
    else unplaced.push(String(item.detail));
  }
  if (problem.detail) formError(form, prefix + problem.detail);
  for (const message of unplaced) {
    if (message !== problem.detail) formError(form, prefix + message);
  }
}

export function showMessage(form, message) {
  formError(form, message);
}

// ------------------------------------------------------------------ results

// A length of the API (mm) as the page shows it: its number in the page's units and the unit.
export const lengthText = (mm) => `${fmt(fromApi(mm, 'mm'))} ${unitText('mm')}`;

// A number for people: at most 4 decimals (trailing zeros dropped), 4 significant digits for
// very small or very large magnitudes.
export function fmt(value) {
  if (typeof value !== 'number' || !Number.isFinite(value)) return String(value);
  const magnitude = Math.abs(value);
  if (magnitude !== 0 && (magnitude < 1e-3 || magnitude >= 1e7)) {
    return value.toPrecision(4).replace(/\.?0+(?=e|$)/, '');
  }
  const text = value.toFixed(4).replace(/\.?0+$/, '');
  return text === '-0' ? '0' : text;
}

// The value at JSON Pointer `pointer` in `body`, or undefined.
export function at(body, pointer) {
  let node = body;
  for (const token of pointerTokens(pointer)) {
    if (node === null || typeof node !== 'object' || !(token in node)) return undefined;
    node = node[token];
  }
  return node;
}

// The element showing the value at `pointer` of `body`: in the page's units (units.js), rounded
// for display, the API's full value in data-value, the unit shown in data-unit and, unless
// `bare` (a table column names it), beside it. `unit` is the API's unit id (catalogue unit.<id>).
// `source` names the answering endpoint where a section has two. `describe` turns a string value
// (a code such as "nose_arc") into words for people.
export function value(
  body,
  pointer,
  unit = '',
  source = undefined,
  describe = undefined,
  bare = false,
) {
  const v = at(body, pointer);
  const shown = typeof v === 'number' ? fmt(fromApi(v, unit)) : (describe?.(v) ?? String(v));
  const num = h(
    'span',
    {
      class: typeof v === 'number' ? 'num' : 'num words',
      'data-result': pointer,
      'data-value': String(v),
      'data-unit': unit ? shownUnit(unit) : undefined,
      'data-source': source,
    },
    shown,
  );
  return unit && !bare
    ? h('span', { class: 'quantity' }, num, '\u00a0', h('span', { class: 'unit' }, unitText(unit)))
    : num;
}

// A program's warnings: each code (data-result) with the API's sentence for it, in the language
// the page asked for (Accept-Language); the API keeps the one catalogue of warnings. Its detail,
// English with the numbers, is the program's comment line: shown only when there is no message.
export function warningList(body) {
  const warnings = Array.isArray(body.warnings) ? body.warnings : [];
  if (!warnings.length) return [];
  const sentence = (w) => w.message ?? w.detail;
  return h(
    'ul',
    { class: 'warnings' },
    warnings.map((w, i) => h('li', {}, value(body, `/warnings/${i}/code`), ': ', sentence(w))),
  );
}

// A list of "label: value unit" rows. rows = [[labelNodes, pointer, unit, describe?], ...]
export function valueList(body, rows, source = undefined) {
  return h(
    'dl',
    { class: 'values' },
    rows
      .filter(([, pointer]) => at(body, pointer) !== undefined)
      .map(([label, pointer, unit, describe]) =>
        h('div', {}, h('dt', {}, label), h('dd', {}, value(body, pointer, unit, source, describe))),
      ),
  );
}

// A paper symbol with a subscript: sym('L', 'vr') -> <var class="sym">L<sub>vr</sub></var>.
// Symbols are not words: no language changes them.
export function sym(base, sub = '') {
  return [h('var', { class: 'sym' }, base, sub ? h('sub', {}, sub) : null)];
}

// The ISO 3002 / cutting-data symbol shown beside a paper symbol where the two differ
// (S_z -> f_z), so that a letter means one thing across the page.
export function iso(base, sub = '') {
  return [' ', h('var', { class: 'iso' }, base, sub ? h('sub', {}, sub) : null)];
}

export function noDiagram(what) {
  return h('p', { class: 'no-diagram' }, t('result.no_diagram', { what }));
}
