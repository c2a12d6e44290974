#!/usr/bin/env node
// The C++ tests' contract checker (contract.mjs: Ajv, JSON Schema 2020-12, openapi.yaml).
//
//   check.mjs clear <log>                 empties the exchange log (ctest fixture setup)
//   check.mjs exchanges <openapi> <log>   checks every answer the tests logged (ctest fixture
//                                         cleanup); exit 1 on any violation, 2 on a setup error
//   check.mjs serve [--lazy] <openapi>    synchronous checks for tests/support/openapi_contract.cpp:
//                                         one JSON request per stdin line, one JSON answer per line;
//                                         --lazy compiles each schema when first used
//
// The exchange log (tests/support/exchange_log.cpp) has one JSON object per line: test, method,
// path, status, response_headers (object), body (the response bytes as a string). serve's first
// line is {"ready":true} or {"error":...}; then for {"op":"response"|"request"|"headers"|"schema",
// ...} it answers {"violations":[...]} or {"error":...}.
import { closeSync, openSync, readFileSync, writeFileSync, mkdirSync } from 'node:fs';
import path from 'node:path';
import readline from 'node:readline';
import { Contract, isJsonMediaType } from './contract.mjs';

function die(message) {
  console.error(`contract check: ${message}`);
  process.exit(2);
}

function header(headers, name) {
  const key = Object.keys(headers ?? {}).find(k => k.toLowerCase() === name);
  return key === undefined ? undefined : headers[key];
}

function checkExchanges(openapi, log) {
  const contract = new Contract(openapi);
  let text;
  try {
    text = readFileSync(log, 'utf8');
  } catch (e) {
    die(`cannot read the exchange log ${log}: ${e.message}`);
  }
  const lines = text.split('\n').filter(l => l.trim() !== '');
  const perOperation = new Map();
  const failures = [];
  lines.forEach((line, i) => {
    let x;
    try {
      x = JSON.parse(line);
    } catch (e) {
      failures.push({ where: `line ${i + 1}`, violations: [`not JSON: ${e.message}`] });
      return;
    }
    const contentType = header(x.response_headers, 'content-type') ?? '';
    const head = x.method.toUpperCase() === 'HEAD';
    let body = head || x.body === '' ? undefined : x.body;
    const violations = [];
    if (body !== undefined && isJsonMediaType(contentType)) {
      try {
        body = JSON.parse(body);
      } catch {
        violations.push(`the body is not JSON although Content-Type is ${contentType}: ${x.body.slice(0, 120)}`);
      }
    }
    if (!violations.length) {
      violations.push(...contract.checkResponse({
        method: x.method, path: x.path, status: x.status, contentType, headers: x.response_headers, body,
      }));
    }
    const op = `${x.method.toUpperCase()} ${contract.template(x.path) ?? '(unmatched route)'} ${x.status}`;
    perOperation.set(op, (perOperation.get(op) ?? 0) + 1);
    if (violations.length) failures.push({ where: `${x.test ?? '?'}: ${x.method} ${x.path} -> ${x.status}`, violations });
  });
  for (const f of failures.slice(0, 50)) {
    console.log(`VIOLATION ${f.where}`);
    for (const v of f.violations.slice(0, 10)) console.log(`    ${v}`);
  }
  if (process.env.CONTRACT_CHECK_VERBOSE === '1') {
    for (const [op, n] of [...perOperation].sort()) console.log(`  ${String(n).padStart(6)}  ${op}`);
  }
  console.log(`contract check: ${lines.length} exchanges checked against ${path.basename(openapi)} ` +
    `(${perOperation.size} method/path/status combinations), ${failures.length} with violations`);
  process.exit(failures.length ? 1 : 0);
}

function serve(openapi, lazy) {
  let contract;
  try {
    contract = new Contract(openapi, { compileAll: !lazy });
  } catch (e) {
    process.stdout.write(JSON.stringify({ error: e.message }) + '\n');
    process.exit(0);
  }
  process.stdout.write('{"ready":true}\n');
  const rl = readline.createInterface({ input: process.stdin, crlfDelay: Infinity });
  rl.on('line', line => {
    let answer;
    try {
      const q = JSON.parse(line);
      let violations;
      if (q.op === 'response') {
        violations = contract.checkResponse({ method: q.method, path: q.path, status: q.status, contentType: q.content_type, body: q.body });
      } else if (q.op === 'request') {
        violations = contract.checkRequest(q.method, q.path, q.body);
      } else if (q.op === 'headers') {
        violations = contract.checkResponseHeaders(q.method, q.path, q.status, q.headers);
      } else if (q.op === 'schema') {
        violations = contract.checkSchema(q.ref, q.value);
      } else {
        throw new Error(`unknown op ${q.op}`);
      }
      answer = { violations };
    } catch (e) {
      answer = { error: e.message };
    }
    process.stdout.write(JSON.stringify(answer) + '\n');
  });
}

const [mode, ...args] = process.argv.slice(2);
if (mode === 'clear' && args.length === 1) {
  mkdirSync(path.dirname(args[0]), { recursive: true });
  writeFileSync(args[0], '');
  closeSync(openSync(args[0], 'r'));
  console.log(`contract check: cleared ${args[0]}`);
} else if (mode === 'exchanges' && args.length === 2) {
  try {
    checkExchanges(args[0], args[1]);
  } catch (e) {
    die(e.message);
  }
} else if (mode === 'serve' && args.length === 1) {
  serve(args[0], false);
} else if (mode === 'serve' && args.length === 2 && args[0] === '--lazy') {
  serve(args[1], true);
} else {
  die('usage: check.mjs clear <log> | exchanges <openapi.yaml> <log> | serve [--lazy] <openapi.yaml>');
}
