#!/usr/bin/env node
// The reference replayer: sends every reference case (shared/reference/*.json), the operations
// endpoints and a list of bad-input requests to a cutcalc, checks each answer against the
// reference (status; numbers within the file's tolerance, strings exactly, lists element-wise,
// objects recursively; expect.max / expect.min bounds; warning codes as a multiset; the problem's
// errors[] naming expect.pointer, as application/problem+json; the program facts of
// expect.program: loops, layers, z_min, g95_flat_F, g94_F, last_C; the lathe facts first_lines,
// last_lines, spindle_line, feed_moves, z_feed_moves, dwell_blocks, min_x, x_feed_travel,
// z_feed_travel; the lathe flat facts dialect, feed_mode, c_steps, x_word_min/max, c_word_min/max,
// first_line, last_line) and every answer, success or
// problem, against openapi.yaml (contract.mjs: Ajv, JSON Schema 2020-12; status, media type,
// headers, body). A case listed in tests/reference-corrections.json (a request that contradicts the spec
// it cites) is replayed with its corrected request, said in the output. rs274 acceptance of the programs (expect.program.rs274) is tests/gcode's.
//
// Where cutcalc is:
//   --start BIN          starts BIN on a free loopback port (ctest: the build's own binary)
//   --base-url URL       a running cutcalc (ci-container.sh: the container)
//   --prism              through Prism (ci-contract.sh), from PRISM_STRICT_URL, PRISM_RELAXED_URL
//                        and CUTCALC_URL; see below
// Options: --reference-dir DIR (default <repo>/../shared/reference, or CUTCALC_REFERENCE_DIR): its
// *.json plus the next/ files the route table lists (tools/routes/route_table.mjs; --routes FILE,
// else the --start binary's, CUTCALC_ROUTES_FILE or CUTCALC_BIN's `cutcalc --routes`),
// --openapi FILE (default <repo>/openapi.yaml, or OPENAPI_FILE), --per-file N (the first N cases
// of each file, always with a non-200 case when the file has one; 0 = all), --concurrency N
// (default 4, or REPLAY_CONCURRENCY), --verbose (or REPLAY_VERBOSE=1: every exchange).
//
// Through Prism: two proxies in front of the same cutcalc (both `prism proxy openapi.yaml <cutcalc> --errors`):
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
// hence contract.mjs on every answer in this mode too.
// Any violation, error or warning, is a failure; so is a status other than the one the reference
// case or the contract's description states, and a 200 reference request that Prism rejects.
// Exit status: 0 clean, 1 failures, 2 setup error.
import { spawn } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';
import { loadRoutes, replayedReferenceFiles } from '../routes/route_table.mjs';
import { Contract, isJsonMediaType } from './contract.mjs';
import { correctedCases } from './reference-corrections.mjs';

const require = createRequire(import.meta.url);
const here = path.dirname(fileURLToPath(import.meta.url));
const repo = path.resolve(here, '..', '..');
const { values: opt } = parseArgs({
  options: {
    start: { type: 'string' }, 'base-url': { type: 'string' }, prism: { type: 'boolean' },
    'reference-dir': { type: 'string' }, openapi: { type: 'string' }, 'per-file': { type: 'string' },
    routes: { type: 'string' },
    concurrency: { type: 'string' }, verbose: { type: 'boolean' },
  },
});
const setupError = message => {
  console.error(`replay: ${message}`);
  process.exit(2);
};
const env = (name, fallback) => {
  const value = process.env[name];
  if (value !== undefined && value !== '') return value;
  if (fallback !== undefined) return fallback;
  return setupError(`${name} is not set`);
};
const MODE = opt.prism ? 'prism' : opt.start ? 'start' : opt['base-url'] ? 'direct' : setupError('give --start BIN, --base-url URL or --prism');
const OPENAPI_FILE = path.resolve(opt.openapi ?? env('OPENAPI_FILE', path.join(repo, 'openapi.yaml')));
const REFERENCE_DIR = path.resolve(repo, opt['reference-dir'] ?? env('CUTCALC_REFERENCE_DIR', path.join('..', 'shared', 'reference')));
const PER_FILE = Number(opt['per-file'] ?? 0);
const VERBOSE = opt.verbose || process.env.REPLAY_VERBOSE === '1';
const TIMEOUT_MS = 20000;
const CONCURRENCY = Math.max(1, Number(opt.concurrency ?? process.env.REPLAY_CONCURRENCY) || 4);
const PRISM_ERROR = 'https://stoplight.io/prism/errors#';
let STRICT, RELAXED, DIRECT;
const contract = new Contract(OPENAPI_FILE);

