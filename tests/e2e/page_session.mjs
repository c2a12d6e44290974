// What the page tests (shop_tool, language_units, print_sheet) share: the running cutcalc, where
// artifacts go, and how long to wait for the page's requests, plus the two checks every one of them
// runs on a page. Each test opens its page itself: they record different things about it.
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
