#!/usr/bin/python3
"""Idle-connection client for bench/idle_memory.sh (issue 24): opens N keep-alive connections to a
cutcalc on 127.0.0.1:PORT (in batches, non-blocking), sends one request on each and reads the
whole answer, then leaves them idle, and samples the server's memory (VmRSS from
/proc/PID/status, Pss from /proc/PID/smaps_rollup) and descriptor count:
  base   before the first connection
  open   when every connection has had its answer
  idle   after --idle seconds of idleness (counted from the last answer)
then checks which connections are still open (poll: readable with nothing to read = closed by the
server), and with --reuse sends one more request on every open one (is it still served?).
Prints readable lines and one line
  IDLE_RESULT {"n":..,"answered":..,"open_after_idle":..,"rss_kib":{"base":..,"open":..,"idle":..},...}

usage: idle_conns.py PID PORT [--n 10000] [--request healthz|post] [--body JSON] [--path P]
                     [--idle 3] [--batch 500] [--reuse]
"""
import argparse
import json
import os
import resource
import select
import socket
import time


def memory(pid):
    out = {"rss_kib": None, "pss_kib": None, "fds": None}
    try:
        with open(f"/proc/{pid}/status") as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    out["rss_kib"] = int(line.split()[1])
    except OSError:
        pass
    try:
        with open(f"/proc/{pid}/smaps_rollup") as f:
            for line in f:
                if line.startswith("Pss:"):
                    out["pss_kib"] = int(line.split()[1])
    except OSError:
        pass
    try:
        out["fds"] = len(os.listdir(f"/proc/{pid}/fd"))
    except OSError:
        pass
    return out


def complete(buf):
    """(status, keep_alive) when buf holds a whole answer, else None."""
    end = buf.find(b"\r\n\r\n")
    if end < 0:
        return None
    head = buf[:end].decode("latin-1").split("\r\n")
    length = 0
    close = False
    for h in head[1:]:
        name, _, value = h.partition(":")
        if name.strip().lower() == "content-length":
            length = int(value.strip())
        elif name.strip().lower() == "connection" and "close" in value.lower():
            close = True
    if len(buf) - end - 4 < length:
        return None
    return int(head[0].split()[1]), not close


def exchange(socks, request, port, connect, timeout_s=30.0):
    """Connects (if connect) and sends request on each socket, reads each answer. Returns a list of
    (status or error string, keep_alive) in the order of socks."""
    poller = select.poll()
    state = {}
    for i, s in enumerate(socks):
        if connect:
            s.setblocking(False)
            s.connect_ex(("127.0.0.1", port))
            poller.register(s.fileno(), select.POLLOUT)
            state[s.fileno()] = [i, s, "connecting", b""]
        else:
            try:
                s.send(request)
            except OSError as e:
                state[s.fileno()] = [i, s, f"send-error:{e.errno}", b""]
                continue
            poller.register(s.fileno(), select.POLLIN)
            state[s.fileno()] = [i, s, "reading", b""]
    results = [None] * len(socks)
    for fd, (i, s, phase, _) in state.items():
        if phase.startswith("send-error"):
            results[i] = (phase, False)
    pending = sum(1 for r in results if r is None)
    deadline = time.monotonic() + timeout_s
    while pending and time.monotonic() < deadline:
        for fd, ev in poller.poll(1000):
            st = state[fd]
            i, s, phase = st[0], st[1], st[2]
            if phase == "connecting":
                err = s.getsockopt(socket.SOL_SOCKET, socket.SO_ERROR)
                if err:
                    results[i] = (f"connect-error:{err}", False)
                    poller.unregister(fd)
                    pending -= 1
                    continue
                s.send(request)
                st[2] = "reading"
                poller.modify(fd, select.POLLIN)
            elif phase == "reading":
                try:
                    data = s.recv(65536)
                except OSError as e:
                    data = None
                    results[i] = (f"recv-error:{e.errno}", False)
                if data == b"":
                    results[i] = ("closed", False)
                elif data:
                    st[3] += data
                    done = complete(st[3])
                    if done:
                        results[i] = done
                        st[3] = b""
                if results[i] is not None:
                    poller.unregister(fd)
                    pending -= 1
    for i, r in enumerate(results):
        if r is None:
            results[i] = ("timeout", False)
    return results


