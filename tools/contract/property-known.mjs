// Findings of the property step (property.mjs) on main that are known and being fixed: printed as
// KNOWN, they do not fail the run, so that the step can run in CI meanwhile. THIS LIST IS MEANT TO
// BE EMPTIED (one entry per fix), not extended. Each entry matches a finding's signature
// "path | rule | where | status [| problem type] [| named codes]": `path` ('*' for any operation),
// `rule` (a regular expression for the whole rule name) and `match` (a regular expression on the
// whole signature). An entry that no finding matches any more is printed as STALE: remove it.
export const KNOWN_FINDINGS = [
  // (2) /v1/main-time/program `extra_path_mm` (schema maximum 0) > 0 is answered as
  // impossible-input (program_needs_straight_path) after the other checks, not as a field error.
  { about: 'main-time/program extra_path_mm > 0 is impossible-input, not a field error', path: '/v1/main-time/program',
    rule: 'fault_answered_impossible|fault_not_named', match: '(above_maximum|past_bound)@/extra_path_mm' },
  // (4) errors[] pointers naming members the request does not have (exit_width_mismatch at
  // /exit/width_mm for an exit arc without width_mm; not_above at /program/clearance_mm when only
  // safe_z_mm was given).
  { about: 'pointer to an absent member: /exit/width_mm', path: '*', rule: 'pointer_to_absent_member', match: '/exit/width_mm exit_width_mismatch' },
  { about: 'pointer to an absent member: /program/clearance_mm', path: '/v1/main-time/program', rule: 'pointer_to_absent_member', match: '/program/clearance_mm not_above' },
];
