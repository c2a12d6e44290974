// The page's machine profile (machine-time.md section 2): one machine for the whole page, edited in
// the Machine fieldset of the Program time section (its inputs carry data-page-wide and are named
// by their JSON Pointer in a /v1/program-time request: /machine/axes/x/max_velocity_mm_per_min).
// It is kept in the link as page-wide keys, the pointer without the section's id
// (machine.axes.x.max_velocity_mm_per_min, url_state.js). Presets fill in the kind and the axes.
// The program sections send it as their request's `machine` when it is the kind of machine their
// program is for (a mill: entry, polygon; a lathe: grooving, flat; their form's data-machine) and
// show the answer's machine_time under their own times.

import { numberLiteral } from './api.js';
import { h, readBody, value } from './form.js';
import { t } from './i18n.js';
import { convertTyped, units } from './units.js';

// The form the profile is edited in.
const PROFILE_FORM = 'program-time-form';

// Axis limits of the presets: [velocity, acceleration] in mm/min and mm/s^2 (deg/min, deg/s^2 for
// C); an axis a preset lacks is left empty (the machine has no such axis).
export const PRESETS = {
  hobby_router: { kind: 'mill', x: [3000, 200], y: [3000, 200], z: [1500, 100] },
  router: { kind: 'mill', x: [12000, 1000], y: [12000, 1000], z: [8000, 600] },
  machining_centre: {
    kind: 'mill',
    x: [36000, 4000],
    y: [36000, 4000],
    z: [36000, 4000],
    c: [18000, 3600],
  },
  lathe: { kind: 'lathe', x: [10000, 1500], z: [12000, 1500], c: [21600, 3600] },
};
const AXES = ['x', 'y', 'z', 'c'];
const ROTARY = new Set(['a', 'b', 'c']);

// The names (JSON Pointers) of an axis's two limits.
export function axisNames(axis) {
  return ROTARY.has(axis)
    ? [`/machine/axes/${axis}/max_velocity_deg_per_min`, `/machine/axes/${axis}/max_acceleration_deg_per_s2`]
    : [`/machine/axes/${axis}/max_velocity_mm_per_min`, `/machine/axes/${axis}/max_acceleration_mm_per_s2`];
}

// The profile's inputs, wherever they are on the page.
export const pageWideControls = () =>
  [...document.querySelectorAll('[data-page-wide]')].filter((c) => !c.disabled);

const profileControl = (name) => pageWideControls().find((c) => c.name === name);

// The profile's kind of machine: mill or lathe.
export const profileKind = () => profileControl('/machine/kind')?.value ?? 'mill';

// The profile as the `machine` member of a request (lengths typed in inches are sent in mm).
export function machineBody() {
  return readBody(document.getElementById(PROFILE_FORM)).machine ?? {};
}

// What of the profile a section's calculation depends on (url_state.js signature): its values
// when the section's program is timed on it, else only its kind.
export function profileSignature(form) {
  const wanted = form.dataset.machine;
  if (wanted === undefined) return '';
  const kind = profileKind();
  if (wanted !== 'any' && wanted !== kind) return kind;
  return JSON.stringify(pageWideControls().map((c) => [c.name, c.value]));
}

// ------------------------------------------------------------------ presets

// A preset's inputs as typed in the page's units (velocities in in/min on an inch page, rounded
// as the page rounds converted inputs; accelerations and the rotary axis as they are).
function presetTexts(preset) {
  const texts = { '/machine/kind': preset.kind };
  for (const axis of AXES) {
    const [velocityName, accelerationName] = axisNames(axis);
    const limits = preset[axis];
    const velocity = limits && !ROTARY.has(axis) ? convertTyped(limits[0], 'mm_per_min', 'mm', units) : limits?.[0];
    texts[velocityName] = limits ? String(velocity) : '';
    texts[accelerationName] = limits ? String(limits[1]) : '';
  }
  return texts;
}

const sameText = (typed, wanted) => {
  if (typed.trim() === '' || wanted === '') return typed.trim() === wanted;
  const literal = numberLiteral(typed);
  return literal === null ? typed === wanted : Number(literal) === Number(wanted);
};

