#!/usr/bin/python3
"""Memory under clients that ask for the largest program and do not read it (issue 31), and under
clients that upload the largest program to time at once: starts nothing itself; talks to a cutcalc
on 127.0.0.1:PORT whose PID is given (a process in a container: its host-side PID,
`podman inspect --format '{{.State.Pid}}'`, read as root), and samples the server's VmRSS / VmHWM
and the memory of its cgroup every 100 ms: cgroup v2 memory.current (and memory.peak), or on a
cgroup v1 host the memory controller's memory.usage_in_bytes (and memory.max_usage_in_bytes),
with the cgroup's OOM kills (v2 memory.events, v1 memory.oom_control: oom_kill). The cgroup is
found once, at start, from /proc/PID/cgroup.

Scenarios (--scenario):
  never-read  N connections opened over --spread seconds, each sends the heavy request and never
              reads; meanwhile /healthz is asked every 100 ms on a separate connection
  slow-read   N connections each read the answer at --rate bytes/s
  ttfb        one client: time to the first byte and the whole answer (and its throughput)
  upload      N connections, all opened first, then all send at once a valid POST /v1/program-time
              of --body-bytes bytes (a LinuxCNC program of G1 moves; default 32 MiB, the route's
              max_body_bytes), reading while they send; each stops sending once an answer begins

Every client whose request was sent must get a complete answer (status line, head, and the
Content-Length body; never-read: the status line) within --answer-timeout seconds (never-read: of
the last request sent; slow-read: of its last byte read; upload: of the start): any status counts
(200, 413, 503; the upload also counts 503s without Retry-After). A connection closed or reset
before that, or no answer in time, is counted in "lost" (by cause in "lost_by"; slow-read also
lists "lost_examples": bytes read of the answer's length, and when); a request that could not even
connect is in "connect_failed", not lost.

Prints readable lines and one line
  MEMORY_RESULT {"scenario":..,"n":..,"rss_peak_kib":..,"hwm_kib":..,"cgroup_peak_bytes":..,
                 "cgroup_hwm_bytes":..,"cgroup":{..},"statuses":{..},"lost":..,"lost_by":{..},
                 "healthz_ms":{"median":..,"max":..},...}

usage: memory_attack.py PID PORT [--scenario never-read|slow-read|ttfb|upload] [--n 200]
                        [--spread 10] [--hold 15] [--rate 65536] [--body JSON] [--path P]
                        [--accept A] [--body-bytes B] [--answer-timeout S]
"""
import argparse
import json
import math
import os
import re
import select
import socket
import statistics
import threading
import time

HEAVY_BODY = ('{"faces":3,"inscribed_diameter_mm":1000000,"depth_mm":1,"step_down_mm":1,'
              '"spindle_speed_rpm":30,"tolerance_mm":0.0001,"loops_per_layer":62,'
              '"synchronization":"c_axis","program":{"dialect":"fanuc","decimals":6}}')
HEAVY_PATH = "/v1/polygon-hole/gcode"
UPLOAD_PATH = "/v1/program-time"
UPLOAD_BODY_BYTES = 32 * 1024 * 1024  # api/routes.h kProgramBodyBytes (cutcalc --routes)
# The machine of openapi.yaml's program-time examples.
UPLOAD_MACHINE = ('{"axes":{'
                  '"x":{"max_velocity_mm_per_min":12000,"max_acceleration_mm_per_s2":1000},'
                  '"y":{"max_velocity_mm_per_min":12000,"max_acceleration_mm_per_s2":1000},'
                  '"z":{"max_velocity_mm_per_min":8000,"max_acceleration_mm_per_s2":600}},'
                  '"max_feed_mm_per_min":12000,"servo_period_ms":1.0}')
# What a refusal says: its first error's code, else its detail (the engine's own refusals, 413 and
# 503 uploads_busy / memory_busy, have no errors, only a detail).
PROBLEM_CODE = re.compile(rb'"code":"([A-Za-z0-9_.-]+)"')
PROBLEM_DETAIL = re.compile(rb'"detail":"([^"]*)"')


def status_kib(pid, key):
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith(key + ":"):
                    return int(line.split()[1])
    except OSError:
        return None
    return None


