// Reference cases whose request contradicts the specification they cite, replayed with the request
// corrected so that their expected values (computed independently by the case's generator) still
// check the service. Plain Node.js, read by replay.mjs (ctest's ReferenceReplay, the contract and the
// container steps). THIS LIST IS MEANT TO BE EMPTIED when ../shared corrects the case, not extended:
// an entry whose case is gone, or whose request already holds the correction, stops the replay as
// STALE. Each entry: `file` (relative to the reference directory), `id`, `request` (members merged
// into the case's request, objects recursively) and `why`.
export const REFERENCE_CORRECTIONS = [
  {
    file: 'next/polygon-hole.json',
    id: 'nx-square-a16-fanuc',
    request: { program: { decimals: 4 } },
    why:
      'programs.md section 4: the printed loop length L_p (P23) uses the dialect\'s `decimals`, 3 for ' +
      'fanuc in mm (section 2), and section 13 keeps loop_length_mm as it is; the case\'s expected ' +
      'loop_length_mm 8.00822093506 and the times from it are those of 4 decimals (8.0085992 at 3)',
  },
];

function isObject(v) {
  return v !== null && typeof v === 'object' && !Array.isArray(v);
}

function merged(base, patch) {
  const out = { ...base };
  for (const [k, v] of Object.entries(patch)) out[k] = isObject(v) && isObject(base[k]) ? merged(base[k], v) : v;
  return out;
}

function holds(request, patch) {
  return Object.entries(patch).every(([k, v]) =>
    isObject(v) ? isObject(request?.[k]) && holds(request[k], v) : JSON.stringify(request?.[k]) === JSON.stringify(v));
}

// The cases of one reference file with their corrections applied; `stale` receives a message per
// entry of this file that no longer applies.
export function correctedCases(file, cases, stale) {
  const entries = REFERENCE_CORRECTIONS.filter(e => e.file === file);
  for (const e of entries) {
    const c = cases.find(x => x.id === e.id);
    if (!c) stale(`${file}:${e.id} is not a case of the file any more`);
    else if (holds(c.request, e.request)) stale(`${file}:${e.id} already asks ${JSON.stringify(e.request)}`);
  }
  return cases.map(c => {
    const e = entries.find(x => x.id === c.id);
    return e ? { ...c, request: merged(c.request, e.request), correction: e.why } : c;
  });
}
