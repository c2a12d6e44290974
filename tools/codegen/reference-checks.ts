// Runtime checks for the generated reference client (gen-reference-client.mjs writes
// reference-client.ts, which imports this file; both are compiled with tsc --strict).
// This client proves that the generated types fit real answers: every field a reference case
// names is in the answer with the JSON type of the expected value (lists with the same length,
// objects recursively), and a problem's errors[] names expect.pointer. Whether the values are
// right is checked once, by the one reference replayer (tools/contract/replay.mjs).

export type Json = null | boolean | number | string | Json[] | { [key: string]: Json };

export interface Expectation {
  body?: Json;
  max?: Json;
  min?: Json;
}

interface Answer {
  status: number;
  headers: Headers;
}

const failures: string[] = [];
const counts = { ok200: 0, typeRejected422: 0, typeValid422: 0 };

function isObject(value: unknown): value is { [key: string]: unknown } {
  return typeof value === "object" && value !== null && !Array.isArray(value);
}

// Walks `expected` and calls `leaf` on every scalar with the value found at the same place.
function walk(
  expected: Json,
  actual: unknown,
  pointer: string,
  key: string,
  out: string[],
  leaf: (want: Json, got: unknown, pointer: string, key: string) => string | undefined,
): void {
  if (Array.isArray(expected)) {
    if (!Array.isArray(actual) || actual.length !== expected.length) {
      out.push(`${pointer}: expected a list of ${expected.length}, got ${JSON.stringify(actual)}`);
      return;
    }
    expected.forEach((item, i) => walk(item, actual[i], `${pointer}/${i}`, key, out, leaf));
  } else if (expected !== null && typeof expected === "object") {
    if (!isObject(actual)) {
      out.push(`${pointer}: expected an object, got ${JSON.stringify(actual)}`);
      return;
    }
    for (const [name, value] of Object.entries(expected)) {
      if (!(name in actual)) out.push(`${pointer}/${name}: missing`);
      else walk(value, actual[name], `${pointer}/${name}`, name, out, leaf);
    }
  } else {
    const why = leaf(expected, actual, pointer, key);
    if (why !== undefined) out.push(why);
  }
}

// The JSON type of a value as the reference files distinguish them.
function kind(value: unknown): string {
  return value === null ? "null" : Array.isArray(value) ? "array" : typeof value;
}

function compareShape(expected: Json, actual: unknown): string[] {
  const out: string[] = [];
  walk(expected, actual, "", "", out, (want, got, pointer) =>
    kind(want) === kind(got) ? undefined : `${pointer}: expected a ${kind(want)}, got ${JSON.stringify(got)}`,
  );
  return out;
}

function mediaType(answer: Answer): string {
  return (answer.headers.get("content-type") ?? "").split(";")[0]!.trim().toLowerCase();
}

function fail(id: string, what: string[]): void {
  failures.push(`FAIL ${id}\n${what.map(w => `     ${w}`).join("\n")}`);
}

// A 200 reference case: the status, the JSON media type and every field the case names.
export function expectOk(id: string, answer: Answer, data: unknown, error: unknown, expect: Expectation): void {
  const problems: string[] = [];
  if (answer.status !== 200) {
    problems.push(`status ${answer.status}, expected 200: ${JSON.stringify(error ?? data).slice(0, 300)}`);
  } else {
    if (mediaType(answer) !== "application/json") problems.push(`content type ${mediaType(answer)}, expected application/json`);
    for (const part of [expect.body, expect.max, expect.min]) {
      if (part !== undefined) problems.push(...compareShape(part, data));
    }
  }
  if (problems.length) fail(id, problems);
  else counts.ok200++;
}

// A 422 reference case: the status, the problem media type and errors[] naming the pointer.
// `typeRejected` says whether the request was written under @ts-expect-error.
export function expectProblem(id: string, answer: Answer, data: unknown, error: unknown, pointer: string, typeRejected: boolean): void {
  const problems: string[] = [];
  if (answer.status !== 422) {
    problems.push(`status ${answer.status}, expected 422: ${JSON.stringify(error ?? data).slice(0, 300)}`);
  } else {
    if (mediaType(answer) !== "application/problem+json") {
      problems.push(`content type ${mediaType(answer)}, expected application/problem+json`);
    }
    const errors = isObject(error) && Array.isArray(error.errors) ? error.errors : [];
    if (!errors.some(e => isObject(e) && e.pointer === pointer)) {
      problems.push(`errors[] has no entry at pointer ${JSON.stringify(pointer)}: ${JSON.stringify(error).slice(0, 300)}`);
    }
  }
  if (problems.length) fail(id, problems);
  else if (typeRejected) counts.typeRejected422++;
  else counts.typeValid422++;
}

// The typed reads of the fields a 200 case checks (their only job is to type-check).
export function read(..._values: unknown[]): void {}

export function transportFailure(id: string, e: unknown): void {
  fail(id, [`request failed: ${e instanceof Error ? e.message : String(e)}`]);
}

// Prints the failures and the summary line; returns the exit status.
export function report(total: { ok200: number; typeRejected422: number; typeValid422: number }, seconds: number): number {
  for (const f of failures) console.log(f);
  const line =
    `codegen reference client: ${counts.ok200}/${total.ok200} 200 cases passed, ` +
    `${counts.typeRejected422}/${total.typeRejected422} 422 cases rejected by the types (and answered 422), ` +
    `${counts.typeValid422}/${total.typeValid422} 422 cases type-valid and answered 422 by the server; ` +
    `${failures.length} failures; ${seconds.toFixed(1)} s`;
  console.log(line);
  return failures.length ? 1 : 0;
}