class Cgroup:
    """The memory cgroup of a process, found once (it may die): v2 (memory.current in the "0::"
    path) or v1 (the "memory" controller's hierarchy under /sys/fs/cgroup/memory)."""

    def __init__(self, pid):
        self.version, self.dir = None, None
        try:
            with open(f"/proc/{pid}/cgroup") as f:
                lines = f.read().splitlines()
        except OSError:
            return
        for line in lines:
            num, controllers, path = (line.split(":", 2) + ["", ""])[:3]
            if num == "0" and controllers == "" and \
                    os.path.exists(f"/sys/fs/cgroup{path}/memory.current"):
                self.version, self.dir = 2, f"/sys/fs/cgroup{path}"
                return
        for line in lines:
            num, controllers, path = (line.split(":", 2) + ["", ""])[:3]
            if "memory" in controllers.split(",") and \
                    os.path.exists(f"/sys/fs/cgroup/memory{path}/memory.usage_in_bytes"):
                self.version, self.dir = 1, f"/sys/fs/cgroup/memory{path}"
                return

    def _int(self, name):
        try:
            with open(f"{self.dir}/{name}") as f:
                return int(f.read().split()[0])
        except (OSError, ValueError, IndexError, TypeError):
            return None

    def _keyed(self, name):
        try:
            with open(f"{self.dir}/{name}") as f:
                return {k: int(v) for k, v in (line.split() for line in f if line.strip())}
        except (OSError, ValueError, TypeError):
            return {}

    def current(self):
        if self.version is None:
            return None
        return self._int("memory.current" if self.version == 2 else "memory.usage_in_bytes")

    def peak(self):
        """The kernel's high-water mark since the cgroup was made (None where there is none)."""
        if self.version is None:
            return None
        return self._int("memory.peak" if self.version == 2 else "memory.max_usage_in_bytes")

    def limit(self):
        if self.version == 2:
            return self._int("memory.max")  # "max": None
        return self._int("memory.limit_in_bytes") if self.version == 1 else None

    def events(self):
        """OOM kills in the cgroup so far, or None when the cgroup is gone. (Not the limit hits:
        v1 memory.failcnt stayed 0 while the usage reached the limit and the OOM killer ran.)"""
        if self.version == 2:
            ev = self._keyed("memory.events")
            return {"oom_kill": ev.get("oom_kill")} if ev else None
        if self.version == 1:
            oom = self._keyed("memory.oom_control")
            return {"oom_kill": oom.get("oom_kill")} if oom else None
        return None


def request_bytes(path, body, accept):
    if isinstance(body, str):
        body = body.encode()
    return (f"POST {path} HTTP/1.1\r\nHost: bench\r\nContent-Type: application/json\r\n"
            f"Accept: {accept}\r\nContent-Length: {len(body)}\r\n\r\n").encode() + body


def status_of(head):
    try:
        return int(head.split(b" ", 2)[1])
    except (IndexError, ValueError):
        return 0


class ChunkedBody:
    """Walks a chunked body (RFC 9112 7.1) as its bytes arrive, holding no more than a size line:
    done once the last chunk and the empty trailer are in."""

    def __init__(self):
        self.line, self.left, self.done, self.last = bytearray(), 0, False, False

    def feed(self, data):
        i = 0
        while i < len(data) and not self.done:
            if self.left > 0:  # chunk data and its CRLF
                take = min(self.left, len(data) - i)
                self.left -= take
                i += take
                continue
            end = data.find(b"\n", i)
            if end < 0:
                self.line += data[i:]
                break
            self.line += data[i:end]
            i = end + 1
            line = bytes(self.line).rstrip(b"\r")
            self.line.clear()
            if self.last:
                self.done = line == b""  # the end of the (empty) trailer section
                continue
            size = int(line.split(b";")[0] or b"0", 16)
            if size == 0:
                self.last = True
            else:
                self.left = size + 2
        return self.done


def parse_answer(data, eof):
    """(status, complete, head fields) of the response at the start of `data`: complete once its
    head and its Content-Length body, or its whole chunked body, are in (neither: at EOF)."""
    end = data.find(b"\r\n\r\n")
    if end < 0:
        return status_of(data), False, {}
    fields = {}
    for line in data[:end].split(b"\r\n")[1:]:
        name, _, value = line.partition(b":")
        fields[name.strip().lower().decode("latin-1")] = value.strip().decode("latin-1")
    length = fields.get("content-length")
    if length is not None and length.isdigit():
        return status_of(data), len(data) - end - 4 >= int(length), fields
    if fields.get("transfer-encoding", "").lower() == "chunked":
        return status_of(data), ChunkedBody().feed(bytes(data[end + 4:])), fields
    return status_of(data), eof, fields


