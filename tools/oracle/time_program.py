#!/usr/bin/python3
"""Times a G-code program with LinuxCNC 2.9's real trajectory planner, headless, in simulation.

Usage:
    /usr/bin/python3 tools/oracle/time_program.py PROGRAM.ngc MACHINE.json [--keep] [--verbose]

MACHINE.json is a machine object as the API takes it (domain/machine-time.md section 2), or a file
whose "machine" member is one. Prints the simulated time in seconds with 3 decimals: the servo
periods from the first to the last period in which motion is not in position, counted by HAL inside
the servo thread (so the host's load does not change it). See README.md beside this file.

As a module: run_program(program_text, machine) -> seconds (float), one simulation.
"""
import argparse
import fcntl
import json
import os
import pwd
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import uuid

HERE = os.path.dirname(os.path.abspath(__file__))
DISPLAY_SCRIPT = os.path.join(HERE, "oracle_display.py")
PYTHON = "/usr/bin/python3"
BIN = "/usr/bin"
RTLIB_DIR = "/usr/lib/linuxcnc/modules"
NML_FILE = "/usr/share/linuxcnc/linuxcnc.nml"
LOCK_FILE = "/tmp/cutcalc-linuxcnc-oracle.lock"
# Shared memory keys that an earlier, killed run may leave behind (uspace HAL, RTAPI, UUID, motion; the NML
# buffers of linuxcnc.nml).
HAL_SHM_KEYS = [0x48414C32, 0x90280A48, 0x48484C34, 0x64]
LINEAR_AXES = "xyz"
ROTARY_AXES = "abc"
SOFT_LIMIT_MM = 2000.0
SOFT_LIMIT_DEG = 1.0e6


class OracleError(Exception):
    pass


def log(verbose, *parts):
    if verbose:
        print("[oracle]", *parts, file=sys.stderr, flush=True)


def axes_of(machine):
    """The machine's axes, in LinuxCNC's order, as (letter, velocity per second, acceleration)."""
    axes = machine.get("axes") or {}
    kind = machine.get("kind", "mill")
    if kind not in ("mill", "lathe"):
        raise OracleError(f"machine.kind must be mill or lathe, not {kind!r}")
    found = []
    for letter in "xyzabc":
        if letter not in axes:
            continue
        spec = axes[letter]
        if letter in LINEAR_AXES:
            vel = float(spec["max_velocity_mm_per_min"]) / 60.0
            acc = float(spec["max_acceleration_mm_per_s2"])
        else:
            vel = float(spec["max_velocity_deg_per_min"]) / 60.0
            acc = float(spec["max_acceleration_deg_per_s2"])
        if vel <= 0 or acc <= 0:
            raise OracleError(f"axis {letter}: velocity and acceleration must be positive")
        found.append((letter, vel, acc))
    if not found:
        raise OracleError("machine.axes names no axis")
    letters = "".join(a[0] for a in found)
    if kind == "lathe" and "y" in letters:
        raise OracleError("a lathe profile has X and Z (and C), no Y")
    return found


def fmt(value):
    return repr(float(value))


