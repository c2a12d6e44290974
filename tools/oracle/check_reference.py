#!/usr/bin/python3
"""Re-times the cases of a reference file with the oracle and compares with their info.sim_time_s.

    /usr/bin/python3 tools/oracle/check_reference.py [FILE] [--tolerance-ms 3]

FILE defaults to ../shared/reference/next/program-time.json (beside the work tree, or /work/shared).
Every case with status 200 and info.sim_time_s is timed once on its request's machine. Fanuc and
Sinumerik cases are timed as the LinuxCNC program with the same motion (the estimate follows
LinuxCNC's meaning of the mode in every dialect, domain/machine-time.md section 3): their exact-stop
words (Fanuc G61, Sinumerik G60) become G61.1, Sinumerik's G71 becomes G21, program delimiters,
O-numbers and ';' comments are dropped. Prints one line per case and exits 1 if any differs by more
than the tolerance.
"""
import argparse
import json
import os
import re
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.dont_write_bytecode = True  # no __pycache__ in the work tree
sys.path.insert(0, HERE)
import time_program  # noqa: E402


def default_file():
    for base in (os.path.join(HERE, "..", "..", "..", "shared"), "/work/shared"):
        path = os.path.join(base, "reference", "next", "program-time.json")
        if os.path.exists(path):
            return os.path.abspath(path)
    return "program-time.json"


def as_linuxcnc(program, dialect):
    if dialect == "linuxcnc":
        return program
    lines = []
    for line in program.splitlines():
        line = line.split(";", 1)[0].strip()
        if not line or line == "%" or re.match(r"^O\d+", line):
            continue
        words = line.split()
        if dialect == "fanuc":
            words = ["G61.1" if w == "G61" else w for w in words]
        elif dialect == "sinumerik":
            words = ["G61.1" if w == "G60" else "G21" if w == "G71" else w for w in words]
        else:
            raise ValueError(f"unknown dialect {dialect}")
        lines.append(" ".join(words))
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("file", nargs="?", default=default_file())
    parser.add_argument("--tolerance-ms", type=float, default=3.0)
    args = parser.parse_args()
    doc = json.load(open(args.file))
    bad = 0
    count = 0
    for case in doc["cases"]:
        want = (case.get("info") or {}).get("sim_time_s")
        if case.get("expect", {}).get("status") != 200 or want is None:
            continue
        request = case["request"]
        program = as_linuxcnc(request["program"], request.get("dialect", "linuxcnc"))
        t0 = time.monotonic()
        try:
            got = time_program.run_program(program, request["machine"])
        except time_program.OracleError as e:
            print(f"{case['id']:34s} FAILED: {e}")
            bad += 1
            continue
        diff_ms = (got - want) * 1000.0
        ok = abs(diff_ms) <= args.tolerance_ms + 1e-6
        bad += 0 if ok else 1
        count += 1
        print(f"{case['id']:34s} expected {want:.3f} s  oracle {got:.3f} s  {diff_ms:+.0f} ms  "
              f"{'ok' if ok else 'DIFFERS'}  (wall {time.monotonic() - t0:.1f} s)", flush=True)
    print(f"{count - bad} of {count} within {args.tolerance_ms:g} ms")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
