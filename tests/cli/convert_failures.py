#!/usr/bin/env python3
"""`sgmp convert` under failure: out of memory, a refused header, and SIGTERM while a
`.vtk` pair replaces another with --force.

A run passes when
  - out of memory (`ulimit -v 90000`, a 10⁶-sphere pack) is one line, "sgmp convert:
    out of memory: …", status 1 (was "sgmp convert: std::bad_alloc");
  - a header value with ESC and BEL is refused in one line with status 1;
  - after SIGTERM at any moment of `convert big.xyz.gz o.vtk --force` over the pair of a
    small pack, o.vtk and o.container.vtk are both the small pack's or both the big one's
    (the old particles were once left without their container), with no temporary.

Usage: convert_failures.py SGMP WORKDIR. Exit 0 when every check passes, 1 with the
failures listed.
"""
import gzip
import os
import shutil
import signal
import subprocess
import sys
import time

def write_big(path, count):
    with gzip.open(path, "wt", compresslevel=1) as out:
        out.write(f'{count}\nProperties=id:I:1:pos:R:3:radius:R:1 pbc="F F F"\n')
        for i in range(count):
            out.write(f"{i + 1} {i % 100 * 0.01:.2f} {i // 100 % 100 * 0.01:.2f} "
                      f"{i // 10000 * 0.01:.2f} 0.004\n")


def run(command, cwd):
    done = subprocess.run(["sh", "-c", command], cwd=cwd, capture_output=True, text=True)
    return done.returncode, done.stderr


def read(path):
    with open(path, "rb") as f:
        return f.read()


def check_out_of_memory(sgmp, work, failures):
    status, err = run(f"ulimit -v 90000; OMP_NUM_THREADS=1 '{sgmp}' convert huge.xyz.gz m.data",
                      work)
    if status != 1 or not err.startswith("sgmp convert: out of memory: ") or err.count("\n") != 1:
        failures.append(f"out of memory: status {status}, {err!r}")
    if os.path.exists(os.path.join(work, "m.data")):
        failures.append("out of memory: m.data was written")


def check_control_characters(sgmp, work, failures):
    with open(os.path.join(work, "esc.xyz"), "w") as f:  # `header` exits 1 on it too
        f.write('1\nProperties=id:I:1:pos:R:3:radius:R:1 note=\x1b[31mred\x07\n1 0 0 0 0.05\n')
    status, err = run(f"'{sgmp}' convert esc.xyz esc_out.xyz", work)
    if status != 1 or "holds a control character" not in err or err.count("\n") != 1:
        failures.append(f"control characters: status {status}, {err!r}")


def check_interrupted_pair(sgmp, work, failures):
    """SIGTERM at spread-out moments of a --force convert over an existing pair."""
    for name, source in (("small", "small.xyz"), ("big", "big.xyz.gz")):
        status, err = run(f"'{sgmp}' convert {source} {name}.vtk", work)
        if status != 0:
            failures.append(f"reference pair {name}: {err!r}")
            return
    pairs = {name: (read(os.path.join(work, f"{name}.vtk")),
                    read(os.path.join(work, f"{name}.container.vtk")))
             for name in ("small", "big")}
    start = time.monotonic()
    run(f"'{sgmp}' convert big.xyz.gz timing.vtk", work)
    duration = time.monotonic() - start
    for step in range(12):
        for suffix in (".vtk", ".container.vtk"):
            shutil.copyfile(os.path.join(work, "small" + suffix),
                            os.path.join(work, "o" + suffix))
        child = subprocess.Popen([sgmp, "convert", "big.xyz.gz", "o.vtk", "--force"], cwd=work,
                                 stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        time.sleep(duration * (0.5 + 0.05 * step))  # around the end, where the pair is renamed
        child.send_signal(signal.SIGTERM)
        status = child.wait()
        got = (read(os.path.join(work, "o.vtk")), read(os.path.join(work, "o.container.vtk")))
        if got not in pairs.values():
            failures.append(f"SIGTERM step {step} (status {status}): o.vtk and "
                            "o.container.vtk are not one pack's pair")
        leftovers = [n for n in os.listdir(work) if ".tmp-" in n]
        if leftovers:
            failures.append(f"SIGTERM step {step}: temporaries left: {leftovers}")


def main(argv):
    sgmp = os.path.abspath(argv[1])
    work = os.path.abspath(argv[2])
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    write_big(os.path.join(work, "huge.xyz.gz"), 1000000)
    write_big(os.path.join(work, "big.xyz.gz"), 300000)
    with open(os.path.join(work, "small.xyz"), "w") as f:
        f.write('2\nProperties=id:I:1:pos:R:3:radius:R:1 pbc="F F F"\n'
                "1 0 0 0 0.05\n2 0.2 0 0 0.05\n")
    failures = []
    check_out_of_memory(sgmp, work, failures)
    check_control_characters(sgmp, work, failures)
    check_interrupted_pair(sgmp, work, failures)
    for failure in failures:
        print("FAIL", failure)
    if not failures:
        shutil.rmtree(work, ignore_errors=True)
        print("convert_failures: all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