def write_config(run_dir, machine, program_text, run_timeout_s):
    axes = axes_of(machine)
    kind = machine.get("kind", "mill")
    servo_ms = float(machine.get("servo_period_ms", 1.0))
    if not 0.1 <= servo_ms <= 10.0:
        raise OracleError("servo_period_ms must be within 0.1-10")
    servo_ns = int(round(servo_ms * 1.0e6))
    letters = "".join(a[0] for a in axes).upper()
    max_linear = [a[1] for a in axes if a[0] in LINEAR_AXES]
    traj_max = float(machine["max_feed_mm_per_min"]) / 60.0 if machine.get("max_feed_mm_per_min") else None
    default_vel = traj_max if traj_max else (max(max_linear) if max_linear else 100.0)

    program_path = os.path.join(run_dir, "program.ngc")
    with open(program_path, "w") as f:
        f.write(program_text if program_text.endswith("\n") else program_text + "\n")

    with open(os.path.join(run_dir, "tool.tbl"), "w") as f:
        for t in range(1, 100):
            f.write(f"T{t} P{t} D0.000 Z+0.000 ;oracle tool {t}\n")

    ini = []
    ini += ["[EMC]", "VERSION = 1.1", "MACHINE = cutcalc-oracle", "DEBUG = 0", ""]
    ini += ["[DISPLAY]", f"DISPLAY = {PYTHON} {DISPLAY_SCRIPT}", "CYCLE_TIME = 0.100",
            "POSITION_OFFSET = RELATIVE", "POSITION_FEEDBACK = ACTUAL", "MAX_FEED_OVERRIDE = 1.0",
            "MAX_SPINDLE_OVERRIDE = 1.0"]
    if kind == "lathe":
        ini += ["LATHE = 1"]
    ini += [""]
    ini += ["[ORACLE]", f"PROGRAM = {program_path}", f"RUN_TIMEOUT_S = {run_timeout_s}", ""]
    ini += ["[TASK]", "TASK = milltask", "CYCLE_TIME = 0.001", ""]
    ini += ["[RS274NGC]", f"PARAMETER_FILE = {os.path.join(run_dir, 'sim.var')}", ""]
    ini += ["[EMCMOT]", "EMCMOT = motmod", "COMM_TIMEOUT = 1.0", "BASE_PERIOD = 0",
            f"SERVO_PERIOD = {servo_ns}", ""]
    # io's cycle as in LinuxCNC's sample configs (0.100 s). It is not neutral: after a sync point (M3,
    # M8, a tool change) it sets when task queues the next moves relative to motion, and that can change
    # the first blends after it (cutcalc's pass program: 5.871 s with 0.100, 6.074 s with 0.001).
    ini += ["[EMCIO]", "EMCIO = io", "CYCLE_TIME = 0.100", f"TOOL_TABLE = {os.path.join(run_dir, 'tool.tbl')}", ""]
    ini += ["[HAL]", f"HALFILE = {os.path.join(run_dir, 'oracle.hal')}", "HALUI = halui", ""]
    ini += ["[TRAJ]", "COORDINATES = " + " ".join(letters), "LINEAR_UNITS = mm", "ANGULAR_UNITS = degree",
            f"DEFAULT_LINEAR_VELOCITY = {fmt(default_vel)}"]
    if traj_max:
        ini += [f"MAX_LINEAR_VELOCITY = {fmt(traj_max)}"]
    ini += ["NO_FORCE_HOMING = 1", ""]
    if machine.get("max_spindle_rpm"):
        # the spindle's speed limit in rev/min: clamps S, and G96's speed when the program gives no D
        rpm = float(machine["max_spindle_rpm"])
        ini += ["[SPINDLE_0]", f"MAX_VELOCITY = {fmt(rpm)}", f"MAX_REVERSE_VELOCITY = {fmt(rpm)}", ""]
    ini += ["[KINS]", f"KINEMATICS = trivkins coordinates={letters}", f"JOINTS = {len(axes)}", ""]
    for letter, vel, acc in axes:
        limit = SOFT_LIMIT_MM if letter in LINEAR_AXES else SOFT_LIMIT_DEG
        ini += [f"[AXIS_{letter.upper()}]", f"MAX_VELOCITY = {fmt(vel)}", f"MAX_ACCELERATION = {fmt(acc)}",
                f"MIN_LIMIT = {fmt(-limit)}", f"MAX_LIMIT = {fmt(limit)}", ""]
    for j, (letter, vel, acc) in enumerate(axes):
        limit = SOFT_LIMIT_MM if letter in LINEAR_AXES else SOFT_LIMIT_DEG
        ini += [f"[JOINT_{j}]", "TYPE = " + ("LINEAR" if letter in LINEAR_AXES else "ANGULAR"), "HOME = 0.0",
                f"MAX_VELOCITY = {fmt(vel)}", f"MAX_ACCELERATION = {fmt(acc)}", "BACKLASH = 0.0",
                f"MIN_LIMIT = {fmt(-limit)}", f"MAX_LIMIT = {fmt(limit)}", "FERROR = 1000.0",
                "MIN_FERROR = 1000.0", "HOME_OFFSET = 0.0", "HOME_SEARCH_VEL = 0.0", "HOME_LATCH_VEL = 0.0",
                "HOME_SEQUENCE = 0", ""]
    ini_path = os.path.join(run_dir, "oracle.ini")
    with open(ini_path, "w") as f:
        f.write("\n".join(ini))

    hal = [
        "# written by tools/oracle/time_program.py: a simulated machine, every joint's position",
        "# command looped back to its feedback, the spindle following its command at once",
        "loadrt tpmod",
        "loadrt homemod",
        "loadrt [KINS]KINEMATICS",
        "loadrt [EMCMOT]EMCMOT servo_period_nsec=[EMCMOT]SERVO_PERIOD num_joints=[KINS]JOINTS",
        "addf motion-command-handler servo-thread",
        "addf motion-controller servo-thread",
    ]
    for j in range(len(axes)):
        hal += [f"net j{j}pos joint.{j}.motor-pos-cmd => joint.{j}.motor-pos-fb"]
    hal += [
        "net estop-loop iocontrol.0.user-enable-out => iocontrol.0.emc-enable-in",
        "net tool-prep-loop iocontrol.0.tool-prepare => iocontrol.0.tool-prepared",
        "net tool-change-loop iocontrol.0.tool-change => iocontrol.0.tool-changed",
        "# G95/G96: the spindle is at the commanded speed at once (spindle.0.at-speed stays TRUE)",
        "net spindle-rps spindle.0.speed-out-rps => spindle.0.speed-in",
        "# the clock: periods from the first to the last period in which motion is not in position",
        "loadrt not names=oracle-moving",
        "loadrt or2 names=oracle-started",
        "loadrt conv_bit_float names=oracle-startedf",
        "loadrt integ names=oracle-elapsed",
        "loadrt mux2 names=oracle-last",
        "addf oracle-moving servo-thread",
        "addf oracle-started servo-thread",
        "addf oracle-startedf servo-thread",
        "addf oracle-elapsed servo-thread",
        "addf oracle-last servo-thread",
        # integ adds gain * in * period: with gain = 1/period it counts periods
        f"setp oracle-elapsed.gain {fmt(1.0e9 / servo_ns)}",
        "net oracle-inpos motion.in-position => oracle-moving.in",
        "net oracle-moving oracle-moving.out => oracle-started.in0 oracle-last.sel",
        "net oracle-started oracle-started.out => oracle-started.in1 oracle-startedf.in",
        "net oracle-startedf oracle-startedf.out => oracle-elapsed.in",
        "net oracle-elapsed oracle-elapsed.out => oracle-last.in1",
        "net oracle-last oracle-last.out => oracle-last.in0",
    ]
    with open(os.path.join(run_dir, "oracle.hal"), "w") as f:
        f.write("\n".join(hal) + "\n")
    return ini_path, servo_ns


