#!/usr/bin/env python3
"""Property test: every numeric option of every command, at its stated bounds, just past
them, and at the extremes (±1e308, NaN, ±inf, 2⁶⁴, −2⁶³−1, the smallest doubles), is either
accepted or refused in one line; no value crashes a tool, hangs it, or leaves a temporary.

Options are found from each command's --help (types INT, UINT, FLOAT, and `FLOAT x 6` for
--region); `sgmp batch`'s grid options are the numeric options of `sgmp pack` it lists.
The bounds are the numbers each option's help text states, each tried as it is and moved
by one part in 10⁹ (one for integers) either way.

A run passes when it
  - exits with 0, 1, 2 or 3 (never a signal: no SIGSEGV, SIGABRT, SIGFPE) within 120 s;
  - on a refusal (status 1 or 2) prints a first stderr line prefixed with the program's
    name, and on a usage error (status 2) exactly one line, which names the option;
  - prints no internal text (std::, terminate, what(), json.exception, Assertion);
  - leaves no `.NAME.tmp-…` temporary in its directory.

Usage: option_extremes.py SGMP SGMP_COMPARE SGMP_REFERENCE WORKDIR [--quick]
(--quick: the extreme values only). Exit 0 when every run passes, 1 with the failures listed.
"""
import concurrent.futures
import math
import os
import re
import shutil
import subprocess
import sys

EXTREMES = ["1e308", "-1e308", "nan", "-nan", "inf", "-inf", "1e30", "-1", "0",
            "18446744073709551616", "-9223372036854775809", "1e-308", "4.9e-324"]
INTERNAL = ["std::", "terminate called", "what()", "json.exception", "Assertion",
            "AddressSanitizer", "Segmentation", "core dumped"]
OPTION = re.compile(r"^\s+(?:-\w,)?--([a-z0-9-]+) (INT|UINT|FLOAT)( x 6)?\b(.*)$")
NUMBER = re.compile(r"(?<![\w.])-?\d+(?:\.\d+)?(?:e[+-]?\d+)?")
TIMEOUT = 120


def options_of(command):
    """(name, type, six, help text) of the numeric options in `command --help`."""
    text = subprocess.run(command + ["--help"], capture_output=True, text=True).stdout
    # A description wrapped at 100 columns continues on lines indented past the option
    # column: join them to their option's line so the bounds are read whole.
    lines = []
    for line in text.splitlines():
        if lines and re.match(r"^ {20,}\S", line) and not line.strip().startswith("-"):
            lines[-1] += " " + line.strip()
        else:
            lines.append(line)
    found = []
    for line in lines:
        m = OPTION.match(line)
        if m and m.group(1) not in ("help",):
            found.append((m.group(1), m.group(2), bool(m.group(3)), m.group(4)))
    return found


def bound_values(kind, text):
    """The numbers the help text states, as given and moved just past each way."""
    values = []
    for token in NUMBER.findall(text.split("(see")[0]):
        x = float(token)
        if not math.isfinite(x):
            continue
        if kind in ("INT", "UINT") and x == int(x):
            values += [str(int(x) - 1), str(int(x)), str(int(x) + 1)]
        else:
            step = abs(x) * 1e-9 if x != 0 else 1e-300
            values += [repr(x - step), token, repr(x + step)]
    return values


class Case:
    def __init__(self, base, option, value, six, work):
        self.base, self.option, self.value = base, option, value
        self.six, self.work = six, work

    def argv(self):
        if self.six:
            values = [self.value] * 6
        else:
            values = [self.value]
        return self.base + ["--" + self.option] + values

    def describe(self):
        return " ".join(self.argv()).replace(self.work, "WORK")


