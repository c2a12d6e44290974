#!/usr/bin/env node
// Writes a TypeScript client (openapi-fetch, typed by openapi-typescript's `paths` from
// openapi.yaml) that sends every reference case of ../shared/reference/*.json to a live cutcalc,
// as an object literal in `client.POST(endpoint, { body: {...} })`:
//   - status 200 cases: the answer must be 200 application/json and have every field that
//     expect.body, expect.max and expect.min name, with the JSON type of the expected value; each
//     of those fields is also read through the typed `data`, so the response types must have it.
//     The values themselves are the one reference replayer's job (tools/contract/replay.mjs, run
//     by ctest in every preset, by the contract step and against the container);
//   - status 422 cases: classified here, from the request schema in openapi.yaml, as expressible
//     in the generated types or not (typeViolations below). An expressible case is written under
//     `// @ts-expect-error`, so tsc fails when the types accept it (too loose); the others are
//     written plain, so tsc fails when the types reject a type-correct request (too strict).
//     Every 422 case is sent (tsc still emits JavaScript for the suppressed lines) and must be
//     answered 422 application/problem+json with errors[] naming expect.pointer.
// Everything comes from openapi.yaml and the reference files at run time: each file's `endpoint`
// (as tools/contract/replay.mjs reads it) and its cases, with the request corrections of
// tests/reference-corrections.json applied. Nothing here is per case.
//
// Usage: node gen-reference-client.mjs --openapi FILE --reference DIR [--routes FILE] --out DIR
// DIR's *.json plus the next/ files the route table lists (--routes: what `cutcalc --routes`
// printed; without it tools/routes/route_table.mjs asks CUTCALC_BIN or the release build).
// Writes DIR/reference-client.ts, DIR/reference-checks.ts (copied), DIR/tsconfig.json and
// DIR/package.json; prints the classification of every 422 case. Exit status 2 on a setup error.
import { copyFileSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';
import YAML from 'yaml';
import { correctedCases } from '../contract/reference-corrections.mjs';
import { loadRoutes, replayedReferenceFiles } from '../routes/route_table.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const { values: args } = parseArgs({
  options: {
    openapi: { type: 'string' }, reference: { type: 'string' }, out: { type: 'string' }, routes: { type: 'string' },
  },
});
const die = message => {
  console.error(`gen-reference-client: ${message}`);
  process.exit(2);
};
if (!args.openapi || !args.reference || !args.out) die('usage: --openapi FILE --reference DIR --out DIR');

const document = YAML.parse(readFileSync(args.openapi, 'utf8'));

// ------------------------------------------------------------------ the contract
function resolve(node, seen = new Set()) {
  while (node && typeof node === 'object' && typeof node.$ref === 'string') {
    if (seen.has(node.$ref)) die(`circular $ref ${node.$ref}`);
    seen.add(node.$ref);
    if (!node.$ref.startsWith('#/')) die(`only local $refs are supported: ${node.$ref}`);
    node = node.$ref
      .slice(2)
      .split('/')
      .map(s => s.replace(/~1/g, '/').replace(/~0/g, '~'))
      .reduce((at, key) => (at === undefined ? undefined : at[key]), document);
    if (node === undefined) die(`unresolvable $ref`);
  }
  return node;
}

const isJsonMedia = type => /^application\/([a-z0-9.+-]*\+)?json$/i.test(type.split(';')[0].trim());

function requestSchema(endpoint) {
  const operation = document.paths?.[endpoint]?.post;
  if (!operation) die(`openapi.yaml has no POST ${endpoint}`);
  const body = resolve(operation.requestBody);
  const entry = Object.entries(body?.content ?? {}).find(([type]) => isJsonMedia(type));
  if (!entry) die(`POST ${endpoint} has no JSON request body`);
  return entry[1].schema;
}

