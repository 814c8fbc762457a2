#!/usr/bin/python3
"""Pack files written by `sgmp convert`, read back by the tools users take them to.

    real_tools.py SGMP SGMP_COMPARE SCRATCH_DIR

- LAMMPS (`lmp`, Debian lammps): `read_data` of the data file; the atom count and every
  radius, written back with `write_dump ... format float %.17g`, equal the pack's exactly.
- VTK (python3-vtk9): vtkPolyDataReader reads the points, the `radius`, `id` and `bin`
  arrays and the provenance, and the container file's 8 corners and 12 edges.
- ASE (python3-ase): ase.io.read(format='extxyz') gets the cell from Lattice, the origin,
  the `bin` and `radius` arrays; a file ASE writes (8 decimals) converts with a warning
  naming the overlaps that come from its text precision.
- Frames: `--up z --length-scale 4e-4 --length-unit m --density 1700` to a data file that
  LAMMPS (units si) reads with each centre at L·(x, −z, y), the floor at zlo = −0.625·L under
  the lowest sphere, and masses ρ·(π/6)·d³; the same to extended XYZ, whose cell ASE reads
  as L·diag(1.25, 1.25, height); and back through `convert`, the pack's centres times L.
- ParaView-style CSV: vtkDelimitedTextReader on g_r.csv gives the header row's columns.

Exit 0 when every check passes, 1 on a failed check, 77 (CTest's skip) when a tool is
missing (scripts/setup installs them all).
"""
import math
import os
import shutil
import subprocess
import sys

SGMP, COMPARE, SCRATCH = sys.argv[1], sys.argv[2], sys.argv[3]
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        failures.append(what)


def run(*args, **kwargs):
    return subprocess.run(list(args), check=True, capture_output=True, text=True, encoding="utf-8", cwd=SCRATCH,
                          **kwargs)


def read_xyz_pack(path):
    """(header line, rows of id x y z radius bin) of our own extended XYZ, by hand."""
    with open(path) as f:
        n = int(f.readline())
        header = f.readline()
        rows = [f.readline().split() for _ in range(n)]
    return header, [(int(r[0]), float(r[1]), float(r[2]), float(r[3]), float(r[4]), int(r[5]))
                    for r in rows]


def tools_present():
    missing = []
    if shutil.which("lmp") is None:
        missing.append("lmp (Debian lammps)")
    for module, package in (("vtk", "python3-vtk9"), ("ase", "python3-ase")):
        try:
            __import__(module)
        except ImportError:
            missing.append(package)
    return missing


def check_lammps(pack_rows, top):
    script = """units lj
atom_style sphere
boundary f f f
read_data pack.data
variable n equal count(all)
compute r all property/atom radius
compute rmin all reduce min c_r
compute rmax all reduce max c_r
thermo_style custom step v_n c_rmin c_rmax
run 0
write_dump all custom lammps.dump id type radius x y z modify sort id format float %.17g
"""
    with open(os.path.join(SCRATCH, "in.check"), "w") as f:
        f.write(script)
    out = run("lmp", "-in", "in.check", "-log", "none", "-screen", "lammps.screen")
    with open(os.path.join(SCRATCH, "lammps.dump")) as f:
        lines = f.read().splitlines()
    count = int(lines[lines.index("ITEM: NUMBER OF ATOMS") + 1])
    check(count == len(pack_rows), f"LAMMPS read_data: {count} atoms, pack has {len(pack_rows)}")
    start = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS")) + 1
    radii = {int(l.split()[0]): float(l.split()[2]) for l in lines[start:]}
    expected = {r[0]: r[4] for r in pack_rows}
    check(radii == expected, "LAMMPS read_data: every radius equals the pack's (%.17g)")
    ylo, yhi = map(float, lines[lines.index("ITEM: BOX BOUNDS ff ff ff") + 2].split())
    check((ylo, yhi) == (-0.625, top), f"LAMMPS box y = [{ylo}, {yhi}], the container to the top")
    types = {int(l.split()[1]) for l in lines[start:]}
    # The dump file: read_dump replaces the coordinates (zeroed first) by the dump's.
    with open(os.path.join(SCRATCH, "in.dump"), "w") as f:
        f.write("units lj\natom_style sphere\nboundary f f f\nread_data pack.data\n"
                "set group all x 0.0\nread_dump pack.dump 0 x y z box yes\n"
                "write_dump all custom lammps2.dump id x y z modify sort id format float %.17g\n")
    screen = run("lmp", "-in", "in.dump", "-log", "none").stdout
    check(f"{len(pack_rows)} atoms replaced" in screen, "LAMMPS read_dump: every atom replaced")
    with open(os.path.join(SCRATCH, "lammps2.dump")) as f:
        lines = f.read().splitlines()
    start = lines.index("ITEM: ATOMS id x y z") + 1
    centres = {int(l.split()[0]): tuple(map(float, l.split()[1:4])) for l in lines[start:]}
    check(centres == {r[0]: tuple(r[1:4]) for r in pack_rows},
          "LAMMPS read_dump: every centre equals the pack's")
    return types, out