// ------------------------------------------------------------------ cases
// The calculation endpoints and which of them also answer a plain-text program, from the reference
// files' endpoints and openapi.yaml's text/plain 200 answers: a new endpoint needs no entry here.
const TEXT_FORM_PATHS = new Set(
  Object.keys(contract.document.paths).filter(t =>
    Object.keys(contract.findResponse('POST', t, 200).response?.content ?? {}).some(k => k.startsWith('text/plain'))),
);

// The first N cases of a file, always with a non-200 case when the file has one (--per-file).
function pick(cases) {
  if (PER_FILE <= 0 || cases.length <= PER_FILE) return cases;
  const chosen = cases.slice(0, PER_FILE);
  if (!chosen.some(c => c.expect.status !== 200)) {
    const bad = cases.find(c => c.expect.status !== 200);
    if (bad) chosen[chosen.length - 1] = bad;
  }
  return chosen;
}

// The file's tolerance rule (its "compare" text and the case's tolerance object): the allowed
// |got - want| for a number at `key` (the last object key on its path).
function toleranceRule(doc, tol = {}) {
  if ('abs_mm' in tol) return key => (key.endsWith('_time_min') || key === 'main_time_min' ? tol.abs_min : tol.abs_mm);
  if ('abs_min' in tol) return (key, want) => Math.max(tol.abs_min, (tol.rel ?? 0) * Math.abs(want));
  const abs = tol.abs ?? 0;
  const rel = tol.rel ?? 0;
  if ((doc.compare ?? '').includes('tolerance.abs + tolerance.rel')) return (key, want) => abs + rel * Math.abs(want);
  return (key, want) => Math.max(abs, rel * Math.abs(want));
}

function referenceCases() {
  let files;
  let routes;
  try {
    routes = loadRoutes({ routesFile: opt.routes, bin: opt.start });
    files = replayedReferenceFiles(REFERENCE_DIR, routes);
  } catch (e) {
    setupError(`cannot read reference directory ${REFERENCE_DIR} or the route table: ${e.message}`);
  }
  if (files.length === 0) setupError(`no reference files in ${REFERENCE_DIR}`);
  const cases = [];
  const firstValid = {};
  for (const file of files) {
    const doc = JSON.parse(readFileSync(path.join(REFERENCE_DIR, file), 'utf8'));
    doc.cases = correctedCases(file, doc.cases ?? [], why => setupError(`STALE reference correction: ${why} (tests/reference-corrections.json)`));
    for (const c of doc.cases) if (c.correction) console.log(`replay: ${file}:${c.id} replayed with a corrected request: ${c.correction}`);
    const chosen = pick(doc.cases);
    if (chosen.length === 0) setupError(`${file} has no cases`);
    for (const c of doc.cases) {
      if (c.expect.status === 200) firstValid[doc.endpoint] ??= c.request;
    }
    for (const c of chosen) {
      const id = `${file}:${c.id}`;
      const body = JSON.stringify(c.request);
      cases.push({
        id, kind: 'reference', method: 'POST', path: doc.endpoint, body, expect: [c.expect.status],
        reference: { expect: c.expect, request: c.request, tolerance: toleranceRule(doc, c.tolerance) },
      });
      if (c.expect.status === 200 && TEXT_FORM_PATHS.has(doc.endpoint)) {
        cases.push({
          id: `${id} (Accept: text/plain)`, kind: 'reference', method: 'POST', path: doc.endpoint, body,
          accept: 'text/plain', expect: [200],
        });
      }
    }
  }
  return { files, cases, firstValid, routes };
}

// ------------------------------------------------------------------ reference checks
function compareSubset(want, got, tolerance, where, key, out) {
  if (typeof want === 'number') {
    if (typeof got !== 'number') out.push(`${where}: expected a number ${want}, got ${JSON.stringify(got)}`);
    else {
      const allowed = tolerance(key, want);
      if (!(Math.abs(got - want) <= allowed)) out.push(`${where}: expected ${want} +- ${allowed}, got ${got} (off by ${Math.abs(got - want)})`);
    }
  } else if (Array.isArray(want)) {
    if (!Array.isArray(got) || got.length !== want.length) out.push(`${where}: expected a list of ${want.length}, got ${JSON.stringify(got)?.slice(0, 200)}`);
    else want.forEach((w, i) => compareSubset(w, got[i], tolerance, `${where}/${i}`, key, out));
  } else if (want !== null && typeof want === 'object') {
    if (got === null || typeof got !== 'object' || Array.isArray(got)) out.push(`${where}: expected an object, got ${JSON.stringify(got)?.slice(0, 200)}`);
    else {
      for (const [k, w] of Object.entries(want)) {
        if (!(k in got)) out.push(`${where}/${k}: missing`);
        else compareSubset(w, got[k], tolerance, `${where}/${k}`, k, out);
      }
    }
  } else if (want !== got) out.push(`${where}: expected ${JSON.stringify(want)}, got ${JSON.stringify(got)}`);
}

