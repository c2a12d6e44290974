#!/usr/bin/env python3
"""Connection-level probes for the HTTP front (loopback only, bounded in count and time).

  http_probe.py hold  PORT N [--fresh K] [--idle S]
                                          open N keep-alive connections, send one request on
                                          each and keep them open, idle (S seconds, default 0);
                                          then time K requests on fresh connections (each:
                                          connect, POST, full response)
  http_probe.py burst PORT N              N connections connect at the same instant and POST once;
                                          prints the spread of connect+response times

Prints one summary line per measurement. Used by bench/http_rootcause.sh.
"""
import socket
import sys
import threading
import time

BODY = b'{"cutter_diameter_mm": 20, "offset_mm": 0, "entry": {"contour": "straight", "width_mm": 60, "angle_deg": 90}}'
TIMEOUT_S = 15.0


def request_bytes(path="/v1/entry-length"):
    return (b"POST " + path.encode() + b" HTTP/1.1\r\nHost: 127.0.0.1\r\n"
            b"Content-Type: application/json\r\nContent-Length: " + str(len(BODY)).encode() +
            b"\r\n\r\n" + BODY)


def read_response(sock):
    data = b""
    while b"\r\n\r\n" not in data:
        chunk = sock.recv(65536)
        if not chunk:
            raise ConnectionError("closed before the response head")
        data += chunk
    head, _, rest = data.partition(b"\r\n\r\n")
    status = int(head.split(b" ", 2)[1])
    length = 0
    for line in head.split(b"\r\n")[1:]:
        name, _, value = line.partition(b":")
        if name.strip().lower() == b"content-length":
            length = int(value.strip())
    while len(rest) < length:
        chunk = sock.recv(65536)
        if not chunk:
            raise ConnectionError("closed in the body")
        rest += chunk
    return status


def one_request(port, sock=None):
    own = sock is None
    if own:
        sock = socket.create_connection(("127.0.0.1", port), timeout=TIMEOUT_S)
    try:
        sock.sendall(request_bytes())
        return read_response(sock)
    finally:
        if own:
            sock.close()


def summary(name, times_ms, failures):
    times_ms = sorted(times_ms)
    if not times_ms:
        print(f"{name}: all {failures} failed")
        return
    def pct(p):
        return times_ms[min(len(times_ms) - 1, int(p / 100.0 * len(times_ms)))]
    slow = sum(1 for t in times_ms if t >= 900)
    print(f"{name}: n={len(times_ms)} failed={failures} min={times_ms[0]:.1f}ms "
          f"p50={pct(50):.1f}ms p99={pct(99):.1f}ms max={times_ms[-1]:.1f}ms >=900ms:{slow}")


def hold(port, n, fresh, idle_s):
    held = []
    try:
        for _ in range(n):
            s = socket.create_connection(("127.0.0.1", port), timeout=TIMEOUT_S)
            held.append(s)
        # One request on each, all in flight together (the server may serve only some at once).
        for s in held:
            s.sendall(request_bytes())
        for s in held:
            read_response(s)
        print(f"hold: {n} keep-alive connections open and idle", flush=True)
        time.sleep(idle_s)
        times, failures = [], 0
        for _ in range(fresh):
            start = time.monotonic()
            try:
                one_request(port)
                times.append((time.monotonic() - start) * 1000)
            except OSError:
                failures += 1
        summary(f"fresh request with {n} idle keep-alive connections", times, failures)
    finally:
        for s in held:
            s.close()


def burst(port, n):
    barrier = threading.Barrier(n)
    times, failures = [], []
    lock = threading.Lock()

    def run():
        barrier.wait()
        start = time.monotonic()
        try:
            one_request(port)
            with lock:
                times.append((time.monotonic() - start) * 1000)
        except OSError:
            with lock:
                failures.append(1)

    threads = [threading.Thread(target=run) for _ in range(n)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    summary(f"burst of {n} connections", times, len(failures))


def main(argv):
    if len(argv) < 4 or argv[1] not in ("hold", "burst"):
        print(__doc__, file=sys.stderr)
        return 2
    port, n = int(argv[2]), int(argv[3])
    if not 1 <= n <= 1000:
        print("N must be 1..1000", file=sys.stderr)
        return 2
    if argv[1] == "hold":
        opts = dict(zip(argv[4::2], argv[5::2]))
        fresh = int(opts.get("--fresh", 5))
        idle_s = min(float(opts.get("--idle", 0)), 60.0)
        hold(port, n, fresh, idle_s)
    else:
        burst(port, n)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
