#!/usr/bin/env node
// Property-based contract step (Schemathesis-style): for every operation of openapi.yaml with an
// application/json request body, generates request bodies from the request schema itself ($ref,
// allOf, oneOf alternatives and discriminated branches, not, dependentRequired, required,
// additionalProperties false, enum, const, pattern, minimum/maximum/exclusive*, integer,
// minItems/maxItems, default), sends them to a running cutcalc and checks every answer.
//
// Categories of bodies (deterministic for a seed):
//   valid     schema-valid bodies: random ones, and the reference cases' 200 requests
//   fault1    one member broken: wrong type, out of range, a number too large for a double, not an
//             integer, missing required, unknown key, bad enum/const, pattern, list length; or one
//             rule between members broken (oneOf alternatives, not, dependentRequired)
//   fault2    two members broken at once
//   faultN    three to six members broken at once (a number too large for a double aside)
//   boundary  every numeric bound of every member and the exact next double past it (the bound
//             of an integer member also +-1)
//   defaults  every schema default sent explicitly, beside the same body without them
// Oracle, every answer: no transport error (reset, socket error, timeout), no 5xx, a status the
// operation declares with its declared media type and a body valid against the schema of that
// status (contract.mjs, Ajv, JSON Schema 2020-12); every errors[].pointer names a member of the
// request (or, for `required`, an absent member whose parent exists). Per category:
//   valid, boundary at a bound, defaults: never 400 and never a 422 `invalid-input` with a field
//             error (codes of the field rules of ErrorCode); a 422 `impossible-input` is allowed
//             (random combinations are often impossible for the model). A 422 `invalid-input` with
//             only rules between fields that the schema does not state (dialect_only, not_above,
//             ...) is a note (a gap between schema and service, listed, not a failure);
//   fault1, boundary past a bound: 422 `invalid-input` (400 allowed) whose errors[] names the
//             broken member (a broken rule between members: "" or one of its members);
//   fault2:   both broken members named when both faults are field-level (else at least one);
//   faultN:   every broken member named; an emptied object: every required member of it named;
//   defaults: the same answer as the body without the defaults (200: the same JSON; a problem:
//             the same type and the same errors' (pointer, code)).
// Every finding is deduplicated (operation, rule, fault kinds at their schema locations, status,
// problem type), minimised (optional members removed while the finding stays) and printed with a
// reproducer: method, path, body, status, answer. Known findings (property-known.mjs) are printed
// but do not fail the run.
//
// Usage: property.mjs [--base-url URL] [--seed N] [--requests N] [--seconds S] [--concurrency N]
//                     [--openapi FILE] [--reference-dir DIR] [--report-json FILE] [--verbose]
// Environment: CUTCALC_URL, PROPERTY_SEED (default 20261127), PROPERTY_REQUESTS (default 5000),
// PROPERTY_SECONDS (default 150: no new case after it; minimising stops at 1.15 x it),
// PROPERTY_CONCURRENCY (default 4), OPENAPI_FILE, CUTCALC_REFERENCE_DIR (missing: random bases only).
// Exit status: 0 no finding (or only known ones), 1 findings, 2 setup error.
import { existsSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';
import { Contract } from './contract.mjs';
import { KNOWN_FINDINGS } from './property-known.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const repo = path.resolve(here, '..', '..');
const { values: opt } = parseArgs({
  options: {
    'base-url': { type: 'string' }, seed: { type: 'string' }, requests: { type: 'string' }, seconds: { type: 'string' },
    concurrency: { type: 'string' }, openapi: { type: 'string' }, 'reference-dir': { type: 'string' },
    'report-json': { type: 'string' }, verbose: { type: 'boolean' },
  },
});
const setupError = message => {
  console.error(`property: ${message}`);
  process.exit(2);
};
const env = name => (process.env[name] !== undefined && process.env[name] !== '' ? process.env[name] : undefined);
const BASE_URL = (opt['base-url'] ?? env('CUTCALC_URL') ?? setupError('give --base-url URL or CUTCALC_URL')).replace(/\/$/, '');
const SEED = Number(opt.seed ?? env('PROPERTY_SEED') ?? 20261127) >>> 0;
const REQUESTS = Math.max(100, Number(opt.requests ?? env('PROPERTY_REQUESTS') ?? 5000));
const SECONDS = Math.max(5, Number(opt.seconds ?? env('PROPERTY_SECONDS') ?? 150));
const CONCURRENCY = Math.max(1, Number(opt.concurrency ?? env('PROPERTY_CONCURRENCY') ?? 4));
const OPENAPI_FILE = path.resolve(opt.openapi ?? env('OPENAPI_FILE') ?? path.join(repo, 'openapi.yaml'));
const REFERENCE_DIR = path.resolve(repo, opt['reference-dir'] ?? env('CUTCALC_REFERENCE_DIR') ?? path.join('..', 'shared', 'reference'));
const VERBOSE = opt.verbose || env('PROPERTY_VERBOSE') === '1';
const TIMEOUT_MS = 30000;
const MINIMISE_REQUESTS_PER_FINDING = 60;

let contract;
try {
  contract = new Contract(OPENAPI_FILE);
} catch (e) {
  setupError(e.message);
}

// Codes of ErrorCode's field rules (a schema-valid body must never get one) and of its rules
// between fields (`invalid-input` too; stated by the schema only in part).
const FIELD_CODES = new Set(['required', 'required_choice', 'not_a_number', 'not_finite', 'not_an_integer', 'must_be_positive',
  'must_not_be_negative', 'below_resolution', 'out_of_range', 'wrong_list_length', 'not_a_boolean', 'not_a_string',
  'not_an_object', 'not_one_of', 'unknown_field', 'body_not_an_object']);
const INVALID = 'urn:cutcalc:problem:invalid-input';
const IMPOSSIBLE = 'urn:cutcalc:problem:impossible-input';

// ------------------------------------------------------------------ random numbers (sfc32)
function makeRng(...seeds) {
  let h = 1779033703;
  for (const s of seeds) for (const ch of String(s)) h = Math.imul(h ^ ch.charCodeAt(0), 3432918353) >>> 0, h = (h << 13) | (h >>> 19);
  let a = h ^ 0x9e3779b9, b = Math.imul(h, 0x85ebca6b) >>> 0, c = Math.imul(h ^ 0xc2b2ae35, 0x27d4eb2f) >>> 0, d = 1;
  const next = () => {
    a >>>= 0; b >>>= 0; c >>>= 0; d >>>= 0;
    const t = (a + b + d) >>> 0;
    d = (d + 1) >>> 0;
    a = b ^ (b >>> 9);
    b = (c + (c << 3)) >>> 0;
    c = (c << 21) | (c >>> 11);
    c = (c + t) >>> 0;
    return t / 4294967296;
  };
  for (let i = 0; i < 12; i++) next();
  const rng = {
    next,
    int: (lo, hi) => lo + Math.floor(next() * (hi - lo + 1)),
    pick: list => list[Math.floor(next() * list.length)],
    chance: p => next() < p,
    uniform: (lo, hi) => lo + (hi - lo) * next(),
    logUniform: (lo, hi) => Math.exp(Math.log(lo) + (Math.log(hi) - Math.log(lo)) * next()),
  };
  return rng;
}

// ------------------------------------------------------------------ doubles
const f64 = new Float64Array(1);
const u64 = new BigUint64Array(f64.buffer);
function nextUp(x) {
  if (Number.isNaN(x) || x === Infinity) return x;
  if (x === 0) return Number.MIN_VALUE;
  f64[0] = x;
  u64[0] += x > 0 ? 1n : -1n;
  return f64[0];
}
const nextDown = x => -nextUp(-x);

// ------------------------------------------------------------------ JSON with raw number text
// A Raw is a number written as given ("1e400", "4.0"); `value` is what a JSON parser reads.
class Raw {
  constructor(text, value) {
    this.text = text;
    this.value = value;
  }
}
function toJson(v) {
  if (v instanceof Raw) return v.text;
  if (Array.isArray(v)) return `[${v.map(toJson).join(',')}]`;
  if (v && typeof v === 'object') return `{${Object.entries(v).map(([k, x]) => `${JSON.stringify(k)}:${toJson(x)}`).join(',')}}`;
  return JSON.stringify(v);
}
// The value a validator sees (1e400 cannot be represented: the string "1e400", a type error too).
function plain(v) {
  if (v instanceof Raw) return Number.isFinite(v.value) ? v.value : v.text;
  if (Array.isArray(v)) return v.map(plain);
  if (v && typeof v === 'object') return Object.fromEntries(Object.entries(v).map(([k, x]) => [k, plain(x)]));
  return v;
}
function clone(v) {
  if (v instanceof Raw) return v;
  if (Array.isArray(v)) return v.map(clone);
  if (v && typeof v === 'object') return Object.fromEntries(Object.entries(v).map(([k, x]) => [k, clone(x)]));
  return v;
}
const isObject = v => v !== null && typeof v === 'object' && !Array.isArray(v) && !(v instanceof Raw);

// ------------------------------------------------------------------ JSON Pointers
const esc = t => String(t).replace(/~/g, '~0').replace(/\//g, '~1');
const unesc = t => t.replace(/~1/g, '/').replace(/~0/g, '~');
const tokens = p => (p === '' ? [] : p.split('/').slice(1).map(unesc));
const join = (p, k) => `${p}/${esc(k)}`;
function resolvePointer(v, p) {
  let cur = v;
  for (const t of tokens(p)) {
    if (Array.isArray(cur) && /^(0|[1-9][0-9]*)$/.test(t) && Number(t) < cur.length) cur = cur[Number(t)];
    else if (isObject(cur) && Object.prototype.hasOwnProperty.call(cur, t)) cur = cur[t];
    else return { found: false };
  }
  return { found: true, value: cur };
}
function parentOf(p) {
  const ts = tokens(p);
  return { parent: ts.slice(0, -1).map(t => '/' + esc(t)).join(''), key: ts[ts.length - 1] };
}
function setAt(body, p, value) {
  const { parent, key } = parentOf(p);
  const r = resolvePointer(body, parent);
  if (!r.found) throw new Error(`no parent for ${p}`);
  if (Array.isArray(r.value)) r.value[Number(key)] = value;
  else r.value[key] = value;
}
function removeAt(body, p) {
  const { parent, key } = parentOf(p);
  const r = resolvePointer(body, parent);
  if (r.found && isObject(r.value)) delete r.value[key];
}
// "/contact_angles_deg/3" -> "/contact_angles_deg/*" (the schema location, for deduplication).
const generic = p => p.replace(/\/(0|[1-9][0-9]*)(?=\/|$)/g, '/*');
const related = (a, b) => a === b || a.startsWith(b + '/') || b.startsWith(a + '/');

// ------------------------------------------------------------------ the schema, flattened
// A schema with its $refs followed and its allOf merged: { type, props, required, closed,
// dependentRequired, choices (oneOf alternatives that only require members), branches (oneOf
// alternatives that are schemas of their own), nots, enum, const, bounds, items, pattern, default }.
function deref(s) {
  let seen = 0;
  while (s && typeof s === 'object' && typeof s.$ref === 'string') {
    if (++seen > 50) throw new Error(`$ref loop at ${s.$ref}`);
    s = contract.at(s.$ref.slice(1)).value;
  }
  return s ?? {};
}
function flatten(schema, into) {
  const s = deref(schema);
  const f = into ?? { props: {}, required: new Set(), dependentRequired: {}, choices: [], branches: [], nots: [] };
  for (const k of ['type', 'enum', 'const', 'minimum', 'maximum', 'exclusiveMinimum', 'exclusiveMaximum', 'minItems', 'maxItems',
    'items', 'pattern', 'default']) {
    if (s[k] !== undefined && f[k] === undefined) f[k] = s[k];
  }
  if (s.const !== undefined && f.type === undefined) f.type = typeof s.const === 'string' ? 'string' : f.type;
  if (s.additionalProperties === false) f.closed = true;
  for (const [k, v] of Object.entries(s.properties ?? {})) {
    f.props[k] = f.props[k] ? { allOf: [f.props[k], v] } : v;
  }
  for (const r of s.required ?? []) f.required.add(r);
  for (const [k, v] of Object.entries(s.dependentRequired ?? {})) f.dependentRequired[k] = [...(f.dependentRequired[k] ?? []), ...v];
  if (s.not) f.nots.push(deref(s.not));
  if (s.oneOf || s.anyOf) {
    const alts = (s.oneOf ?? s.anyOf).map(deref);
    if (alts.every(a => !a.properties && !a.type && Array.isArray(a.required))) f.choices.push({ exactlyOne: !!s.oneOf, alts: alts.map(a => a.required) });
    else f.branches.push(...alts);
  }
  for (const part of s.allOf ?? []) flatten(part, f);
  return f;
}
const flat = s => flatten(s);
const typeOf = f => f.type ?? (f.enum ? typeof f.enum[0] : f.const !== undefined ? typeof f.const : Object.keys(f.props).length ? 'object' : undefined);
// The branch of a discriminated oneOf that a value takes (its consts match), with the parent merged in.
function branchFor(f, value) {
  if (!f.branches.length) return f;
  let best = f.branches[0];
  for (const b of f.branches) {
    const consts = Object.entries(b.properties ?? {}).filter(([, p]) => deref(p).const !== undefined);
    if (consts.length && consts.every(([k, p]) => isObject(value) && value[k] === deref(p).const)) best = b;
  }
  return mergeBranch(f, best);
}
function mergeBranch(f, branch) {
  const g = { ...f, props: { ...f.props }, required: new Set(f.required), branches: [], nots: [...f.nots], choices: [...f.choices] };
  return flatten(branch, g);
}
function bounds(f) {
  const lo = f.minimum ?? (f.exclusiveMinimum !== undefined ? nextUp(f.exclusiveMinimum) : undefined);
  const hi = f.maximum ?? (f.exclusiveMaximum !== undefined ? nextDown(f.exclusiveMaximum) : undefined);
  return { lo, hi };
}

// ------------------------------------------------------------------ strings from a pattern
// Enough of regular expressions for the patterns of request schemas: literals, classes with
// ranges, groups with alternatives, quantifiers ? * + {m} {m,n}; ^ and $ are dropped.
function patternString(pattern, rng) {
  let i = 0;
  const src = pattern.replace(/^\^/, '').replace(/\$$/, '');
  const parseAlt = () => {
    const alts = [[]];
    while (i < src.length && src[i] !== ')') {
      if (src[i] === '|') { i++; alts.push([]); continue; }
      alts[alts.length - 1].push(parseQuantified());
    }
    return { alts };
  };
  const parseAtom = () => {
    const c = src[i++];
    if (c === '(') {
      if (src.startsWith('?:', i)) i += 2;
      const g = parseAlt();
      i++;
      return { group: g };
    }
    if (c === '[') {
      const chars = [];
      while (src[i] !== ']') {
        let a = src[i++];
        if (a === '\\') a = src[i++];
        if (src[i] === '-' && src[i + 1] !== ']') {
          const b = src[i + 1];
          i += 2;
          for (let x = a.charCodeAt(0); x <= b.charCodeAt(0); x++) chars.push(String.fromCharCode(x));
        } else chars.push(a);
      }
      i++;
      return { chars };
    }
    if (c === '\\') {
      const d = src[i++];
      if (d === 'd') return { chars: '0123456789'.split('') };
      return { chars: [d] };
    }
    if (c === '.') return { chars: 'abcXYZ019_'.split('') };
    return { chars: [c] };
  };
  const parseQuantified = () => {
    const atom = parseAtom();
    let min = 1, max = 1;
    if (src[i] === '?') { min = 0; max = 1; i++; } else if (src[i] === '*') { min = 0; max = 4; i++; } else if (src[i] === '+') { min = 1; max = 4; i++; } else if (src[i] === '{') {
      const close = src.indexOf('}', i);
      const [a, b] = src.slice(i + 1, close).split(',');
      min = Number(a);
      max = b === undefined ? min : b === '' ? min + 4 : Number(b);
      i = close + 1;
    }
    return { atom, min, max };
  };
  const tree = parseAlt();
  const emit = node => node.alts ? rng.pick(node.alts).map(q => {
    const n = rng.int(q.min, Math.min(q.max, q.min + 8));
    let s = '';
    for (let k = 0; k < n; k++) s += q.atom.group ? emit(q.atom.group) : rng.pick(q.atom.chars);
    return s;
  }).join('') : '';
  const out = emit(tree);
  if (!new RegExp(pattern, 'u').test(out)) throw new Error(`pattern ${pattern}: generated ${out}`);
  return out;
}

// ------------------------------------------------------------------ valid values
function genNumber(f, rng, integer) {
  let { lo, hi } = bounds(f);
  if (integer) {
    lo = lo === undefined ? -1000 : Math.ceil(lo);
    hi = hi === undefined ? 1000 : Math.floor(hi);
    const r = rng.next();
    let n;
    if (r < 0.6) n = rng.int(lo, Math.min(hi, lo + 12));
    else if (r < 0.75) n = rng.pick([lo, hi]);
    else n = rng.int(lo, hi);
    // "an integer-valued number such as 2.0 is accepted"
    return rng.chance(0.1) ? new Raw(`${n}.0`, n) : n;
  }
  const L = lo ?? -1e6, H = hi ?? 1e6;
  const r = rng.next();
  let x;
  if (r < 0.55) {
    // moderate sizes: shop-floor numbers, most likely to be answered 200
    const mlo = Math.max(L, L >= 0 ? Math.min(0.1, H) : -100), mhi = Math.min(H, 200);
    if (mlo >= mhi) x = rng.uniform(L, H);
    else x = mlo > 0 ? rng.logUniform(mlo, mhi) : rng.uniform(mlo, mhi);
    if (rng.chance(0.6)) x = Math.min(H, Math.max(L, Number(x.toFixed(rng.int(0, 3)))));
  } else if (r < 0.65) x = rng.pick([L, H]);
  else if (r < 0.8 && L >= 0) x = rng.logUniform(Math.max(L, 1e-6), Math.max(H, 1e-6));
  else if (r < 0.9) x = rng.uniform(L, H);
  else x = Math.min(H, Math.max(L, rng.int(Math.ceil(Math.max(L, -20)), Math.floor(Math.min(H, 20)))));
  if (x < L) x = L;
  if (x > H) x = H;
  if (Object.is(x, -0)) x = 0;
  return spelled(x, rng);
}

// Other JSON spellings of the same number (exponent, upper-case E, -0 for 0, trailing zeros).
function spelled(x, rng) {
  if (!rng.chance(0.08)) return x;
  if (x === 0) return rng.chance(0.5) ? new Raw('-0', 0) : new Raw('0.0e0', 0);
  const e = x.toExponential();
  const options = [e, e.toUpperCase(), e.replace('e+', 'e'), Number.isInteger(x) ? `${x}.000` : `${x}0`];
  const text = rng.pick(options);
  return Number(text) === x ? new Raw(text, x) : x;
}

function genValue(schema, rng, depth = 0) {
  let f = flat(schema);
  if (f.branches.length) f = mergeBranch(f, rng.pick(f.branches));
  if (f.const !== undefined) return f.const;
  if (f.enum) return rng.pick(f.enum);
  const t = Array.isArray(f.type) ? f.type[0] : typeOf(f);
  switch (t) {
    case 'number': return genNumber(f, rng, false);
    case 'integer': return genNumber(f, rng, true);
    case 'boolean': return rng.chance(0.5);
    case 'string': return f.pattern ? patternString(f.pattern, rng) : rng.pick(['a', 'text', 'Wert']);
    case 'array': {
      const min = f.minItems ?? 0;
      const max = f.maxItems ?? min + 6;
      const n = rng.chance(0.9) ? rng.int(min, Math.min(max, min + 5)) : rng.int(min, max);
      return Array.from({ length: n }, () => genValue(f.items ?? {}, rng, depth + 1));
    }
    case 'object': return genObject(f, rng, depth);
    default: return null;
  }
}

function genObject(f, rng, depth) {
  const out = {};
  const names = new Set(f.required);
  const excluded = new Set();
  for (const c of f.choices) {
    const chosen = rng.pick(c.alts);
    chosen.forEach(n => names.add(n));
    for (const a of c.alts) if (a !== chosen) a.filter(n => !chosen.includes(n)).forEach(n => excluded.add(n));
  }
  const pOptional = depth === 0 ? 0.45 : 0.5;
  for (const k of Object.keys(f.props)) if (!names.has(k) && !excluded.has(k) && rng.chance(pOptional)) names.add(k);
  // dependentRequired, to a fixed point
  for (let changed = true; changed;) {
    changed = false;
    for (const k of [...names]) for (const d of f.dependentRequired[k] ?? []) if (!names.has(d)) { names.add(d); changed = true; }
  }
  for (const k of Object.keys(f.props)) if (names.has(k)) out[k] = genValue(f.props[k], rng, depth + 1);
  // not: drop an optional member of a forbidden combination
  for (const n of f.nots) {
    if (notMatches(n, out)) {
      const optional = (n.required ?? []).filter(k => !f.required.has(k) && !f.choices.some(c => c.alts.some(a => a.includes(k))));
      if (optional.length) delete out[rng.pick(optional)];
    }
  }
  return out;
}

// Whether a value matches a `not` schema of the shape used here: required members, members with a const.
function notMatches(n, value) {
  if (!isObject(value)) return false;
  if (!(n.required ?? []).every(k => k in value)) return false;
  return Object.entries(n.properties ?? {}).every(([k, p]) => p === true || !(k in value) || deref(p).const === undefined || plain(value[k]) === deref(p).const);
}

// ------------------------------------------------------------------ faults
// A fault: { kind, pointer, fieldLevel, expect (pointers of which errors[] must name one), apply(body) }.
const WRONG_TYPE = { number: ['"12"', 'true', 'null', '{}', '[1]'], integer: ['"3"', 'false', 'null', '[]'], string: ['7', 'true', 'null', '{}'],
  boolean: ['"true"', '1', 'null'], array: ['{}', '"1,2"', '5', 'null'], object: ['[]', '"x"', '3', 'true', 'null'] };

function faultsOf(schema, body, rng) {
  const out = [];
  const walk = (s, value, p, isRoot) => {
    let f = flat(s);
    if (f.branches.length) {
      f = branchFor(f, value);
    }
    const t = Array.isArray(f.type) ? f.type[0] : typeOf(f);
    const before = out.length;
    if (!isRoot) {
      const wrong = WRONG_TYPE[t] ?? WRONG_TYPE.number;
      const w = rng.pick(wrong);
      out.push(fieldFault('wrong_type', p, () => new Raw(w, JSON.parse(w))));
    }
    if (f.const !== undefined || f.enum) out.push(fieldFault(f.const !== undefined ? 'bad_const' : 'bad_enum', p, () => 'not_a_listed_value'));
    if (f.const !== undefined) out.slice(before).forEach(x => { x.discriminator = true; });
    if (t === 'number' || t === 'integer') {
      const { lo, hi } = bounds(f);
      if (lo !== undefined) out.push(fieldFault('below_minimum', p, () => (lo > 1 ? lo / 2 - 1 : lo - rng.pick([1, 0.5, Math.abs(lo) + 1]))));
      if (hi !== undefined) out.push(fieldFault('above_maximum', p, () => (hi > 0 ? hi * 10 + 1 : hi + 1)));
      out.push(fieldFault('too_large_for_double', p, () => (rng.chance(0.5) ? new Raw('1e400', Infinity) : new Raw('-1e400', -Infinity))));
      if (t === 'integer') out.push(fieldFault('not_an_integer', p, () => (lo ?? 0) + 0.5));
    }
    if (t === 'string' && f.pattern) out.push(fieldFault('pattern', p, () => 'lower case!'));
    if (t === 'array' && Array.isArray(value)) {
      if ((f.minItems ?? 0) > 0) out.push(fieldFault('too_few_items', p, () => []));
      if (f.maxItems !== undefined) out.push(fieldFault('too_many_items', p, () => Array.from({ length: f.maxItems + 1 }, (_, i) => plain(value[i % Math.max(1, value.length)] ?? 0))));
      value.forEach((x, i) => walk(f.items ?? {}, x, join(p, i), false));
    }
    if (t === 'object' && isObject(value)) {
      if (f.closed) out.push(fieldFault('unknown_key', join(p, 'zz_unknown_member'), () => 1, { add: true }));
      // every required member missing at once: each one listed
      const requiredHere = [...f.required].filter(k => f.props[k] && !f.choices.some(c => c.alts.some(a => a.includes(k))));
      if (!isRoot && requiredHere.length > 1) {
        // without its discriminator the object has no branch: only the discriminator can be named
        const discriminators = requiredHere.filter(k => flat(f.props[k]).const !== undefined);
        out.push({ kind: 'emptied_object', pointer: p, fieldLevel: true, all: true, expect: (discriminators.length ? discriminators : requiredHere).map(k => join(p, k)),
          discriminator: discriminators.length > 0, apply: b => setAt(b, p, {}) });
      }
      const choiceMembers = new Set(f.choices.flatMap(c => c.alts.flat()));
      for (const k of Object.keys(value)) {
        const kp = join(p, k);
        if (f.required.has(k) && !choiceMembers.has(k)) {
          out.push({ kind: 'missing_required', pointer: kp, fieldLevel: true, expect: [kp], apply: b => removeAt(b, kp),
            discriminator: f.props[k] !== undefined && flat(f.props[k]).const !== undefined });
        }
        if (f.props[k]) walk(f.props[k], value[k], kp, false);
      }
      // rules between members
      for (const c of f.choices) {
        const present = c.alts.filter(a => a.every(k => k in value));
        const members = [...new Set(c.alts.flat())];
        const expect = ['', ...members.map(k => join(p, k))];
        if (present.length === 1) {
          const gone = present[0].filter(k => !f.required.has(k));
          if (gone.length) out.push({ kind: 'no_alternative', pointer: join(p, gone[0]), fieldLevel: false, expect, apply: b => gone.forEach(k => removeAt(b, join(p, k))) });
          const other = c.alts.find(a => a !== present[0]);
          if (other && c.exactlyOne) {
            out.push({ kind: 'two_alternatives', pointer: join(p, other[0]), fieldLevel: false, expect,
              apply: b => other.forEach(k => { if (!(k in resolvePointer(b, p).value)) setAt(b, join(p, k), genValue(f.props[k] ?? {}, rng)); }) });
          }
        }
      }
      for (const n of f.nots) {
        const req = n.required ?? [];
        if (!req.length || !req.every(k => f.props[k])) continue;
        const consts = Object.entries(n.properties ?? {}).filter(([, x]) => x !== true && deref(x).const !== undefined);
        // members the combination needs inside a member (`not: {required: [a, b], properties: {b:
        // {required: [c]}}}`): b/c is part of it, and may be the member named
        const nested = Object.entries(n.properties ?? {}).flatMap(([k, x]) =>
          x !== true && Array.isArray(deref(x).required) ? deref(x).required.map(c => [k, c]) : []);
        out.push({ kind: 'forbidden_combination', pointer: join(p, req[req.length - 1]), fieldLevel: false,
          expect: ['', ...req.map(k => join(p, k)), ...nested.map(([k, c]) => join(join(p, k), c))],
          apply: b => {
            const obj = resolvePointer(b, p).value;
            for (const k of req) if (!(k in obj)) obj[k] = genValue(f.props[k], rng);
            for (const [k, x] of consts) obj[k] = deref(x).const;
            for (const [k, c] of nested) {
              const inner = obj[k];
              const schema = deref(f.props[k] ?? {});
              if (inner && typeof inner === 'object' && !(c in inner)) inner[c] = genValue(deref(schema.properties?.[c] ?? {}), rng);
            }
          } });
      }
      for (const [k, deps] of Object.entries(f.dependentRequired)) {
        if (!(k in value)) continue;
        for (const d of deps) {
          if (!(d in value) || f.required.has(d)) continue;
          // every member that needs d may be named (the one left when two faults remove more)
          const needing = Object.entries(f.dependentRequired).filter(([, ds]) => ds.includes(d)).map(([x]) => join(p, x));
          out.push({ kind: 'dependency_missing', pointer: join(p, d), fieldLevel: false, expect: ['', join(p, d), ...needing], apply: b => removeAt(b, join(p, d)) });
        }
      }
    }
  };
  walk(schema, body, '', true);
  return out;
}
function fieldFault(kind, pointer, make, { add = false } = {}) {
  return { kind, pointer, fieldLevel: true, expect: [pointer], add, apply: b => setAt(b, pointer, make()) };
}

// ------------------------------------------------------------------ numeric members and their bounds
// Every numeric member the schema allows in this body (present or absent, in present objects).
function numericMembers(schema, body) {
  const out = [];
  const walk = (s, value, p) => {
    let f = flat(s);
    if (f.branches.length) f = branchFor(f, value);
    const t = Array.isArray(f.type) ? f.type[0] : typeOf(f);
    if ((t === 'number' || t === 'integer') && p !== '') out.push({ pointer: p, f, integer: t === 'integer' });
    if (t === 'array' && p !== '' && Array.isArray(value) && (f.minItems !== undefined || f.maxItems !== undefined)) out.push({ pointer: p, f, array: value });
    if (t === 'object' && isObject(value)) {
      for (const [k, ps] of Object.entries(f.props)) {
        if (k in value) walk(ps, value[k], join(p, k));
        else {
          const g = flat(ps);
          const gt = typeOf(g);
          if (gt === 'number' || gt === 'integer') out.push({ pointer: join(p, k), f: g, integer: gt === 'integer', absent: true, owner: f, ownerPointer: p, key: k });
        }
      }
    }
    if (t === 'array' && Array.isArray(value) && value.length) walk(f.items ?? {}, value[0], join(p, 0));
  };
  walk(schema, body, '');
  return out;
}
// A body with the member at `m.pointer` present, and whatever the schema then asks for: the other
// alternatives of a oneOf removed, dependencies added, a forbidden partner removed.
function withMember(schema, body, m, value, rng) {
  const b = clone(body);
  const { parent, key } = parentOf(m.pointer);
  const owner = resolvePointer(b, parent).value;
  if (!isObject(owner) && !Array.isArray(owner)) return undefined;
  let f = flat(resolveSchemaAt(schema, b, parent));
  if (f.branches.length) f = branchFor(f, owner);
  owner[key] = value;
  if (isObject(owner)) {
    for (const c of f.choices) {
      const mine = c.alts.find(a => a.includes(key));
      if (!mine) continue;
      for (const a of c.alts) if (a !== mine) a.filter(k => !mine.includes(k) && !f.required.has(k)).forEach(k => delete owner[k]);
    }
    for (let changed = true; changed;) {
      changed = false;
      for (const k of Object.keys(owner)) for (const d of f.dependentRequired[k] ?? []) if (!(d in owner)) { owner[d] = genValue(f.props[d], rng); changed = true; }
    }
    for (const n of f.nots) if (notMatches(n, owner)) for (const k of n.required ?? []) if (k !== key && !f.required.has(k)) delete owner[k];
  }
  return b;
}
// The schema of the value at pointer p of body.
function resolveSchemaAt(schema, body, p) {
  let s = schema;
  let v = body;
  for (const t of tokens(p)) {
    let f = flat(s);
    if (f.branches.length) f = branchFor(f, v);
    s = Array.isArray(v) ? f.items ?? {} : f.props[t] ?? {};
    v = Array.isArray(v) ? v[Number(t)] : v?.[t];
  }
  return s;
}

// Every schema default, sent explicitly, in the body and in every object in it (recursively).
function withDefaults(schema, body) {
  const b = clone(body);
  const added = [];
  const walk = (s, value, p) => {
    let f = flat(s);
    if (f.branches.length) f = branchFor(f, value);
    if (isObject(value)) {
      for (const [k, ps] of Object.entries(f.props)) {
        const g = flat(ps);
        if (!(k in value) && g.default !== undefined) {
          value[k] = clone(g.default);
          added.push(join(p, k));
        }
        if (k in value) walk(ps, value[k], join(p, k));
      }
    } else if (Array.isArray(value)) value.forEach((x, i) => walk(f.items ?? {}, x, join(p, i)));
  };
  walk(schema, b, '');
  return { body: b, added };
}
// Absent optional objects that need no member, given as {} (so that their defaults are sent too).
function withEmptyObjects(schema, body) {
  const b = clone(body);
  let f = flat(schema);
  for (const [k, ps] of Object.entries(f.props)) {
    const g = flat(ps);
    if (!(k in b) && typeOf(g) === 'object' && g.required.size === 0 && !g.branches.length) b[k] = {};
  }
  return b;
}

// ------------------------------------------------------------------ operations and bases
function operations() {
  const ops = [];
  for (const [p, item] of Object.entries(contract.document.paths)) {
    for (const m of ['post', 'put', 'patch']) {
      const rb = item[m]?.requestBody && contract.at(`/paths/${esc(p)}/${m}/requestBody`).value;
      const key = Object.keys(rb?.content ?? {}).find(k => k.split(';')[0].trim() === 'application/json');
      if (key && rb.content[key].schema) ops.push({ method: m.toUpperCase(), path: p, schema: rb.content[key].schema });
    }
  }
  return ops;
}
function referenceBases(opPath) {
  if (!existsSync(REFERENCE_DIR)) return [];
  const out = [];
  for (const file of readdirSync(REFERENCE_DIR).filter(f => f.endsWith('.json')).sort()) {
    const doc = JSON.parse(readFileSync(path.join(REFERENCE_DIR, file), 'utf8'));
    if (doc.endpoint !== opPath) continue;
    for (const c of doc.cases ?? []) if (c.expect?.status === 200) out.push({ body: c.request, from: `${file}:${c.id}` });
  }
  return out;
}
const schemaValid = (op, body) => contract.checkRequest(op.method, op.path, plain(body)).length === 0;
function randomValid(op, rng) {
  for (let i = 0; i < 40; i++) {
    const b = genValue(op.schema, rng);
    if (schemaValid(op, b)) return b;
  }
  throw new Error(`${op.path}: no schema-valid body in 40 tries: ${contract.checkRequest(op.method, op.path, plain(genValue(op.schema, rng))).join('; ')}`);
}

// ------------------------------------------------------------------ cases
// A case: { op, category, body, faults?, note?, pair? (defaults: the body without them) }.
function buildCases(ops) {
  const cases = [];
  const perOp = Math.floor(REQUESTS / ops.length);
  ops.forEach(op => {
    const rng = makeRng(SEED, op.path);
    const refs = referenceBases(op.path).filter(r => schemaValid(op, r.body));
    const bases = [...refs.map(r => r.body)];
    const base = () => (refs.length && rng.chance(0.4) ? clone(rng.pick(refs).body) : randomValid(op, rng));
    const mine = [];
    const budget = { valid: Math.round(perOp * 0.2), fault1: Math.round(perOp * 0.22), fault2: Math.round(perOp * 0.14), faultN: Math.round(perOp * 0.06),
      boundary: Math.round(perOp * 0.28), defaults: Math.round(perOp * 0.1) };
    // valid: the reference requests, then random ones
    for (const r of refs) if (mine.filter(c => c.category === 'valid').length < budget.valid / 3) mine.push({ op, category: 'valid', body: r.body, note: r.from });
    while (mine.filter(c => c.category === 'valid').length < budget.valid) mine.push({ op, category: 'valid', body: randomValid(op, rng) });
    // one fault
    // every (kind, schema location) first, a broken rule between members on several bases (what
    // else the base has may hide it), then random ones with each kind given a fair share
    const seenFaults = new Map();
    const wanted = x => (x.fieldLevel ? 1 : 6);
    for (let n = 0, tries = 0; n < budget.fault1 && tries < budget.fault1 * 5; tries++) {
      const b = base();
      const faults = faultsOf(op.schema, b, rng);
      const keyOf = x => `${x.kind}@${generic(x.pointer)}`;
      const unseen = faults.filter(x => (seenFaults.get(keyOf(x)) ?? 0) < wanted(x));
      const kinds = [...new Set((unseen.length ? unseen : faults).map(x => x.kind))];
      const kind = rng.pick(kinds);
      const fault = rng.pick((unseen.length ? unseen : faults).filter(x => x.kind === kind));
      seenFaults.set(keyOf(fault), (seenFaults.get(keyOf(fault)) ?? 0) + 1);
      const c = faultCase(op, b, [fault], 'fault1');
      if (c) { mine.push(c); n++; }
    }
    // two faults
    for (let n = 0, tries = 0; n < budget.fault2 && tries < budget.fault2 * 5; tries++) {
      const b = base();
      const faults = faultsOf(op.schema, b, rng);
      const first = rng.pick(faults.filter(x => x.fieldLevel || rng.chance(0.3)));
      // a broken discriminator (or a removed one) leaves its siblings without a schema: pair it with other objects only
      const apart = x => x !== first && !related(x.pointer, first.pointer) &&
        (!(x.discriminator || first.discriminator) || parentOf(x.pointer).parent !== parentOf(first.pointer).parent);
      const second = rng.pick(faults.filter(apart));
      if (!second) continue;
      const c = faultCase(op, b, [first, second], 'fault2');
      if (c) { mine.push(c); n++; }
    }
    // three to six members broken at once (1e400 aside: it hides the others, see fault2): each one named
    for (let n = 0, tries = 0; n < budget.faultN && tries < budget.faultN * 5; tries++) {
      const b = base();
      const faults = faultsOf(op.schema, b, rng).filter(x => x.fieldLevel && x.kind !== 'too_large_for_double');
      const chosen = [];
      for (const x of sample(faults, faults.length, rng)) {
        if (chosen.length >= rng.int(3, 6)) break;
        if (chosen.every(y => !related(x.pointer, y.pointer) && !((x.discriminator || y.discriminator) && parentOf(x.pointer).parent === parentOf(y.pointer).parent))) chosen.push(x);
      }
      if (chosen.length < 3) continue;
      const c = faultCase(op, b, chosen, 'faultN');
      if (c) { mine.push(c); n++; }
    }
    // boundaries: every bound of every numeric member, on the reference bases first, then random ones
    const boundaryCases = [];
    const boundaryBases = [...bases.slice(0, 4), ...Array.from({ length: 3 }, () => randomValid(op, rng))];
    for (const b of boundaryBases) {
      for (const m of numericMembers(op.schema, b)) {
        for (const [at, past] of boundaryPairs(m)) {
          const valid = withMember(op.schema, b, m, at, rng);
          if (!valid || !schemaValid(op, valid)) continue;
          const show = v => (Array.isArray(v) ? `a list of ${v.length}` : toJson(v));
          const atCase = { op, category: 'boundary', body: valid, note: `${m.pointer} = ${show(at)} (at the bound)`, member: m.pointer, bound: `${show(at)}/${show(past)}` };
          boundaryCases.push(atCase);
          const bad = clone(valid);
          setAt(bad, m.pointer, past);
          if (schemaValid(op, bad)) continue;
          boundaryCases.push({ op, category: 'boundary', body: bad, base: valid, note: `${m.pointer} = ${show(past)} (past the bound)`, pastOf: atCase,
            faults: [{ kind: 'past_bound', pointer: m.pointer, fieldLevel: true, expect: [m.pointer] }] });
        }
      }
    }
    // every (member, bound) once (at and past it), then a sample of the others
    const seenBounds = new Set();
    const firstOfEach = [];
    const rest = [];
    for (let i = 0; i < boundaryCases.length; i++) {
      const c = boundaryCases[i];
      if (c.faults) continue;
      const key = `${generic(c.member)} ${c.bound}`;
      const past = boundaryCases[i + 1]?.pastOf === c ? [boundaryCases[i + 1]] : [];
      if (seenBounds.has(key)) rest.push(c, ...past);
      else { seenBounds.add(key); firstOfEach.push(c, ...past); }
    }
    mine.push(...firstOfEach, ...sample(rest, Math.max(0, budget.boundary - firstOfEach.length), rng));
    // explicit defaults: pairs, on every reference base and random ones, with and without the optional objects
    const defaultBases = [...bases, ...Array.from({ length: Math.max(0, Math.ceil(budget.defaults / 2) - bases.length) }, () => randomValid(op, rng))];
    let pairs = 0;
    for (const b0 of defaultBases) {
      if (pairs * 2 >= budget.defaults) break;
      const b = pairs % 2 === 1 ? withEmptyObjects(op.schema, b0) : b0;
      if (!schemaValid(op, b)) continue;
      const d = withDefaults(op.schema, b);
      if (!d.added.length) continue;
      mine.push({ op, category: 'defaults', body: d.body, pair: b, note: `defaults sent: ${d.added.join(', ')}`, schemaInvalid: !schemaValid(op, d.body) });
      pairs++;
    }
    // a share of the answers in the other forms the contract states: the plain-text program, Russian problems
    const textForm = Object.keys(contract.findResponse(op.method, op.path, 200).response?.content ?? {}).find(k => k.startsWith('text/plain'));
    for (const c of mine) {
      if (textForm && !c.faults && c.category !== 'defaults' && rng.chance(0.2)) c.headers = { accept: 'text/plain' };
      else if (c.faults && rng.chance(0.2)) c.headers = { language: 'ru-RU,ru;q=0.9' };
    }
    cases.push(...mine);
  });
  return cases;
}
function sample(list, n, rng) {
  const idx = list.map((_, i) => i);
  for (let i = idx.length - 1; i > 0; i--) {
    const j = Math.floor(rng.next() * (i + 1));
    [idx[i], idx[j]] = [idx[j], idx[i]];
  }
  return idx.slice(0, n).sort((a, b) => a - b).map(i => list[i]);
}
// [value at the bound (valid), value just past it (invalid)] for each bound of a member.
function boundaryPairs(m) {
  const f = m.f;
  const out = [];
  if (m.array) {
    const list = n => Array.from({ length: n }, (_, i) => clone(m.array[i % m.array.length]));
    if (f.minItems !== undefined && m.array.length) out.push([list(f.minItems), list(Math.max(0, f.minItems - 1))]);
    if (f.maxItems !== undefined && m.array.length) out.push([list(f.maxItems), list(f.maxItems + 1)]);
    return out.filter(([a, b]) => a.length !== b.length);
  }
  if (f.minimum !== undefined) {
    out.push([f.minimum, nextDown(f.minimum)]);
    if (m.integer) out.push([f.minimum, f.minimum - 1]);
  }
  if (f.maximum !== undefined) {
    out.push([f.maximum, nextUp(f.maximum)]);
    if (m.integer) out.push([f.maximum, f.maximum + 1]);
  }
  if (f.exclusiveMinimum !== undefined) out.push([nextUp(f.exclusiveMinimum), f.exclusiveMinimum]);
  if (f.exclusiveMaximum !== undefined) out.push([nextDown(f.exclusiveMaximum), f.exclusiveMaximum]);
  return out;
}
function faultCase(op, base, faults, category) {
  const b = clone(base);
  for (const f of faults) {
    try {
      f.apply(b);
    } catch {
      return undefined;
    }
  }
  if (schemaValid(op, b)) return undefined; // not a fault after all (e.g. a default-like value)
  return { op, category, body: b, base, faults: faults.map(({ kind, pointer, fieldLevel, expect, discriminator, all }) => ({ kind, pointer, fieldLevel, expect, discriminator, all })) };
}

// ------------------------------------------------------------------ HTTP
let requestCounter = 0;
async function send(op, body, { accept = 'application/json', language } = {}) {
  const text = toJson(body);
  const started = Date.now();
  try {
    const requestHeaders = { 'content-type': 'application/json', accept, 'x-request-id': `property-${++requestCounter}` };
    if (language) requestHeaders['accept-language'] = language;
    const res = await fetch(BASE_URL + op.path, {
      method: op.method,
      headers: requestHeaders,
      body: Buffer.from(text, 'utf8'), signal: AbortSignal.timeout(TIMEOUT_MS), redirect: 'manual',
    });
    const raw = await res.text();
    const headers = Object.fromEntries(res.headers);
    const contentType = headers['content-type'] ?? '';
    let json;
    if (/^application\/([a-z0-9.+-]*\+)?json\b/i.test(contentType)) {
      try { json = JSON.parse(raw); } catch { json = undefined; }
    }
    return { status: res.status, headers, contentType, raw, json, text, ms: Date.now() - started };
  } catch (e) {
    return { error: `${e.name}: ${e.message}${e.cause ? ` (${e.cause.code ?? ''} ${e.cause.message ?? e.cause})` : ''}`, text, ms: Date.now() - started };
  }
}

// ------------------------------------------------------------------ the oracle
// Findings of one answer: [{ rule, detail, faults? }] (the signature is built from these).
function check(c, r, pairAnswer) {
  const out = [];
  const add = (rule, detail, extra = {}) => out.push({ rule, detail, ...extra });
  if (r.error) {
    add('transport', r.error);
    return out;
  }
  if (r.status >= 500) add('5xx', `status ${r.status}`);
  let body = r.raw;
  if (/json/i.test(r.contentType)) {
    if (r.json === undefined) add('contract', `the body is not JSON although Content-Type is ${r.contentType}`);
    else body = r.json;
  }
  const violations = contract.checkResponse({ method: c.op.method, path: c.op.path, status: r.status, contentType: r.contentType, headers: r.headers, body });
  if (violations.length) add('contract', violations.slice(0, 6).join('; '), { at: generic(violations[0].replace(/[0-9.e+-]{3,}/g, 'N')).slice(0, 160) });
  const problem = r.status >= 400 && isObject(r.json) ? r.json : undefined;
  const errors = Array.isArray(problem?.errors) ? problem.errors.filter(isObject) : [];
  const sent = plain(c.body);
  // every pointer names a member of the request, or an absent member of an object the request
  // has (a missing required member; or, as ProblemFieldError documents, a member whose default or
  // implied value is at fault)
  for (const e of errors) {
    if (typeof e.pointer !== 'string' || e.pointer === '') continue;
    if (resolvePointer(sent, e.pointer).found) continue;
    const parentFound = resolvePointer(sent, parentOf(e.pointer).parent).found;
    if (parentFound) continue;
    add('pointer_to_absent_member', `errors[] names ${e.pointer} (${e.code}), which the request does not have`, { at: `${generic(e.pointer)} ${e.code}` });
  }
  const fieldErrors = errors.filter(e => FIELD_CODES.has(e.code));
  const named = new Set(errors.map(e => e.pointer));
  const expectValid = c.category === 'valid' || c.category === 'defaults' || (c.category === 'boundary' && !c.faults);
  if (expectValid) {
    if (c.schemaInvalid) add('defaults_not_schema_valid', `the body with every default is not schema-valid: ${contract.checkRequest(c.op.method, c.op.path, sent).slice(0, 3).join('; ')}`);
    if (r.status === 400) add('valid_answered_400', `a schema-valid body answered 400 (${problem?.type})`);
    if (r.status === 422 && problem?.type === INVALID) {
      if (fieldErrors.length) {
        add('valid_with_field_error', `a schema-valid body answered 422 invalid-input with field errors ${fieldErrors.map(e => `${e.pointer} ${e.code}`).join(', ')}`,
          { at: fieldErrors.map(e => `${generic(e.pointer)} ${e.code}`).sort().join(' + ') });
      } else {
        // defaults: judged against the same body without them, below
        if (c.category !== 'defaults') {
          for (const e of errors) {
            add('valid_refused_by_rule_not_in_schema', `a schema-valid body answered 422 invalid-input: ${errors.map(x => `${x.pointer} ${x.code}`).join(', ')}`,
              { at: `${generic(e.pointer)} ${e.code}` });
          }
        }
      }
    }
    if (r.status !== 200 && r.status !== 422 && r.status !== 400 && r.status < 500) add('valid_unexpected_status', `status ${r.status}`);
  }
  if (c.category === 'defaults' && pairAnswer && !pairAnswer.error && !out.length) {
    const same = pairAnswer.status === r.status && (r.status === 200 ? pairAnswer.raw === r.raw
      : JSON.stringify(problemKey(pairAnswer.json)) === JSON.stringify(problemKey(r.json)));
    if (!same) {
      const before = new Set(problemKey(pairAnswer.json)?.errors ?? []);
      const now = (problemKey(r.json)?.errors ?? []).filter(e => !before.has(e)).map(e => e.replace(/^(\S*)/, m => generic(m)));
      add('defaults_change_answer', `without the defaults: ${pairAnswer.status} ${pairAnswer.raw.slice(0, 300)}; with them: ${r.status} ${r.raw.slice(0, 300)}`,
        { at: now.length ? `adds ${now.join(' + ')}` : `${pairAnswer.status} -> ${r.status}` });
    }
  }
  if (c.faults) {
    if (r.status !== 422 && r.status !== 400) add('fault_not_refused', `a body with ${faultText(c.faults)} answered ${r.status}`, { faults: c.faults });
    else {
      if (r.status === 422 && problem?.type !== INVALID && c.faults.some(f => f.fieldLevel)) {
        add('fault_answered_impossible', `a body with ${faultText(c.faults)} answered ${problem?.type}, not invalid-input`, { faults: c.faults });
      }
      // a field error where nothing is broken (beside a broken discriminator its siblings may be unknown)
      for (const e of fieldErrors) {
        if (typeof e.pointer !== 'string') continue;
        const explained = c.faults.some(f => f.expect.includes(e.pointer) || related(e.pointer, f.pointer) ||
          (f.discriminator && parentOf(e.pointer).parent === parentOf(f.pointer).parent));
        if (!explained) add('spurious_field_error', `errors[] has ${e.pointer} ${e.code}, which is not broken (broken: ${faultText(c.faults)})`, { at: `${generic(e.pointer)} ${e.code}` });
      }
      const missing = c.faults.filter(f => (f.all ? !f.expect.every(p => named.has(p)) : !f.expect.some(p => named.has(p))));
      const allField = c.faults.every(f => f.fieldLevel);
      const unnamed = allField || c.faults.length === 1 ? missing : missing.length === c.faults.length ? missing : [];
      if (unnamed.length) {
        add('fault_not_named', `errors[] names ${[...named].map(p => JSON.stringify(p)).join(', ') || 'nothing'}, not ${unnamed.map(f => `${f.kind} at ${f.pointer}`).join(' / ')}`,
          { faults: unnamed });
      }
    }
  }
  return out;
}
const problemKey = j => (isObject(j) ? { type: j.type, errors: (j.errors ?? []).map(e => `${e.pointer} ${e.code}`).sort() } : j);
const faultText = faults => faults.map(f => `${f.kind} at ${f.pointer}`).join(' and ');
function signature(c, r, x) {
  // Two faults: the kinds only (a fault that hides another hides it wherever the two are).
  // Two faults, one named: the named one hides the other wherever the two are; the signature is its kind.
  const hider = c.faults?.length === 2 && x.faults?.length === 1 ? c.faults.find(g => !x.faults.some(f => f.pointer === g.pointer && f.kind === g.kind)) : undefined;
  // (1e400 hides every other error: one signature for all of them)
  const faults = hider?.kind === 'too_large_for_double' ? `any fault hidden by ${hider.kind}`
    : hider ? `${x.faults[0].kind}@${generic(x.faults[0].pointer)} hidden by ${hider.kind}@${generic(hider.pointer)}`
      : (x.faults ?? c.faults ?? []).map(f => `${f.kind}@${generic(f.pointer)}`).sort().join('+');
  const status = r.error ? 'transport' : r.status;
  const type = r.json?.type ? r.json.type.replace('urn:cutcalc:problem:', '') : '';
  const parts = [c.op.path, x.rule, x.at ?? faults, status];
  if (['fault_not_named', 'fault_not_refused', 'fault_answered_impossible', '5xx', 'contract', 'transport'].includes(x.rule)) parts.push(type);
  if (x.rule === 'fault_not_named') {
    const codes = (r.json?.errors ?? []).map(e => e?.code);
    parts.push(r.json?.type === IMPOSSIBLE ? 'named impossible-input' : codes.every(k => FIELD_CODES.has(k)) ? 'named field errors' : 'named rule errors');
  }
  return parts.join(' | ');
}
const isKnown = sig => KNOWN_FINDINGS.find(k => (k.path === '*' || sig.startsWith(k.path + ' | ')) && new RegExp(`^(${k.rule})$`).test(sig.split(' | ')[1]) &&
  (k.match ? new RegExp(k.match).test(sig) : true));
const countsAsFinding = rule => rule !== 'valid_refused_by_rule_not_in_schema';

// ------------------------------------------------------------------ minimising
// Removes optional members (not the broken ones, nor their parents) one at a time while the same
// finding stays.
async function minimise(fd, deadline) {
  let c = fd.case;
  let r = fd.answer;
  let spent = 0;
  // the broken members and every member a broken rule involves stay
  const protectedPointers = (c.faults ?? []).flatMap(f => [f.pointer, ...f.expect.filter(p => p !== '')]);
  for (let progress = true; progress && spent < MINIMISE_REQUESTS_PER_FINDING && Date.now() < deadline;) {
    progress = false;
    const candidates = [];
    const walk = (v, p) => {
      if (isObject(v)) for (const k of Object.keys(v)) { candidates.push(join(p, k)); walk(v[k], join(p, k)); }
    };
    walk(c.body, '');
    for (const p of candidates) {
      if (spent >= MINIMISE_REQUESTS_PER_FINDING || Date.now() >= deadline) break;
      if (protectedPointers.some(q => related(p, q) && !p.startsWith(q + '/'))) continue;
      const body = clone(c.body);
      removeAt(body, p);
      if (c.faults && schemaValid(c.op, body)) continue;
      let base;
      if (c.base) {
        base = clone(c.base);
        removeAt(base, p);
        if (!schemaValid(c.op, base)) continue;
      } else if (c.category !== 'defaults' && !c.faults && !schemaValid(c.op, body)) continue;
      let pair;
      if (c.pair) {
        pair = clone(c.pair);
        removeAt(pair, p);
        if (!schemaValid(c.op, pair)) continue;
      }
      const trial = { ...c, body, base, pair };
      spent++;
      const tr = await send(c.op, body, c.headers);
      const pr = pair ? (spent++, await send(c.op, pair)) : undefined;
      const same = check(trial, tr, pr).some(x => signature(trial, tr, x) === fd.signature);
      if (same) {
        c = trial;
        r = tr;
        progress = true;
        break;
      }
    }
  }
  // then rounder numbers (two significant digits) where the finding stays
  const leaves = [];
  const walkNumbers = (v, p) => {
    if (isObject(v) || Array.isArray(v)) for (const [k, x] of Object.entries(v)) walkNumbers(x, join(p, k));
    else if (typeof v === 'number' && Number.isFinite(v) && !protectedPointers.some(q => related(p, q))) leaves.push(p);
  };
  walkNumbers(c.body, '');
  for (const p of leaves) {
    if (spent >= MINIMISE_REQUESTS_PER_FINDING || Date.now() >= deadline) break;
    const x = resolvePointer(c.body, p).value;
    const rounder = Number(x.toPrecision(2));
    if (rounder === x) continue;
    const body = clone(c.body);
    setAt(body, p, rounder);
    if (c.faults && schemaValid(c.op, body)) continue;
    let base;
    if (c.base) {
      base = clone(c.base);
      if (resolvePointer(base, p).found) setAt(base, p, rounder);
      if (!schemaValid(c.op, base)) continue;
    } else if (!c.faults && !schemaValid(c.op, body)) continue;
    let pair;
    if (c.pair) {
      pair = clone(c.pair);
      if (resolvePointer(pair, p).found) setAt(pair, p, rounder);
      if (!schemaValid(c.op, pair)) continue;
    }
    const trial = { ...c, body, base, pair };
    spent++;
    const tr = await send(c.op, body, c.headers);
    const pr = pair ? (spent++, await send(c.op, pair)) : undefined;
    if (check(trial, tr, pr).some(x2 => signature(trial, tr, x2) === fd.signature)) {
      c = trial;
      r = tr;
    }
  }
  fd.case = c;
  fd.answer = r;
  fd.minimiseRequests = spent;
  return spent;
}

// Pointers of the members `after` has and `before` has not.
function addedMembers(before, after, p = '') {
  const out = [];
  if (isObject(after)) {
    for (const [k, v] of Object.entries(after)) {
      if (!isObject(before) || !(k in before)) out.push(join(p, k));
      else out.push(...addedMembers(before[k], v, join(p, k)));
    }
  }
  return out;
}

// ------------------------------------------------------------------ run
async function main() {
  const started = Date.now();
  const deadline = started + SECONDS * 1000;
  try {
    const health = await fetch(`${BASE_URL}/healthz`, { signal: AbortSignal.timeout(5000) });
    if (health.status !== 200) setupError(`${BASE_URL}/healthz answers ${health.status}`);
  } catch (e) {
    setupError(`cutcalc is not reachable at ${BASE_URL}: ${e.message}`);
  }
  const ops = operations();
  if (!ops.length) setupError(`${OPENAPI_FILE} has no operation with an application/json request body`);
  const cases = buildCases(ops);
  const stats = new Map(); // op -> category -> { sent, 200, impossible, invalid, 400, other, findings }
  const bump = (c, key) => {
    const o = stats.get(c.op.path) ?? new Map();
    stats.set(c.op.path, o);
    const s = o.get(c.category) ?? { sent: 0, s200: 0, impossible: 0, invalid: 0, s400: 0, other: 0, findings: 0, notes: 0 };
    o.set(c.category, s);
    s[key]++;
  };
  const findings = new Map();
  const notes = new Map();
  let sent = 0, skipped = 0;
  let next = 0;
  const worker = async () => {
    while (next < cases.length) {
      const c = cases[next++];
      if (Date.now() > deadline) { skipped++; continue; }
      const r = await send(c.op, c.body, c.headers);
      sent++;
      let pr;
      if (c.pair) { pr = await send(c.op, c.pair); sent++; }
      bump(c, 'sent');
      if (r.error) bump(c, 'other');
      else if (r.status === 200) bump(c, 's200');
      else if (r.status === 422) bump(c, r.json?.type === IMPOSSIBLE ? 'impossible' : 'invalid');
      else if (r.status === 400) bump(c, 's400');
      else bump(c, 'other');
      if (VERBOSE) console.log(`  ${c.category.padEnd(8)} ${c.op.path} ${r.error ?? r.status} ${r.ms} ms ${toJson(c.body).slice(0, 160)}`);
      for (const x of check(c, r, pr)) {
        const sig = signature(c, r, x);
        const into = countsAsFinding(x.rule) ? findings : notes;
        bump(c, countsAsFinding(x.rule) ? 'findings' : 'notes');
        const fd = into.get(sig);
        if (!fd) into.set(sig, { signature: sig, rule: x.rule, detail: x.detail, case: c, answer: r, pairAnswer: pr, count: 1 });
        else {
          fd.count++;
          if (toJson(c.body).length < toJson(fd.case.body).length) Object.assign(fd, { detail: x.detail, case: c, answer: r, pairAnswer: pr });
        }
      }
    }
  };
  await Promise.all(Array.from({ length: CONCURRENCY }, worker));
  const tested = Date.now();
  // minimise, in signature order
  let minimiseRequests = 0;
  const minimiseDeadline = started + SECONDS * 1150;
  const sortedFindings = [...findings.values()].sort((a, b) => a.signature.localeCompare(b.signature));
  for (const fd of sortedFindings) {
    if (Date.now() > minimiseDeadline) break;
    minimiseRequests += await minimise(fd, minimiseDeadline);
    if (fd.case.pair) fd.pairAnswer = await send(fd.case.op, fd.case.pair);
  }
  // report
  const line = (s = '') => console.log(s);
  line(`property: seed ${SEED}, ${cases.length} cases planned for ${ops.length} operations, ${sent} requests sent` +
    (skipped ? ` (${skipped} cases not run: the ${SECONDS} s budget ran out)` : '') +
    `, ${minimiseRequests} more to minimise; ${((tested - started) / 1000).toFixed(1)} s testing, ${((Date.now() - started) / 1000).toFixed(1)} s in all`);
  line('');
  line('operation                   category   sent    200  422-imp  422-inv   400  other  findings  notes   (findings: answers with one, known ones included)');
  for (const [p, o] of stats) {
    for (const cat of ['valid', 'fault1', 'fault2', 'faultN', 'boundary', 'defaults']) {
      const s = o.get(cat);
      if (!s) continue;
      line(`${p.padEnd(27)} ${cat.padEnd(9)} ${[s.sent, s.s200, s.impossible, s.invalid, s.s400, s.other, s.findings, s.notes]
        .map((n, i) => String(n).padStart([5, 6, 8, 8, 5, 6, 9, 6][i])).join(' ')}`);
    }
  }
  const describe = (fd, label) => {
    const c = fd.case;
    const r = fd.answer;
    line(`${label} ${fd.signature}  (${fd.count}x)`);
    line(`    ${fd.rule}: ${fd.detail}`);
    if (c.pair) line(`    case: defaults sent: ${addedMembers(c.pair, c.body).join(', ')}`);
    else if (c.note) line(`    case: ${c.note}`);
    if (c.faults) line(`    broken: ${faultText(c.faults)}`);
    line(`    request: ${c.op.method} ${c.op.path}  ${toJson(c.body)}`);
    line(`    answer: ${r.error ?? `${r.status} ${r.contentType} ${r.raw.length > 1200 ? r.raw.slice(0, 1200) + '...' : r.raw}`}`);
    if (c.pair) line(`    without the defaults: ${toJson(c.pair)}\n      -> ${fd.pairAnswer?.error ?? `${fd.pairAnswer?.status} ${fd.pairAnswer?.raw.slice(0, 600)}`}`);
  };
  const known = [], unknown = [];
  for (const fd of sortedFindings) (isKnown(fd.signature) ? known : unknown).push(fd);
  line('');
  for (const fd of unknown) describe(fd, 'FINDING');
  for (const fd of known) describe(fd, `KNOWN (${isKnown(fd.signature).about})`);
  for (const fd of [...notes.values()].sort((a, b) => a.signature.localeCompare(b.signature))) describe(fd, 'NOTE (schema-valid, refused by a rule the schema does not state)');
  const stale = KNOWN_FINDINGS.filter(k => !sortedFindings.some(fd => isKnown(fd.signature) === k));
  for (const k of stale) line(`STALE known finding (not seen; remove it from property-known.mjs): ${k.about}`);
  line('');
  line(`property: ${unknown.length} findings, ${known.length} known findings (property-known.mjs), ${notes.size} notes`);
  if (opt['report-json']) {
    writeFileSync(opt['report-json'], JSON.stringify({
      seed: SEED, sent, skipped, minimiseRequests, stats: Object.fromEntries([...stats].map(([p, o]) => [p, Object.fromEntries(o)])),
      findings: sortedFindings.map(fd => ({ signature: fd.signature, known: isKnown(fd.signature)?.about, rule: fd.rule, detail: fd.detail, count: fd.count,
        method: fd.case.op.method, path: fd.case.op.path, body: toJson(fd.case.body), faults: fd.case.faults, status: fd.answer.status ?? fd.answer.error, answer: fd.answer.raw })),
      notes: [...notes.values()].map(fd => ({ signature: fd.signature, detail: fd.detail, body: toJson(fd.case.body), answer: fd.answer.raw })),
    }, null, 2));
  }
  process.exit(unknown.length ? 1 : 0);
}

process.on('beforeExit', () => setupError('the run ended before its summary (a promise never settled)'));
main().catch(e => {
  console.error(`property: ${e.stack || e}`);
  process.exit(2);
});
