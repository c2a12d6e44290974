#!/usr/bin/python3
"""Memory under clients that ask for the largest program and do not read it (issue 31): starts
nothing itself; talks to a cutcalc on 127.0.0.1:PORT whose PID is given, and samples the server's
VmRSS / VmHWM (and memory.current of its cgroup v2, when readable) every 100 ms.

Scenarios (--scenario):
  never-read  N connections opened over --spread seconds, each sends the heavy request and never
              reads; meanwhile /healthz is asked every 100 ms on a separate connection
  slow-read   N connections each read the answer at --rate bytes/s
  ttfb        one client: time to the first byte and the whole answer (and its throughput)

Prints readable lines and one line
  MEMORY_RESULT {"scenario":..,"n":..,"rss_peak_kib":..,"hwm_kib":..,"cgroup_peak_bytes":..,
                 "statuses":{..},"healthz_ms":{"median":..,"max":..},...}

usage: memory_attack.py PID PORT [--scenario never-read|slow-read|ttfb] [--n 200] [--spread 10]
                        [--hold 15] [--rate 65536] [--body JSON] [--path P] [--accept A]
"""
import argparse
import json
import os
import select
import socket
import statistics
import threading
import time

HEAVY_BODY = ('{"faces":3,"inscribed_diameter_mm":1000000,"depth_mm":1,"step_down_mm":1,'
              '"spindle_speed_rpm":30,"tolerance_mm":0.0001,"loops_per_layer":62,'
              '"synchronization":"c_axis","program":{"dialect":"fanuc","decimals":6}}')


def status_kib(pid, key):
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith(key + ":"):
                    return int(line.split()[1])
    except OSError:
        return None
    return None


def cgroup_current(pid):
    try:
        with open(f"/proc/{pid}/cgroup") as f:
            path = f.read().strip().split("::", 1)[1]
        with open(f"/sys/fs/cgroup{path}/memory.current") as f:
            return int(f.read())
    except (OSError, IndexError, ValueError):
        return None


def request_bytes(path, body, accept):
    return (f"POST {path} HTTP/1.1\r\nHost: bench\r\nContent-Type: application/json\r\n"
            f"Accept: {accept}\r\nContent-Length: {len(body)}\r\n\r\n{body}").encode()


def status_of(head):
    try:
        return int(head.split(b" ", 2)[1])
    except (IndexError, ValueError):
        return 0


class Sampler(threading.Thread):
    def __init__(self, pid):
        super().__init__(daemon=True)
        self.pid, self.stop, self.rss, self.cgroup = pid, False, [], []

    def run(self):
        while not self.stop:
            rss = status_kib(self.pid, "VmRSS")
            if rss is not None:
                self.rss.append(rss)
            current = cgroup_current(self.pid)
            if current is not None:
                self.cgroup.append(current)
            time.sleep(0.1)


def healthz_loop(port, until, latencies):
    sock = socket.create_connection(("127.0.0.1", port))
    while time.time() < until:
        start = time.perf_counter()
        sock.sendall(b"GET /healthz HTTP/1.1\r\nHost: bench\r\n\r\n")
        data = b""
        while b"\r\n\r\n" not in data or not data.endswith(b"}"):
            chunk = sock.recv(4096)
            if not chunk:
                return
            data += chunk
        latencies.append((time.perf_counter() - start) * 1000)
        time.sleep(0.1)


def first_status(sock, timeout):
    """Reads until the status line is in (the rest stays unread); 0 when none came."""
    sock.setblocking(False)
    head = b""
    end = time.time() + timeout
    while time.time() < end and b"\r\n" not in head:
        ready, _, _ = select.select([sock], [], [], 0.05)
        if ready:
            try:
                chunk = sock.recv(64)
            except OSError:
                return 0
            if not chunk:
                return 0
            head += chunk
    return status_of(head)


def never_read(args, payload):
    socks, statuses = [], {}
    latencies = []
    until = time.time() + args.spread + args.hold
    probe = threading.Thread(target=healthz_loop, args=(args.port, until, latencies), daemon=True)
    probe.start()
    for i in range(args.n):
        s = socket.create_connection(("127.0.0.1", args.port))
        s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)  # hold as little as possible
        s.sendall(payload)
        socks.append(s)
        time.sleep(args.spread / max(args.n, 1))
    # Peek at each status line only: a 200 leaves its body unread.
    for s in socks:
        code = first_status(s, 0.2)
        statuses[code] = statuses.get(code, 0) + 1
    time.sleep(max(0.0, until - time.time()))
    probe.join(timeout=2)
    for s in socks:
        s.close()
    return {"statuses": statuses, "healthz_ms": summary(latencies)}


def slow_read(args, payload):
    statuses, done = {}, []
    lock = threading.Lock()

    def client():
        s = socket.create_connection(("127.0.0.1", args.port))
        s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 65536)
        s.sendall(payload)
        got, head, start = 0, b"", time.time()
        while True:
            chunk = s.recv(8192)
            if not chunk:
                break
            if len(head) < 64:
                head += chunk[:64]
            got += len(chunk)
            ahead = got / args.rate - (time.time() - start)
            if ahead > 0:
                time.sleep(ahead)
        with lock:
            code = status_of(head)
            statuses[code] = statuses.get(code, 0) + 1
            done.append(got)
        s.close()

    threads = [threading.Thread(target=client, daemon=True) for _ in range(args.n)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=args.hold + 600)
    return {"statuses": statuses, "bytes_read": sum(done)}


def ttfb(args, payload):
    s = socket.create_connection(("127.0.0.1", args.port))
    start = time.perf_counter()
    s.sendall(payload.replace(b"HTTP/1.1\r\n", b"HTTP/1.1\r\nConnection: close\r\n", 1))
    first = None
    total = 0
    while True:
        chunk = s.recv(1 << 20)
        if not chunk:
            break
        if first is None:
            first = time.perf_counter()
        total += len(chunk)
    end = time.perf_counter()
    return {"ttfb_ms": (first - start) * 1000, "total_ms": (end - start) * 1000,
            "bytes": total, "mb_per_s": total / 1e6 / (end - start)}


def summary(values):
    if not values:
        return None
    return {"median": round(statistics.median(values), 2), "max": round(max(values), 2),
            "count": len(values)}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("pid", type=int)
    parser.add_argument("port", type=int)
    parser.add_argument("--scenario", default="never-read",
                        choices=["never-read", "slow-read", "ttfb"])
    parser.add_argument("--n", type=int, default=200)
    parser.add_argument("--spread", type=float, default=10.0)
    parser.add_argument("--hold", type=float, default=10.0)
    parser.add_argument("--rate", type=float, default=65536.0)
    parser.add_argument("--body", default=HEAVY_BODY)
    parser.add_argument("--path", default="/v1/polygon-hole/gcode")
    parser.add_argument("--accept", default="text/plain")
    args = parser.parse_args()
    payload = request_bytes(args.path, args.body, args.accept)
    sampler = Sampler(args.pid)
    sampler.start()
    if args.scenario == "never-read":
        result = never_read(args, payload)
    elif args.scenario == "slow-read":
        result = slow_read(args, payload)
    else:
        result = ttfb(args, payload)
    sampler.stop = True
    sampler.join()
    result.update({"scenario": args.scenario, "n": args.n,
                   "rss_peak_kib": max(sampler.rss) if sampler.rss else None,
                   "hwm_kib": status_kib(args.pid, "VmHWM"),
                   "cgroup_peak_bytes": max(sampler.cgroup) if sampler.cgroup else None})
    print("MEMORY_RESULT " + json.dumps(result, sort_keys=True))


if __name__ == "__main__":
    main()
