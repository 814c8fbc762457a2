"""The parts every benchmark shares (scripts/bench and scripts/bench-*).

- Options and help: `parser(doc)` makes the script's argparse parser, its help the script's
  docstring; a bad option exits 2.
- The build: `executables("sgmp/sgmp", ...)` returns the executables of the build
  directory. With SGMP_BUILD_DIR set, that directory is used as it is (a missing executable
  is a runtime failure); without it, build/ is made or brought up to date by scripts/build
  first when an executable is missing or a source file is newer than one.
- Measuring: `run(command)` runs a command once and measures it; `best_of(command, runs=3)`
  runs it several times and keeps the least wall clock, CPU seconds and peak memory. Wall
  seconds come from a monotonic clock around the process; CPU seconds (user + system) from
  os.wait4, so they cover every process the command waits for (the ranks under mpirun, the
  threads of the process). The peak resident set size is GNU time's (`/usr/bin/time -f %M`,
  Debian `time`), which starts the command from its own small process: Linux carries a
  process's memory high-water mark across exec, so a command started from this Python
  process would report at least the interpreter's own (about 14 MB) however little it uses.
  The CPU seconds include GNU time's own start, about 0.4 ms.
- Reporting: `Table` prints a header, a rule and rows of columns separated by " | ";
  `Targets` gives PASS/FAIL verdicts against targets, prints target lines, and keeps the
  exit status.
- Exit codes, through `main`: 0 every target met, 3 a target missed (a failed check),
  1 a runtime failure (`RunFailure`: a command failed, an executable is missing, the build
  failed), 2 a usage error, 130 interrupted.
"""
import argparse
import math
import os
import re
import shlex
import signal
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

EXIT_MET = 0
EXIT_RUNTIME_FAILURE = 1
EXIT_USAGE = 2
EXIT_MISSED = 3
EXIT_INTERRUPTED = 130

# What a build of build/ is made from: a file here newer than an executable means the
# executable is out of date.
SOURCE_FOLDERS = ("sgmp", "compare", "reference", "tests", "cmake")
SOURCE_SUFFIXES = (".cpp", ".hpp", ".h", ".in", ".cmake")

current_script = "bench"


class RunFailure(Exception):
    """A command that failed, a missing executable or a failed build: exit status 1."""


def main(script_name, body):
    """Runs body() from the project root and exits with its status (0 or 3), 1 when it
    raises RunFailure, 2 on a usage error, 130 when interrupted."""
    global current_script
    current_script = script_name
    sys.stdout.reconfigure(line_buffering=True)
    os.chdir(ROOT)
    try:
        status = body()
    except RunFailure as failure:
        print(f"{current_script}: {failure}", file=sys.stderr)
        status = EXIT_RUNTIME_FAILURE
    except KeyboardInterrupt:
        print(f"{current_script}: interrupted", file=sys.stderr)
        status = EXIT_INTERRUPTED
    sys.exit(status)


def parser(doc):
    """An argparse parser whose help is the script's docstring."""
    return argparse.ArgumentParser(prog=f"scripts/{current_script}", description=doc,
                                   formatter_class=argparse.RawDescriptionHelpFormatter)


def note(message):
    """A line on stderr, prefixed with the script's name (progress, skipped parts)."""
    print(f"{current_script}: {message}", file=sys.stderr, flush=True)


def cpus():
    """The CPUs this process may run on (its affinity mask), as nproc counts them."""
    return len(os.sched_getaffinity(0))


def load_average():
    with open("/proc/loadavg") as f:
        return " ".join(f.read().split()[:3])


# --- The build -----------------------------------------------------------------------------

def build_dir():
    """SGMP_BUILD_DIR (relative to the project root) when set, else build/."""
    chosen = os.environ.get("SGMP_BUILD_DIR")
    return (ROOT / chosen).resolve() if chosen else ROOT / "build"


def _newest_source_after(moment):
    """A source file changed after `moment` (seconds since the epoch), or None."""
    for folder in SOURCE_FOLDERS:
        for directory, _, files in os.walk(ROOT / folder):
            for file_name in files:
                if file_name == "CMakeLists.txt" or file_name.endswith(SOURCE_SUFFIXES):
                    path = Path(directory) / file_name
                    if path.stat().st_mtime > moment:
                        return path
    top = ROOT / "CMakeLists.txt"
    return top if top.stat().st_mtime > moment else None


def _is_executable(path):
    return path.is_file() and os.access(path, os.X_OK)