// ------------------------------------------------------------------ what the types can express
// The JSON Schema keywords that openapi-typescript 7 turns into TypeScript types, and so the
// violations that tsc can see in an object literal (the rule that classifies a 422 case):
//   type          a value of the wrong JSON type (integer is `number`: 2.5 for an integer is not);
//   enum, const   a value outside the literal union;
//   required      a missing property of an object schema (one with `type: object` or `properties`;
//                 a schema that only says `required`, as a oneOf branch, becomes `unknown`);
//   additionalProperties: false
//                 a property no schema of the intersection (allOf) declares: TypeScript's excess
//                 property check on a fresh object literal (the generated code writes literals);
//   properties, items, additionalProperties: {schema}
//                 the same rules one level down;
//   allOf         every member (an intersection);
//   oneOf, anyOf  a union: a violation only when every branch sees one (a discriminated union is
//                 narrowed by its `const` tag, so a branch with a different tag sees one).
// Not expressible (ignored here): minimum, maximum, exclusive*, multipleOf, minLength, maxLength,
// pattern, format, minItems/maxItems (tuples only with --array-length, not used), uniqueItems,
// not, dependentRequired, dependentSchemas, if/then/else, integer-ness.
const jsonType = v =>
  v === null ? 'null' : Array.isArray(v) ? 'array' : typeof v === 'object' ? 'object' : typeof v;

function declaredProperties(schema) {
  // Properties visible in the TypeScript intersection of schema and its allOf members.
  const s = resolve(schema);
  const names = new Set(Object.keys(s?.properties ?? {}));
  for (const member of s?.allOf ?? []) for (const n of declaredProperties(member)) names.add(n);
  return names;
}

function closedSomewhere(schema) {
  const s = resolve(schema);
  return s?.additionalProperties === false || (s?.allOf ?? []).some(closedSomewhere);
}

function typeViolations(schemaNode, value, pointer, visibleNames) {
  const schema = resolve(schemaNode);
  if (schema === true || schema === undefined || schema === null || typeof schema !== 'object') return [];
  if (schema === false) return [{ pointer, rule: 'false schema' }];
  const out = [];
  const actual = jsonType(value);

  if (schema.type !== undefined) {
    const allowed = (Array.isArray(schema.type) ? schema.type : [schema.type]).map(t => (t === 'integer' ? 'number' : t));
    if (!allowed.includes(actual)) out.push({ pointer, rule: `type: ${actual} where ${allowed.join(' | ')}` });
  }
  if (Array.isArray(schema.enum) && !schema.enum.some(e => JSON.stringify(e) === JSON.stringify(value))) {
    out.push({ pointer, rule: `enum: ${JSON.stringify(value)} not in ${JSON.stringify(schema.enum)}` });
  }
  if ('const' in schema && JSON.stringify(schema.const) !== JSON.stringify(value)) {
    out.push({ pointer, rule: `const: ${JSON.stringify(value)} is not ${JSON.stringify(schema.const)}` });
  }

  const objectShape = schema.type === 'object' || schema.properties !== undefined;
  if (actual === 'object' && objectShape) {
    for (const name of schema.required ?? []) {
      if (!(name in value)) out.push({ pointer: `${pointer}/${name}`, rule: 'required: missing property' });
    }
    // The names the intersection declares (this schema and, from the caller, its allOf siblings).
    const names = visibleNames ?? declaredProperties(schema);
    for (const [name, v] of Object.entries(value)) {
      const p = `${pointer}/${name}`;
      if (schema.properties && name in schema.properties) {
        out.push(...typeViolations(schema.properties[name], v, p));
      } else if (names.has(name)) {
        // declared by another member of the intersection: checked there
      } else if (schema.additionalProperties === false) {
        out.push({ pointer: p, rule: 'additionalProperties: false (excess property in an object literal)' });
      } else if (schema.additionalProperties && typeof schema.additionalProperties === 'object') {
        out.push(...typeViolations(schema.additionalProperties, v, p));
      }
    }
  }
  if (actual === 'array' && schema.items !== undefined && typeof schema.items === 'object') {
    value.forEach((item, i) => out.push(...typeViolations(schema.items, item, `${pointer}/${i}`)));
  }

  if (Array.isArray(schema.allOf)) {
    const names = actual === 'object' ? declaredProperties(schema) : undefined;
    for (const member of schema.allOf) out.push(...typeViolations(member, value, pointer, names));
  }
  for (const keyword of ['oneOf', 'anyOf']) {
    if (!Array.isArray(schema[keyword])) continue;
    const perBranch = schema[keyword].map(branch => typeViolations(branch, value, pointer));
    if (perBranch.every(v => v.length > 0)) {
      out.push({
        pointer,
        rule: `${keyword}: no branch of the union accepts it (${perBranch.map(v => v.map(x => `${x.pointer} ${x.rule}`).join(', ')).join(' / ')})`,
      });
    }
  }
  return out;
}