def check(case, program):
    directory = case.work
    try:
        run = subprocess.run(case.argv(), capture_output=True, text=True, cwd=directory,
                             timeout=TIMEOUT, errors="replace")
    except subprocess.TimeoutExpired:
        return f"{case.describe()}: still running after {TIMEOUT} s"
    problems = []
    lines = [line for line in run.stderr.splitlines() if line.strip()]
    if run.returncode < 0 or run.returncode not in (0, 1, 2, 3):
        problems.append(f"exit {run.returncode}")
    if run.returncode in (1, 2):
        if not lines or not lines[0].startswith(program):
            problems.append("a refusal not prefixed with the program's name")
    if run.returncode == 2:
        if len(lines) != 1:
            problems.append(f"{len(lines)} lines on a usage error")
        elif case.option not in lines[0]:
            problems.append("a usage error that does not name the option")
    for marker in INTERNAL:
        if marker in run.stderr or marker in run.stdout:
            problems.append(f"internal text '{marker}'")
    for name in os.listdir(directory):
        if ".tmp-" in name:
            problems.append(f"temporary {name} left")
            shutil.rmtree(os.path.join(directory, name), ignore_errors=True)
    if problems:
        first = lines[0] if lines else ""
        return f"{case.describe()}: {'; '.join(problems)} [{first[:160]}]"
    return None


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    quick = "--quick" in sys.argv
    if len(args) != 4:
        print("option_extremes: usage: option_extremes.py SGMP SGMP_COMPARE SGMP_REFERENCE "
              "WORKDIR [--quick]", file=sys.stderr)
        return 2
    sgmp, compare, reference, work = (os.path.abspath(a) for a in args)
    work = os.path.abspath(work)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    pack = os.path.join(work, "p.xyz")
    subprocess.run([sgmp, "pack", "--count", "40", "--arrangement", "loose-random",
                    "--out", pack], check=True, capture_output=True)
    other = os.path.join(work, "q.xyz")
    subprocess.run([sgmp, "pack", "--count", "40", "--arrangement", "loose-random",
                    "--seed", "2", "--out", other], check=True, capture_output=True)
    manifest = os.path.join(work, "manifest.csv")
    with open(manifest, "w") as f:
        f.write("role,group,count,seed,seconds,path\n"
                f"candidate,a,40,1,,{pack}\nreference,b,40,2,,{other}\n")
    out = os.path.join(work, "out")
    # Each command with arguments that make it valid, so the option under test decides.
    commands = {
        "sgmp pack": [sgmp, "pack", "--count", "40", "--arrangement", "loose-random",
                      "--out", out + ".xyz", "--force"],
        "sgmp arrange": [sgmp, "arrange", "--count", "40", "--arrangement", "loose-random",
                         "--out", out + ".xyz", "--force"],
        "sgmp convert": [sgmp, "convert", pack, out + ".data", "--force"],
        "sgmp render": [sgmp, "render", pack, "--out", out + ".png", "--force", "--size", "64x64"],
        "sgmp batch": [sgmp, "batch", "--seeds", "1", "--count", "40", "--arrangement",
                       "loose-random", "--no-packs", "--summary", out + ".csv", "--force",
                       "--progress-seconds", "0"],
        "sgmp-compare measure": [compare, "measure", pack, "--out", out, "--force"],
        "sgmp-compare report": [compare, "report", "--a", pack, "--b", other, "--out", out,
                                "--force"],
        "sgmp-compare crossval": [compare, "crossval", "--manifest", manifest, "--out", out,
                                  "--force"],
        "sgmp-reference pour": [reference, "pour", "--count", "40", "--seed", "1", "--out",
                                out + ".xyz", "--force", "--liggghts", "/bin/true"],
        "sgmp-reference settle": [reference, "settle", pack, "--friction", "0.5", "--out",
                                  out + ".xyz", "--force", "--liggghts", "/bin/true"],
    }
    cases = []
    pack_numeric = {name: (kind, text) for name, kind, _, text in options_of([sgmp, "pack"])}
    for label, base in commands.items():
        program = label.split()[0]
        found = options_of(base[:2])
        if label == "sgmp batch":
            listed = subprocess.run(base[:2] + ["--help"], capture_output=True,
                                    text=True).stdout
            found += [(name, kind, False, text) for name, (kind, text) in pack_numeric.items()
                      if re.search(rf"--{name} TEXT", listed) and name != "seed"]
        if not found and label not in ("sgmp-compare report", "sgmp-compare crossval"):
            print(f"option_extremes: {label} lists no numeric option", file=sys.stderr)
            return 1
        for name, kind, six, text in found:
            values = EXTREMES if quick else EXTREMES + bound_values(kind, text)
            for value in dict.fromkeys(values):
                directory = os.path.join(work, f"run{len(cases)}")
                os.makedirs(directory)
                base_here = [a.replace(out, os.path.join(directory, "out")) for a in base]
                cases.append((Case(base_here, name, value, six, directory), program))
    failures = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        for result in pool.map(lambda c: check(*c), cases):
            if result:
                failures.append(result)
    options = {(c.base[0], c.base[1], c.option) for c, _ in cases}
    print(f"option_extremes: {len(cases)} runs over {len(options)} options, "
          f"{len(failures)} failed")
    for failure in failures:
        print("  " + failure)
    if not failures:
        shutil.rmtree(work, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
