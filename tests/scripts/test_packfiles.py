"""scripts/lib/packfiles.py and the entry point on it, scripts/lib/references.py."""
import contextlib
import gzip
import io
import pathlib
import shutil
import subprocess
import sys

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "scripts" / "lib"))
import packfiles  # noqa: E402
import references  # noqa: E402


@pytest.mark.parametrize("count, mu, seed", [(150, "0.5", 1), (1002, "0.01", 20), (9000, "0", 3),
                                             (15000, "0.5", 5), (10000, 0.01, 12)])
def test_reference_names_round_trip(count, mu, seed):
    name = packfiles.reference_name(count, mu, seed)
    assert name == f"n{count:04d}-mu{mu if isinstance(mu, str) else f'{mu:g}'}-seed{seed}.xyz.gz"
    parsed = packfiles.parse_reference_name("data/reference/" + name)
    assert (parsed.count, parsed.mu, parsed.seed, parsed.suffix) == \
        (count, mu if isinstance(mu, str) else f"{mu:g}", seed, ".xyz.gz")
    assert packfiles.reference_name(parsed.count, parsed.mu, parsed.seed, parsed.suffix) == name


def test_reference_names_spelled_out():
    assert packfiles.reference_name(150, "0.5", 1) == "n0150-mu0.5-seed1.xyz.gz"
    assert packfiles.reference_name(1002, "0.01", 7, ".dump.gz") == "n1002-mu0.01-seed7.dump.gz"
    assert packfiles.parse_reference_name("n1002-mu0.01-seed7.dump.gz").suffix == ".dump.gz"
    for other in ("n1002-seed1.xyz", "pack.xyz.gz", "n12-mu0.5-seed1.xyz.gz", "n1002-mu0.5-seedX.xyz.gz"):
        assert packfiles.parse_reference_name(other) is None


def test_reference_files_by_seed(tmp_path):
    for seed in (10, 2, 1):
        (tmp_path / packfiles.reference_name(1002, "0.5", seed)).write_text("")
    (tmp_path / packfiles.reference_name(1002, "0.01", 3)).write_text("")
    (tmp_path / packfiles.reference_name(3000, "0.5", 4)).write_text("")
    assert packfiles.reference_seeds(tmp_path, 1002, "0.5") == [1, 2, 10]
    assert [p.name for p in packfiles.reference_files(tmp_path, 1002, "0.01")] == \
        ["n1002-mu0.01-seed3.xyz.gz"]
    assert packfiles.reference_seeds(tmp_path, 2001, "0.5") == []


def test_header_values_with_quotes(tmp_path):
    header = ('Properties=id:I:1:pos:R:3:radius:R:1 pbc="F F F" count=2 '
              'contact_model="hertz tangential_history" empty= note="a, b" seed=7')
    text = f"2\n{header}\n1 0 0 0 0.1\n2 1 1 1 0.1\n"
    plain = tmp_path / "pack.xyz"
    plain.write_text(text)
    packed = tmp_path / "pack.xyz.gz"
    with gzip.open(packed, "wt") as f:
        f.write(text)
    for path in (plain, packed):
        values = packfiles.header_values(path)
        assert values["pbc"] == "F F F"
        assert values["contact_model"] == "hertz tangential_history"
        assert values["note"] == "a, b"
        assert values["empty"] == ""
        assert packfiles.header_value(path, "seed") == "7"
        assert packfiles.header_value(path, "missing") == ""
        assert packfiles.header_value(path, "missing", "none") == "none"
    assert list(packfiles.header_values(plain))[:3] == ["Properties", "pbc", "count"]


def test_header_values_of_lammps_files(tmp_path):
    data = tmp_path / "pack.data"
    data.write_text("LAMMPS data file (atom_style sphere) of a sphere pack\n"
                    "# count=2\n# seed=3\n# density per species (size_modes): mass = x\n"
                    "# LAMMPS boundary f f f\n\n2 atoms\n")
    assert packfiles.header_values(data) == {"count": "2", "seed": "3"}
    dump = tmp_path / "pack.dump"
    dump.write_text("ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n0\n")
    assert packfiles.header_values(dump) == {}


def test_header_values_agree_with_stored_pours():
    pour = ROOT / "data" / "reference" / "n0150-mu0.5-seed1.xyz.gz"
    if not pour.exists():
        pytest.skip("no stored pour")
    values = packfiles.header_values(pour)
    assert values["count"] == "150" and values["friction"] == "0.5" and values["seed"] == "1"
    assert values["contact_model"] == "hertz tangential_history rolling_friction_cdt"