// The value of word `letter` in a block ("X-1.2345" -> "-1.2345"), or "" when absent.
function word(block, letter) {
  const m = block.match(new RegExp(`(?:^|\\s)${letter}(-?[0-9]+\\.[0-9]+)`));
  return m ? m[1] : '';
}

// Facts of a polygon program: G2/G3 blocks, Z after each loop, the deepest Z word, the G95 F
// words, the last G94 F word, the last C word of an arc.
function programFacts(program, blocksPerLoop) {
  const facts = { arcBlocks: 0, loopEndZ: [], deepestZ: '', g95F: new Set(), g94F: '', lastC: '' };
  let z = 0;
  let deepest = 0;
  for (const line of program.split('\n')) {
    if (line === '' || line[0] === '(' || line[0] === '%') continue;
    const zWord = word(line, 'Z');
    if (zWord !== '') {
      z = Number(zWord);
      if (z < deepest) [deepest, facts.deepestZ] = [z, zWord];
    }
    if (line.startsWith('G2 ') || line.startsWith('G3 ')) {
      facts.arcBlocks++;
      if (blocksPerLoop > 0 && facts.arcBlocks % blocksPerLoop === 0) facts.loopEndZ.push(z);
      const c = word(line, 'C');
      if (c !== '') facts.lastC = c;
    }
    if (line.includes('G95') && word(line, 'F') !== '') facts.g95F.add(word(line, 'F'));
    if (line.includes('G94') && word(line, 'F') !== '') facts.g94F = word(line, 'F');
  }
  return facts;
}

// Facts of a lathe program (grooving-cycle.md section 5.5): its lines, the one block that starts
// the spindle, the G1 blocks (with a Z word), the dwell blocks, the smallest printed X (a dwell's
// fanuc X is seconds, not a diameter) and the sums of |change| of the printed X and Z over the
// G1 blocks. Comments: `( )` and `;`.
function latheProgramFacts(program) {
  const lines = program.split('\n');
  if (lines.at(-1) === '') lines.pop();
  const facts = { lines, spindleLines: [], feedMoves: 0, zFeedMoves: 0, dwellBlocks: 0, minX: Infinity, xTravel: 0, zTravel: 0 };
  let x;
  let z;
  for (const line of lines) {
    const block = line.replace(/\([^)]*\)/g, '').replace(/;.*$/, '').trim();
    if (block === '' || block === '%') continue;
    const words = block.split(/\s+/);
    const has = (...w) => words.some(v => w.includes(v));
    if (has('M3', 'M03', 'M4', 'M04')) facts.spindleLines.push(line);
    if (has('G4', 'G04')) {
      facts.dwellBlocks++;
      continue;
    }
    const xWord = word(block, 'X');
    const zWord = word(block, 'Z');
    if (has('G1', 'G01')) {
      facts.feedMoves++;
      if (zWord !== '') facts.zFeedMoves++;
      if (xWord !== '' && x !== undefined) facts.xTravel += Math.abs(Number(xWord) - x);
      if (zWord !== '' && z !== undefined) facts.zTravel += Math.abs(Number(zWord) - z);
    }
    if (xWord !== '') {
      x = Number(xWord);
      facts.minX = Math.min(facts.minX, x);
    }
    if (zWord !== '') z = Number(zWord);
  }
  return facts;
}

function checkLatheProgram(checks, body, out) {
  const facts = latheProgramFacts(body.program);
  const step = 10 ** -body.decimals;
  const same = (a, b) => JSON.stringify(a) === JSON.stringify(b);
  if ('first_lines' in checks && !same(facts.lines.slice(0, checks.first_lines.length), checks.first_lines)) {
    out.push(`program: first lines ${JSON.stringify(facts.lines.slice(0, checks.first_lines.length))}, want ${JSON.stringify(checks.first_lines)}`);
  }
  if ('last_lines' in checks && !same(facts.lines.slice(-checks.last_lines.length), checks.last_lines)) {
    out.push(`program: last lines ${JSON.stringify(facts.lines.slice(-checks.last_lines.length))}, want ${JSON.stringify(checks.last_lines)}`);
  }
  if ('spindle_line' in checks && !same(facts.spindleLines, [checks.spindle_line])) {
    out.push(`program: spindle blocks ${JSON.stringify(facts.spindleLines)}, want [${JSON.stringify(checks.spindle_line)}]`);
  }
  for (const [key, got] of [['feed_moves', facts.feedMoves], ['z_feed_moves', facts.zFeedMoves], ['dwell_blocks', facts.dwellBlocks]]) {
    if (key in checks && got !== checks[key]) out.push(`program: ${key} ${got}, want ${checks[key]}`);
  }
  if ('min_x' in checks && !(Math.abs(facts.minX - checks.min_x) <= 0.5 * step * (1 + 1e-9))) {
    out.push(`program: min X ${facts.minX}, want ${checks.min_x} within ${0.5 * step}`);
  }
  for (const [key, got] of [['x_feed_travel', facts.xTravel], ['z_feed_travel', facts.zTravel]]) {
    const bound = facts.feedMoves * step;
    if (key in checks && !(Math.abs(got - checks[key]) <= bound)) out.push(`program: ${key} ${got}, want ${checks[key]} within ${bound}`);
  }
}

