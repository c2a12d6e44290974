// What every browser test shares: its environment, the repository, the reference cases and Debian's
// Chromium driven by playwright-core (tools/e2e; never a downloaded browser).
import { readFileSync } from 'node:fs';
import { after, before } from 'node:test';
import { createRequire } from 'node:module';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadRoutes, pageSections, replayedReferenceFiles } from '../../tools/routes/route_table.mjs';

export const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
// playwright-core lives in tools/e2e/node_modules (npm ci there); resolve it from that package.
const requireFromTools = createRequire(path.join(repo, 'tools', 'e2e', 'package.json'));
export const { chromium } = requireFromTools('playwright-core');

export const env = (name, fallback) => {
  const value = process.env[name];
  return value !== undefined && value !== '' ? value : fallback;
};
export const REFERENCE_DIR = path.resolve(repo, env('CUTCALC_REFERENCE_DIR', path.join('..', 'shared', 'reference')));
export const reference = name => JSON.parse(readFileSync(path.join(REFERENCE_DIR, name), 'utf8'));
// The calculation route table (`cutcalc --routes` of CUTCALC_BIN, tools/routes/route_table.mjs):
// the page's sections in order, and the reference files (reference/*.json plus the listed next/).
export const ROUTES = loadRoutes();
export const PAGE_SECTIONS = pageSections(ROUTES);
export const referenceFiles = () => replayedReferenceFiles(REFERENCE_DIR, ROUTES);
export const CHROMIUM = env('CHROMIUM_PATH', '/usr/bin/chromium');
export const CHROMIUM_ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking'];
// Debian's Chromium, headless: one per test file, launched before its tests and closed after
// them. Returns a getter (the browser exists once the file's tests start).
export function chromiumForThisFile() {
  let browser;
  before(async () => {
    browser = await chromium.launch({ executablePath: CHROMIUM, args: CHROMIUM_ARGS, timeout: 60000 });
  });
  after(async () => {
    await browser?.close();
  });
  return () => browser;
}
