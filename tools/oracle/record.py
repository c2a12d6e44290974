#!/usr/bin/python3
"""Times the oracle's programs with LinuxCNC and writes tests/oracle/linuxcnc-times.json.

    /usr/bin/python3 tools/oracle/record.py [--only ID ...] [--runs 2] [--out FILE]

Reads tests/oracle/programs/manifest.json (profiles; each case's id, profile, category, about) and
<id>.ngc beside it, times every program --runs times (default 2), one simulation at a time, with
time_program.run_program, and writes the cases in the manifest's order. With --only, only those ids
are re-timed and the other cases are kept from the existing output file. A case whose runs differ by
more than 1 ms gets --extra-runs more runs (default 3), is flagged in the output ("runs_differ":
true) and on stderr; its sim_time_s is the median run (the first run's lower median when even).
"""
import argparse
import datetime
import json
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.dont_write_bytecode = True  # no __pycache__ in the work tree
sys.path.insert(0, HERE)
import time_program  # noqa: E402

PROGRAMS = os.path.join(ROOT, "tests", "oracle", "programs")
OUT = os.path.join(ROOT, "tests", "oracle", "linuxcnc-times.json")
CATEGORIES = ("single", "g61.1", "g61", "g64", "g64p")


def linuxcnc_version():
    try:
        out = subprocess.run(["dpkg-query", "-W", "-f=${Version}", "linuxcnc-uspace"], capture_output=True,
                             text=True, timeout=10)
        return out.stdout.strip() or "unknown"
    except (OSError, subprocess.SubprocessError):
        return "unknown"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--only", nargs="*", help="re-time these ids only, keep the others")
    parser.add_argument("--runs", type=int, default=2)
    parser.add_argument("--extra-runs", type=int, default=3,
                        help="more runs for a case whose first runs differ by more than 1 ms")
    parser.add_argument("--out", default=OUT)
    parser.add_argument("--verbose", "-v", action="store_true")
    args = parser.parse_args()

    manifest = json.load(open(os.path.join(PROGRAMS, "manifest.json")))
    profiles = manifest["profiles"]
    old = {}
    if os.path.exists(args.out):
        old = {c["id"]: c for c in json.load(open(args.out))["cases"]}
    only = set(args.only or [])
    unknown = only - {c["id"] for c in manifest["cases"]}
    if unknown:
        sys.exit(f"record: not in the manifest: {sorted(unknown)}")

    cases = []
    flagged = []
    failures = []
    started = time.monotonic()
    for entry in manifest["cases"]:
        cid = entry["id"]
        if entry["category"] not in CATEGORIES:
            sys.exit(f"record: {cid}: unknown category {entry['category']}")
        if entry["profile"] not in profiles:
            sys.exit(f"record: {cid}: unknown profile {entry['profile']}")
        with open(os.path.join(PROGRAMS, cid + ".ngc")) as f:
            program = f.read()
        if only and cid not in only:
            if cid not in old:
                sys.exit(f"record: {cid} has no recorded time to keep; re-time it too")
            if old[cid]["program"] != program:
                sys.exit(f"record: {cid}: the program changed since it was recorded; re-time it")
            cases.append(old[cid])
            continue
        runs = []
        # a case known not to repeat (manifest "unstable") gets the extra runs at once
        planned = args.runs + (args.extra_runs if entry.get("unstable") else 0)
        while len(runs) < planned:
            t0 = time.monotonic()
            try:
                seconds = time_program.run_program(program, profiles[entry["profile"]], verbose=args.verbose)
            except time_program.OracleError as e:
                print(f"  ** {cid}: FAILED: {e}", file=sys.stderr, flush=True)
                failures.append(cid)
                break
            runs.append(round(seconds, 3))
            print(f"{cid:36s} {entry['profile']:17s} {entry['category']:6s} {seconds:8.3f} s "
                  f"(wall {time.monotonic() - t0:.1f} s)", flush=True)
            if len(runs) == args.runs and max(runs) - min(runs) > 0.0015:
                planned = args.runs + args.extra_runs  # show the spread of a case that does not repeat
        if len(runs) < planned:
            if cid in old and old[cid]["program"] == program:
                cases.append(old[cid])  # keep the earlier record of a case that failed now
            continue
        record = {"id": cid, "about": entry["about"], "category": entry["category"],
                  "profile": entry["profile"], "dialect": "linuxcnc", "program": program,
                  "sim_time_s": sorted(runs)[(len(runs) - 1) // 2], "runs": runs}
        if entry.get("note"):
            record["note"] = entry["note"]
        if max(runs) - min(runs) > 0.0015:
            record["runs_differ"] = True
            flagged.append(cid)
            print(f"  ** {cid}: runs differ: {runs}", file=sys.stderr, flush=True)
        cases.append(record)

    doc = {
        "about": ("Programs timed by LinuxCNC's own trajectory planner (linuxcnc-uspace "
                  f"{linuxcnc_version()}, Debian 12), run headless in simulation by "
                  "tools/oracle/time_program.py: sim_time_s is the simulated time in servo periods from "
                  "the first period in which motion is not in position to the period in which it is back "
                  "in position after the last move (dwells between moves included, nothing after the last "
                  "move). Each program was run len(runs) times (two; five where the first two differ by more than "
                  "1 ms, flagged runs_differ) and sim_time_s is the median run (the lower of the middle two "
                  "for an even count). Recorded "
                  f"{datetime.date.today().isoformat()} by tools/oracle/record.py from "
                  "tests/oracle/programs/ (manifest.json, <id>.ngc). category: single = one move alone, "
                  "g61.1 exact stop, g61 exact path, g64 blend without P, g64p blend with P (a program "
                  "mixing modes takes the loosest)."),
        "profiles": profiles,
        "cases": cases,
    }
    with open(args.out, "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")
    print(f"{len(cases)} cases in {args.out} ({time.monotonic() - started:.0f} s)"
          + (f"; runs differ: {', '.join(flagged)}" if flagged else "")
          + (f"; FAILED: {', '.join(failures)}" if failures else ""))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
