// The calculation route table (api/routes.cpp) for the Node.js tools and tests: the reference
// replay, the generated reference client and the browser tests read it from `cutcalc --routes`
// (api/route_table_json.h), never from a list of their own. No packages: plain Node.js.
//
// Where the table comes from, first match:
//   a file:  `routesFile`, else CUTCALC_ROUTES_FILE (what `cutcalc --routes` printed; ci-container
//            takes it from the image);
//   a binary: `bin`, else CUTCALC_BIN, else <repo>/build/release/service/cutcalc, run with --routes.
import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');

export function loadRoutes({ routesFile, bin } = {}) {
  const file = routesFile || process.env.CUTCALC_ROUTES_FILE;
  if (file) return JSON.parse(readFileSync(file, 'utf8'));
  const binary = bin || process.env.CUTCALC_BIN || path.join(repo, 'build', 'release', 'service', 'cutcalc');
  if (!existsSync(binary)) {
    throw new Error(`no route table: give CUTCALC_ROUTES_FILE or a cutcalc binary (${binary} does not exist)`);
  }
  return JSON.parse(execFileSync(binary, ['--routes'], { encoding: 'utf8' }));
}

// The reference files every consumer replays: <referenceDir>/*.json plus the next/ files the
// routes list (cases of the same or a new endpoint that joined once the service answers them),
// relative to referenceDir, sorted.
export function replayedReferenceFiles(referenceDir, routes) {
  const files = new Set(readdirSync(referenceDir).filter(f => f.endsWith('.json')));
  for (const route of routes) {
    for (const file of route.next_reference_files) files.add(file);
  }
  return [...files].sort();
}

// The page sections of the web calculator in route order, each once (routes without a page left
// out): the sections the browser tests walk.
export function pageSections(routes) {
  return [...new Set(routes.map(r => r.page_section).filter(Boolean))];
}