// Sanity check of the rule on the 200 cases: a request the service accepts must show no violation
// here (else the rule, or the contract, is wrong).
// ------------------------------------------------------------------ emit
const isIdentifier = k => /^[A-Za-z_$][A-Za-z0-9_$]*$/.test(k);
const access = k => (typeof k === 'number' ? `?.[${k}]` : isIdentifier(k) ? `?.${k}` : `?.[${JSON.stringify(k)}]`);

// Typed reads of every leaf that `expected` names, e.g. data?.start?.x_mm, data?.points?.[0]?.rz_um.
function typedReads(expected, base, out) {
  if (Array.isArray(expected)) expected.forEach((v, i) => typedReads(v, base + access(i), out));
  else if (expected !== null && typeof expected === 'object') {
    for (const [k, v] of Object.entries(expected)) typedReads(v, base + access(k), out);
  } else out.push(base);
  return out;
}

// Expectation keys this client reads (warning_codes and program are the replayer's alone).
const CHECKED_EXPECT = new Set(['status', 'body', 'max', 'min', 'pointer']);

let files;
try {
  files = replayedReferenceFiles(args.reference, loadRoutes({ routesFile: args.routes }));
} catch (e) {
  die(`cannot read reference directory ${args.reference} or the route table: ${e.message}`);
}
if (files.length === 0) die(`no reference files in ${args.reference}`);

const lines = [];
const caseFunctions = [];
const classification = [];
const unchecked = new Map();
const total = { ok200: 0, typeRejected422: 0, typeValid422: 0 };
const ruleProblems = [];

for (const file of files) {
  const doc = JSON.parse(readFileSync(path.join(args.reference, file), 'utf8'));
  // The requests that contradict the spec they cite, corrected as the replay corrects them.
  doc.cases = correctedCases(file, doc.cases ?? [], why => die(`STALE reference correction: ${why}`));
  const endpoint = doc.endpoint;
  if (typeof endpoint !== 'string') die(`${file} names no endpoint`);
  const schema = requestSchema(endpoint);
  lines.push('', `// ---------------------------------------------------------------- ${file}: POST ${endpoint}`);
  for (const c of doc.cases) {
    const id = `${file}:${c.id}`;
    const status = c.expect?.status;
    for (const k of Object.keys(c.expect ?? {})) if (!CHECKED_EXPECT.has(k)) unchecked.set(k, (unchecked.get(k) ?? 0) + 1);
    // `satisfies RequestBody<...>`: openapi-fetch infers its init argument into a type parameter,
    // which turns off TypeScript's excess property check on the literal (an unknown field would
    // pass; openapi-ts/openapi-typescript#2329); `satisfies` checks the literal against the
    // generated request type itself, the same type the client's signature uses.
    const call =
      `await client.POST(${JSON.stringify(endpoint)}, ` +
      `{ body: ${JSON.stringify(c.request)} satisfies RequestBody<${JSON.stringify(endpoint)}> })`;
    // One function per case: one function with every case is too large for tsc's control flow analysis.
    const fn = `case${caseFunctions.length + 1}`;
    caseFunctions.push(fn);
    lines.push(`// ${id} (${status})`, `async function ${fn}(): Promise<void> {`, '  try {');
    if (status === 200) {
      total.ok200++;
      const violations = typeViolations(schema, c.request, '');
      if (violations.length) ruleProblems.push(`${id}: a 200 request shows type-level violations: ${violations.map(v => `${v.pointer} ${v.rule}`).join('; ')}`);
      const expect = {};
      for (const k of ['body', 'max', 'min']) if (c.expect[k] !== undefined) expect[k] = c.expect[k];
      const reads = [
        ...typedReads(c.expect.body ?? {}, 'data', []),
        ...typedReads(c.expect.max ?? {}, 'data', []),
        ...typedReads(c.expect.min ?? {}, 'data', []),
      ];
      lines.push(
        `    const { data, error, response } = ${call};`,
        `    read(${[...new Set(reads)].join(', ')});`,
        `    expectOk(${JSON.stringify(id)}, response, data, error, ${JSON.stringify(expect)});`,
      );
    } else if (status === 422) {
      if (typeof c.expect.pointer !== 'string') die(`${id}: a 422 case without expect.pointer`);
      const violations = typeViolations(schema, c.request, '');
      const expressible = violations.length > 0;
      classification.push({ id, pointer: c.expect.pointer, expressible, violations });
      if (expressible) {
        total.typeRejected422++;
        lines.push(
          `    // type-expressible: ${violations.map(v => `${v.pointer || '(body)'} ${v.rule}`).join('; ').replace(/\n/g, ' ')}`,
          `    // @ts-expect-error -- the types must reject this request`,
        );
      } else {
        total.typeValid422++;
        lines.push(`    // not expressible in the types: type-correct, the server must answer 422 at ${JSON.stringify(c.expect.pointer)}`);
      }
      lines.push(
        `    const { data, error, response } = ${call};`,
        `    expectProblem(${JSON.stringify(id)}, response, data, error, ${JSON.stringify(c.expect.pointer)}, ${expressible});`,
      );
    } else {
      die(`${id}: expect.status ${status} is neither 200 nor 422`);
    }
    lines.push(`  } catch (e) {`, `    transportFailure(${JSON.stringify(id)}, e);`, '  }', '}');
  }
}
if (ruleProblems.length) die(`the classification rule disagrees with the 200 cases:\n  ${ruleProblems.join('\n  ')}`);