def check_periodic_lammps():
    """A periodic blend, as .data: LAMMPS runs it with the boundary the file's comment
    line names (x and z periodic; x and y when written z up), keeps every atom, and its
    box has those flags."""
    run(SGMP, "pack", "--count", "600", "--arrangement", "loose-random", "--seed", "3",
        "--sides", "periodic", "--size-modes", "1:0.5,0.5:0.5", "--fraction-basis", "volume",
        "--out", "periodic.xyz")
    for name, up, flags in (("periodic.data", "y", "pp ff pp"), ("periodic-z.data", "z", "pp pp ff")):
        run(SGMP, "convert", "periodic.xyz", name, "--up", up)
        with open(os.path.join(SCRATCH, name)) as f:
            boundary = next(l for l in f if l.startswith("# LAMMPS boundary ")).split()[3:]
        check(" ".join(b + b for b in boundary) == flags,
              f"{name}: the comment line names boundary {' '.join(boundary)}")
        with open(os.path.join(SCRATCH, "in.periodic"), "w") as f:
            f.write(f"units lj\natom_style sphere\nboundary {' '.join(boundary)}\n"
                    f"read_data {name}\nrun 0\n"
                    "write_dump all custom periodic.dump id x y z modify sort id\n")
        run("lmp", "-in", "in.periodic", "-log", "none", "-screen", "none")
        with open(os.path.join(SCRATCH, "periodic.dump")) as f:
            lines = f.read().splitlines()
        count = int(lines[lines.index("ITEM: NUMBER OF ATOMS") + 1])
        check(count == 600, f"LAMMPS, periodic ({name}): {count} of 600 atoms kept")
        check(f"ITEM: BOX BOUNDS {flags}" in lines, f"LAMMPS, periodic ({name}): box {flags}")