// Facts of a lathe flat program (lathe-flat.md, the file's `compare`): the G1 blocks with a C word,
// whether each is under G93 (the modal feed mode of the blocks before it, or its own word) with
// its own F word, and the smallest and largest of their printed X and C words, kept as text.
function flatProgramFacts(program) {
  const facts = { cSteps: 0, cStepsNotG93: 0, cStepsWithoutF: 0, x: [], c: [] };
  let inverseTime = false;
  for (const line of program.split('\n')) {
    const block = line.replace(/\([^)]*\)/g, '').replace(/;.*$/, '').trim();
    if (block === '' || block === '%') continue;
    const words = block.split(/\s+/);
    if (words.includes('G93')) inverseTime = true;
    if (words.includes('G94') || words.includes('G95')) inverseTime = false;
    if (!(words.includes('G1') || words.includes('G01')) || word(block, 'C') === '') continue;
    facts.cSteps++;
    if (!inverseTime) facts.cStepsNotG93++;
    if (word(block, 'F') === '') facts.cStepsWithoutF++;
    for (const letter of ['X', 'C']) {
      if (word(block, letter) !== '') facts[letter.toLowerCase()].push(word(block, letter));
    }
  }
  const extreme = (texts, pick) => (texts.length === 0 ? '' : texts.reduce((a, b) => (pick(Number(b), Number(a)) ? b : a)));
  for (const letter of ['x', 'c']) {
    facts[`${letter}Min`] = extreme(facts[letter], (b, a) => b < a);
    facts[`${letter}Max`] = extreme(facts[letter], (b, a) => b > a);
  }
  return facts;
}

function checkFlatProgram(checks, body, out) {
  const facts = flatProgramFacts(body.program);
  const lines = body.program.split('\n');
  if (lines.at(-1) === '') lines.pop();
  if ('dialect' in checks && body.dialect !== checks.dialect) out.push(`program: dialect ${body.dialect}, want ${checks.dialect}`);
  if ('feed_mode' in checks) {
    if (checks.feed_mode !== 'G93') out.push(`program: feed_mode ${checks.feed_mode} is not a mode this replayer knows`);
    else if (facts.cStepsNotG93 > 0 || facts.cStepsWithoutF > 0) {
      out.push(`program: of ${facts.cSteps} G1 blocks with C, ${facts.cStepsNotG93} not under G93 and ${facts.cStepsWithoutF} without their own F`);
    }
  }
  if ('c_steps' in checks && facts.cSteps !== checks.c_steps) out.push(`program: c_steps ${facts.cSteps}, want ${checks.c_steps}`);
  for (const [key, got] of [['x_word_min', facts.xMin], ['x_word_max', facts.xMax], ['c_word_min', facts.cMin], ['c_word_max', facts.cMax]]) {
    if (key in checks && got !== checks[key]) out.push(`program: ${key} ${JSON.stringify(got)}, want ${JSON.stringify(checks[key])}`);
  }
  if ('first_line' in checks && lines[0] !== checks.first_line) out.push(`program: first line ${JSON.stringify(lines[0])}, want ${JSON.stringify(checks.first_line)}`);
  if ('last_line' in checks && lines.at(-1) !== checks.last_line) out.push(`program: last line ${JSON.stringify(lines.at(-1))}, want ${JSON.stringify(checks.last_line)}`);
}

const kPolygonFacts = ['loops', 'layers', 'z_min', 'g95_flat_F', 'g94_F', 'last_C'];
// rs274's acceptance is the gcode tests' to check (tests/gcode), with the program translated.
const kCheckedByGcodeTests = ['rs274'];
const kLatheFacts = ['first_lines', 'last_lines', 'spindle_line', 'feed_moves', 'z_feed_moves', 'dwell_blocks', 'min_x', 'x_feed_travel', 'z_feed_travel'];
const kFlatFacts = ['dialect', 'feed_mode', 'c_steps', 'x_word_min', 'x_word_max', 'c_word_min', 'c_word_max', 'first_line', 'last_line'];

