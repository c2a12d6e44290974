// Runtime checks for the generated reference client (gen-reference-client.mjs writes
// reference-client.ts, which imports this file; both are compiled with tsc --strict).
// The comparison rules are those of the reference files' `compare` texts and of the C++ reference
// tests (tests/support/reference_compare.cpp): every number listed in expect.body within the
// file's tolerance, strings and booleans equal, lists element-wise with the same length, objects
// recursively, fields not listed unchecked; expect.max / expect.min as bounds; expect.warning_codes
// as the multiset of warnings[].code; a problem's errors[] naming expect.pointer.

export type Json = null | boolean | number | string | Json[] | { [key: string]: Json };

// How a reference file combines its tolerance numbers (derived by the generator from the file).
export type Tolerance =
  | { kind: "exact" }
  | { kind: "max"; abs: number; rel: number } // max(abs, rel |want|)
  | { kind: "sum"; abs: number; rel: number } // abs + rel |want|
  | { kind: "by-key"; abs_mm: number; abs_min: number }; // abs_min for *_time_min and main_time_min, abs_mm otherwise

export interface Expectation {
  body?: Json;
  max?: Json;
  min?: Json;
  warning_codes?: string[];
}

interface Answer {
  status: number;
  headers: Headers;
}

const failures: string[] = [];
const counts = { ok200: 0, typeRejected422: 0, typeValid422: 0 };

function allowed(tolerance: Tolerance, key: string, want: number): number {
  switch (tolerance.kind) {
    case "exact":
      return 0;
    case "max":
      return Math.max(tolerance.abs, tolerance.rel * Math.abs(want));
    case "sum":
      return tolerance.abs + tolerance.rel * Math.abs(want);
    case "by-key":
      return key.endsWith("_time_min") || key === "main_time_min" ? tolerance.abs_min : tolerance.abs_mm;
  }
}

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

function compareBody(expected: Json, actual: unknown, tolerance: Tolerance): string[] {
  const out: string[] = [];
  walk(expected, actual, "", "", out, (want, got, pointer, key) => {
    if (typeof want === "number") {
      if (typeof got !== "number") return `${pointer}: expected a number ${want}, got ${JSON.stringify(got)}`;
      const limit = allowed(tolerance, key, want);
      const off = Math.abs(got - want);
      return off <= limit ? undefined : `${pointer}: expected ${want} +- ${limit}, got ${got} (off by ${off})`;
    }
    return want === got ? undefined : `${pointer}: expected ${JSON.stringify(want)}, got ${JSON.stringify(got)}`;
  });
  return out;
}

function compareBound(bound: Json, actual: unknown, which: "max" | "min"): string[] {
  const out: string[] = [];
  walk(bound, actual, "", "", out, (limit, got, pointer) => {
    if (typeof limit !== "number" || typeof got !== "number") {
      return `${pointer}: expected a number for the ${which} bound ${JSON.stringify(limit)}, got ${JSON.stringify(got)}`;
    }
    const inside = which === "max" ? got <= limit : got >= limit;
    return inside ? undefined : `${pointer}: ${got} is ${which === "max" ? "above the maximum" : "below the minimum"} ${limit}`;
  });
  return out;
}

function warningCodes(actual: unknown): string[] | undefined {
  if (!isObject(actual) || !Array.isArray(actual.warnings)) return undefined;
  return actual.warnings.map(w => (isObject(w) && typeof w.code === "string" ? w.code : JSON.stringify(w))).sort();
}

function mediaType(answer: Answer): string {
  return (answer.headers.get("content-type") ?? "").split(";")[0]!.trim().toLowerCase();
}

function fail(id: string, what: string[]): void {
  failures.push(`FAIL ${id}\n${what.map(w => `     ${w}`).join("\n")}`);
}

// A 200 reference case: the status, the JSON media type and the expected values.
export function expectOk(id: string, answer: Answer, data: unknown, error: unknown, expect: Expectation, tolerance: Tolerance): void {
  const problems: string[] = [];
  if (answer.status !== 200) {
    problems.push(`status ${answer.status}, expected 200: ${JSON.stringify(error ?? data).slice(0, 300)}`);
  } else {
    if (mediaType(answer) !== "application/json") problems.push(`content type ${mediaType(answer)}, expected application/json`);
    if (expect.body !== undefined) problems.push(...compareBody(expect.body, data, tolerance));
    if (expect.max !== undefined) problems.push(...compareBound(expect.max, data, "max"));
    if (expect.min !== undefined) problems.push(...compareBound(expect.min, data, "min"));
    if (expect.warning_codes !== undefined) {
      const got = warningCodes(data);
      const want = [...expect.warning_codes].sort();
      if (JSON.stringify(got) !== JSON.stringify(want)) {
        problems.push(`warning codes ${JSON.stringify(got)}, expected ${JSON.stringify(want)} (order free)`);
      }
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