def nml_keys():
    keys = []
    try:
        with open(NML_FILE) as f:
            for line in f:
                parts = line.split()
                if len(parts) >= 10 and parts[0] == "B" and parts[2] == "SHMEM":
                    keys.append(int(parts[9]))
    except OSError:
        pass
    return keys


def shm_segments():
    """key -> (shmid, attached processes) of the System V shared memory segments."""
    found = {}
    try:
        with open("/proc/sysvipc/shm") as f:
            next(f)
            for line in f:
                parts = line.split()
                found[int(parts[0])] = (int(parts[1]), int(parts[6]))
    except OSError:
        pass
    return found


def clear_stale_shm(verbose):
    """Removes the fixed-key segments a killed run left behind; refuses if something still uses them."""
    segments = shm_segments()
    for key in HAL_SHM_KEYS + nml_keys():
        if key in segments:
            shmid, attached = segments[key]
            if attached:
                raise OracleError(f"shared memory key {key:#x} is in use ({attached} attached): "
                                  "another LinuxCNC is running; the oracle runs one simulation at a time")
            log(verbose, f"removing stale shared memory key {key:#x}")
            subprocess.run(["ipcrm", "-m", str(shmid)], check=False, stderr=subprocess.DEVNULL)


def pids_with_token(token):
    """The processes whose environment carries this run's token: everything the run started,
    including the daemons that forked away (linuxcncsvr) and rtapi_app."""
    needle = f"CUTCALC_ORACLE_RUN={token}".encode()
    found = []
    for name in os.listdir("/proc"):
        if not name.isdigit() or int(name) == os.getpid():
            continue
        try:
            with open(f"/proc/{name}/environ", "rb") as f:
                if needle in f.read().split(b"\0"):
                    found.append(int(name))
        except OSError:
            continue
    return found


def raise_priority():
    """Runs in the child before exec: the simulation's processes get the CPU before anything else on
    the machine (nice -20 as root). Motion's servo thread counts simulated time, but task queues the
    moves and times dwells in wall-clock time: it has to keep pace with the servo thread even while a
    build loads every core."""
    try:
        os.nice(-20)
    except OSError:
        pass