function checkProgram(checks, body, request, out) {
  if (typeof body.program !== 'string') return out.push('/program: missing');
  // A fact this replayer does not know would pass unchecked: refuse it instead.
  const unknown = Object.keys(checks).filter(k => ![...kPolygonFacts, ...kLatheFacts, ...kFlatFacts, ...kCheckedByGcodeTests].includes(k));
  if (unknown.length > 0) return out.push(`program: facts this replayer cannot check: ${unknown.join(', ')}`);
  const perLoop = body.blocks_per_loop;
  const facts = programFacts(body.program, Number.isInteger(perLoop) ? perLoop : 0);
  if ('loops' in checks) {
    if (!(perLoop > 0) || facts.arcBlocks % perLoop !== 0 || facts.arcBlocks / perLoop !== checks.loops) {
      out.push(`program: ${facts.arcBlocks} G2/G3 blocks, want ${checks.loops} loops of ${perLoop}`);
    }
  }
  if ('layers' in checks) {
    // The loops end at Z = -k depth / n, k = 1..n, and at nothing else.
    const levels = [...new Set(facts.loopEndZ.map(z => Math.round((-z / request.depth_mm) * checks.layers * 1000)))].sort((a, b) => a - b);
    const want = Array.from({ length: checks.layers }, (_, k) => (k + 1) * 1000);
    if (JSON.stringify(levels) !== JSON.stringify(want)) out.push(`program: loops end at levels ${levels}, want ${want} (x1000 of depth/layers)`);
  }
  if ('z_min' in checks && facts.deepestZ !== checks.z_min) out.push(`program: deepest Z ${facts.deepestZ}, want ${checks.z_min}`);
  if ('g95_flat_F' in checks && !facts.g95F.has(checks.g95_flat_F)) out.push(`program: G95 F words ${[...facts.g95F]}, want ${checks.g95_flat_F}`);
  if ('g94_F' in checks && facts.g94F !== checks.g94_F) out.push(`program: G94 F ${facts.g94F}, want ${checks.g94_F}`);
  if ('last_C' in checks && facts.lastC !== checks.last_C) out.push(`program: last C ${facts.lastC}, want ${checks.last_C}`);
  checkLatheProgram(checks, body, out);
  checkFlatProgram(checks, body, out);
  return out;
}

// Mismatches of an answer with its reference case (status checked by the caller).
function referenceMismatches(c, r) {
  const { expect, tolerance, request } = c.reference;
  const out = [];
  if (r.status !== expect.status) return out;
  const body = r.json;
  if (body === undefined) return [`the answer is not JSON: ${r.text.slice(0, 200)}`];
  if (r.status === 200) {
    if (r.contentType.split(';')[0].trim() !== 'application/json') out.push(`Content-Type ${r.contentType}, want application/json`);
    if (expect.body) compareSubset(expect.body, body, tolerance, '', '', out);
    for (const [k, bound] of Object.entries(expect.max ?? {})) {
      if (!(typeof body[k] === 'number' && body[k] <= bound)) out.push(`/${k}: ${body[k]}, want <= ${bound}`);
    }
    for (const [k, bound] of Object.entries(expect.min ?? {})) {
      if (!(typeof body[k] === 'number' && body[k] >= bound)) out.push(`/${k}: ${body[k]}, want >= ${bound}`);
    }
    if (expect.warning_codes) {
      const got = (body.warnings ?? []).map(w => w.code).sort();
      const want = [...expect.warning_codes].sort();
      if (JSON.stringify(got) !== JSON.stringify(want)) out.push(`warning codes ${JSON.stringify(got)}, want ${JSON.stringify(want)}`);
    }
    if (expect.program) checkProgram(expect.program, body, request, out);
  } else if ('pointer' in expect) {
    if (r.contentType.split(';')[0].trim() !== 'application/problem+json') out.push(`Content-Type ${r.contentType}, want application/problem+json`);
    const pointers = (body.errors ?? []).map(e => e?.pointer);
    if (!pointers.includes(expect.pointer)) out.push(`errors[] pointers ${JSON.stringify(pointers)}, want "${expect.pointer}"`);
  }
  return out;
}