class Sampler(threading.Thread):
    def __init__(self, pid):
        super().__init__(daemon=True)
        self.pid, self.stop, self.rss, self.cgroup = pid, False, [], []
        self.group = Cgroup(pid)
        self.events = self.group.events()
        # Kept from the last sample: an OOM kill takes the cgroup (and these files) with it.
        self.limit, self.hwm = self.group.limit(), self.group.peak()

    def run(self):
        while not self.stop:
            rss = status_kib(self.pid, "VmRSS")
            if rss is not None:
                self.rss.append(rss)
            current = self.group.current()
            if current is not None:
                self.cgroup.append(current)
            events = self.group.events()
            if events is not None:
                self.events = events
            hwm = self.group.peak()
            if hwm is not None:
                self.hwm = hwm
            time.sleep(0.1)


def healthz_loop(port, until, latencies):
    try:
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
    except OSError:
        return


def count(table, key):
    table[key] = table.get(key, 0) + 1


def status_lines(socks, deadline):
    """Reads each socket's status line only (the rest stays unread), all at once, until each has
    one, ended without one, or the deadline passes. Returns {sock: status or "closed"/"reset"},
    without the sockets still silent at the deadline."""
    heads, outcome = {s: b"" for s in socks}, {}
    for s in socks:
        s.setblocking(False)
    while len(outcome) < len(socks):
        waiting = [s for s in socks if s not in outcome]
        left = deadline - time.time()
        if left <= 0:
            break
        ready, _, _ = select.select(waiting, [], [], min(left, 0.5))
        for s in ready:
            try:
                chunk = s.recv(64)
            except OSError:
                outcome[s] = "reset"
                continue
            if not chunk:
                outcome[s] = "closed"
                continue
            heads[s] += chunk
            if b"\r\n" in heads[s]:
                outcome[s] = status_of(heads[s])
    return outcome


def never_read(args, payload):
    socks, statuses, lost_by = [], {}, {}
    latencies = []
    connect_failed = 0
    until = time.time() + args.spread + args.hold
    probe = threading.Thread(target=healthz_loop, args=(args.port, until, latencies), daemon=True)
    probe.start()
    for i in range(args.n):
        try:
            s = socket.create_connection(("127.0.0.1", args.port))
            s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)  # hold as little as possible
            s.sendall(payload)
            socks.append(s)
        except OSError:
            connect_failed += 1
        time.sleep(args.spread / max(args.n, 1))
    # Peek at each status line only: a 200 leaves its body unread. Every request must have one
    # within --answer-timeout of the last one sent (the calculation timeout bounds the wait).
    outcome = status_lines(socks, max(until, time.time() + args.answer_timeout))
    for s in socks:
        code = outcome.get(s, "no_answer")
        if isinstance(code, int) and code > 0:
            count(statuses, code)
        else:
            count(lost_by, code if isinstance(code, str) else "malformed")
    time.sleep(max(0.0, until - time.time()))
    probe.join(timeout=2)
    for s in socks:
        s.close()
    return {"statuses": statuses, "lost": sum(lost_by.values()), "lost_by": lost_by,
            "connect_failed": connect_failed, "healthz_ms": summary(latencies)}


def slow_read(args, payload):
    statuses, lost_by, done, lost_examples = {}, {}, [], []
    lock = threading.Lock()
    began = time.time()

    def client():
        try:
            s = socket.create_connection(("127.0.0.1", args.port))
        except OSError:
            with lock:
                count(lost_by, "connect_failed")
            return
        s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 65536)
        s.settimeout(args.answer_timeout)
        data, got, outcome = bytearray(), 0, None
        head_end, code, total, chunked = -1, 0, None, None
        try:
            s.sendall(payload)
            start = time.time()
            while True:
                chunk = s.recv(8192)
                if not chunk:
                    outcome = "closed"
                    break
                if got == 0:
                    start = time.time()  # the rate is the answer's, from its first byte
                got += len(chunk)
                if head_end < 0:
                    data += chunk
                    head_end = data.find(b"\r\n\r\n")
                    if head_end >= 0:
                        code, _, fields = parse_answer(bytes(data[:head_end + 4]), False)
                        length = fields.get("content-length")
                        total = head_end + 4 + int(length) if length and length.isdigit() else None
                        if fields.get("transfer-encoding", "").lower() == "chunked":
                            chunked = ChunkedBody()
                            chunk = bytes(data[head_end + 4:])
                if chunked is not None and chunked.feed(chunk):
                    outcome = code
                    break
                if head_end >= 0 and total is not None and got >= total:
                    outcome = code
                    break
                ahead = got / args.rate - (time.time() - start)
                if ahead > 0:
                    time.sleep(ahead)
        except socket.timeout:
            outcome = "no_answer" if head_end < 0 else "stalled"
        except OSError:
            outcome = "reset"
        if outcome == "closed" and head_end >= 0 and total is None:
            outcome = code  # a close-delimited answer is complete at EOF
        with lock:
            if isinstance(outcome, int):
                count(statuses, outcome)
            else:
                count(lost_by, outcome if head_end < 0 else f"{outcome}_after_status_{code}")
                lost_examples.append({"outcome": outcome, "status": code if head_end >= 0 else None,
                                      "bytes": got, "of": total if head_end >= 0 else None,
                                      "after_s": round(time.time() - began, 2)})
            done.append(got)
        s.close()

    threads = [threading.Thread(target=client, daemon=True) for _ in range(args.n)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=args.hold + 600)
    connect_failed = lost_by.pop("connect_failed", 0)
    return {"statuses": statuses, "lost": sum(lost_by.values()), "lost_by": lost_by,
            "lost_examples": sorted(lost_examples, key=lambda e: e["after_s"])[:10],
            "connect_failed": connect_failed, "bytes_read": sum(done)}


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


