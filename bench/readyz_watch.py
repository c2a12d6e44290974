#!/usr/bin/python3
"""Readiness watcher for bench/restart_check.sh (issue 24): sends SIGTERM to a cutcalc process,
then polls its GET /readyz every --interval-ms on a fresh connection each time until the process
has exited (gone or a zombie), and prints what a health checker would have seen: one line
  WATCH {"saw_503_before_refused": true|false, "first_503_ms": .., "last_503_ms": .., ...}
(after a first line SIGTERM_AT_MS <epoch ms>) and one human-readable line of the phases, e.g.
  503 x40 0-1950 ms | refused x3 2000-2100 ms
A process still running after --limit-s gets SIGKILL (so that the caller's wait ends).

usage: readyz_watch.py PID PORT [--interval-ms 50] [--limit-s 60]
Outcomes of a probe: an HTTP status ("200", "503", ...), "refused" (connection refused: the
listener is closed), "timeout" (connected but no answer within 1 s: e.g. accepted by the kernel's
backlog but never served), "closed" (connection closed without an answer), "reset", "error".
"""
import argparse
import json
import os
import signal
import socket
import time


def alive(pid):
    try:
        with open(f"/proc/{pid}/stat") as f:
            stat = f.read()
    except (FileNotFoundError, ProcessLookupError):
        return False
    return stat.rsplit(")", 1)[1].split()[0] not in ("Z", "X")


def probe(port):
    try:
        s = socket.create_connection(("127.0.0.1", port), timeout=1.0)
    except ConnectionRefusedError:
        return "refused"
    except socket.timeout:
        return "timeout"
    except OSError:
        return "error"
    try:
        s.sendall(b"GET /readyz HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")
        data = b""
        while b"\r\n" not in data:
            chunk = s.recv(4096)
            if not chunk:
                break
            data += chunk
        if not data:
            return "closed"
        parts = data.split(b" ", 2)
        return parts[1].decode("ascii", "replace") if len(parts) > 1 else "error"
    except socket.timeout:
        return "timeout"
    except ConnectionResetError:
        return "reset"
    except OSError:
        return "error"
    finally:
        s.close()


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("pid", type=int)
    ap.add_argument("port", type=int)
    ap.add_argument("--interval-ms", type=float, default=50.0)
    ap.add_argument("--limit-s", type=float, default=60.0)
    args = ap.parse_args()

    interval = args.interval_ms / 1000.0
    t0 = time.monotonic()
    os.kill(args.pid, signal.SIGTERM)
    print(f"SIGTERM_AT_MS {int(time.time() * 1000)}", flush=True)  # wall clock, for the caller's stop time
    samples = []  # (ms since SIGTERM, outcome)
    tick = 0
    while alive(args.pid) and time.monotonic() - t0 < args.limit_s:
        samples.append((round((time.monotonic() - t0) * 1000), probe(args.port)))
        tick += 1
        delay = t0 + tick * interval - time.monotonic()
        if delay > 0:
            time.sleep(delay)
    exit_ms = round((time.monotonic() - t0) * 1000)
    killed = alive(args.pid)
    if killed:
        os.kill(args.pid, signal.SIGKILL)

    t503 = [t for t, o in samples if o == "503"]
    refused = [t for t, o in samples if o == "refused"]
    first_refused = refused[0] if refused else None
    saw = bool(t503) and (first_refused is None or t503[0] < first_refused)
    phases = []
    for t, o in samples:
        if phases and phases[-1][0] == o:
            phases[-1][2] = t
            phases[-1][3] += 1
        else:
            phases.append([o, t, t, 1])
    result = {
        "saw_503_before_refused": saw,
        # first to last 503 seen: 0 for a single 503 (the race at the instant of SIGTERM can give one)
        "phase_503_ms": (t503[-1] - t503[0]) if t503 else None,
        "first_503_ms": t503[0] if t503 else None,
        "last_503_ms": t503[-1] if t503 else None,
        "first_refused_ms": first_refused,
        "exit_seen_ms": exit_ms,
        "killed_after_limit": killed,
        "probes": len(samples),
        "outcomes": {o: sum(1 for _, x in samples if x == o) for o in sorted({x for _, x in samples})},
    }
    print("WATCH " + json.dumps(result, separators=(",", ":")))
    print(" | ".join(f"{o} x{n} {a}-{b} ms" for o, a, b, n in phases) or "(process gone before the first probe)")


if __name__ == "__main__":
    main()
