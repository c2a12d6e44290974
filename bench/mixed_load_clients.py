#!/usr/bin/python3
"""Clients of bench/mixed_load.sh (the Python standard library only). Each prints one JSON line.

check PORT PATH ACCEPT BODY
    POSTs BODY once (Content-Type: application/json, the given Accept) and prints its status,
    Content-Type, size and time; exit status 1 unless 200. If BODY has a loops_per_layer, it also
    POSTs it with one loop more and prints that status: 422 says BODY is at the program size limit.
heavy PORT PATH ACCEPT BODY SECONDS
    One keep-alive connection POSTing BODY in a loop for SECONDS (the request in flight then is
    finished), reading every answer whole. A 503 is a valid answer of a full pool: counted apart,
    and its Retry-After honoured up to 1 s before the next request, as a well-behaved client does.
    Other statuses and socket errors are counted too (after one, a new connection).
probe PORT SECONDS INTERVAL_MS
    GET /healthz on a fresh connection every INTERVAL_MS for SECONDS (a Kubernetes probe's way);
    the latency of one probe is connect + request + whole answer; a probe failing or taking over
    5 s counts as failed (with the time it took).
"""
import http.client
import json
import math
import socket
import sys
import time

PROBE_TIMEOUT_S = 5.0
HEAVY_TIMEOUT_S = 120.0
MAX_RETRY_AFTER_S = 1.0


def post(conn, path, accept, body):
    conn.request("POST", path, body=body, headers={"Content-Type": "application/json", "Accept": accept})
    resp = conn.getresponse()
    data = resp.read()
    return resp, data


def check(port, path, accept, body):
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=HEAVY_TIMEOUT_S)
    start = time.perf_counter()
    resp, data = post(conn, path, accept, body.encode())
    elapsed_ms = (time.perf_counter() - start) * 1000.0
    out = {"status": resp.status, "content_type": resp.getheader("Content-Type"), "bytes": len(data),
           "ms": round(elapsed_ms, 1)}
    if resp.status != 200:
        out["answer"] = data[:400].decode("utf-8", "replace")
    request = json.loads(body)
    if isinstance(request.get("loops_per_layer"), int):
        request["loops_per_layer"] += 1
        more, _ = post(conn, path, accept, json.dumps(request).encode())
        out["one_loop_more_status"] = more.status
    conn.close()
    print(json.dumps(out))
    return 0 if resp.status == 200 else 1


def heavy(port, path, accept, body, seconds):
    body = body.encode()
    counts = {"ok": 0, "s503": 0, "other": 0, "errors": 0, "bytes": 0}
    start = time.monotonic()
    end = start + seconds
    conn = None
    while time.monotonic() < end:
        if conn is None:
            conn = http.client.HTTPConnection("127.0.0.1", port, timeout=HEAVY_TIMEOUT_S)
        try:
            resp, data = post(conn, path, accept, body)
        except (OSError, http.client.HTTPException):
            counts["errors"] += 1
            conn.close()
            conn = None
            time.sleep(0.05)
            continue
        counts["bytes"] += len(data)
        if resp.status == 200:
            counts["ok"] += 1
        elif resp.status == 503:
            counts["s503"] += 1
            try:
                wait = float(resp.getheader("Retry-After", "0"))
            except ValueError:
                wait = 0.0
            time.sleep(min(max(wait, 0.0), MAX_RETRY_AFTER_S, max(end - time.monotonic(), 0.0)))
        else:
            counts["other"] += 1
        if resp.will_close:
            conn.close()
            conn = None
    if conn is not None:
        conn.close()
    counts["seconds"] = round(time.monotonic() - start, 3)
    print(json.dumps(counts))
    return 0


def probe_once(port):
    """One GET /healthz on a new connection: (ok, seconds)."""
    start = time.perf_counter()
    ok = False
    try:
        with socket.create_connection(("127.0.0.1", port), timeout=PROBE_TIMEOUT_S) as sock:
            sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
            sock.sendall(b"GET /healthz HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")
            data = b""
            need = None  # bytes of head + body once the head is in
            while need is None or len(data) < need:
                if time.perf_counter() - start > PROBE_TIMEOUT_S:
                    raise TimeoutError
                chunk = sock.recv(65536)
                if not chunk:
                    break
                data += chunk
                if need is None and b"\r\n\r\n" in data:
                    head = data.split(b"\r\n\r\n", 1)[0]
                    length = 0
                    for line in head.split(b"\r\n")[1:]:
                        name, _, value = line.partition(b":")
                        if name.strip().lower() == b"content-length":
                            length = int(value.strip())
                    need = len(head) + 4 + length
            ok = data.startswith((b"HTTP/1.1 200", b"HTTP/1.0 200")) and need is not None and len(data) >= need
    except (OSError, ValueError):
        ok = False
    return ok, time.perf_counter() - start


def percentile(sorted_values, p):
    """Nearest-rank percentile (as wrk reports)."""
    if not sorted_values:
        return float("nan")
    rank = max(1, math.ceil(p / 100.0 * len(sorted_values)))
    return sorted_values[rank - 1]


def probe(port, seconds, interval_ms):
    interval = interval_ms / 1000.0
    start = time.monotonic()
    end = start + seconds
    latencies = []
    failed = 0
    tick = start
    while tick < end:
        ok, elapsed = probe_once(port)
        latencies.append(elapsed * 1000.0)
        failed += not ok
        tick += interval
        now = time.monotonic()
        if tick < now:  # a slow probe: the next one now, not a burst of missed ones
            tick = now
        time.sleep(max(tick - now, 0.0))
    latencies.sort()
    print(json.dumps({"count": len(latencies), "failed": failed,
                      "p50_ms": round(percentile(latencies, 50), 3),
                      "p99_ms": round(percentile(latencies, 99), 3),
                      "max_ms": round(latencies[-1], 3) if latencies else None}))
    return 0


def main(argv):
    try:
        if argv[1] == "check" and len(argv) == 6:
            return check(int(argv[2]), argv[3], argv[4], argv[5])
        if argv[1] == "heavy" and len(argv) == 7:
            return heavy(int(argv[2]), argv[3], argv[4], argv[5], float(argv[6]))
        if argv[1] == "probe" and len(argv) == 5:
            return probe(int(argv[2]), float(argv[3]), float(argv[4]))
    except IndexError:
        pass
    sys.stderr.write(__doc__)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