def check_blend_masses():
    """A propellant-like blend from a CSV stating its unit and densities (diameter_um; 200,
    50 and 30 um; 1950, 1950 and 2700 kg/m3; mass fractions), periodic: `convert --length-unit
    m` scales it with no --length-scale, LAMMPS (units si, the data file's neighbor line)
    runs it without a neighbour-list overflow and sums the same total mass as computed here
    from the pack's radii and the CSV (relative 1e-6: the issue's bound; text is exact to
    ~1e-16), ASE reads the extended XYZ's masses and the dump carries a mass column."""
    with open(os.path.join(SCRATCH, "blend.csv"), "w") as f:
        f.write("diameter_um,fraction,density\n200,0.6,1950\n50,0.2,1950\n30,0.2,2700\n")
    run(SGMP, "pack", "--count", "20000", "--arrangement", "loose-random", "--seed", "2",
        "--sides", "periodic", "--size-distribution", "blend.csv", "--fraction-basis", "mass",
        "--out", "blend.xyz")
    with open(os.path.join(SCRATCH, "blend.xyz")) as f:
        n = int(f.readline())
        f.readline()
        rows = [f.readline().split() for _ in range(n)]  # id x y z radius bin species mass
    density = {1: 1950.0, 2: 1950.0, 3: 2700.0}
    scale = 200e-6 / max(2 * float(r[4]) for r in rows)  # metres per control-volume side
    expected = sum(density[int(r[6])] * math.pi / 6 * (2 * float(r[4]) * scale) ** 3 for r in rows)
    run(SGMP, "convert", "blend.xyz", "blend.data", "--up", "z", "--length-unit", "m")
    with open(os.path.join(SCRATCH, "blend.data")) as f:
        comments = [l.split() for l in f if l.startswith("# LAMMPS ")]
    boundary = next(c for c in comments if c[2] == "boundary")[3:]
    skin = next(c for c in comments if c[2] == "neighbor")[3]
    with open(os.path.join(SCRATCH, "in.blend"), "w") as f:
        f.write(f"units si\natom_style sphere\nboundary {' '.join(boundary)}\nread_data blend.data\n"
                "pair_style gran/hertz/history 1e6 NULL 0 NULL 0.5 0\npair_coeff * *\n"
                f"comm_modify vel yes\nneighbor {skin} bin\nvariable m atom mass\n"
                "compute total all reduce sum v_m\nthermo_style custom step atoms c_total\n"
                "thermo_modify format float %.17g\nrun 0\n")
    log = run("lmp", "-in", "in.blend", "-log", "none").stdout.splitlines()
    row = log[next(i for i, l in enumerate(log) if l.split()[:2] == ["Step", "Atoms"]) + 1].split()
    total = float(row[2])
    check(int(row[1]) == n and abs(total - expected) <= 1e-6 * expected,
          f"LAMMPS, a periodic blend in m: {row[1]} of {n} atoms, total mass {total:.9g} kg "
          f"against {expected:.9g} kg from the CSV's densities (relative {abs(total / expected - 1):.1g})")
    run(SGMP, "convert", "blend.xyz", "blend-m.xyz", "--length-unit", "m")
    import ase.io
    masses = ase.io.read(os.path.join(SCRATCH, "blend-m.xyz"), format="extxyz").get_masses()
    check(abs(masses.sum() - expected) <= 1e-9 * expected,
          f"ASE: the extended XYZ's masses sum to {masses.sum():.9g} kg")
    run(SGMP, "convert", "blend.xyz", "blend.dump", "--length-unit", "m")
    with open(os.path.join(SCRATCH, "blend.dump")) as f:
        atoms = next(l for l in f if l.startswith("ITEM: ATOMS")).split()[2:]
    check("mass" in atoms, f"the dump's columns {' '.join(atoms)} hold the mass")
    status = subprocess.run([SGMP, "convert", "blend.xyz", "x.data", "--density", "1950"],
                            capture_output=True, text=True, cwd=SCRATCH)
    check(status.returncode == 2 and "states a density per species" in status.stderr,
          "--density on a blend with a density per species: refused (exit 2)")