class Run:
    def __init__(self, run_dir, ini_path, verbose):
        self.run_dir = run_dir
        self.ini = ini_path
        self.verbose = verbose
        self.token = uuid.uuid4().hex
        self.children = []
        self.env = dict(os.environ)
        self.env.update({
            "CUTCALC_ORACLE_RUN": self.token,
            "INI_FILE_NAME": ini_path,
            "HAL_RTMOD_DIR": RTLIB_DIR,
            "LINUXCNC_HOME": "/usr",
            "PATH": BIN + ":" + os.environ.get("PATH", "/usr/sbin:/usr/bin:/sbin:/bin"),
            "LANG": "C",
        })
        fifo_dir = os.path.join(run_dir, "rtapi")
        os.mkdir(fifo_dir)
        os.chmod(fifo_dir, 0o1777)
        self.env["RTAPI_FIFO_PATH"] = os.path.join(fifo_dir, "rtapi_fifo")
        if os.getuid() == 0:
            # rtapi_app refuses to run as root without a fallback (non-root) user
            self.env["RTAPI_UID"] = str(pwd.getpwnam(os.environ.get("ORACLE_RTAPI_USER", "nobody")).pw_uid)
        self.log_path = os.path.join(run_dir, "linuxcnc.log")
        self.log = open(self.log_path, "ab")

    def cmd(self, args, timeout, what, quiet=False):
        if not quiet:
            log(self.verbose, "$", " ".join(args))
        # output to a file, not a pipe: a daemon (linuxcncsvr) keeps a pipe open after its parent exits
        with tempfile.TemporaryFile() as out:
            try:
                done = subprocess.run(args, env=self.env, cwd=self.run_dir, stdin=subprocess.DEVNULL,
                                      stdout=out, stderr=subprocess.STDOUT, timeout=timeout,
                                      preexec_fn=raise_priority)
            except subprocess.TimeoutExpired:
                raise OracleError(f"{what}: timed out after {timeout} s")
            out.seek(0)
            text = out.read()
        self.log.write(text)
        self.log.flush()
        text = text.decode(errors="replace")
        if done.returncode != 0:
            raise OracleError(f"{what} failed ({done.returncode}): {text[-600:]}")
        return text

    def spawn(self, args):
        log(self.verbose, "&", " ".join(args))
        proc = subprocess.Popen(args, env=self.env, cwd=self.run_dir, stdin=subprocess.DEVNULL,
                                stdout=self.log, stderr=subprocess.STDOUT, preexec_fn=raise_priority)
        self.children.append(proc)
        return proc

    def components(self):
        return self.cmd([f"{BIN}/halcmd", "list", "comp"], 10, "halcmd list comp", quiet=True).split()

    def wait_component(self, name, proc, timeout):
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            if proc is not None and proc.poll() is not None:
                raise OracleError(f"{name} exited ({proc.returncode}) before it was ready")
            if name in self.components():
                return
            time.sleep(0.05)
        raise OracleError(f"HAL component {name} not ready within {timeout} s")

    def start(self):
        self.cmd([f"{BIN}/linuxcncsvr", "-ini", self.ini], 20, "linuxcncsvr")
        # rtapi_app as the master of this run's HAL; the halcmd calls below talk to it
        rtapi = self.spawn([f"{BIN}/rtapi_app"])
        end = time.monotonic() + 10
        while not os.path.exists(self.env["RTAPI_FIFO_PATH"]):
            if rtapi.poll() is not None or time.monotonic() > end:
                raise OracleError("rtapi_app did not start (see linuxcnc.log)")
            time.sleep(0.02)
        io = self.spawn([f"{BIN}/io", "-ini", self.ini])
        self.wait_component("iocontrol", io, 15)
        halui = self.spawn([f"{BIN}/halui", "-ini", self.ini])
        self.wait_component("halui", halui, 15)
        self.cmd([f"{BIN}/halcmd", "-i", self.ini, "-f", os.path.join(self.run_dir, "oracle.hal")], 30, "HAL file")
        # milltask initialises motion through the servo thread: start the threads, then wait for it
        task = self.spawn([f"{BIN}/milltask", "-ini", self.ini])
        self.cmd([f"{BIN}/halcmd", "start"], 10, "halcmd start")
        self.wait_component("inihal", task, 30)

    def run_display(self, timeout):
        args = [PYTHON, DISPLAY_SCRIPT, "-ini", self.ini]
        log(self.verbose, "$", " ".join(args))
        try:
            done = subprocess.run(args, env=self.env, cwd=self.run_dir, stdin=subprocess.DEVNULL,
                                  stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=timeout,
                                  preexec_fn=raise_priority)
        except subprocess.TimeoutExpired:
            raise OracleError(f"the display script timed out after {timeout} s")
        out = done.stdout.decode(errors="replace")
        self.log.write(done.stdout)
        self.log.flush()
        if done.returncode != 0 or "done" not in out.split():
            raise OracleError(f"the program did not run: {out.strip()[-600:]}")

    def getp(self, pin):
        return float(self.cmd([f"{BIN}/halcmd", "-s", "getp", pin], 10, f"halcmd getp {pin}").strip())

    def stop(self):
        """Orderly shutdown, then every process that carries this run's token is killed by its pid."""
        for args in (["halcmd", "stop"], ["halcmd", "unload", "all"]):
            try:
                self.cmd([f"{BIN}/{args[0]}"] + args[1:], 15, " ".join(args))
            except OracleError as e:
                log(self.verbose, "shutdown:", e)
        for proc in self.children:
            if proc.poll() is None:
                proc.send_signal(signal.SIGTERM)
        try:
            self.cmd([f"{BIN}/rtapi_app", "exit"], 10, "rtapi_app exit")
        except OracleError as e:
            log(self.verbose, "shutdown:", e)
        end = time.monotonic() + 5
        while time.monotonic() < end:
            left = pids_with_token(self.token)
            if not left:
                break
            for pid in left:
                try:
                    os.kill(pid, signal.SIGTERM)
                except ProcessLookupError:
                    pass
            time.sleep(0.2)
        for pid in pids_with_token(self.token):
            log(self.verbose, f"killing {pid}")
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        for proc in self.children:
            try:
                proc.wait(timeout=5)
            except subprocess.TimeoutExpired:
                pass
        self.log.close()