// The preset the profile's kind and axes are, or '' (custom).
function matchingPreset() {
  for (const [name, preset] of Object.entries(PRESETS)) {
    const texts = presetTexts(preset);
    const all = Object.entries(texts).every(([control, text]) => {
      const c = profileControl(control);
      return c !== undefined && sameText(c.value, text);
    });
    if (all) return name;
  }
  return '';
}

// The preset select of the Machine fieldset: choosing one fills in the kind and the axes (the
// trajectory's maximum and the servo period stay); it shows the preset the inputs are, or Custom.
export function wirePresets(form) {
  const select = form.querySelector('select[data-role="machine-preset"]');
  if (!select) return;
  const show = () => {
    select.value = matchingPreset();
  };
  // A choice fires input, then change: the preset is applied on the first, before the form's
  // listeners below see the event.
  const apply = () => {
    const preset = PRESETS[select.value];
    if (!preset) return;
    for (const [name, text] of Object.entries(presetTexts(preset))) {
      const control = profileControl(name);
      if (control) control.value = text;
    }
  };
  select.addEventListener('input', apply);
  select.addEventListener('change', apply);
  // After every edit, and after the page itself set the inputs (a link, back and forward: the
  // named selects are announced with change events, url_state.js applyToForm).
  form.addEventListener('input', show);
  form.addEventListener('change', show);
  show();
}

// ------------------------------------------------------------------ the program sections

// The API refused the request only because of the profile: the program moves an axis the
// profile lacks, or the profile is wrong (Program time shows its messages at its inputs).
function onlyProfileErrors(answer) {
  const errors = answer.json?.errors;
  return (
    answer.status === 422 &&
    Array.isArray(errors) &&
    errors.length > 0 &&
    errors.every((e) => typeof e.pointer === 'string' && e.pointer.startsWith('/machine'))
  );
}

// POSTs a program section's `body` with the profile as its `machine` when the profile is the
// `kind` of machine the program is for and has the `axes` the program moves. Refused for the
// profile alone (another axis it lacks, a wrong limit), the program is asked for again without it. Returns {answer, sent (the body
// answered), note (why the program is not timed on the machine, or null)}.
export async function postWithMachine(api, path, body, kind, axes) {
  const profile = profileKind();
  const machine = machineBody();
  const lacking = axes.filter((axis) => !machine.axes?.[axis]);
  if (profile !== kind || lacking.length) {
    const answer = await api.postJson(path, body);
    const note =
      profile !== kind
        ? t(`result.machine_not_timed_${profile}`)
        : t('result.machine_not_timed_axes', { axes: lacking.map((a) => a.toUpperCase()).join(', ') });
    return { answer, sent: body, note };
  }
  const withMachine = { ...body, machine: { ...(body.machine ?? {}), ...machine } };
  const answer = await api.postJson(path, withMachine);
  if (!onlyProfileErrors(answer)) return { answer, sent: withMachine, note: null };
  const reason = answer.json.errors.map((e) => e.detail).join('; ');
  const again = await api.postJson(path, body);
  return { answer: again, sent: body, note: t('result.machine_not_timed_refused', { reason }) };
}

// Marks `form` as timed on the profile (its last request sent it), for its printed sheet.
export function markTimed(form, sent) {
  form.toggleAttribute('data-timed', Boolean(sent?.machine?.axes));
}

const profileLink = () =>
  h('a', { href: '#program-time-machine', 'data-role': 'machine-profile-link' }, t('result.machine_profile_link'));

// Under a program section's times: "On this machine (machine profile): T_e min, nominal T_n min"
// from the answer's machine_time, or why the program is not timed on the machine. `source` names
// the answering endpoint where the section has several (entry).
export function machineTimeLine(answerJson, note, source = undefined) {
  if (note) {
    return h('p', { class: 'source-note', 'data-role': 'machine-time-note' }, note, ' (', profileLink(), ').');
  }
  if (!answerJson?.machine_time) return null;
  return h(
    'p',
    { class: 'machine-time', 'data-role': 'machine-time' },
    t('result.on_this_machine'),
    ' (',
    profileLink(),
    '): ',
    value(answerJson, '/machine_time/estimated_time_min', 'min', source),
    ', ',
    t('result.nominal_short'),
    ' ',
    value(answerJson, '/machine_time/nominal_time_min', 'min', source),
  );
}