def check_vtk(pack_rows, ending):
    """The legacy (.vtk, vtkPolyDataReader) or XML binary (.vtp, vtkXMLPolyDataReader)
    file and its container file, read by VTK itself."""
    import vtk
    name = ending.upper()
    reader = vtk.vtkPolyDataReader() if ending == "vtk" else vtk.vtkXMLPolyDataReader()
    reader.SetFileName(os.path.join(SCRATCH, "pack." + ending))
    if ending == "vtk":
        reader.ReadAllScalarsOn()
        reader.ReadAllFieldsOn()
    reader.Update()
    data = reader.GetOutput()
    n = data.GetNumberOfPoints()
    check(n == len(pack_rows), f"{name} {type(reader).__name__}: {n} points")
    check(data.GetNumberOfVerts() == n, f"{name}: one vertex per point")
    arrays = data.GetPointData()
    radius, ids, bins, species = (arrays.GetArray(a) for a in ("radius", "id", "bin", "species"))
    check(all(a is not None for a in (radius, ids, bins, species)),
          f"{name}: radius, id, bin and species arrays")
    check([radius.GetValue(i) for i in range(n)] == [r[4] for r in pack_rows],
          f"{name}: every radius equals the pack's")
    check([ids.GetValue(i) for i in range(n)] == [r[0] for r in pack_rows]
          and [bins.GetValue(i) for i in range(n)] == [r[5] for r in pack_rows],
          f"{name}: ids and bins equal the pack's")
    check(all(data.GetPoint(i) == tuple(pack_rows[i][1:4]) for i in range(n)),
          f"{name}: every point equals the pack's centre, bit for bit")
    provenance = data.GetFieldData().GetAbstractArray("provenance")
    entries = [provenance.GetValue(i) for i in range(provenance.GetNumberOfValues())]
    check("container=-0.625 0.625 -0.625 0.625 -0.625" in entries
          and "converted_by=sgmp convert" in entries,
          f"{name}: provenance strings read back")
    box_reader = vtk.vtkPolyDataReader() if ending == "vtk" else vtk.vtkXMLPolyDataReader()
    box_reader.SetFileName(os.path.join(SCRATCH, "pack.container." + ending))
    box_reader.Update()
    box = box_reader.GetOutput()
    check(box.GetNumberOfPoints() == 8 and box.GetNumberOfLines() == 12,
          f"{name}: the container file has 8 corners and 12 edges")


def check_ase(top):
    import ase.io
    atoms = ase.io.read(os.path.join(SCRATCH, "pack.xyz"), format="extxyz")
    cell = atoms.cell.array.tolist()
    height = top + 0.625
    check(cell == [[1.25, 0, 0], [0, height, 0], [0, 0, 1.25]],
          f"ASE: the cell from Lattice is diag(1.25, {height}, 1.25)")
    check(list(atoms.info.get("Origin", [])) == [-0.625, -0.625, -0.625], "ASE: Origin in info")
    check("bin" in atoms.arrays and "radius" in atoms.arrays, "ASE: bin and radius arrays")
    check(atoms.info.get("generator") == "sgmp", "ASE: the header keys in info")
    # ASE writes 8 decimals: the pack's contacts come back as overlaps, and convert says so.
    ase.io.write(os.path.join(SCRATCH, "ase.xyz"), atoms, format="extxyz")
    result = subprocess.run([SGMP, "convert", "ase.xyz", "from-ase.xyz"], cwd=SCRATCH,
                            capture_output=True, text=True, encoding="utf-8")
    warning = [l for l in result.stderr.splitlines() if "warning" in l]
    check(result.returncode == 0 and len(warning) == 1 and "(8 decimals)" in warning[0]
          and "overlaps of at most" in warning[0],
          "ASE round trip: one warning line: " + (warning[0] if warning else result.stderr))