def still_open(socks):
    """Sockets the server has not closed: not readable (an idle keep-alive connection gets
    nothing), or readable with data (unexpected, counted open)."""
    poller = select.poll()
    by_fd = {s.fileno(): s for s in socks}
    for s in socks:
        poller.register(s.fileno(), select.POLLIN | select.POLLRDHUP)
    closed = set()
    for fd, ev in poller.poll(0):
        if ev & (select.POLLHUP | select.POLLRDHUP | select.POLLERR):
            closed.add(fd)
            continue
        try:
            if by_fd[fd].recv(1, socket.MSG_PEEK | socket.MSG_DONTWAIT) == b"":
                closed.add(fd)
        except BlockingIOError:
            pass
        except OSError:
            closed.add(fd)
    return [s for s in socks if s.fileno() not in closed]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("pid", type=int)
    ap.add_argument("port", type=int)
    ap.add_argument("--n", type=int, default=10000)
    ap.add_argument("--request", choices=("healthz", "post"), default="healthz")
    ap.add_argument("--path", default="/v1/roughness/groove-wall")
    ap.add_argument("--body", default="")
    ap.add_argument("--idle", type=float, default=3.0)
    ap.add_argument("--batch", type=int, default=500)
    ap.add_argument("--reuse", action="store_true")
    args = ap.parse_args()

    soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    if soft < hard:
        resource.setrlimit(resource.RLIMIT_NOFILE, (hard, hard))
        soft = hard
    if args.n + 64 > soft:
        raise SystemExit(f"idle_conns: {args.n} connections need more descriptors than RLIMIT_NOFILE {soft}")

    if args.request == "post":
        body = args.body.encode()
        request = (f"POST {args.path} HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
                   f"Content-Length: {len(body)}\r\n\r\n").encode() + body
    else:
        request = b"GET /healthz HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n"

    mem = {"base": memory(args.pid)}
    socks = []
    statuses = {}
    t_start = time.monotonic()
    for start in range(0, args.n, args.batch):
        batch = [socket.socket(socket.AF_INET, socket.SOCK_STREAM) for _ in range(min(args.batch, args.n - start))]
        for (status, keep), s in zip(exchange(batch, request, args.port, connect=True), batch):
            key = f"{status}{'' if keep or not isinstance(status, int) else ' (Connection: close)'}"
            statuses[key] = statuses.get(key, 0) + 1
            socks.append(s)
    t_open = time.monotonic()
    mem["open"] = memory(args.pid)
    answered = statuses.get("200", 0)
    time.sleep(max(0.0, args.idle - (time.monotonic() - t_open)))
    mem["idle"] = memory(args.pid)
    open_socks = still_open(socks)
    reuse = None
    if args.reuse:
        res = exchange(open_socks, request, args.port, connect=False)
        reuse = sum(1 for status, _ in res if status == 200)
        mem["reuse"] = memory(args.pid)
    for s in socks:
        s.close()

    n = args.n
    base = mem["base"]["rss_kib"]
    idle = mem["idle"]["rss_kib"]
    result = {
        "n": n,
        "request": args.request,
        "answers": statuses,
        "answered_200": answered,
        "open_seconds": round(t_open - t_start, 3),
        "idle_seconds": args.idle,
        "open_after_idle": len(open_socks),
        "reuse_200": reuse,
        "rss_kib": {k: v["rss_kib"] for k, v in mem.items()},
        "pss_kib": {k: v["pss_kib"] for k, v in mem.items()},
        "server_fds": {k: v["fds"] for k, v in mem.items()},
        "kib_per_conn_rss": round((idle - base) / n, 2) if base and idle else None,
    }
    pb, pi = mem["base"]["pss_kib"], mem["idle"]["pss_kib"]
    result["kib_per_conn_pss"] = round((pi - pb) / n, 2) if pb and pi else None
    print(f"opened {n} connections in {result['open_seconds']} s; answers: {statuses}")
    print(f"still open after {args.idle:g} s idle: {len(open_socks)} of {n}"
          + (f"; a second request answered 200 on {reuse}" if reuse is not None else ""))
    for k, v in mem.items():
        print(f"server {k:5}: VmRSS {v['rss_kib'] / 1024:7.1f} MiB, Pss "
              f"{(v['pss_kib'] or 0) / 1024:7.1f} MiB, {v['fds']} descriptors")
    print("IDLE_RESULT " + json.dumps(result, separators=(",", ":")))


if __name__ == "__main__":
    main()
