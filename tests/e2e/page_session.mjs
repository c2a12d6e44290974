// What the page tests (shop_tool, language_units, print_sheet) share: the running cutcalc, where
// artifacts go, how long to wait for the page's requests, a page that records them, and the two
// checks every one of them runs on a page (print_sheet opens its page itself: it stubs printing).
import assert from 'node:assert/strict';
import path from 'node:path';

import { env, repo } from './browser.mjs';

export const API = (env('CUTCALC_URL') ?? '').replace(/\/$/, '');
if (!API) throw new Error('CUTCALC_URL is not set (the base URL of a running cutcalc)');
export const PAGE_URL = env('E2E_PAGE_URL', `${API}/`);
export const ARTIFACT_DIR = path.resolve(repo, env('E2E_ARTIFACT_DIR', path.join('build', 'e2e')));
export const WAIT_MS = 20000;
export const TEST_MS = 120000;
// Longer than the page's pause before it recalculates (calculation.js PAUSE_MS, 600 ms): a page
// this long without a request has nothing left to send.
export const QUIET_MS = 1200;

// Waits until no request is in flight and none has started for QUIET_MS, counting from now at
// the earliest (the request of a key press just made may not have been reported yet), then for the
// answers a test's log records (log.exchanges[].done), if it records them.
export async function settle(log) {
  log.lastActivity = Math.max(log.lastActivity, Date.now());
  const deadline = Date.now() + WAIT_MS;
  while (log.inFlight > 0 || Date.now() - log.lastActivity < QUIET_MS) {
    assert.ok(Date.now() < deadline, `the page's requests did not settle within ${WAIT_MS} ms`);
    await new Promise(resolve => setTimeout(resolve, 50));
  }
  await Promise.all((log.exchanges ?? []).map(e => e.done));
}

// No console error, page error, failed request, HTTP error or CSP violation on the page.
export async function assertClean(page, log, label) {
  const csp = await page.evaluate(() => window.__cspViolations ?? []);
  assert.deepEqual([...log.problems, ...csp.map(v => `CSP violation: ${v}`)], [], `${label}: trouble on the page`);
}

// Opens `url` in a new context of `browser` and records every API exchange, in the order the
// requests were sent (path, url, body, request headers; once answered: status, Content-Language,
// text, json), and every sign of trouble: console and page errors, failed requests, HTTP errors
// (except while log.expectProblems is set, for answers a test asks for on purpose) and CSP
// violations (read by assertClean). `clipboard`: the page may read and write the clipboard.
export async function openRecordedPage(browser, url, { viewport = { width: 1280, height: 900 }, clipboard = false } = {}) {
  const context = await browser.newContext({ viewport, acceptDownloads: true });
  if (clipboard) await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: new URL(API).origin });
  const page = await context.newPage();
  page.setDefaultTimeout(WAIT_MS);
  const log = { exchanges: [], problems: [], inFlight: 0, lastActivity: Date.now(), expectProblems: false };
  await page.addInitScript(() => {
    window.__cspViolations = [];
    document.addEventListener('securitypolicyviolation', e =>
      window.__cspViolations.push(`${e.violatedDirective} ${e.blockedURI}`),
    );
  });
  page.on('console', msg => {
    if (msg.type() === 'error') log.problems.push(`console error: ${msg.text()}`);
  });
  page.on('pageerror', error => log.problems.push(`page error: ${error.message}`));
  page.on('request', request => {
    log.inFlight += 1;
    log.lastActivity = Date.now();
    const u = new URL(request.url());
    if (request.method() === 'POST' && u.pathname.startsWith('/v1/')) {
      const entry = { path: u.pathname, url: request.url(), body: request.postData() ?? '', headers: request.headers(), status: 0, json: null };
      entry.done = request
        .response()
        .then(async response => {
          entry.status = response?.status() ?? 0;
          entry.language = response?.headers()['content-language'];
          entry.text = (await response?.text()) ?? '';
          try {
            entry.json = JSON.parse(entry.text);
          } catch {
            entry.json = null;
          }
        })
        .catch(() => {});
      log.exchanges.push(entry);
    }
  });
  const finished = () => {
    log.inFlight -= 1;
    log.lastActivity = Date.now();
  };
  page.on('requestfinished', finished);
  page.on('requestfailed', request => {
    finished();
    log.problems.push(`request failed: ${request.method()} ${request.url()}: ${request.failure()?.errorText}`);
  });
  page.on('response', response => {
    if (response.status() >= 400 && !log.expectProblems) {
      log.problems.push(`HTTP ${response.status()} for ${response.request().method()} ${response.url()}`);
    }
  });
  const response = await page.goto(url, { waitUntil: 'load' });
  assert.equal(response?.status(), 200, `GET ${url}`);
  return { context, page, log };
}
