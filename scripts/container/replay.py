#!/usr/bin/python3
"""Replays the reference cases (/work/shared/reference/*.json style) against a running cutcalc.

Stdlib only (Debian's /usr/bin/python3). Used by scripts/ci-container.sh against the container:

  replay.py --base-url http://127.0.0.1:PORT --reference-dir ../shared/reference [--per-file N]

For every case it checks the HTTP status; for 200 every number/string in expect.body (within the
file's tolerance), expect.max / expect.min bounds, expect.warning_codes, and the cheap program
checks (z_min, loops); for 422 an application/problem+json body whose errors[] holds
expect.pointer. Checks it cannot do without extra tools (rs274) are skipped. --per-file N takes
the first N cases of each file, always including a 422 case when the file has one. Exits 1 on any
mismatch or when a reference file yields no case.
"""

import argparse
import glob
import json
import math
import os
import re
import sys
import urllib.error
import urllib.request


def post(base_url, path, payload, accept="application/json", timeout=30):
    req = urllib.request.Request(
        base_url + path,
        data=json.dumps(payload).encode(),
        headers={"Content-Type": "application/json", "Accept": accept},
        method="POST",
    )
    try:
        with urllib.request.urlopen(req, timeout=timeout) as resp:
            return resp.status, resp.headers.get("Content-Type", ""), resp.read()
    except urllib.error.HTTPError as err:
        return err.code, err.headers.get("Content-Type", ""), err.read()


class Tolerance:
    """The comparison rule written in the reference file's "compare" text."""

    def __init__(self, doc, case):
        self.tol = case.get("tolerance", {})
        self.additive = "tolerance.abs + tolerance.rel" in doc.get("compare", "")

    def ok(self, key, got, want):
        if "abs_mm" in self.tol or "abs_min" in self.tol:
            is_time = key.endswith("_time_min") or key == "main_time_min"
            limit = self.tol.get("abs_min" if is_time else "abs_mm", 0.0)
        else:
            abs_t, rel_t = self.tol.get("abs", 0.0), self.tol.get("rel", 0.0)
            limit = abs_t + rel_t * abs(want) if self.additive else max(abs_t, rel_t * abs(want))
        return math.isfinite(got) and abs(got - want) <= limit


def compare(want, got, tol, where, key, errors):
    if isinstance(want, bool) or want is None or isinstance(want, str):
        if got != want:
            errors.append(f"{where}: got {got!r}, want {want!r}")
    elif isinstance(want, (int, float)):
        if isinstance(got, bool) or not isinstance(got, (int, float)):
            errors.append(f"{where}: got {got!r}, want number {want!r}")
        elif not tol.ok(key, float(got), float(want)):
            errors.append(f"{where}: got {got!r}, want {want!r}")
    elif isinstance(want, list):
        if not isinstance(got, list) or len(got) != len(want):
            errors.append(f"{where}: got {got!r}, want list of {len(want)}")
        else:
            for i, (w, g) in enumerate(zip(want, got)):
                compare(w, g, tol, f"{where}/{i}", key, errors)
    elif isinstance(want, dict):
        if not isinstance(got, dict):
            errors.append(f"{where}: got {got!r}, want object")
        else:
            for k, w in want.items():
                if k not in got:
                    errors.append(f"{where}/{k}: missing")
                else:
                    compare(w, got[k], tol, f"{where}/{k}", k, errors)


def check_program(program, spec, body, errors):
    if not isinstance(program, str):
        errors.append("program: missing")
        return
    if "z_min" in spec:
        zs = [float(z) for z in re.findall(r"\bZ(-?\d+(?:\.\d+)?)", program)]
        if not zs or abs(min(zs) - float(spec["z_min"])) > 1e-9:
            errors.append(f"program z_min: got {min(zs) if zs else None}, want {spec['z_min']}")
    if "loops" in spec and body.get("blocks_per_loop"):
        arcs = len(re.findall(r"^\s*(?:N\d+\s+)?G0?[23]\b", program, flags=re.M))
        if arcs != spec["loops"] * body["blocks_per_loop"]:
            errors.append(
                f"program loops: {arcs} G2/G3 blocks, want {spec['loops']} x {body['blocks_per_loop']}"
            )


def run_case(base_url, doc, case):
    exp = case["expect"]
    status, ctype, raw = post(base_url, doc["endpoint"], case["request"])
    errors = []
    if status != exp["status"]:
        return [f"status {status}, want {exp['status']}: {raw[:200]!r}"]
    try:
        body = json.loads(raw)
    except ValueError:
        return [f"body is not JSON: {raw[:200]!r}"]
    if status == 422:
        if not ctype.startswith("application/problem+json"):
            errors.append(f"Content-Type {ctype!r}, want application/problem+json")
        pointers = [e.get("pointer") for e in body.get("errors", []) if isinstance(e, dict)]
        if "pointer" in exp and exp["pointer"] not in pointers:
            errors.append(f"errors[] pointers {pointers}, want {exp['pointer']!r}")
        return errors
    tol = Tolerance(doc, case)
    compare(exp.get("body", {}), body, tol, "", "", errors)
    for k, bound in exp.get("max", {}).items():
        if not isinstance(body.get(k), (int, float)) or body[k] > bound:
            errors.append(f"/{k}: got {body.get(k)!r}, want <= {bound}")
    for k, bound in exp.get("min", {}).items():
        if not isinstance(body.get(k), (int, float)) or body[k] < bound:
            errors.append(f"/{k}: got {body.get(k)!r}, want >= {bound}")
    if "warning_codes" in exp:
        got = sorted(w.get("code") for w in body.get("warnings", []))
        if got != sorted(exp["warning_codes"]):
            errors.append(f"warning codes {got}, want {sorted(exp['warning_codes'])}")
    if "program" in exp:
        check_program(body.get("program"), exp["program"], body, errors)
    return errors


def pick(cases, per_file):
    if per_file <= 0 or len(cases) <= per_file:
        return cases
    chosen = cases[:per_file]
    if not any(c["expect"]["status"] != 200 for c in chosen):
        bad = [c for c in cases if c["expect"]["status"] != 200]
        if bad:
            chosen[-1] = bad[0]
    return chosen


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--base-url", required=True)
    ap.add_argument("--reference-dir", required=True)
    ap.add_argument("--per-file", type=int, default=0, help="cases per file (0 = all)")
    args = ap.parse_args()

    files = sorted(glob.glob(os.path.join(args.reference_dir, "*.json")))
    if not files:
        print(f"replay: no reference files in {args.reference_dir}", file=sys.stderr)
        return 1
    total = failed = 0
    endpoints = set()
    for path in files:
        with open(path, encoding="utf-8") as fh:
            doc = json.load(fh)
        cases = pick(doc.get("cases", []), args.per_file)
        if not cases:
            print(f"FAIL {os.path.basename(path)}: no cases")
            failed += 1
            continue
        bad = 0
        for case in cases:
            errors = run_case(args.base_url, doc, case)
            total += 1
            if errors:
                bad += 1
                print(f"FAIL {doc['endpoint']} {case['id']}:")
                for e in errors[:10]:
                    print(f"    {e}")
        endpoints.add(doc["endpoint"])
        failed += bad
        print(f"  {doc['endpoint']:<28} {len(cases) - bad}/{len(cases)} cases ok")
    print(f"replay: {total - failed}/{total} cases ok over {len(endpoints)} endpoints")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
