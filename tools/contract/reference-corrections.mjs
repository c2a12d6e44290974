// tests/reference-corrections.json for the Node.js consumers of the reference cases: each listed
// case's request with its merge patch (RFC 7396) applied, and the entries that no longer apply.
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const CORRECTIONS = JSON.parse(readFileSync(path.join(repo, 'tests', 'reference-corrections.json'), 'utf8')).corrections;

function isObject(v) {
  return v !== null && typeof v === 'object' && !Array.isArray(v);
}

// RFC 7396.
function mergePatch(target, patch) {
  if (!isObject(patch)) return patch;
  const out = isObject(target) ? { ...target } : {};
  for (const [k, v] of Object.entries(patch)) {
    if (v === null) delete out[k];
    else out[k] = mergePatch(out[k], v);
  }
  return out;
}

// The cases of one reference file with their corrections applied (`correction`: why); `stale`
// receives a message per entry of this file that no longer applies.
export function correctedCases(file, cases, stale) {
  const entries = CORRECTIONS.filter(e => e.file === file);
  for (const e of entries) {
    const c = cases.find(x => x.id === e.id);
    if (!c) stale(`${file}:${e.id} is not a case of the file any more`);
    else if (JSON.stringify(mergePatch(c.request, e.request)) === JSON.stringify(c.request)) {
      stale(`${file}:${e.id} already asks ${JSON.stringify(e.request)}`);
    }
  }
  return cases.map(c => {
    const e = entries.find(x => x.id === c.id);
    return e ? { ...c, request: mergePatch(c.request, e.request), correction: e.why } : c;
  });
}
