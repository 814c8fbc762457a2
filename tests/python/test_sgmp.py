"""The Python module against the command line: the same pack bytes as `sgmp pack`, the
same metrics as `sgmp-compare measure`, the same one-line errors, read/write round trips,
and the README's example script."""

import json
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import sgmp

# CTest sets these; run by hand (PYTHONPATH=build/sgmp/python /usr/bin/python3 -m pytest
# tests/python) they default to the source tree holding this file and its build/.
SOURCE = pathlib.Path(os.environ.get("SGMP_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
SGMP = os.environ.get("SGMP_EXECUTABLE", SOURCE / "build" / "sgmp" / "sgmp")
COMPARE = os.environ.get("SGMP_COMPARE_EXECUTABLE", SOURCE / "build" / "compare" / "sgmp-compare")


def run(*args):
    return subprocess.run([str(a) for a in args], capture_output=True, text=True, check=False)


@pytest.mark.parametrize(
    "options, cli",
    [
        (dict(count=300, arrangement="small-dense", seed=3), []),
        (
            dict(count=200, arrangement="large-dense", seed=5, gap="random", contact="roll",
                 sweep_stages="8,120", circle_factor=40, size_modes="1:0.7,0.5:0.3"),
            ["--gap", "random", "--contact", "roll", "--sweep-stages", "8,120",
             "--circle-factor", "40", "--size-modes", "1:0.7,0.5:0.3"],
        ),
        (
            dict(count=150, arrangement="loose-random", seed=2, relax="frictionless",
                 relax_stages=3, fall="step", fall_step=0.002),
            ["--relax", "frictionless", "--relax-stages", "3", "--fall", "step",
             "--fall-step", "0.002", "--keep-uncertified"],
        ),
        (
            dict(count=50, arrangement="loose-random", seed=3, size_modes="1:0.6,0.5:0.4",
                 fraction_basis="volume", relax="frictional", relax_friction=0.3,
                 relax_stages=1),
            ["--size-modes", "1:0.6,0.5:0.4", "--fraction-basis", "volume", "--relax",
             "frictional", "--relax-friction", "0.3", "--relax-stages", "1",
             "--keep-uncertified"],
        ),
    ],
)
@pytest.mark.cli
def test_pack_writes_the_same_bytes_as_sgmp_pack(tmp_path, options, cli):
    ours = tmp_path / "python.xyz"
    theirs = tmp_path / "cli.xyz"
    sgmp.write(sgmp.pack(**options), ours)
    r = run(SGMP, "pack", "--count", options["count"], "--arrangement", options["arrangement"],
            "--seed", options["seed"], "--out", theirs, *cli)
    assert r.returncode == 0, r.stderr
    assert ours.read_bytes() == theirs.read_bytes()


def test_arrays_and_header():
    p = sgmp.pack(count=120, arrangement="loose-random", seed=4)
    assert len(p) == 120
    assert p.positions.shape == (120, 3) and p.positions.dtype == np.float64
    assert p.radii.shape == (120,) and p.bins.shape == (120,)
    assert set(np.unique(p.bins)) <= set(range(10))
    assert list(p.ids) == list(range(1, 121))
    h = p.header
    assert h["generator"] == "sgmp" and h["seed"] == 4 and h["arrangement"] == "loose-random"
    # Sizing rule: d = (18 phi* / (pi N))^(1/3) with phi* = 0.63.
    d = (18 * 0.63 / (np.pi * 120)) ** (1 / 3)
    assert np.allclose(2 * p.radii, d, rtol=1e-15, atol=0)
    start = sgmp.arrange(count=120, arrangement="loose-random", seed=4)
    assert start.header["generator"] == "sgmp" and len(start) == 120


@pytest.mark.cli
def test_measure_equals_sgmp_compare_measure(tmp_path):
    path = tmp_path / "p.xyz"
    sgmp.write(sgmp.pack(count=600, arrangement="large-dense", seed=1), path)
    r = run(COMPARE, "measure", path, "--out", tmp_path / "m")
    assert r.returncode == 0, r.stderr
    expected = json.loads((tmp_path / "m" / "p.metrics.json").read_text())
    m = sgmp.measure(sgmp.read(path))
    for key in ["phi", "count", "overlaps", "z_mean_tol_1e-3", "z_mean_tol_1e-2", "split_ratio",
                "q6_global", "q6_local_mean", "voronoi_phi_mean", "voronoi_phi_sd", "top"]:
        assert m[key] == expected[key], key  # exactly: the same code on the same pack
    g = np.genfromtxt(tmp_path / "m" / "p.g_r.csv", delimiter=",", comments="#", names=True)
    # The CSV's numbers are written in shortest round-trip form, so they read back exactly.
    assert np.array_equal(m["g_r"][:, 0], g["r_over_d"])
    assert np.array_equal(m["g_r"][:, 1], g["g"])
    phi_y = np.genfromtxt(tmp_path / "m" / "p.phi_y.csv", delimiter=",", comments="#",
                          names=True)
    assert np.array_equal(m["phi_y"][:, 1], phi_y["phi"])
    p_z = np.genfromtxt(tmp_path / "m" / "p.p_z.csv", delimiter=",", comments="#", names=True)
    assert np.array_equal(m["p_z"][:, 0], p_z["z"])
    assert np.array_equal(m["p_z"][:, 1 + m["p_z_tolerances"].index("1e-3")], p_z["p_tol_1e3"])
    # P(Z) sums to 1 at every tolerance (each origin has one Z).
    assert np.allclose(m["p_z"][:, 1:].sum(axis=0), 1.0, rtol=0, atol=1e-12)
    assert "g_r_partial" not in m and "phi_y_species" not in m  # one species


@pytest.mark.cli
def test_metric_table_names_every_scalar_measure_returns():
    table = sgmp.metric_table()
    names = [d["name"] for d in table]
    assert len(names) == len(set(names))
    m = sgmp.measure(sgmp.pack(count=300, arrangement="small-dense", seed=1))
    for d in table:
        assert d["kind"] in ("scalar", "curve", "distribution")
        assert d["definition"].startswith("compare/docs/definitions.md#")
        if d["in_metrics_json"]:
            assert d["kind"] == "scalar" and d["name"] in m, d["name"]
    assert {d["name"] for d in table if d["kind"] == "curve"} == {"g_r"}
    assert [d["summary_column"] for d in table if d["name"] == "z_mean_tol_1e-3"] == ["z_1e-3"]


def test_measure_of_a_blend_gives_the_partial_curves_of_sgmp_compare(tmp_path):
    path = tmp_path / "b.xyz"
    sgmp.write(sgmp.pack(count=800, arrangement="loose-random", seed=2, sides="periodic",
                         size_modes="1:0.5,0.5:0.5", fraction_basis="volume"), path)
    r = run(COMPARE, "measure", path, "--out", tmp_path / "m")
    assert r.returncode == 0, r.stderr
    expected = json.loads((tmp_path / "m" / "b.metrics.json").read_text())
    g = np.genfromtxt(tmp_path / "m" / "b.g_r.csv", delimiter=",", comments="#", names=True)
    m = sgmp.measure(sgmp.read(path))
    pairs = {pair["column"]: pair for pair in expected["species"]["pairs"]}
    assert sorted(m["g_r_partial"]) == sorted(pairs) == ["g_1_1", "g_1_2", "g_2_2"]
    for name, curve in m["g_r_partial"].items():
        assert np.array_equal(curve[:, 1], g[name])  # the CSV's column, exactly
        # Centred on the pair type's own bins: the common centres plus its offset.
        assert np.allclose(curve[:, 0], g["r_over_d"] + pairs[name]["bin_offset_over_d"],
                           rtol=0, atol=1e-12)
    phi_y = np.genfromtxt(tmp_path / "m" / "b.phi_y.csv", delimiter=",", comments="#",
                          names=True)
    assert sorted(m["phi_y_species"]) == ["phi_1", "phi_2"]
    for name, profile in m["phi_y_species"].items():
        assert np.array_equal(profile[:, 1], phi_y[name])
    # The species' profiles add up to the pack's (to rounding of a two-term sum).
    total = m["phi_y_species"]["phi_1"][:, 1] + m["phi_y_species"]["phi_2"][:, 1]
    assert np.allclose(total, m["phi_y"][:, 1], rtol=1e-12, atol=1e-15)


@pytest.mark.parametrize(
    "options, cli, value",
    [
        (dict(gap="banana"), ["--gap", "banana"], "banana"),
        (dict(circle_factor=0.5), ["--circle-factor", "0.5"], "0.5"),
        (dict(relax="sideways"), ["--relax", "sideways"], "sideways"),
        (dict(momentum=1.5), ["--momentum", "1.5"], "1.5"),
    ],
)
@pytest.mark.cli
def test_bad_options_raise_value_error_with_the_command_line_text(tmp_path, options, cli, value):
    with pytest.raises(ValueError) as error:
        sgmp.pack(count=100, arrangement="small-dense", seed=1, **options)
    # "keyword = value: rule", the keyword as typed in Python.
    keyword = next(iter(options))
    assert str(error.value).startswith(f"{keyword} = {value}: ")
    rule = str(error.value).split(": ", 1)[1]
    r = run(SGMP, "pack", "--count", "100", "--arrangement", "small-dense", "--seed", "1",
            "--out", tmp_path / "x.xyz", *cli)
    assert r.returncode == 2
    # The command line says the same, with the keyword spelt as its option.
    assert r.stderr == f"sgmp: {cli[0]} {value}: {rule}\n"
    assert not (tmp_path / "x.xyz").exists()


def test_other_bad_input():
    with pytest.raises(ValueError, match="^count = 0: must be between 1"):
        sgmp.pack(count=0, arrangement="small-dense")
    with pytest.raises(ValueError, match="^arrangement = heap: must be one of"):
        sgmp.pack(count=10, arrangement="heap")
    with pytest.raises(ValueError, match="^seed = -1: "):
        sgmp.pack(count=10, arrangement="small-dense", seed=-1)
    with pytest.raises(TypeError, match="colour_factor"):  # Python's own word for it
        sgmp.pack(count=10, arrangement="small-dense", colour_factor=2)
    with pytest.raises(ValueError, match="^circle_factor = fifty: must be a number"):
        sgmp.pack(count=10, arrangement="small-dense", circle_factor="fifty")
    with pytest.raises(ValueError, match="^slab = -1: must be a positive number"):
        sgmp.measure(sgmp.pack(count=60, arrangement="small-dense"), slab=-1)


def test_read_write_round_trip(tmp_path):
    p = sgmp.pack(count=250, arrangement="loose-random", seed=7, relax="frictionless")
    for name in ["p.xyz", "p.xyz.gz"]:
        sgmp.write(p, tmp_path / name)
        q = sgmp.read(tmp_path / name)
        assert np.array_equal(q.positions, p.positions)  # full precision text
        assert np.array_equal(q.radii, p.radii)
        assert np.array_equal(q.bins, p.bins) and np.array_equal(q.ids, p.ids)
        assert q.header == p.header
    # FileExistsError (an OSError), worded for Python: force=True, not --force.
    with pytest.raises(FileExistsError, match="p.xyz: exists; pass force=True to replace it$"):
        sgmp.write(p, tmp_path / "p.xyz")
    sgmp.write(p, tmp_path / "p.xyz", force=True)
    # A pack made from arrays, written and read back.
    made = sgmp.Pack(p.positions, p.radii, bins=p.bins, header={"generator": "numpy", "seed": 7})
    sgmp.write(made, tmp_path / "made.xyz")
    back = sgmp.read(tmp_path / "made.xyz")
    assert np.array_equal(back.positions, p.positions) and back.header["generator"] == "numpy"
    with pytest.raises(ValueError, match="radii"):
        sgmp.Pack(p.positions, p.radii[:-1])
    (tmp_path / "bad.xyz").write_text("2\nProperties=pos:R:3\n1 2\n")
    with pytest.raises(ValueError, match="bad.xyz:"):
        sgmp.read(tmp_path / "bad.xyz")


def test_example_script_runs(tmp_path):
    script = SOURCE / "sgmp" / "python" / "examples" / "pack_measure_plot.py"
    r = subprocess.run([sys.executable, str(script), str(tmp_path), "300"], capture_output=True,
                       text=True, check=False, env=dict(os.environ, MPLBACKEND="Agg"))
    assert r.returncode == 0, r.stderr
    assert "relaxed: N = 300" in r.stdout
    png = (tmp_path / "g_r.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    assert len(sgmp.read(tmp_path / "relaxed.xyz")) == 300


def test_every_format_through_the_pack_library(tmp_path):
    p = sgmp.pack(count=200, arrangement="loose-random", seed=3, size_modes="1:0.6,0.7:0.4")
    for name in ["p.data", "p.dump"]:
        sgmp.write(p, tmp_path / name)
        q = sgmp.read(tmp_path / name)
        order = np.argsort(q.ids)
        assert np.array_equal(q.ids[order], p.ids)
        assert np.array_equal(q.positions[order], p.positions), name  # %.17g: exact
        assert np.array_equal(q.radii[order], p.radii), name
    sgmp.write(p, tmp_path / "p.vtk")
    assert (tmp_path / "p.vtk").read_text().startswith("# vtk DataFile")
    assert (tmp_path / "p.container.vtk").exists()
    sgmp.write(p, tmp_path / "named", format="dump")
    assert len(sgmp.read(tmp_path / "named")) == 200
    with pytest.raises(ValueError, match="^format = pdf: must be one of"):
        sgmp.write(p, tmp_path / "x.pdf", format="pdf")
    with pytest.raises(ValueError, match="^path = .*x.pdf: its ending names no format"):
        sgmp.write(p, tmp_path / "x.pdf")
    # Multi-frame extended XYZ: frame picks one, radius replaces every radius.
    one = tmp_path / "p.xyz"
    sgmp.write(p, one)
    text = one.read_text()
    (tmp_path / "two.xyz").write_text(text + text)
    assert np.array_equal(sgmp.read(tmp_path / "two.xyz", frame=1).positions, p.positions)
    assert np.all(sgmp.read(tmp_path / "two.xyz", radius=0.01).radii == 0.01)


@pytest.mark.parametrize(
    "positions, radii, bins, message",
    [
        ([[0.0, 0.0, np.nan]], [0.05], None, "positions: row 0 is not finite"),
        ([[0.0, np.inf, 0.0]], [0.05], None, "positions: row 0 is not finite"),
        ([[0.0, 0.0, 0.0]], [-0.05], None, "radii: entry 0 = -0.05 must be a finite number > 0"),
        ([[0.0, 0.0, 0.0]], [np.nan], None, "radii: entry 0 = nan must be a finite number > 0"),
        ([[0.0, 0.0, 0.0]], [0.05 + 0j], None, "radii: must be real numbers (dtype complex128)"),
        ([[0.0, 0.0, 0.0j]], [0.05], None, "positions: must be real numbers (dtype complex128)"),
        ([[0.0, 0.0, 0.0]], [0.05], [2**32 + 1], "bins: entry 0 = 4294967297 must be from 0"),
        ([[0.0, 0.0, 0.0]], [0.05], [-1], "bins: entry 0 = -1 must be from 0"),
    ],
)
def test_pack_refuses_impossible_particles(positions, radii, bins, message):
    # They used to be accepted and written, so the project's own readers refused the file.
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
        sgmp.Pack(np.array(positions), np.array(radii), bins=bins)


def test_ctrl_c_interrupts_a_long_pack_at_once():
    """SIGINT during sgmp.pack raises KeyboardInterrupt at the engine's next progress call
    (every 1000 particles dropped, every 1000 relaxation steps, after every LP of the
    settling), not when the call ends: a certified relaxation of 3000 spheres takes
    minutes. One LP cannot be interrupted; at N = 3000 the first takes a few seconds (6.1 s
    to stop was measured beside another job), hence the 20 s bound."""
    import signal
    import time
    script = ("import sgmp, sys\n"
              "print('started', flush=True)\n"
              "try:\n"
              "    sgmp.pack(count=3000, arrangement='loose-random', seed=1, relax='frictionless')\n"
              "    print('finished', flush=True)\n"
              "except KeyboardInterrupt:\n"
              "    print('interrupted', flush=True)\n")
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True,
                             env=dict(os.environ))
    assert child.stdout.readline().strip() == "started"
    time.sleep(1.5)
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    out, _ = child.communicate(timeout=60)
    waited = time.monotonic() - sent
    assert out.strip() == "interrupted"
    assert waited < 20.0, f"took {waited:.1f} s to stop"


@pytest.mark.cli
def test_write_in_a_frame_matches_sgmp_convert(tmp_path):
    """write(up='z', length_scale=..., length_unit=..., density=...) gives the bytes of
    `sgmp convert --up z --length-scale --length-unit --density`, and reads back y up."""
    pack = sgmp.pack(count=150, arrangement="loose-random", seed=4)
    sgmp.write(pack, tmp_path / "p.xyz")
    sgmp.write(pack, tmp_path / "py.data", up="z", length_scale=0.004, length_unit="m",
               density=1950)
    r = run(SGMP, "convert", tmp_path / "p.xyz", tmp_path / "cli.data", "--up", "z",
            "--length-scale", "0.004", "--length-unit", "m", "--density", "1950")
    assert r.returncode == 0, r.stderr
    ours = (tmp_path / "py.data").read_text().splitlines()
    theirs = (tmp_path / "cli.data").read_text().splitlines()
    # convert adds its provenance (converted_by, _version, _from); the rest is the same.
    assert ours == [line for line in theirs if "converted_" not in line]
    back = sgmp.read(tmp_path / "py.data")
    np.testing.assert_array_equal(back.positions, 0.004 * pack.positions)
    with pytest.raises(ValueError, match="length_scale = 0.004: needs length_unit"):
        sgmp.write(pack, tmp_path / "x.data", length_scale=0.004)
    with pytest.raises(ValueError, match="up = x: must be y or z"):
        sgmp.write(pack, tmp_path / "x.data", up="x")
    with pytest.raises(ValueError, match="density = -1: must be a finite number > 0"):
        sgmp.write(pack, tmp_path / "x.data", density=-1)
