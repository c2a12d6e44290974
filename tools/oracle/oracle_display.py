#!/usr/bin/python3
"""The [DISPLAY] program of the oracle's LinuxCNC configuration (see README.md).

Run as `/usr/bin/python3 oracle_display.py -ini FILE` once linuxcncsvr, io, the motion modules, the
HAL file and milltask are up. It takes the machine out of E-stop, turns it on, opens the program named
by [ORACLE] PROGRAM in the INI, runs it in MODE_AUTO and waits until the interpreter is idle and motion
is in position. It prints `done` on success; any operator or NML error is printed as `error: ...`
and makes it exit with status 2. It never reads a clock for the answer: the simulated time is counted
in the servo thread by HAL (oracle.hal) and read by time_program.py with `halcmd getp`.
"""
import configparser
import os
import sys
import time

import linuxcnc


def ini_value(path, section, key):
    parser = configparser.ConfigParser(strict=False, interpolation=None, inline_comment_prefixes=None)
    parser.optionxform = str
    parser.read(path)
    return parser.get(section, key)


def main():
    if len(sys.argv) < 3 or sys.argv[1] != "-ini":
        print("usage: oracle_display.py -ini FILE", file=sys.stderr)
        return 64
    ini = sys.argv[2]
    program = ini_value(ini, "ORACLE", "PROGRAM")
    timeout_s = float(ini_value(ini, "ORACLE", "RUN_TIMEOUT_S"))

    stat = linuxcnc.stat()
    command = linuxcnc.command()
    errors = linuxcnc.error_channel()
    problems = []

    def drain_errors():
        while True:
            got = errors.poll()
            if not got:
                return
            kind, text = got
            if kind in (linuxcnc.NML_ERROR, linuxcnc.OPERATOR_ERROR):
                problems.append(text)

    def step(what, call, *args):
        call(*args)
        if command.wait_complete(10.0) == -1:
            raise RuntimeError(f"{what}: no answer from task within 10 s")
        drain_errors()

    trace_path = os.environ.get("ORACLE_TRACE")
    trace = open(trace_path, "w") if trace_path else None

    def wait_for(what, predicate, limit_s):
        end = time.monotonic() + limit_s
        while time.monotonic() < end:
            stat.poll()
            drain_errors()
            if trace:
                # debugging aid: how far task has read and queued against what motion executes
                trace.write(f"{time.monotonic():.4f} read {stat.read_line} queue {stat.queue} "
                            f"motion {stat.motion_line} current {stat.current_line} vel {stat.current_vel:.3f}\n")
            if predicate():
                return
            time.sleep(0.001 if trace else 0.01)
        raise RuntimeError(f"timed out after {limit_s} s waiting for {what}")

    try:
        stat.poll()
        step("estop reset", command.state, linuxcnc.STATE_ESTOP_RESET)
        step("machine on", command.state, linuxcnc.STATE_ON)
        wait_for("machine on", lambda: stat.task_state == linuxcnc.STATE_ON, 10.0)
        step("mode auto", command.mode, linuxcnc.MODE_AUTO)
        wait_for("auto mode", lambda: stat.task_mode == linuxcnc.MODE_AUTO, 10.0)
        step("program open", command.program_open, program)
        if problems:
            raise RuntimeError("; ".join(problems))
        command.auto(linuxcnc.AUTO_RUN, 0)
        # The run has started once the interpreter leaves idle (or, for a program that ends at
        # once, once it has read past line 0).
        wait_for("the program to start",
                 lambda: stat.interp_state != linuxcnc.INTERP_IDLE or stat.motion_line > 0 or problems, 10.0)
        wait_for("the program to end",
                 lambda: problems or (stat.interp_state == linuxcnc.INTERP_IDLE and stat.queue == 0
                                      and stat.inpos and stat.exec_state == linuxcnc.EXEC_DONE),
                 timeout_s)
        time.sleep(0.05)
        drain_errors()
        if problems:
            raise RuntimeError("; ".join(problems))
    except RuntimeError as failure:
        print(f"error: {failure}", flush=True)
        return 2
    print("done", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