def executables(*relative):
    """The executables `relative` (paths inside the build directory, e.g. "sgmp/sgmp"),
    built first when needed: see the module's docstring."""
    directory = build_dir()
    paths = [directory / r for r in relative]
    chosen = bool(os.environ.get("SGMP_BUILD_DIR"))
    if not chosen:
        missing = [p for p in paths if not _is_executable(p)]
        changed = None if missing else _newest_source_after(min(p.stat().st_mtime for p in paths))
        if missing or changed:
            reason = (f"{missing[0].relative_to(ROOT)} is missing" if missing
                      else f"{changed.relative_to(ROOT)} is newer than the executables")
            note(f"building with scripts/build ({reason}; log: build/build.log)")
            if subprocess.run([str(ROOT / "scripts" / "build")]).returncode != 0:
                raise RunFailure("scripts/build failed")
    for path in paths:
        if not _is_executable(path):
            hint = (" (SGMP_BUILD_DIR is used as it is: build it there, or unset SGMP_BUILD_DIR "
                    "to build build/ with scripts/build)" if chosen else "")
            raise RunFailure(f"{path} is missing{hint}")
    return paths


# --- Measuring -----------------------------------------------------------------------------

@dataclass
class Measurement:
    """One measured command: seconds of wall clock, CPU seconds (user + system) and the
    peak resident set size in bytes, with what it printed."""
    wall: float
    cpu: float
    peak_rss: int
    stdout: str = ""
    stderr: str = ""
    stopped: bool = False  # stopped at its time limit (run(..., limit=...))


@dataclass
class Best:
    """Several measurements of one command and the least of each figure over them."""
    runs: list = field(default_factory=list)

    @property
    def wall(self):
        return min(m.wall for m in self.runs)

    @property
    def cpu(self):
        return min(m.cpu for m in self.runs)

    @property
    def peak_rss(self):
        return min(m.peak_rss for m in self.runs)

    @property
    def last(self):
        return self.runs[-1]


def shown(command):
    return " ".join(shlex.quote(str(part)) for part in command)


GNU_TIME = "/usr/bin/time"


def _stop_group(process, grace=10):
    """SIGTERM to the process group of `process` (its own session), SIGKILL after `grace` s."""
    try:
        os.killpg(process.pid, signal.SIGTERM)
        process.wait(timeout=grace)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass


def _stop_at_limit(process, done, grace=10):
    """At the time limit (on the timer's thread): SIGTERM to the command's process group,
    SIGKILL after `grace` s unless it has ended. It never waits for the process: the
    caller's wait4 reaps it (a wait here raced it, and wait4 then found no child)."""
    try:
        os.killpg(process.pid, signal.SIGTERM)
        if not done.wait(grace):
            os.killpg(process.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass


def _run_once(command, cwd, env, limit=None):
    if not _is_executable(Path(GNU_TIME)):
        raise RunFailure(f"{GNU_TIME} is missing (Debian package `time`, from scripts/setup)")
    with tempfile.TemporaryFile() as out, tempfile.TemporaryFile() as err, \
            tempfile.NamedTemporaryFile(mode="r", prefix="bench-rss-") as rss:
        start = time.perf_counter()
        # With a time limit the command gets its own session, so that the whole of it (GNU
        # time and what it runs) can be stopped at the limit or on an interrupt.
        process = subprocess.Popen([GNU_TIME, "-f", "%M", "-o", rss.name]
                                   + [str(part) for part in command], cwd=cwd, env=env,
                                   stdin=subprocess.DEVNULL, stdout=out, stderr=err,
                                   start_new_session=limit is not None)
        done = threading.Event()
        timer = (threading.Timer(limit, _stop_at_limit, (process, done))
                 if limit is not None else None)
        if timer:
            timer.start()
        try:
            _, wait_status, usage = os.wait4(process.pid, 0)
            done.set()
        except BaseException:
            done.set()
            # Interrupted: Ctrl-C reached the command too (GNU time waits for it), unless it
            # runs in its own session.
            if timer:
                timer.cancel()
                _stop_group(process)
            try:
                process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()
            raise
        stopped = False
        if timer:
            timer.cancel()
            stopped = time.perf_counter() - start >= limit
        wall = time.perf_counter() - start
        process.returncode = os.waitstatus_to_exitcode(wait_status)
        out.seek(0)
        err.seek(0)
        reported = rss.read().split()
        measurement = Measurement(wall=wall, cpu=usage.ru_utime + usage.ru_stime,
                                  peak_rss=int(reported[-1]) * 1024 if reported else 0,
                                  stdout=out.read().decode(errors="replace"),
                                  stderr=err.read().decode(errors="replace"),
                                  stopped=stopped)
    return process.returncode, measurement


def run(command, *, repeat=1, cwd=None, env=None, check=True, limit=None):
    """Runs `command` (a list) `repeat` times back to back and measures it: wall and CPU
    seconds are the mean of one run (repeat a command shorter than the clocks resolve), the
    peak RSS the largest. A failing run raises RunFailure with the end of its stderr, unless
    check=False. The output is that of the last run. With `limit` (seconds), a run still
    going at the limit is stopped (SIGTERM, then SIGKILL) and returned with stopped=True."""
    total_wall = total_cpu = 0.0
    peak = 0
    for _ in range(repeat):
        status, m = _run_once(command, cwd, env, limit)
        if m.stopped:
            return m
        if status != 0 and check:
            tail = (m.stderr or m.stdout)[-2000:].rstrip()
            raise RunFailure(f"{shown(command)} failed (status {status})"
                             + (f":\n{tail}" if tail else ""))
        total_wall += m.wall
        total_cpu += m.cpu
        peak = max(peak, m.peak_rss)
    return Measurement(wall=total_wall / repeat, cpu=total_cpu / repeat, peak_rss=peak,
                       stdout=m.stdout, stderr=m.stderr)


def best_of(command, runs=3, *, once_above=None, **options):
    """Measures `command` `runs` times (see run; options go to it) and returns them all,
    with the least wall clock, CPU seconds and peak RSS over them. A command whose run takes
    more than `once_above` CPU seconds is not measured again."""
    best = Best()
    for _ in range(runs):
        best.runs.append(run(command, **options))
        if once_above is not None and best.runs[-1].cpu > once_above:
            break
    return best


def pack_header(path):
    """The header keys of an extended XYZ pack file (its second line) as a dict."""
    with open(path) as f:
        f.readline()
        line = f.readline()
    keys = {}
    for token in shlex.split(line):
        key, sep, value = token.partition("=")
        if sep:
            keys[key] = value
    return keys


def seconds_of_clock(text):
    """Seconds of a clock reading h:mm:ss or m:ss(.ss)."""
    total = 0.0
    for part in text.split(":"):
        total = 60.0 * total + float(part)
    return total


# --- Reporting -----------------------------------------------------------------------------

class Table:
    """Rows of columns separated by " | ". Each column is (title, width): a positive width
    right-aligns, a negative one left-aligns, 0 (the last column) is not padded."""

    def __init__(self, *columns, out=None):
        self.columns = columns
        self.out = out or sys.stdout

    def _line(self, cells):
        parts = []
        for (_, width), cell in zip(self.columns, cells):
            text = str(cell)
            parts.append(text if width == 0 else
                         text.rjust(width) if width > 0 else text.ljust(-width))
        return " | ".join(parts)

    def header(self):
        print(self._line([title for title, _ in self.columns]), file=self.out)
        rule = []
        last = len(self.columns) - 1
        for i, (title, width) in enumerate(self.columns):
            span = abs(width) if width else max(len(title), 6)
            rule.append("-" * (span + (1 if i in (0, last) else 2)))
        print("|".join(rule), file=self.out)

    def row(self, *cells):
        print(self._line(cells), file=self.out)


def met(value, relation, target):
    """Whether `value` meets `target` under `relation` ("<=" or ">=")."""
    if relation == "<=":
        return value <= target
    if relation == ">=":
        return value >= target
    raise ValueError(f"relation {relation!r} is neither <= nor >=")


class Targets:
    """Verdicts against targets. A binding verdict that fails makes the exit status 3; with
    binding=False (quick sizes, where the targets do not apply) verdicts only show the
    format."""

    def __init__(self, binding=True):
        self.binding = binding
        self.missed = 0

    def verdict(self, value, relation, target):
        """PASS or FAIL (counted as missed when binding); "-" without a target."""
        if target is None:
            return "-"
        if isinstance(value, float) and math.isnan(value):
            ok = False
        else:
            ok = met(value, relation, target)
        if not ok and self.binding:
            self.missed += 1
        return "PASS" if ok else "FAIL"

    def line(self, caption, value, unit, relation, target):
        """Prints "  caption  value unit  target <=|>= target unit  PASS|FAIL"."""
        verdict = self.verdict(value, relation, target)
        print(f"  {caption:34s} {value:10.3f} {unit:5s} target {relation} {target:8.3f} "
              f"{unit:5s} {verdict}")
        return verdict

    @staticmethod
    def info(caption, value, unit, remark=""):
        """Prints "  caption  value unit  remark": a figure without a target."""
        print(f"  {caption:34s} {value:10.3f} {unit:5s} {remark}".rstrip())

    def status(self):
        return EXIT_MISSED if self.missed else EXIT_MET


def combined_status(statuses):
    """The status of several benchmarks: 1 when one failed to run (any status but 0 and 3),
    else 3 when one missed a target, else 0."""
    if any(s not in (EXIT_MET, EXIT_MISSED) for s in statuses):
        return EXIT_RUNTIME_FAILURE
    return EXIT_MISSED if EXIT_MISSED in statuses else EXIT_MET


def first_number(pattern, text, what):
    """The first group of `pattern` in `text` as a float; RunFailure naming `what` if absent."""
    found = re.search(pattern, text, re.MULTILINE)
    if not found:
        raise RunFailure(f"no {what} in the output:\n{text[-2000:]}")
    return float(found.group(1))
