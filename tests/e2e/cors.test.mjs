// CORS the way a browser front end meets it. Two small pages on loopback origins of their own (node
// http servers started here) and a cutcalc started here with `--cors-origin` naming the first one.
// From the allowed page, Chromium's fetch of every POST endpoint (the paths with a `post` operation
// in the openapi.yaml the service serves) with a JSON body (the endpoint's first 200 reference case)
// is preflighted (the service logs the OPTIONS) and answered: 200, the same JSON as the service
// gives the same request from here, and X-Request-Id readable by the script. From the other page the
// fetch is refused (TypeError), Chromium logs the CORS error, and the request never reaches the
// service.
//
// Environment:
//   CUTCALC_BIN             the cutcalc binary (default build/release/service/cutcalc in the repo)
//   CUTCALC_REFERENCE_DIR   reference cases (default ../shared/reference, relative to the repo)
//   CHROMIUM_PATH           the browser (default /usr/bin/chromium; never downloaded)
import { after, before, test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { readdirSync } from 'node:fs';
import http from 'node:http';
import path from 'node:path';

import { REFERENCE_DIR, env, chromiumForThisFile, reference, referenceFiles, repo } from './browser.mjs';

const BIN = path.resolve(repo, env('CUTCALC_BIN', path.join('build', 'release', 'service', 'cutcalc')));
const TEST_MS = 120000;
const START_MS = 20000;

// A page server: any path answers an empty HTML page, so that the page's origin is this server's.
async function pageServer() {
  const server = http.createServer((req, res) => {
    res.writeHead(200, { 'content-type': 'text/html; charset=utf-8' });
    res.end('<!doctype html><html lang="en"><head><title>front end</title></head><body></body></html>');
  });
  await new Promise(resolve => server.listen(0, '127.0.0.1', resolve));
  return { server, origin: `http://127.0.0.1:${server.address().port}` };
}

// cutcalc on a free loopback port allowing `origin`; its log (one line per request) is kept.
async function startCutcalc(origin) {
  const child = spawn(BIN, ['--host', '127.0.0.1', '--port', '0', '--threads', '2', '--log-level', 'info',
    '--log-format', 'text', '--cors-origin', origin], { stdio: ['ignore', 'pipe', 'pipe'] });
  const service = { child, log: '' };
  const port = await new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`cutcalc did not listen within ${START_MS} ms:\n${service.log}`)), START_MS);
    const read = chunk => {
      service.log += chunk;
      const m = /listening on http:\/\/127\.0\.0\.1:(\d+)/.exec(service.log);
      if (m) {
        clearTimeout(timer);
        resolve(Number(m[1]));
      }
    };
    child.stdout.setEncoding('utf8').on('data', read);
    child.stderr.setEncoding('utf8').on('data', read);
    child.on('exit', code => reject(new Error(`cutcalc (${BIN}) exited with ${code} at start:\n${service.log}`)));
  });
  service.url = `http://127.0.0.1:${port}`;
  return service;
}

// The paths of openapi.yaml with a `post` operation (a path key at indent 2, its operations at 4).
function postPaths(yaml) {
  const paths = [];
  let current = null;
  for (const line of yaml.split('\n')) {
    const pathKey = /^ {2}(\/\S*):$/.exec(line);
    if (pathKey) current = pathKey[1];
    else if (/^\S/.test(line)) current = null;
    else if (current && line === '    post:') paths.push(current);
  }
  return paths;
}

// The request of each endpoint's first 200 reference case.
function referenceBodies() {
  const bodies = new Map();
  for (const file of referenceFiles()) {
    const doc = reference(file);
    const kase = doc.cases.find(c => c.expect?.status === 200);
    if (kase && !bodies.has(doc.endpoint)) bodies.set(doc.endpoint, { id: kase.id, request: kase.request });
  }
  return bodies;
}

// fetch() in the page: a JSON POST, preflighted (application/json is not a CORS-safelisted type).
const postFromPage = (page, url, body, requestId) =>
  page.evaluate(
    async ({ url, body, requestId }) => {
      try {
        const r = await fetch(url, {
          method: 'POST',
          headers: { 'content-type': 'application/json', 'x-request-id': requestId },
          body,
        });
        return { status: r.status, type: r.headers.get('content-type'), requestId: r.headers.get('x-request-id'), text: await r.text() };
      } catch (e) {
        return { error: e.name, message: e.message };
      }
    },
    { url, body, requestId },
  );

