#!/usr/bin/env node
// Contract replay: sends every reference case (shared/reference/*.json), the operations
// endpoints and a list of bad-input requests through Prism's validating proxy in front of a
// running cutcalc, and fails when any response, success or problem, does not match openapi.yaml.
//
// Two Prism proxies in front of the same cutcalc (both `prism proxy openapi.yaml <cutcalc> --errors`):
//   PRISM_STRICT_URL   request validation on (Prism's default);
//   PRISM_RELAXED_URL  `--validate-request=false`.
// How Prism 5 (--errors) signals what it found:
//   - response violation of severity error: Prism answers 500 application/problem+json with
//     type https://stoplight.io/prism/errors#VIOLATIONS, `validation[]` listing them, and an
//     `sl-violations` header (JSON array of {location: ["response", ...], severity, code, message});
//   - response violation of severity warning (e.g. a 4xx/5xx status the operation does not list):
//     the upstream answer passes with an `sl-violations` header entry whose location starts with
//     "response";
//   - request violation: Prism does not forward; it answers 422 with type
//     https://stoplight.io/prism/errors#UNPROCESSABLE_ENTITY and `validation[]` (no header);
//   - a body Prism cannot parse (invalid JSON under a JSON content type) is answered by Prism's HTTP
//     layer itself (400 {"error":{"code":"invalid_json"}}), not forwarded; so is a method the path
//     does not list (405 NO_METHOD_MATCHED_ERROR).
// Every case goes to the strict proxy first. A request violation there is expected for a bad input
// (it is deliberately invalid) and for a reference case that expects 422; the case is then replayed
// through the relaxed proxy, so cutcalc's own answer is still validated by Prism. A reference case
// that expects 200 must not be rejected (that would be a contract stricter than the service).
// When Prism cannot forward a request at all, or rewrites its bytes (Prism parses and re-serialises
// JSON bodies: duplicate keys collapse, 1e400 becomes null), the request goes directly to cutcalc
// (CUTCALC_URL) and its response is validated here with Prism's own validator
// (@stoplight/prism-http validateOutput on the operations Prism builds from the same document).
// One case (20000 nesting levels) goes directly only: it crashes Prism 5.14 (RangeError in its logger).
// Prism 5 validates OpenAPI 3.1 schemas as draft-07 and ignores newer keywords (dependentRequired),
// so every body cutcalc sent is also validated as JSON Schema 2020-12 with Ajv.
// Any response violation, error or warning, is a failure; so is a status other than the one the
// reference case or the contract's description states, and a 200 reference request that Prism
// rejects. Exit status: 0 clean, 1 failures, 2 setup error.
//
// Environment: PRISM_STRICT_URL, PRISM_RELAXED_URL, CUTCALC_URL (required); OPENAPI_FILE
// (default <repo>/openapi.yaml; must be the document the proxies serve); CUTCALC_REFERENCE_DIR
// (default <repo>/../shared/reference, relative to the repository root); REPLAY_CONCURRENCY
// (requests in flight, default 4); REPLAY_VERBOSE=1 prints every exchange.
import { readFileSync, readdirSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const require = createRequire(import.meta.url);
const { getHttpOperationsFromSpec } = require('@stoplight/prism-http');
const { validateOutput } = require('@stoplight/prism-http/dist/validator');
const Ajv2020 = require('ajv/dist/2020').default;
const addFormats = require('ajv-formats').default;

const here = path.dirname(fileURLToPath(import.meta.url));
const repo = path.resolve(here, '..', '..');
const env = (name, fallback) => {
  const value = process.env[name];
  if (value !== undefined && value !== '') return value;
  if (fallback !== undefined) return fallback;
  console.error(`replay: ${name} is not set`);
  process.exit(2);
};
const STRICT = env('PRISM_STRICT_URL').replace(/\/$/, '');
const RELAXED = env('PRISM_RELAXED_URL').replace(/\/$/, '');
const DIRECT = env('CUTCALC_URL').replace(/\/$/, '');
const OPENAPI_FILE = path.resolve(env('OPENAPI_FILE', path.join(repo, 'openapi.yaml')));
const REFERENCE_DIR = path.resolve(repo, env('CUTCALC_REFERENCE_DIR', path.join('..', 'shared', 'reference')));
const VERBOSE = process.env.REPLAY_VERBOSE === '1';
const TIMEOUT_MS = 20000;
const CONCURRENCY = Math.max(1, Number(process.env.REPLAY_CONCURRENCY) || 4);
const PRISM_ERROR = 'https://stoplight.io/prism/errors#';

// ------------------------------------------------------------------ cases
// The calculation endpoints and which of them also answer a plain-text program, from the reference
// files' endpoints and openapi.yaml's text/plain 200 answers: a new endpoint needs no entry here.
const TEXT_FORM_PATHS = new Set(
  [...readFileSync(OPENAPI_FILE, 'utf8').matchAll(/^  (\/v1\/[^:]+):\n(?:(?!^  \/).*\n)*?            text\/plain/gm)]
    .map(m => m[1]),
);

function referenceCases() {
  let files;
  try {
    files = readdirSync(REFERENCE_DIR).filter(f => f.endsWith('.json')).sort();
  } catch (e) {
    console.error(`replay: cannot read reference directory ${REFERENCE_DIR}: ${e.message}`);
    process.exit(2);
  }
  const cases = [];
  const firstValid = {};
  for (const file of files) {
    const doc = JSON.parse(readFileSync(path.join(REFERENCE_DIR, file), 'utf8'));
    for (const c of doc.cases) {
      const id = `${file}:${c.id}`;
      const body = JSON.stringify(c.request);
      cases.push({ id, kind: 'reference', method: 'POST', path: doc.endpoint, body, expect: [c.expect.status] });
      if (c.expect.status === 200) {
        firstValid[doc.endpoint] ??= c.request;
        if (TEXT_FORM_PATHS.has(doc.endpoint)) {
          cases.push({
            id: `${id} (Accept: text/plain)`, kind: 'reference', method: 'POST', path: doc.endpoint, body,
            accept: 'text/plain', expect: [200],
          });
        }
      }
    }
  }
  return { files, cases, firstValid };
}


// Top-level fields of a valid request that the contract requires to be positive sizes: numbers
// ending in _mm whose request schema has minimum > 0 or exclusiveMinimum >= 0.
function sizeFields(p, request) {
  const op = findOperation('POST', p);
  const props = op?.request?.body?.contents?.[0]?.schema?.properties ?? {};
  return Object.entries(request)
    .filter(([k, v]) => typeof v === 'number' && /_mm$/.test(k))
    .filter(([k]) => {
      const s = props[k] ?? {};
      return (typeof s.minimum === 'number' && s.minimum > 0) || (typeof s.exclusiveMinimum === 'number' && s.exclusiveMinimum >= 0);
    })
    .map(([k]) => k);
}

// The request as JSON text with the value of its top-level key `key` replaced by the raw text `raw`.
function withRawValue(request, key, raw) {
  const marker = '"__RAW_VALUE_MARKER__"';
  return JSON.stringify({ ...request, [key]: '__RAW_VALUE_MARKER__' }).replace(marker, raw);
}

function badInputCases(firstValid) {
  const cases = [];
  for (const p of Object.keys(firstValid)) {
    const base = firstValid[p];
    if (!base) {
      console.error(`replay: no reference case with status 200 for ${p} to derive bad inputs from`);
      process.exit(2);
    }
    const valid = JSON.stringify(base);
    const sizes = sizeFields(p, base);
    const firstKey = Object.keys(base)[0];
    const size = sizes[0] ?? firstKey;
    const add = (name, body, expect, extra = {}) =>
      cases.push({ id: `bad:${p}:${name}`, kind: 'bad', method: 'POST', path: p, body, expect, ...extra });
    add('empty body', '', [400]);
    add('not JSON', valid.slice(0, Math.floor(valid.length / 2)), [400], { exact: true });
    add('wrong content type', valid, [415], { contentType: 'text/plain' });
    add('no content type', valid, [415], { contentType: null });
    add('1 MiB body', JSON.stringify({ ...base, padding: 'x'.repeat(1024 * 1024) }), [413]);
    add('deeply nested JSON (64 levels)', JSON.stringify({ ...base, nested: JSON.parse('['.repeat(64) + ']'.repeat(64)) }), [400]);
    // Prism 5.14 dies on this one (RangeError in its request logger), so it goes to cutcalc only.
    add('deeply nested JSON (20000 levels)', `{"nested":${'['.repeat(20000)}${']'.repeat(20000)}}`, [400],
      { directOnly: 'Prism crashes on 20000 nesting levels' });
    add(`string for a number (${size})`, JSON.stringify({ ...base, [size]: String(base[size]) }), [422]);
    add(`NaN literal (${size})`, withRawValue(base, size, 'NaN'), [400], { exact: true });
    add(`1e400 (${size})`, withRawValue(base, size, '1e400'), [422], { exact: true });
    for (const field of sizes.slice(0, 2)) {
      add(`negative size (${field})`, JSON.stringify({ ...base, [field]: -base[field] }), [422]);
      add(`zero size (${field})`, JSON.stringify({ ...base, [field]: 0 }), [422]);
    }
    add('unknown field', JSON.stringify({ ...base, unknown_field_mm: 1 }), [422]);
    add('duplicate key', valid.replace(/^\{/, `{${JSON.stringify(firstKey)}:${JSON.stringify(base[firstKey])},`), [400], { exact: true });
    add('array instead of object', JSON.stringify([base]), [422]);
    add('null body', 'null', [422], { exact: true });
    add('empty object', '{}', [422]);
  }
  // Methods a path does not support (Prism answers these itself; validated directly).
  cases.push({ id: 'bad:GET /v1/entry-length', kind: 'bad', method: 'GET', path: '/v1/entry-length', expect: [405] });
  cases.push({ id: 'bad:POST /healthz', kind: 'bad', method: 'POST', path: '/healthz', body: '{}', expect: [405] });
  return cases;
}

function operationsCases() {
  const cases = ['/healthz', '/readyz', '/version', '/metrics', '/openapi.yaml'].map(p => ({
    id: `ops:GET ${p}`, kind: 'operations', method: 'GET', path: p, expect: [200],
  }));
  // Every documented HEAD and OPTIONS operation (on a path without parameters).
  for (const o of operations.filter(o => (o.method === 'head' || o.method === 'options') && !o.path.includes('{'))) {
    const method = o.method.toUpperCase();
    cases.push({ id: `ops:${method} ${o.path}`, kind: 'operations', method, path: o.path, expect: [method === 'HEAD' ? 200 : 204] });
  }
  return cases;
}

// ------------------------------------------------------------------ HTTP
let requestCounter = 0;

async function send(base, c) {
  const headers = { 'x-request-id': `contract-${++requestCounter}` };
  if (c.body !== undefined) {
    if (c.contentType !== null) headers['content-type'] = c.contentType ?? 'application/json';
  }
  headers.accept = c.accept ?? (c.path === '/metrics' ? 'text/plain' : c.path === '/openapi.yaml' ? 'application/yaml' : 'application/json');
  let body;
  if (c.body !== undefined) body = Buffer.from(c.body, 'utf8'); // bytes: fetch adds no Content-Type
  const res = await fetch(base + c.path, {
    method: c.method, headers, body, signal: AbortSignal.timeout(TIMEOUT_MS), redirect: 'manual',
  });
  const text = await res.text();
  const hdrs = Object.fromEntries(res.headers);
  const contentType = hdrs['content-type'] ?? '';
  let json;
  if (/^application\/([a-z0-9.+-]*\+)?json\b/i.test(contentType)) {
    try { json = JSON.parse(text); } catch { json = undefined; }
  }
  return { status: res.status, headers: hdrs, text, json, contentType };
}

function parseViolationHeader(value) {
  if (!value) return [];
  try {
    return JSON.parse(value);
  } catch {
    return [{ location: ['response'], severity: 'Error', message: `unparsable sl-violations header: ${value.slice(0, 300)}` }];
  }
}

// Classifies an answer from a Prism proxy.
function classify(r) {
  const type = r.json && typeof r.json.type === 'string' ? r.json.type : '';
  const headerViolations = parseViolationHeader(r.headers['sl-violations']);
  const responseViolations = headerViolations.filter(v => (v.location ?? [])[0] !== 'request');
  const requestNotes = headerViolations.filter(v => (v.location ?? [])[0] === 'request');
  if (type === `${PRISM_ERROR}VIOLATIONS`) {
    const listed = (r.json.validation ?? []).filter(v => (v.location ?? [])[0] !== 'request');
    const merged = responseViolations.length ? responseViolations : listed;
    return { origin: 'prism-violation', responseViolations: merged.length ? merged : [{ message: r.json.detail }], requestNotes };
  }
  if (type === `${PRISM_ERROR}UNPROCESSABLE_ENTITY` || type === `${PRISM_ERROR}INVALID_CONTENT_TYPE`) {
    return { origin: 'prism-request-rejected', requestViolations: r.json.validation ?? [], responseViolations: [] };
  }
  if (r.headers['x-request-id'] !== undefined) {
    return { origin: 'upstream', responseViolations, requestNotes };
  }
  return { origin: 'prism-other', responseViolations: [], requestNotes };
}

// ------------------------------------------------------------------ validation outside the proxy
let operations;

function findOperation(method, p) {
  const m = method.toLowerCase();
  return operations.find(o => o.path === p && o.method === m) ?? operations.find(o => o.path === p);
}

function bodyForValidation(c, r) {
  if (/^application\/([a-z0-9.+-]*\+)?json\b/i.test(r.contentType) && r.status !== 204 && c.method !== 'HEAD') {
    return r.json === undefined ? { error: `response body is not JSON: ${r.text.slice(0, 200)}` } : { body: r.json };
  }
  return { body: r.text };
}

const severityName = s => (s === 0 ? 'Error' : s === 1 ? 'Warning' : s === 2 ? 'Information' : s === 3 ? 'Hint' : String(s));

// Prism's own response validator (the code the proxy runs), for answers taken directly from cutcalc.
function validateWithPrism(c, r) {
  const op = findOperation(c.method, c.path);
  if (!op) return [{ message: `no operation in the document for ${c.path}` }];
  const b = bodyForValidation(c, r);
  if (b.error) return [{ location: ['response', 'body'], message: b.error }];
  const result = validateOutput({ resource: op, element: { statusCode: r.status, headers: r.headers, body: b.body } });
  if (result._tag === 'Right') return [];
  return result.left.map(d => ({
    location: ['response', ...(d.path ?? [])], severity: severityName(d.severity), code: d.code, message: d.message,
  }));
}

// Prism 5 validates OpenAPI 3.1 schemas as JSON Schema draft-07 and ignores 2019-09/2020-12
// keywords (the contract uses dependentRequired). Every body cutcalc sent is therefore also
// validated against its response schema as JSON Schema 2020-12, the dialect of OpenAPI 3.1.
const ajv = new Ajv2020({ strict: false, allErrors: true, validateFormats: true });
addFormats(ajv);
const compiled = new WeakMap();

function schemaFor(c, r) {
  const op = findOperation(c.method, c.path);
  const response = op?.responses?.find(x => x.code === String(r.status));
  if (!response?.contents?.length) return undefined;
  const type = r.contentType.split(';')[0].trim().toLowerCase();
  const content = response.contents.find(x => x.mediaType.split(';')[0].trim().toLowerCase() === type);
  return content?.schema; // a missing status or media type is reported by Prism itself
}

function validate2020(c, r) {
  const schema = schemaFor(c, r);
  if (!schema) return [];
  const b = bodyForValidation(c, r);
  if (b.error) return [{ location: ['response', 'body'], message: b.error }];
  let validate = compiled.get(schema);
  if (!validate) {
    const { $schema, ...rest } = schema; // Prism labels it draft-07; it is 2020-12
    validate = ajv.compile(rest);
    compiled.set(schema, validate);
  }
  if (validate(b.body)) return [];
  return validate.errors.map(e => ({
    location: ['response', 'body', ...e.instancePath.split('/').filter(Boolean)], severity: 'Error',
    code: `2020-12 ${e.keyword}`, message: `${e.instancePath || '(body)'} ${e.message}${e.params ? ' ' + JSON.stringify(e.params) : ''}`,
  }));
}

// ------------------------------------------------------------------ run
const stats = { cases: 0, throughPrism: 0, directOnly: 0, strict: 0, relaxed: 0, direct: 0, rejectedByPrism: 0, violations: 0, statusMismatch: 0, unexpectedRejections: 0 };
const failures = [];

function fail(c, via, status, what, details) {
  failures.push({ id: c.id, op: `${c.method} ${c.path}`, via, status, what, details });
}

function describe(v) {
  const where = (v.location ?? []).join('.');
  return `${v.severity ?? 'Error'} ${v.code ?? ''} at ${where || '(document)'}: ${v.message}`;
}

function checkUpstream(c, via, r, { checkStatus = true } = {}) {
  const v = validate2020(c, r);
  if (v.length) {
    stats.violations += v.length;
    fail(c, via, r.status, 'response body violates its schema (JSON Schema 2020-12)', v.map(describe));
  }
  if (checkStatus && !c.expect.includes(r.status)) {
    stats.statusMismatch++;
    fail(c, via, r.status, `status ${r.status}, expected ${c.expect.join(' or ')}`, [r.text.slice(0, 300)]);
  }
}

async function runDirect(c, reason) {
  const r = await send(DIRECT, c);
  stats.direct++;
  const v = validateWithPrism(c, r);
  if (VERBOSE) console.log(`  direct  ${c.id}: ${r.status} (${reason})${v.length ? ' VIOLATION' : ''}`);
  if (v.length) {
    stats.violations += v.length;
    fail(c, 'direct', r.status, "response violates the contract (Prism's validator)", v.map(describe));
  }
  checkUpstream(c, 'direct', r);
}

// Returns true when the case is settled (cutcalc's answer was validated by this proxy).
async function runThroughPrism(c, base, label) {
  const r = await send(base, c);
  stats[label]++;
  const k = classify(r);
  if (VERBOSE) console.log(`  ${label.padEnd(7)} ${c.id}: ${r.status} ${k.origin}${k.responseViolations.length ? ' VIOLATION' : ''}`);
  if (k.responseViolations.length) {
    stats.violations += k.responseViolations.length;
    fail(c, `prism-${label}`, k.origin === 'upstream' ? r.status : `${r.status} from Prism`, 'response violates the contract (Prism proxy)',
      k.responseViolations.map(describe));
    return { done: true };
  }
  if (k.origin === 'upstream') {
    // An `exact` body reached cutcalc rewritten by Prism: its status says nothing about the case.
    checkUpstream(c, `prism-${label}`, r, { checkStatus: !c.exact });
    return { done: true };
  }
  return { done: false, k, r };
}

async function runCase(c) {
  stats.cases++;
  if (c.directOnly) {
    stats.directOnly++;
    await runDirect(c, c.directOnly);
    return;
  }
  stats.throughPrism++;
  const strict = await runThroughPrism(c, STRICT, 'strict');
  let settled = strict.done;
  if (!settled && strict.k.origin === 'prism-request-rejected') {
    stats.rejectedByPrism++;
    if (c.kind !== 'bad' && c.expect.includes(200)) {
      stats.unexpectedRejections++;
      fail(c, 'prism-strict', strict.r.status, 'Prism rejects a request the reference case answers 200 (request schema too strict)',
        (strict.k.requestViolations ?? []).map(describe));
    }
    settled = (await runThroughPrism(c, RELAXED, 'relaxed')).done;
  }
  if (!settled) await runDirect(c, 'Prism answered itself');
  else if (c.exact) await runDirect(c, 'body bytes that Prism rewrites');
}

async function main() {
  const started = Date.now();
  operations = await getHttpOperationsFromSpec(OPENAPI_FILE);
  const { files, cases: refCases, firstValid } = referenceCases();
  if (refCases.length === 0) {
    console.error(`replay: no reference cases in ${REFERENCE_DIR}`);
    process.exit(2);
  }
  const bad = badInputCases(firstValid);
  const ops = operationsCases();
  const all = [...refCases, ...ops, ...bad];
  let next = 0;
  const worker = async () => {
    while (next < all.length) {
      const c = all[next++];
      try {
        await runCase(c);
      } catch (e) {
        fail(c, 'transport', '-', `request failed: ${e.message}`, []);
      }
    }
  };
  await Promise.all(Array.from({ length: CONCURRENCY }, worker));
  failures.sort((a, b) => all.findIndex(c => c.id === a.id) - all.findIndex(c => c.id === b.id));
  for (const f of failures) {
    console.log(`FAIL ${f.id} [${f.op}] via ${f.via}, status ${f.status}: ${f.what}`);
    for (const d of f.details) console.log(`     ${d}`);
  }
  const seconds = ((Date.now() - started) / 1000).toFixed(1);
  console.log(
    `contract replay: ${stats.cases} cases (${refCases.length} reference from ${files.length} files, ${ops.length} operations, ${bad.length} bad-input); ` +
      `${stats.strict + stats.relaxed} requests through Prism (${stats.strict} strict, ${stats.relaxed} relaxed after a request violation), ` +
      `${stats.direct} sent directly and checked with Prism's validator; ${seconds} s`,
  );
  console.log(
    `${stats.throughPrism} cases through Prism` + (stats.directOnly ? ` (+${stats.directOnly} direct only)` : '') + `, ${stats.violations} violations` +
      (failures.length ? `; ${failures.length} failures (${stats.statusMismatch} status mismatches, ${stats.unexpectedRejections} valid requests rejected)` : ''),
  );
  process.exit(failures.length ? 1 : 0);
}

main().catch(e => {
  console.error(`replay: ${e.stack || e}`);
  process.exit(2);
});