// The top-level properties of the request schema of POST `p` (each with its $refs followed).
function requestProperties(p) {
  const esc = t => t.replace(/~/g, '~0').replace(/\//g, '~1');
  const deref = s => {
    while (s?.$ref) s = contract.at(s.$ref.slice(1)).value;
    return s ?? {};
  };
  const schema = deref(contract.at(`/paths/${esc(p)}/post/requestBody/content/application~1json/schema`).value);
  return Object.fromEntries(Object.entries(schema.properties ?? {}).map(([k, v]) => [k, deref(v)]));
}

// Top-level fields of a valid request that the contract requires to be positive sizes: numbers
// ending in _mm whose request schema has minimum > 0 or exclusiveMinimum >= 0.
function sizeFields(p, request) {
  const props = requestProperties(p);
  return Object.entries(request)
    .filter(([k, v]) => typeof v === 'number' && /_mm$/.test(k))
    .filter(([k]) => {
      const s = props[k] ?? {};
      return (typeof s.minimum === 'number' && s.minimum > 0) || (typeof s.exclusiveMinimum === 'number' && s.exclusiveMinimum >= 0);
    })
    .map(([k]) => k);
}

// A top-level member of the request schema that is a number, for the cases that put something else
// there: a size of the request, else a numeric member the request gives, else one the schema
// declares (sent at a valid value: its minimum, else 1; /v1/program-time's profile_points), else
// none (undefined: the cases are skipped, as a route whose numbers are all nested would need a
// pointer of its own). { key, value }.
function numericMember(p, request, sizes) {
  if (sizes.length) return { key: sizes[0], value: request[sizes[0]] };
  const props = requestProperties(p);
  const isNumeric = s => s.type === 'number' || s.type === 'integer';
  const given = Object.keys(request).find(k => typeof request[k] === 'number' && isNumeric(props[k] ?? {}));
  if (given) return { key: given, value: request[given] };
  const declared = Object.entries(props).find(([, s]) => isNumeric(s));
  if (!declared) return undefined;
  const [key, s] = declared;
  return { key, value: typeof s.minimum === 'number' ? s.minimum : 1 };
}

// The largest request body a route takes: its `max_body_bytes` in the route table (`cutcalc
// --routes`), 0 there meaning the service's default (HttpLimits::max_body_bytes, 64 KiB).
const DEFAULT_MAX_BODY_BYTES = 64 * 1024;
function bodyLimit(routes, p) {
  const route = routes.find(r => r.path === p);
  return route?.max_body_bytes > 0 ? route.max_body_bytes : DEFAULT_MAX_BODY_BYTES;
}
// Over-the-limit bodies are sent for limits up to this; above it (POST /v1/program-time, 32 MiB)
// the case is left to tests/service/large_body_test.cpp, which sends the head over a raw socket and
// reads the 413 without the body: here every such case would push limit + 1 bytes through Prism
// (which reads, parses and re-serialises the whole body before forwarding), four at a time, and
// cutcalc answers 413 from the head and closes while the client is still sending, which fetch
// may report as a reset instead of the answer.
const MAX_BODY_LIMIT_SENT = 1024 * 1024;

// `request` as JSON text of exactly `bytes` bytes (a `padding` string member added; ASCII).
function bodyOfLength(request, bytes) {
  const empty = JSON.stringify({ ...request, padding: '' });
  if (bytes < empty.length) throw new Error(`a body of ${bytes} bytes cannot hold the request (${empty.length} bytes)`);
  const text = JSON.stringify({ ...request, padding: 'x'.repeat(bytes - empty.length) });
  if (Buffer.byteLength(text, 'utf8') !== bytes) throw new Error(`padded body of ${Buffer.byteLength(text, 'utf8')} bytes, want ${bytes}`);
  return text;
}

// The request as JSON text with the value of its top-level key `key` replaced by the raw text `raw`.
function withRawValue(request, key, raw) {
  const marker = '"__RAW_VALUE_MARKER__"';
  return JSON.stringify({ ...request, [key]: '__RAW_VALUE_MARKER__' }).replace(marker, raw);
}

function badInputCases(firstValid, routes) {
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
    const numeric = numericMember(p, base, sizes);
    const limit = bodyLimit(routes, p);
    const add = (name, body, expect, extra = {}) =>
      cases.push({ id: `bad:${p}:${name}`, kind: 'bad', method: 'POST', path: p, body, expect, ...extra });
    add('empty body', '', [400]);
    add('not JSON', valid.slice(0, Math.floor(valid.length / 2)), [400], { exact: true });
    add('wrong content type', valid, [415], { contentType: 'text/plain' });
    add('no content type', valid, [415], { contentType: null });
    if (limit <= MAX_BODY_LIMIT_SENT) {
      // The route's own limit, exactly: one byte over it is refused, a body of the limit is read
      // (and refused for its unknown member).
      add(`body over the limit (${limit + 1} bytes)`, bodyOfLength(base, limit + 1), [413]);
      add(`body at the limit (${limit} bytes)`, bodyOfLength(base, limit), [422]);
    } else {
      console.log(`replay: ${p}: no over-the-limit body sent (its limit is ${limit} bytes; tests/service/large_body_test.cpp sends it)`);
    }
    add('deeply nested JSON (64 levels)', JSON.stringify({ ...base, nested: JSON.parse('['.repeat(64) + ']'.repeat(64)) }), [400]);
    // Prism 5.14 dies on this one (RangeError in its request logger), so it goes to cutcalc only.
    add('deeply nested JSON (20000 levels)', `{"nested":${'['.repeat(20000)}${']'.repeat(20000)}}`, [400],
      { directOnly: 'Prism crashes on 20000 nesting levels' });
    if (numeric) {
      const { key, value } = numeric;
      add(`string for a number (${key})`, JSON.stringify({ ...base, [key]: String(value) }), [422]);
      add(`NaN literal (${key})`, withRawValue(base, key, 'NaN'), [400], { exact: true });
      add(`1e400 (${key})`, withRawValue(base, key, '1e400'), [422], { exact: true });
    } else {
      console.log(`replay: ${p}: no top-level numeric member, no string-for-a-number, NaN or 1e400 case`);
    }
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
  for (const [p, item] of Object.entries(contract.document.paths)) {
    if (p.includes('{')) continue;
    for (const method of ['HEAD', 'OPTIONS']) {
      if (item[method.toLowerCase()]) cases.push({ id: `ops:${method} ${p}`, kind: 'operations', method, path: p, expect: [method === 'HEAD' ? 200 : 204] });
    }
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
let operations; // Prism's operations (prism mode only)

function findOperation(method, p) {
  const m = method.toLowerCase();
  return operations.find(o => o.path === p && o.method === m) ?? operations.find(o => o.path === p);
}

function bodyForValidation(c, r) {
  if (isJsonMediaType(r.contentType) && r.status !== 204 && c.method !== 'HEAD') {
    return r.json === undefined ? { error: `response body is not JSON: ${r.text.slice(0, 200)}` } : { body: r.json };
  }
  return { body: r.text };
}

const severityName = s => (s === 0 ? 'Error' : s === 1 ? 'Warning' : s === 2 ? 'Information' : s === 3 ? 'Hint' : String(s));

// Prism's own response validator (the code the proxy runs), for answers taken directly from cutcalc.
function validateWithPrism(c, r) {
  const { validateOutput } = require('@stoplight/prism-http/dist/validator');
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

// contract.mjs on cutcalc's answer: status, headers, media type, body (JSON Schema 2020-12).
function validateContract(c, r) {
  const b = bodyForValidation(c, r);
  if (b.error) return [{ location: ['response', 'body'], message: b.error }];
  const headers = Object.fromEntries(Object.entries(r.headers).filter(([k]) => k !== 'sl-violations'));
  return contract.checkResponse({
    method: c.method, path: c.path, status: r.status, contentType: r.contentType, headers, body: b.body,
  })
    .map(message => ({ location: ['response'], severity: 'Error', code: 'openapi.yaml', message }));
}

// ------------------------------------------------------------------ run
const stats = {
  cases: 0, throughPrism: 0, directOnly: 0, strict: 0, relaxed: 0, direct: 0, rejectedByPrism: 0, violations: 0,
  statusMismatch: 0, unexpectedRejections: 0, referenceChecked: 0, referenceMismatches: 0,
};
const failures = [];

function fail(c, via, status, what, details) {
  failures.push({ id: c.id, op: `${c.method} ${c.path}`, via, status, what, details });
}

function describe(v) {
  const where = (v.location ?? []).join('.');
  return `${v.severity ?? 'Error'} ${v.code ?? ''} at ${where || '(document)'}: ${v.message}`;
}

// Checks one answer of cutcalc: the contract, the status, and the reference case's expectations.
function checkUpstream(c, via, r, { checkStatus = true } = {}) {
  const v = validateContract(c, r);
  if (v.length) {
    stats.violations += v.length;
    fail(c, via, r.status, 'the answer violates openapi.yaml (contract.mjs, JSON Schema 2020-12)', v.map(describe));
  }
  if (!checkStatus) return;
  if (!c.expect.includes(r.status)) {
    stats.statusMismatch++;
    fail(c, via, r.status, `status ${r.status}, expected ${c.expect.join(' or ')}`, [r.text.slice(0, 300)]);
  } else if (c.reference && !c.referenceChecked) {
    c.referenceChecked = true;
    stats.referenceChecked++;
    const m = referenceMismatches(c, r);
    if (m.length) {
      stats.referenceMismatches++;
      fail(c, via, r.status, 'the answer differs from the reference case', m.slice(0, 10));
    }
  }
}

async function runDirect(c, reason) {
  const r = await send(DIRECT, c);
  stats.direct++;
  if (MODE === 'prism') {
    const v = validateWithPrism(c, r);
    if (v.length) {
      stats.violations += v.length;
      fail(c, 'direct', r.status, "response violates the contract (Prism's validator)", v.map(describe));
    }
  }
  if (VERBOSE) console.log(`  direct  ${c.id}: ${r.status}${reason ? ` (${reason})` : ''}`);
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
  if (MODE !== 'prism') {
    await runDirect(c);
    return;
  }
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

// Starts the cutcalc binary on a free loopback port; resolves when it reports its port.
function startCutcalc(bin) {
  return new Promise((resolve, reject) => {
    const child = spawn(bin, ['--host', '127.0.0.1', '--port', '0', '--threads', '2', '--log-level', 'info', '--log-format', 'text'],
      { stdio: ['ignore', 'pipe', 'pipe'] });
    let output = '';
    const timer = setTimeout(() => reject(new Error(`cutcalc did not report its port within 20 s: ${output}`)), 20000);
    const onData = d => {
      output += d;
      const m = output.match(/listening on http:\/\/127\.0\.0\.1:(\d+)/);
      if (m) {
        clearTimeout(timer);
        child.stdout.removeAllListeners('data');
        child.stdout.resume();
        child.stderr.resume();
        resolve({ child, url: `http://127.0.0.1:${m[1]}` });
      }
    };
    child.stdout.on('data', onData);
    child.stderr.on('data', onData);
    child.on('error', reject);
    child.on('exit', code => reject(new Error(`cutcalc exited at start (${code}): ${output}`)));
  });
}

async function main() {
  const started = Date.now();
  let child;
  if (MODE === 'prism') {
    STRICT = env('PRISM_STRICT_URL').replace(/\/$/, '');
    RELAXED = env('PRISM_RELAXED_URL').replace(/\/$/, '');
    DIRECT = env('CUTCALC_URL').replace(/\/$/, '');
    const { getHttpOperationsFromSpec } = require('@stoplight/prism-http');
    operations = await getHttpOperationsFromSpec(OPENAPI_FILE);
  } else if (MODE === 'start') {
    ({ child, url: DIRECT } = await startCutcalc(opt.start));
  } else {
    DIRECT = opt['base-url'].replace(/\/$/, '');
  }
  const { files, cases: refCases, firstValid, routes } = referenceCases();
  const bad = badInputCases(firstValid, routes);
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
  if (child) {
    child.removeAllListeners('exit');
    const exited = new Promise(resolve => child.once('exit', (code, signal) => resolve({ code, signal })));
    child.kill('SIGTERM');
    const { code } = await exited;
    if (code !== 0) fail({ id: 'cutcalc', method: '-', path: '-' }, 'process', '-', `cutcalc exited with ${code} on SIGTERM`, []);
  }
  failures.sort((a, b) => all.findIndex(c => c.id === a.id) - all.findIndex(c => c.id === b.id));
  for (const f of failures) {
    console.log(`FAIL ${f.id} [${f.op}] via ${f.via}, status ${f.status}: ${f.what}`);
    for (const d of f.details) console.log(`     ${d}`);
  }
  const seconds = ((Date.now() - started) / 1000).toFixed(1);
  const referenceTotal = refCases.filter(c => c.reference).length;
  const where = MODE === 'prism'
    ? `${stats.strict + stats.relaxed} requests through Prism (${stats.strict} strict, ${stats.relaxed} relaxed after a request violation), ` +
      `${stats.direct} sent directly and checked with Prism's validator`
    : `${stats.direct} requests to ${MODE === 'start' ? `${path.basename(opt.start)} (started here)` : DIRECT}`;
  console.log(
    `replay: ${stats.cases} cases (${refCases.length} reference from ${files.length} files` +
      (PER_FILE > 0 ? `, ${PER_FILE} per file` : '') + `, ${ops.length} operations, ${bad.length} bad-input); ${where}; ${seconds} s`,
  );
  console.log(
    `replay: ${stats.referenceChecked - stats.referenceMismatches}/${referenceTotal} reference cases match their expectations, ` +
      `${stats.violations} contract violations` + (MODE === 'prism' ? `, ${stats.throughPrism} cases through Prism` + (stats.directOnly ? ` (+${stats.directOnly} direct only)` : '') : '') +
      (failures.length ? `; ${failures.length} failures (${stats.statusMismatch} status mismatches, ${stats.referenceMismatches} reference mismatches, ${stats.unexpectedRejections} valid requests rejected)` : '; 0 failures'),
  );
  process.exit(failures.length ? 1 : 0);
}

process.on('beforeExit', () => setupError('the run ended before its summary (a promise never settled)'));
main().catch(e => {
  console.error(`replay: ${e.stack || e}`);
  process.exit(2);
});