def run_program(program_text, machine, verbose=False, keep=False, lock_timeout_s=600.0):
    """One simulation: returns the simulated time in seconds."""
    # a generous budget for the run itself: the program runs in real time
    run_timeout_s = 120.0
    lock = open(LOCK_FILE, "a")
    end = time.monotonic() + lock_timeout_s
    while True:
        try:
            fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
            break
        except BlockingIOError:
            if time.monotonic() > end:
                raise OracleError(f"another oracle run held {LOCK_FILE} for {lock_timeout_s} s")
            time.sleep(0.2)
    run_dir = tempfile.mkdtemp(prefix="cutcalc-oracle-")
    os.chmod(run_dir, 0o755)
    run = None
    try:
        ini_path, servo_ns = write_config(run_dir, machine, program_text, run_timeout_s)
        clear_stale_shm(verbose)
        run = Run(run_dir, ini_path, verbose)
        run.start()
        run.run_display(run_timeout_s + 30)
        periods = run.getp("oracle-last.out")
        elapsed = run.getp("oracle-elapsed.out")
        log(verbose, f"periods {periods} (elapsed since start {elapsed})")
        # The last not-in-position period plus the one in which motion is back in position (the
        # reference's count, program-time.json: 0.601 s for G0 X80 where 600 periods are flagged)
        return (round(periods) + 1) * servo_ns * 1.0e-9
    except OracleError as e:
        if run is not None:
            raise OracleError(f"{e} (log: {run.log_path})" if keep else str(e))
        raise
    finally:
        if run is not None:
            run.stop()
        clear_stale_shm(verbose)
        if keep:
            print(f"[oracle] kept {run_dir}", file=sys.stderr)
        else:
            shutil.rmtree(run_dir, ignore_errors=True)
        fcntl.flock(lock, fcntl.LOCK_UN)
        lock.close()
        # let another process waiting for the lock take it before this one runs again
        time.sleep(0.3)


def load_machine(arg):
    text = open(arg).read() if os.path.exists(arg) else arg
    data = json.loads(text)
    if isinstance(data, dict) and "machine" in data and "axes" not in data:
        data = data["machine"]
    return data


def stop_on_signal(signum, _frame):
    # SIGTERM (e.g. from timeout(1)) unwinds like an error, so that everything started is stopped
    raise OracleError(f"stopped by signal {signum}")


def main():
    signal.signal(signal.SIGTERM, stop_on_signal)
    signal.signal(signal.SIGHUP, stop_on_signal)
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("program", help="G-code file (LinuxCNC dialect)")
    parser.add_argument("machine", help="machine object: a JSON file or inline JSON")
    parser.add_argument("--keep", action="store_true", help="keep the run directory (INI, HAL, log)")
    parser.add_argument("--verbose", "-v", action="store_true")
    args = parser.parse_args()
    try:
        with open(args.program) as f:
            program = f.read()
        seconds = run_program(program, load_machine(args.machine), verbose=args.verbose, keep=args.keep)
    except (OracleError, OSError, ValueError, KeyError) as e:
        print(f"time_program: {e}", file=sys.stderr)
        return 1
    print(f"{seconds:.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
