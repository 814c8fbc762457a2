"""The package's types: mypy (strict on the calls) accepts a user's script written against
the stubs (_sgmp.pyi, py.typed), and rejects one that passes the wrong types."""
import os
import pathlib
import subprocess
import sys

import pytest

import sgmp

GOOD = '''
import numpy
import sgmp

p: sgmp.Pack = sgmp.pack(150, "loose-random", seed=1, sweep_stages=(8, 120))
m = sgmp.measure(p, gr_bin=0.02)
g = m["g_r"]
box = p.header["container"]
q = sgmp.read("x.xyz", frame=1)
sgmp.write(q, "y.xyz", force=True, up="z")
n: int = len(p)
r: numpy.ndarray = p.positions
'''

BAD = '''
import sgmp

p = sgmp.pack("150", "loose-random")
sgmp.write(p, "y.xyz", force="yes")
'''


def mypy(tmp_path, text):
    script = tmp_path / "script.py"
    script.write_text(text)
    package_root = pathlib.Path(sgmp.__file__).resolve().parent.parent
    environment = dict(os.environ, MYPYPATH=str(package_root))
    return subprocess.run([sys.executable, "-m", "mypy", "--no-incremental",
                           "--disallow-untyped-calls", "--cache-dir", str(tmp_path / "cache"),
                           str(script)], capture_output=True, text=True, env=environment,
                          cwd=tmp_path)


def test_the_package_is_marked_typed():
    here = pathlib.Path(sgmp.__file__).resolve().parent
    assert (here / "py.typed").exists() and (here / "_sgmp.pyi").exists()


def test_mypy_accepts_a_typed_script_and_refuses_wrong_types(tmp_path):
    pytest.importorskip("mypy")
    good = mypy(tmp_path, GOOD)
    assert good.returncode == 0, good.stdout + good.stderr
    bad = mypy(tmp_path, BAD)
    assert bad.returncode == 1, bad.stdout + bad.stderr
    assert 'Argument 1 to "pack" has incompatible type "str"; expected "int"' in bad.stdout
    assert 'Argument "force" to "write" has incompatible type "str"' in bad.stdout