def test_csv_with_quoted_commas(tmp_path):
    rows = [{"role": "candidate", "group": "DEM mu=0.5, tall", "path": 'a "b", c'},
            {"role": "reference", "group": "plain", "path": "x/y.xyz"}]
    out = tmp_path / "t.csv"
    packfiles.write_csv(out, ["role", "group", "path"], rows, comments=["tool: test"])
    assert out.read_text() == ('role,group,path\n# tool: test\n'
                               'candidate,"DEM mu=0.5, tall","a ""b"", c"\n'
                               'reference,plain,x/y.xyz\n')
    columns, back = packfiles.read_csv(out)
    assert columns == ["role", "group", "path"]
    assert back == rows
    assert packfiles.csv_field("") == "" and packfiles.csv_field(3) == "3"
    assert packfiles.csv_line(["a", "b,c", 'd"']) == 'a,"b,c","d"""'


def test_numbers():
    assert packfiles.fixed("0.00534", 4) == "0.0053"
    assert packfiles.fixed("", 4) == "0.0000"
    assert packfiles.fixed(0.56994, 4) == "0.5699"
    assert packfiles.awk_number(2.0) == "2"
    assert packfiles.awk_number(1234567.0) == "1234567"
    assert packfiles.awk_number(1000 * 12.34 / 5678) == "2.1733"  # %.6g
    assert packfiles.awk_number(0.1 + 0.2) == "0.3"


def test_awk_number_matches_awk():
    if shutil.which("awk") is None:
        pytest.skip("no awk")
    values = [2.0, 1234567.0, 1e20, 2.1733004579077, 0.000123456789, 3.0e-7, 100.5]
    script = "BEGIN { " + " ".join(f"print {v!r};" for v in values) + " }"
    printed = subprocess.run(["awk", script], capture_output=True, text=True, check=True).stdout
    assert printed.split("\n")[:-1] == [packfiles.awk_number(v) for v in values]


def test_speedup_lines(tmp_path):
    for name, wall, steps in (("s.xyz", "12.34", "5678"), ("m.xyz", "6.5", "5600")):
        (tmp_path / name).write_text(f"1\nwall_seconds={wall} steps={steps}\n")
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        references.main(["speedup", "3000", str(tmp_path / "s.xyz"), str(tmp_path / "m.xyz")])
    assert out.getvalue() == ("serial    12.34 s    5678 steps    2.173 ms/step\n"
                              "mpi2        6.5 s    5600 steps    1.161 ms/step\n"
                              "count 3000: 2-rank speed-up per time step 1.87 (processors 2 1 1)\n")


def test_list_pours(tmp_path, capsys):
    (tmp_path / "n0150-mu0.5-seed2.xyz.gz").write_text("")
    (tmp_path / "n0150-mu0.5-seed10.xyz.gz").write_text("")
    references.main(["list", str(tmp_path), "--counts", "150 300", "--frictions", "0.5"])
    assert capsys.readouterr().out == (f"150 0.5 2 {tmp_path}/n0150-mu0.5-seed2.xyz.gz\n"
                                       f"150 0.5 10 {tmp_path}/n0150-mu0.5-seed10.xyz.gz\n"
                                       f"300 0.5 1 {tmp_path}/n0300-mu0.5-seed1.xyz.gz\n")
    references.main(["list", str(tmp_path), "--counts", "150 300", "--frictions", "0.5",
                     "--stored"])
    assert capsys.readouterr().out.count("\n") == 2
    references.main(["list", "d", "--counts", "1 2", "--frictions", "a b", "--seeds", "4",
                     "--by", "friction"])
    assert capsys.readouterr().out == ("1 a 4 d/n0001-mua-seed4.xyz.gz\n2 a 4 d/n0002-mua-seed4.xyz.gz\n"
                                       "1 b 4 d/n0001-mub-seed4.xyz.gz\n2 b 4 d/n0002-mub-seed4.xyz.gz\n")


def run_manifest(args, stdin=b""):
    return subprocess.run([sys.executable, str(ROOT / "scripts" / "lib" / "manifest.py"), *args],
                          input=stdin, capture_output=True, check=True).stdout