def check_frame(rows, top):
    scale, density = 4e-4, 1700.0
    run(SGMP, "convert", "pack.xyz", "z.data", "--up", "z", "--length-scale", str(scale),
        "--length-unit", "m", "--density", str(density))
    with open(os.path.join(SCRATCH, "in.frame"), "w") as f:
        f.write("units si\natom_style sphere\nboundary f f f\nread_data z.data\n"
                "write_dump all custom frame.dump id x y z radius mass modify sort id "
                "format float %.17g\n")
    run("lmp", "-in", "in.frame", "-log", "none", "-screen", "none")
    with open(os.path.join(SCRATCH, "frame.dump")) as f:
        lines = f.read().splitlines()
    bounds = [tuple(map(float, lines[lines.index("ITEM: BOX BOUNDS ff ff ff") + k].split()))
              for k in (1, 2, 3)]
    start = next(i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS")) + 1
    atoms = {int(l.split()[0]): list(map(float, l.split()[1:])) for l in lines[start:]}
    worst = max(max(abs(a[0] - scale * r[1]), abs(a[1] + scale * r[3]), abs(a[2] - scale * r[2]),
                    abs(a[3] - scale * r[4]))
                for r in rows for a in [atoms[r[0]]])
    check(worst <= 1e-15, f"LAMMPS units si, z up: every centre is L*(x, -z, y) (worst {worst:.2g} m)")
    floor = min(a[2] - a[3] for a in atoms.values())
    check(abs(bounds[2][0] + 0.625 * scale) <= 1e-18 and -1e-15 <= floor - bounds[2][0] <= 1e-3 * scale,
          f"LAMMPS: zlo {bounds[2][0]} m is the floor, the lowest sphere {floor - bounds[2][0]:.2g} m above it")
    mass_error = max(abs(a[4] - density * math.pi / 6 * (2 * a[3]) ** 3) / a[4] for a in atoms.values())
    check(mass_error <= 1e-12, f"LAMMPS: mass = 1700 kg/m3 * (pi/6) d^3 (relative error {mass_error:.1g})")
    run(SGMP, "convert", "pack.xyz", "z.xyz", "--up", "z", "--length-scale", str(scale),
        "--length-unit", "m")
    import ase.io
    cell = ase.io.read(os.path.join(SCRATCH, "z.xyz"), format="extxyz").cell.array
    expected = [1.25 * scale, 1.25 * scale, (top + 0.625) * scale]
    check(max(abs(cell[k][k] - expected[k]) for k in range(3)) <= 1e-18,
          f"ASE: the z-up cell is L*diag(1.25, 1.25, height) = {[float(cell[k][k]) for k in range(3)]}")
    run(SGMP, "convert", "z.data", "back.xyz")
    _, back = read_xyz_pack(os.path.join(SCRATCH, "back.xyz"))
    worst = max(max(abs(b[k] - scale * r[k]) for k in (1, 2, 3, 4)) for r, b in zip(rows, back))
    check(worst <= 1e-18, f"convert back: y up again, centres L times the pack's (worst {worst:.2g})")


def check_csv():
    import vtk
    run(COMPARE, "measure", "pack.xyz", "--out", "metrics")
    reader = vtk.vtkDelimitedTextReader()
    reader.SetFileName(os.path.join(SCRATCH, "metrics", "pack.g_r.csv"))
    reader.SetHaveHeaders(True)
    reader.SetFieldDelimiterCharacters(",")
    reader.Update()
    table = reader.GetOutput()
    names = [table.GetColumnName(i) for i in range(table.GetNumberOfColumns())]
    with open(os.path.join(SCRATCH, "metrics", "pack.g_r.csv")) as f:
        header = f.readline().strip().split(",")
    check(names == header, f"CSV (vtkDelimitedTextReader): columns {names}")
    text_rows = 0
    for i in range(table.GetNumberOfRows()):
        try:
            float(table.GetValue(i, 0).ToString())
        except ValueError:
            text_rows += 1
    print(f"note VTK 9.1's vtkDelimitedTextReader has no comment option: the '#' lines come "
          f"as {text_rows} leading rows of text, so the columns are read as strings")


def check_bad_input():
    """Bad input: one line on stderr naming the value and the rule, the exit code, no file."""
    def write(name, text):
        with open(os.path.join(SCRATCH, name), "w") as f:
            f.write(text)

    def convert(*args):
        r = subprocess.run([SGMP, "convert", *args], cwd=SCRATCH, capture_output=True,
                           text=True, encoding="utf-8")
        return r.returncode, r.stderr.splitlines()

    write("zero.xyz", "1\nProperties=id:I:1:pos:R:3:radius:R:1\n0 0 0 0 0.1\n")
    write("species.xyz", "2\nProperties=species:S:1:pos:R:3\nAr 0 0 0\nAr 0.5 0 0\n")
    write("frames.xyz", "1\nProperties=pos:R:3:radius:R:1\n0 0 0 0.1\n" * 2)
    cases = [
        (("zero.xyz", "zero.data"), 1,
         "sgmp convert: format data cannot carry id 0: LAMMPS atom ids must be positive",
         "zero.data"),
        (("pack.xyz", "p.out", "--to", "vtu"), 2,
         "sgmp convert: --to 'vtu': must be one of xyz, xyz.gz, data, dump, vtk, vtp", "p.out"),
        (("species.xyz", "species.data"), 1,
         "sgmp convert: species.xyz:2: Properties lacks a 'radius' or 'diameter' column; give "
         "the radius (--radius R)", "species.data"),
        (("frames.xyz", "frames.dump", "--frame", "3"), 1,
         "sgmp convert: frames.xyz: frame 3 does not exist: the file has 2 frame(s), counted "
         "from 1", "frames.dump"),
        (("pack.xyz", "pack.data"), 2,
         "sgmp convert: OUT pack.data: exists; pass --force to replace it", None),
        (("pack.xyz", "m.data", "--length-scale", "0.01"), 2,
         "sgmp convert: --length-scale 0.01: name the unit it is in with --length-unit (for "
         "example m or um)", "m.data"),
        (("pack.xyz", "m.data", "--length-unit", "m"), 2,
         "sgmp convert: --length-unit 'm': give --length-scale, the length of one "
         "control-volume side in it", "m.data"),
    ]
    for args, code, message, output in cases:
        rc, lines = convert(*args)
        left = output is not None and os.path.exists(os.path.join(SCRATCH, output))
        check(rc == code and lines == [message] and not left,
              f"bad input {' '.join(args)}: exit {rc}, {lines}" + (", file left" if left else ""))
    rc, _ = convert("species.xyz", "species.data", "--radius", "0.2")
    check(rc == 0, "a species-only file converts with --radius")
    # Far-apart centres and tiny radii are valid files: they once gave "cannot create
    # std::vector larger than max_size()" from the overlap grid.
    write("far.xyz", "2\nProperties=id:I:1:pos:R:3:radius:R:1\n1 1e20 0 0 0.1\n2 0 0 0 0.1\n")
    write("tiny.xyz", "2\nProperties=id:I:1:pos:R:3\n1 0.1 0 0\n2 0 0 0\n")
    for args in (("far.xyz", "far.data"), ("far.xyz", "far.vtk"),
                 ("tiny.xyz", "tiny.dump", "--radius", "1e-21")):
        rc, lines = convert(*args)
        check(rc == 0 and not any("max_size" in line for line in lines),
              f"{' '.join(args)}: exit {rc}, {lines}")


def main():
    missing = tools_present()
    if missing:
        print("SKIP: missing " + ", ".join(missing) + " (scripts/setup installs them)")
        return 77
    shutil.rmtree(SCRATCH, ignore_errors=True)
    os.makedirs(SCRATCH)
    run(SGMP, "pack", "--count", "300", "--arrangement", "loose-random", "--seed", "2",
        "--size-modes", "1:0.7,0.5:0.3", "--out", "pack.xyz")
    for out in ("pack.data", "pack.dump", "pack.vtk", "pack.vtp"):
        run(SGMP, "convert", "pack.xyz", out)
    header, rows = read_xyz_pack(os.path.join(SCRATCH, "pack.xyz"))
    top = max(r[2] + r[4] for r in rows)
    types, _ = check_lammps(rows, top)
    check(types == {1, 2}, f"LAMMPS: atom types {sorted(types)} from the two size modes")
    check_vtk(rows, "vtk")
    check_vtk(rows, "vtp")
    check_ase(top)
    check_frame(rows, top)
    check_periodic_lammps()
    check_blend_masses()
    check_csv()
    check_bad_input()
    # The same input gives the same bytes.
    for out in ("pack.data", "pack.dump", "pack.vtk", "pack.vtp"):
        again = "again." + out.split(".")[1]
        run(SGMP, "convert", "pack.xyz", again)
        with open(os.path.join(SCRATCH, out), "rb") as a, open(os.path.join(SCRATCH, again), "rb") as b:
            first, second = a.read(), b.read()
        check(first.replace(b"again.", b"pack.") == second.replace(b"again.", b"pack.") or
              first == second, f"{out}: the same bytes on a second conversion")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