def program_time_body(size):
    """A valid POST /v1/program-time body of exactly `size` bytes: a LinuxCNC program of G1 moves
    round a 1000-sided polygon (r 40 mm, 0.25 mm a side), over and over, JSON whitespace at the
    end making up the last bytes."""
    head = '{"dialect":"linuxcnc","machine":' + UPLOAD_MACHINE + \
           ',"program":"G21 G90 G17 G64\\nF4000\\nG0 X90.000 Y50.000\\n'
    tail = 'M2\\n"}'
    loop = "".join(f"G1 X{50 + 40 * math.cos(2 * math.pi * k / 1000):.3f} "
                   f"Y{50 + 40 * math.sin(2 * math.pi * k / 1000):.3f}\\n"
                   for k in range(1, 1001))
    room = size - len(head) - len(tail)
    if room < 0:
        raise SystemExit(f"--body-bytes {size} is too small for a program to time")
    # Whole loops, then what whole lines of the next loop fit; the rest is whitespace.
    body = loop * (room // len(loop))
    rest = room - len(body)
    part = loop[:loop.rfind("\\n", 0, rest - 1) + 2] if loop.find("\\n") + 2 <= rest else ""
    body = head + body + part + tail[:-1] + " " * (rest - len(part)) + "}"
    assert len(body) == size, (len(body), size)
    return body.encode()


def upload(args, payload):
    """N connections, all opened first, then all send at once; each reads while it sends and stops
    sending once an answer begins (an early 413 or 503), and must get a complete answer."""
    statuses, lost_by, reasons, times, lost_examples = {}, {}, {}, [], []
    no_retry_after = 0
    lock = threading.Lock()
    view = memoryview(payload)
    head_bytes = payload.index(b"\r\n\r\n") + 4
    socks = []
    connect_failed = 0
    for _ in range(args.n):
        try:
            socks.append(socket.create_connection(("127.0.0.1", args.port)))
        except OSError:
            connect_failed += 1
    start_line = threading.Barrier(len(socks) + 1) if socks else None
    sent_total = []

    def client(s):
        nonlocal no_retry_after
        s.setblocking(False)
        start_line.wait()
        start = time.time()
        sent, data, outcome, fields = 0, bytearray(), None, {}
        writing, eof = True, False
        while outcome is None:
            status, complete, fields = parse_answer(bytes(data), eof) if data else (0, False, {})
            if complete:
                outcome = status
                break
            if eof:
                outcome = "closed"
                break
            left = start + args.answer_timeout - time.time()
            if left <= 0:
                outcome = "no_answer"
                break
            want = [s] if writing and sent < len(payload) else []
            try:
                readable, writable, _ = select.select([s], want, [], min(left, 0.5))
            except (OSError, ValueError):
                outcome = "reset"
                break
            if readable:
                try:
                    chunk = s.recv(1 << 16)
                except BlockingIOError:
                    chunk = None
                except OSError:
                    outcome = "reset"
                    break
                if chunk == b"":
                    eof = True
                elif chunk:
                    data += chunk
                    writing = False  # an answer has begun: the rest of the body is not wanted
            if writable and writing:
                try:
                    sent += s.send(view[sent:sent + (1 << 18)])
                except BlockingIOError:
                    pass
                except OSError:
                    writing = False  # the server stopped reading: its answer may still be in
        with lock:
            sent_total.append(sent)
            if isinstance(outcome, int) and outcome > 0:
                count(statuses, outcome)
                times.append((time.time() - start) * 1000)
                if outcome != 200:
                    match = PROBLEM_CODE.search(bytes(data)) or PROBLEM_DETAIL.search(bytes(data))
                    count(reasons, f"{outcome} {match.group(1).decode() if match else '?'}")
                    if outcome == 503 and "retry-after" not in fields:
                        no_retry_after += 1
            else:
                phase = "before_head_sent" if sent < head_bytes else "after_head_sent"
                count(lost_by, f"{outcome if isinstance(outcome, str) else 'malformed'}_{phase}")
                lost_examples.append({"outcome": outcome, "sent": sent, "of": len(payload),
                                      "answer_bytes": len(data),
                                      "after_s": round(time.time() - start, 2)})
        s.close()

    threads = [threading.Thread(target=client, args=(s,), daemon=True) for s in socks]
    for t in threads:
        t.start()
    if start_line is not None:
        start_line.wait()
    for t in threads:
        t.join(timeout=args.answer_timeout + 60)
    hung = sum(t.is_alive() for t in threads)
    if hung:
        lost_by["client_hung"] = hung
    return {"statuses": statuses, "lost": sum(lost_by.values()), "lost_by": lost_by,
            "lost_examples": sorted(lost_examples, key=lambda e: e["after_s"])[:10],
            "refusals": reasons, "503_without_retry_after": no_retry_after,
            "connect_failed": connect_failed, "body_bytes": len(payload) - head_bytes,
            "bytes_sent": sum(sent_total), "answer_ms": summary(times)}


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
                        choices=["never-read", "slow-read", "ttfb", "upload"])
    parser.add_argument("--n", type=int, default=200)
    parser.add_argument("--spread", type=float, default=10.0)
    parser.add_argument("--hold", type=float, default=10.0)
    parser.add_argument("--rate", type=float, default=65536.0)
    parser.add_argument("--body", default=None, help="default: the heavy polygon program request "
                        "(upload: a program to time of --body-bytes)")
    parser.add_argument("--path", default=None,
                        help=f"default {HEAVY_PATH} (upload: {UPLOAD_PATH})")
    parser.add_argument("--accept", default=None,
                        help="default text/plain (upload: application/json)")
    parser.add_argument("--body-bytes", type=int, default=UPLOAD_BODY_BYTES,
                        help="upload: the body's size (default 32 MiB, the route's max_body_bytes)")
    parser.add_argument("--answer-timeout", type=float, default=45.0,
                        help="seconds a sent request waits for its answer before it counts as "
                        "lost (default 45: the 30 s calculation timeout, and for an upload the "
                        "transfer time at 1 MB/s, with a margin)")
    args = parser.parse_args()
    if args.scenario == "upload":
        body = args.body.encode() if args.body is not None else program_time_body(args.body_bytes)
        payload = request_bytes(args.path or UPLOAD_PATH, body, args.accept or "application/json")
    else:
        payload = request_bytes(args.path or HEAVY_PATH, args.body or HEAVY_BODY,
                                args.accept or "text/plain")
    sampler = Sampler(args.pid)
    sampler.start()
    if args.scenario == "never-read":
        result = never_read(args, payload)
    elif args.scenario == "slow-read":
        result = slow_read(args, payload)
    elif args.scenario == "upload":
        result = upload(args, payload)
    else:
        result = ttfb(args, payload)
    time.sleep(0.2)  # one more sample after the last client
    sampler.stop = True
    sampler.join()
    group = sampler.group
    result.update({"scenario": args.scenario, "n": args.n,
                   "rss_peak_kib": max(sampler.rss) if sampler.rss else None,
                   "hwm_kib": status_kib(args.pid, "VmHWM"),
                   "cgroup_peak_bytes": max(sampler.cgroup) if sampler.cgroup else None,
                   "cgroup_hwm_bytes": group.peak() or sampler.hwm,
                   "cgroup": {"version": group.version, "dir": group.dir,
                              "limit_bytes": sampler.limit, **(sampler.events or {})}})
    mib = lambda b: f"{b / 1048576:.1f} MiB" if b is not None else "n/a"
    print(f"{args.scenario}: n {args.n}, statuses {result.get('statuses')}, "
          f"lost {result.get('lost', 0)} {result.get('lost_by') or ''}; VmRSS peak "
          f"{mib((result['rss_peak_kib'] or 0) * 1024 if result['rss_peak_kib'] else None)}, "
          f"VmHWM {mib(result['hwm_kib'] * 1024 if result['hwm_kib'] else None)}, cgroup peak "
          f"{mib(result['cgroup_peak_bytes'])} sampled / {mib(result['cgroup_hwm_bytes'])} kernel",
          flush=True)
    print("MEMORY_RESULT " + json.dumps(result, sort_keys=True), flush=True)


if __name__ == "__main__":
    main()