def test_manifest_rows_paths_metrics_select(tmp_path):
    fields = ["candidate", "loose-random", "150", "1", "0.123", '/tmp/run dir, "quoted"/a.xyz',
              "reference", "DEM mu=0.5", "150", "2", "", "data/reference/n0150-mu0.5-seed2.xyz.gz"]
    rows = run_manifest(["rows", "6"], "\0".join(fields).encode() + b"\0")
    assert rows == (b'candidate,loose-random,150,1,0.123,"/tmp/run dir, ""quoted""/a.xyz"\n'
                    b"reference,DEM mu=0.5,150,2,,data/reference/n0150-mu0.5-seed2.xyz.gz\n")
    manifest = tmp_path / "manifest.csv"
    manifest.write_bytes(b"role,group,count,seed,seconds,path\n" + rows)
    assert run_manifest(["paths", str(manifest)]).split(b"\0")[:-1] == \
        [fields[5].encode(), fields[11].encode()]
    pairs = [fields[5], "m/a, b.metrics.json", fields[11], "m/r.metrics.json"]
    assert run_manifest(["metrics", str(manifest)], "\0".join(pairs).encode() + b"\0") == (
        b"role,group,count,seed,seconds,path\n"
        b'candidate,loose-random,150,1,0.123,"m/a, b.metrics.json"\n'
        b"reference,DEM mu=0.5,150,2,,m/r.metrics.json\n")
    assert run_manifest(["select", str(manifest), "--role", "candidate", "--group", "loose-random",
                         "--count", "150"]) == rows.split(b"\n")[0] + b"\n"
    assert run_manifest(["select", str(manifest), "--role", "reference", "--count", "300"]) == b""
    assert run_manifest(["count", str(manifest), "--role", "candidate", "--timed"]) == b"1\n"
    assert run_manifest(["count", str(manifest), "--role", "reference", "--timed"]) == b"0\n"
    assert run_manifest(["count", str(manifest), "--role", "reference"]) == b"1\n"


def test_manifest_verdicts(tmp_path):
    headline = tmp_path / "headline.csv"
    headline.write_text('count,candidate,metric,verdict\n# tool\n150,"a, b",phi,agree\n'
                        "150,c,phi,differ\n150,c,g_r,agree\n")
    assert run_manifest(["verdicts", str(headline)]) == b"2 agree, 1 differ, 0 inconclusive"


def test_manifest_budget(tmp_path):
    """The budget counts a reused pack by its .seconds file and extends by the mean time."""
    (tmp_path / "n0150-seed2.seconds").write_text("300.0\n")
    manifest = tmp_path / "manifest.csv"
    manifest.write_text("role,group,count,seed,seconds,path\n"
                        f"candidate,m+frictional,150,1,100,{tmp_path}/n0150-seed1.xyz\n"
                        f"candidate,m+frictional,150,2,,{tmp_path}/n0150-seed2.xyz\n"
                        f"candidate,m,150,1,1000,{tmp_path}/other.xyz\n"
                        "reference,DEM,150,1,5000,r.xyz.gz\n")
    args = ["budget", str(manifest), "--group", "m+frictional", "--count", "150", "--add", "5"]
    # spent 100 + 300 = 400 s, mean 200 s: five more make 1400 s.
    assert run_manifest(args + ["--budget", "1400"]) == b"1400\n"
    result = subprocess.run([sys.executable, str(ROOT / "scripts" / "lib" / "manifest.py"), *args,
                             "--budget", "1399"], capture_output=True)
    assert result.returncode == 1 and result.stdout == b"1400\n"
    # A pack with no time at all counts at the mean of those timed.
    (tmp_path / "n0150-seed2.seconds").unlink()
    assert run_manifest(args + ["--budget", "1e6"]) == b"700\n"
    # The CPU seconds scripts/run records beside a pack (`times`: the shell's line, then its
    # children's) count before any wall time: seed 1 took 1 min 2.5 s + 0.5 s of CPU.
    (tmp_path / "n0150-seed1.cpu").write_text("0m0.010s 0m0.020s\n1m2.500s 0m0.500s\n")
    (tmp_path / "n0150-seed2.seconds").write_text("300.0\n")
    # spent 63 + 300 = 363 s, mean 181.5 s: five more make 1270.5 s.
    assert run_manifest(args + ["--budget", "1e6"]) == b"1270\n"
    # A .cpu file that is not `times`' output falls back to the wall seconds.
    (tmp_path / "n0150-seed1.cpu").write_text("garbage\n")
    assert run_manifest(args + ["--budget", "1e6"]) == b"1400\n"