const source = `// Generated by tools/codegen/gen-reference-client.mjs from openapi.yaml and ${path.basename(path.resolve(args.reference))}/*.json. Do not edit.
import createClient from "openapi-fetch";
import type { OperationRequestBodyContent, Writable } from "openapi-typescript-helpers";
import type { paths } from "./schema.js";
import { expectOk, expectProblem, read, report, transportFailure } from "./reference-checks.js";

// JSON answers only (a text/plain form of the same answer is asked for with Accept; not here).
type JsonMedia = \`\${string}/json\${string}\`;
// The body type openapi-fetch's POST takes for a path (its RequestBodyOption).
type RequestBody<P extends keyof paths> = Writable<OperationRequestBodyContent<paths[P]["post"]>>;

const baseUrl = process.env.CUTCALC_URL;
if (!baseUrl) {
  console.error("reference-client: CUTCALC_URL is not set");
  process.exit(2);
}
const client = createClient<paths, JsonMedia>({ baseUrl, headers: { accept: "application/json" } });

${lines.join('\n')}

async function main(): Promise<number> {
  const started = performance.now();
  for (const run of [${caseFunctions.join(', ')}]) await run();
  return report(${JSON.stringify(total)}, (performance.now() - started) / 1000);
}

main().then(
  status => process.exit(status),
  (e: unknown) => {
    console.error(e);
    process.exit(2);
  },
);
`;

mkdirSync(args.out, { recursive: true });
writeFileSync(path.join(args.out, 'reference-client.ts'), source);
copyFileSync(path.join(here, 'reference-checks.ts'), path.join(args.out, 'reference-checks.ts'));
writeFileSync(path.join(args.out, 'package.json'), JSON.stringify({ private: true, type: 'module' }, null, 2) + '\n');
writeFileSync(
  path.join(args.out, 'tsconfig.json'),
  JSON.stringify(
    {
      compilerOptions: {
        strict: true,
        noUncheckedIndexedAccess: true,
        noImplicitOverride: true,
        noFallthroughCasesInSwitch: true,
        target: 'ES2022',
        lib: ['ES2022', 'DOM'],
        module: 'NodeNext',
        moduleResolution: 'NodeNext',
        types: ['node'],
        outDir: 'js',
        rootDir: '.',
      },
      files: ['reference-client.ts'],
    },
    null,
    2,
  ) + '\n',
);

// ------------------------------------------------------------------ report
const byId = (a, b) => a.id.localeCompare(b.id);
console.log(`422 cases the types can express (written under @ts-expect-error): ${total.typeRejected422}`);
for (const c of classification.filter(c => c.expressible).sort(byId)) {
  console.log(`  ${c.id} (pointer ${JSON.stringify(c.pointer)}): ${c.violations.map(v => `${v.pointer || '(body)'} ${v.rule}`).join('; ')}`);
}
console.log(`422 cases the types cannot express (type-correct, sent to the server): ${total.typeValid422}`);
for (const c of classification.filter(c => !c.expressible).sort(byId)) console.log(`  ${c.id} (pointer ${JSON.stringify(c.pointer)})`);
if (unchecked.size) {
  console.log(`expectations not checked by this client: ${[...unchecked].map(([k, n]) => `${k} (${n} cases)`).join(', ')}`);
}
console.log(
  `wrote ${path.join(args.out, 'reference-client.ts')}: ${files.length} files, ${total.ok200} cases with status 200, ` +
    `${total.typeRejected422 + total.typeValid422} with status 422`,
);