const browser = chromiumForThisFile();
let allowed;
let other;
let service;
before(async () => {
  allowed = await pageServer();
  other = await pageServer();
  service = await startCutcalc(allowed.origin);
});
after(async () => {
  service?.child.kill('SIGTERM');
  allowed?.server.close();
  other?.server.close();
});

async function openPage(origin) {
  const context = await browser().newContext();
  const page = await context.newPage();
  const consoleErrors = [];
  page.on('console', msg => {
    if (msg.type() === 'error') consoleErrors.push(msg.text());
  });
  page.on('pageerror', error => consoleErrors.push(`page error: ${error.message}`));
  const response = await page.goto(`${origin}/`);
  assert.equal(response?.status(), 200);
  return { context, page, consoleErrors };
}

// The service's access log lines for a method and path ("access OPTIONS "/v1/x" 204 ...").
const logged = (method, p) => service.log.split('\n').filter(l => l.includes(`access ${method} ${JSON.stringify(p)} `));

async function waitFor(condition, what) {
  const deadline = Date.now() + 5000;
  while (!condition()) {
    if (Date.now() > deadline) assert.fail(`${what}; cutcalc log:\n${service.log.slice(-3000)}`);
    await new Promise(r => setTimeout(r, 50));
  }
}

test('a page on the allowed origin calls every POST endpoint with fetch and gets its answer', { timeout: TEST_MS }, async () => {
  const endpoints = postPaths(await (await fetch(`${service.url}/openapi.yaml`)).text());
  assert.ok(endpoints.length >= 7, `openapi.yaml has only ${endpoints.length} POST paths: ${endpoints}`);
  const bodies = referenceBodies();
  const { context, page, consoleErrors } = await openPage(allowed.origin);
  try {
    for (const endpoint of endpoints) {
      const kase = bodies.get(endpoint);
      assert.ok(kase, `no 200 reference case for ${endpoint} in ${REFERENCE_DIR}`);
      const body = JSON.stringify(kase.request);
      const requestId = `cors-allowed-${endpoints.indexOf(endpoint)}`;
      const got = await postFromPage(page, `${service.url}${endpoint}`, body, requestId);
      assert.equal(got.error, undefined, `${endpoint} (${kase.id}): fetch from ${allowed.origin} failed: ${got.error}: ${got.message}; console: ${consoleErrors.join(" / ")}`);
      assert.equal(got.status, 200, `${endpoint} (${kase.id}): ${got.text?.slice(0, 300)}`);
      assert.equal(got.type, 'application/json', endpoint);
      assert.equal(got.requestId, requestId, `${endpoint}: X-Request-Id is not readable by the page`);
      const direct = await fetch(`${service.url}${endpoint}`, { method: 'POST', headers: { 'content-type': 'application/json' }, body });
      assert.equal(direct.status, 200, endpoint);
      assert.deepEqual(JSON.parse(got.text), await direct.json(), `${endpoint}: the page's answer differs from the direct one`);
      await waitFor(() => logged('OPTIONS', endpoint).some(l => / 204 /.test(l)), `no preflight OPTIONS ${endpoint} reached cutcalc`);
      console.log(`# ${endpoint}: ${kase.id} from ${allowed.origin}: preflight 204, POST 200`);
    }
    assert.deepEqual(consoleErrors, [], 'console errors on the allowed page');
  } finally {
    await context.close();
  }
});

test('a page on an origin not allowed is refused', { timeout: TEST_MS }, async () => {
  const endpoint = postPaths(await (await fetch(`${service.url}/openapi.yaml`)).text())[0];
  const { request } = referenceBodies().get(endpoint);
  const { context, page, consoleErrors } = await openPage(other.origin);
  try {
    const got = await postFromPage(page, `${service.url}${endpoint}`, JSON.stringify(request), 'cors-refused');
    assert.equal(got.error, 'TypeError', `fetch from ${other.origin} was not refused: ${JSON.stringify(got).slice(0, 300)}`);
    // Chromium says why: the preflight answer has no Access-Control-Allow-Origin.
    await waitFor(() => consoleErrors.some(e => /blocked by CORS policy/.test(e)), `no CORS error in the console: ${consoleErrors}`);
    assert.ok(consoleErrors.every(e => /CORS|Failed to load resource|Failed to fetch/.test(e)), `other console errors: ${consoleErrors}`);
    assert.ok(!service.log.includes('request_id=cors-refused'), 'the refused POST reached cutcalc');
    console.log(`# ${endpoint} from ${other.origin}: refused (${got.message}); console: ${consoleErrors[0].slice(0, 160)}`);
  } finally {
    await context.close();
  }
});
