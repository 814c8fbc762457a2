"""The equilibrium certificate in a relaxed pack's header, checked by independent code:
scipy's kd-tree for the contacts, scipy's bounded least squares (lsq_linear) for the
residual the pack's own solver reports, and HiGHS (linprog) for the least L1 residual any
non-negative forces can reach, which decides certification whatever the norm."""

import os
import pathlib
import subprocess

import numpy as np
import pytest

scipy = pytest.importorskip("scipy")
from scipy.optimize import linprog, lsq_linear  # noqa: E402
from scipy.sparse import coo_matrix  # noqa: E402
from scipy.spatial import cKDTree  # noqa: E402

SOURCE = pathlib.Path(os.environ.get("SGMP_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
SGMP = os.environ.get("SGMP_EXECUTABLE", SOURCE / "build" / "sgmp" / "sgmp")
HALF = 0.625  # the thesis container: |x|, |z| <= 0.625, floor y = -0.625


def read_xyz(path):
    lines = pathlib.Path(path).read_text().splitlines()
    header = dict(kv.split("=", 1) for kv in lines[1].split() if "=" in kv)
    rows = np.array([[float(v) for v in line.split()[1:5]] for line in lines[2:2 + int(lines[0])]])
    return header, rows[:, :3], rows[:, 3]


def contact_pairs(centres, radii, reach, periodic=False):
    """Pairs i < j closer than `reach` between centres, each with c_i - c_j: the
    minimum-image separation across the x and z faces of the 1.25-wide cell when periodic
    (scipy's periodic kd-tree; y is given a period far beyond the pack)."""
    if not periodic:
        return [(i, j, centres[i] - centres[j])
                for i, j in sorted(cKDTree(centres).query_pairs(reach))]
    box = np.array([2 * HALF, 1e9, 2 * HALF])
    shifted = centres + np.array([HALF, HALF, HALF])
    tree = cKDTree(np.mod(shifted, box), boxsize=box)
    out = []
    for i, j in sorted(tree.query_pairs(reach)):
        delta = shifted[i] - shifted[j]
        delta -= box * np.round(delta / box)
        out.append((i, j, delta))
    return out


def walls_of(periodic):
    """(axis, plane, sign) of the floor and, between walls, the four sides."""
    floor = [(1, -HALF, 1.0)]
    return floor if periodic else floor + [(0, -HALF, 1.0), (0, HALF, -1.0), (2, -HALF, 1.0),
                                           (2, HALF, -1.0)]


def balance_matrix(centres, radii, d, tolerance, periodic=False):
    """Columns: one unit normal force per contact (gap <= tolerance*d); rows: 3 per sphere."""
    n = len(radii)
    rows, cols, vals = [], [], []
    column = 0
    for i, j, delta in contact_pairs(centres, radii, 2 * radii.max() + tolerance * d, periodic):
        gap = np.linalg.norm(delta) - radii[i] - radii[j]
        if gap <= tolerance * d:
            normal = delta / np.linalg.norm(delta)
            for a in range(3):
                rows += [3 * i + a, 3 * j + a]
                cols += [column, column]
                vals += [normal[a], -normal[a]]
            column += 1
    for i in range(n):
        for axis, plane, sign in walls_of(periodic):
            gap = sign * (centres[i, axis] - plane) - radii[i]
            if gap <= tolerance * d:
                rows.append(3 * i + axis)
                cols.append(column)
                vals.append(sign)
                column += 1
    a = coo_matrix((vals, (rows, cols)), shape=(3 * n, column)).tocsr()
    b = np.zeros(3 * n)
    b[1::3] = (2 * radii / d) ** 3  # weights, m*g
    return a, b


@pytest.fixture(scope="module")
def relaxed(tmp_path_factory):
    out = tmp_path_factory.mktemp("certificate") / "relaxed.xyz"
    r = subprocess.run([str(SGMP), "pack", "--count", "300", "--arrangement", "loose-random",
                        "--seed", "4", "--relax", "frictionless", "--keep-uncertified",
                        "--out", str(out)], capture_output=True, text=True, check=False)
    assert r.returncode == 0, r.stderr
    return read_xyz(out)


@pytest.mark.cli
def test_the_header_counts_the_contacts_scipy_finds(relaxed):
    header, centres, radii = relaxed
    d = float(header["diameter"])
    a, _ = balance_matrix(centres, radii, d, float(header["certificate_gap_tolerance"]))
    assert a.shape[1] == int(header["certificate_contacts"])


@pytest.mark.cli
def test_the_reported_residual_is_the_least_squares_one(relaxed):
    header, centres, radii = relaxed
    d = float(header["diameter"])
    a, b = balance_matrix(centres, radii, d, float(header["certificate_gap_tolerance"]))
    solution = lsq_linear(a.toarray(), b, bounds=(0, np.inf), method="bvls", tol=1e-12)
    residual = np.linalg.norm((a @ solution.x - b).reshape(-1, 3), axis=1)
    # The pack's own forces are the least-L1 ones (CLP); at an equilibrium both optima are 0,
    # and out of one the two norms' worst spheres agree to a few per cent of m*g.
    ours = float(header["certificate_residual_max"])
    print(f"largest residual: ours {ours:.6g}, scipy bvls {residual.max():.6g} m*g")
    assert abs(ours - residual.max()) <= 0.05 * max(1.0, residual.max()), (ours, residual.max())


@pytest.mark.cli
def test_highs_reaches_the_certificate_decision(relaxed):
    header, centres, radii = relaxed
    d = float(header["diameter"])
    a, b = balance_matrix(centres, radii, d, float(header["certificate_gap_tolerance"]))
    n_rows, n_cols = a.shape
    # min sum(s+ + s-) subject to A f + s+ - s- = b, f, s+, s- >= 0 (HiGHS).
    from scipy.sparse import eye, hstack
    a_eq = hstack([a, eye(n_rows), -eye(n_rows)]).tocsc()
    cost = np.concatenate([np.zeros(n_cols), np.ones(2 * n_rows)])
    lp = linprog(cost, A_eq=a_eq, b_eq=b, bounds=(0, None), method="highs")
    assert lp.status == 0
    s = lp.x[n_cols:n_cols + n_rows] - lp.x[n_cols + n_rows:]
    worst = np.linalg.norm(s.reshape(-1, 3), axis=1).max()
    certified = header["certified"] == "true"
    # Both solvers reach the same decision at the certificate's tolerance.
    assert certified == (worst <= float(header["certificate_residual_tolerance"]))
    assert certified  # the frictionless relaxation ends in a certified equilibrium


def test_a_column_on_the_floor_is_certified_by_both():
    d = 0.1
    centres = np.array([[0.0, -HALF + 0.5 * d + k * d, 0.0] for k in range(3)])
    radii = np.full(3, 0.5 * d)
    a, b = balance_matrix(centres, radii, d, 1e-6)
    solution = lsq_linear(a.toarray(), b, bounds=(0, np.inf), method="bvls")
    assert np.allclose(sorted(solution.x), [1.0, 2.0, 3.0])


def pyramid(normal, mu):
    """The 8 edges n + mu*cos(pi/8)*(cos t1 + sin t2) of the certificate's pyramid, built
    here from its definition (coulomb_pyramid.hpp): t1 = n x h / |n x h|, h = x unless
    |n_x| >= 0.9, then y; t2 = n x t1."""
    helper = np.array([1.0, 0.0, 0.0]) if abs(normal[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    t1 = np.cross(normal, helper)
    t1 /= np.linalg.norm(t1)
    t2 = np.cross(normal, t1)
    mu_in = mu * np.cos(np.pi / 8)
    return [normal + mu_in * (np.cos(2 * np.pi * k / 8) * t1 + np.sin(2 * np.pi * k / 8) * t2)
            for k in range(8)]


def frictional_balance(centres, radii, d, tolerance, mu, periodic=False):
    """Columns: one per pyramid edge of each contact; rows: force (3) and torque over d (3)
    per sphere, the contact at the surface point c - r*n of the sphere pushed along n."""
    n = len(radii)
    rows, cols, vals = [], [], []
    contacts = []
    for i, j, delta in contact_pairs(centres, radii, 2 * radii.max() + tolerance * d, periodic):
        distance = np.linalg.norm(delta)
        if distance - radii[i] - radii[j] <= tolerance * d:
            contacts.append((i, j, delta / distance))
    for i in range(n):
        for axis, plane, sign in walls_of(periodic):
            if sign * (centres[i, axis] - plane) - radii[i] <= tolerance * d:
                normal = np.zeros(3)
                normal[axis] = sign
                contacts.append((i, None, normal))
    column = 0
    for i, j, normal in contacts:
        for edge in pyramid(normal, mu):
            # Force edge on i at c_i - r_i n, and -edge on j at c_j + r_j n.
            torque_i = np.cross(-radii[i] * normal, edge) / d
            entries = [(6 * i + a, edge[a]) for a in range(3)]
            entries += [(6 * i + 3 + a, torque_i[a]) for a in range(3)]
            if j is not None:
                torque_j = np.cross(radii[j] * normal, -edge) / d
                entries += [(6 * j + a, -edge[a]) for a in range(3)]
                entries += [(6 * j + 3 + a, torque_j[a]) for a in range(3)]
            for row, value in entries:
                rows.append(row)
                cols.append(column)
                vals.append(value)
            column += 1
    a = coo_matrix((vals, (rows, cols)), shape=(6 * n, column)).tocsc()
    b = np.zeros(6 * n)
    b[1::6] = (2 * radii / d) ** 3
    return a, b, len(contacts)


def highs_worst_residual(a, b, per_sphere):
    """The least-L1 residual of non-negative edge forces (HiGHS); the worst sphere's
    Euclidean residual over its `per_sphere` rows."""
    from scipy.sparse import eye, hstack
    n_rows, n_cols = a.shape
    a_eq = hstack([a, eye(n_rows), -eye(n_rows)]).tocsc()
    cost = np.concatenate([np.zeros(n_cols), np.ones(2 * n_rows)])
    lp = linprog(cost, A_eq=a_eq, b_eq=b, bounds=(0, None), method="highs")
    assert lp.status == 0, lp.message
    s = lp.x[n_cols:n_cols + n_rows] - lp.x[n_cols + n_rows:]
    return np.linalg.norm(s.reshape(-1, per_sphere), axis=1).max()


@pytest.mark.cli
@pytest.mark.parametrize("settle", ["lp", "dynamics"])
@pytest.mark.parametrize("mu", ["0.2", "0.5"])
def test_highs_certifies_the_frictional_relaxation(tmp_path, mu, settle):
    # Settled by the LP or by NSGS contact dynamics (in the cone inside the pyramid); either
    # way HiGHS, on scipy's contacts of the final positions, finds forces in the pyramid.
    out = tmp_path / "frictional.xyz"
    r = subprocess.run([str(SGMP), "pack", "--count", "60", "--arrangement", "loose-random",
                        "--seed", "4", "--relax", "frictional", "--relax-friction", mu,
                        "--relax-settle", settle, "--keep-uncertified", "--out", str(out)],
                       capture_output=True, text=True, check=False)
    assert r.returncode == 0, r.stderr
    header, centres, radii = read_xyz(out)
    d = float(header["diameter"])
    assert header["certificate"] == "frictional"
    assert float(header["certificate_friction"]) == float(mu)
    a, b, contacts = frictional_balance(centres, radii, d,
                                        float(header["certificate_gap_tolerance"]), float(mu))
    assert contacts == int(header["certificate_contacts"])
    worst = highs_worst_residual(a, b, 6)
    print(f"mu {mu}: worst residual ours {header['certificate_residual_max']}, "
          f"HiGHS {worst:.3g} m*g over {contacts} contacts")
    assert header["certified"] == "true"
    assert worst <= float(header["certificate_residual_tolerance"])
    # NSGS's own force vectors certify (no certificate LP); HiGHS decides independently.
    if settle == "dynamics":
        assert header["certificate_forces"] == "settling-witness"
    # No sphere overlaps another (scipy's own search): the LP settling's constraints keep
    # every gap at least 0 to rounding; the dynamics' polish leaves overlaps of about
    # 10⁻⁷·d, within the certificate's gap tolerance, which it reports.
    pairs = cKDTree(centres).query_pairs(2 * radii.max())
    gaps = [np.linalg.norm(centres[i] - centres[j]) - radii[i] - radii[j] for i, j in pairs]
    deepest = -min(gaps) / d
    assert deepest <= (1e-12 if settle == "lp"
                       else float(header["certificate_gap_tolerance"]))
    assert deepest <= float(header["certificate_overlap_max"]) * (1 + 1e-6) + 1e-15


def test_highs_decides_the_triangle_by_its_friction():
    # The triangle of settle_test (two spheres on the floor, one on top): it stands at
    # mu = 0.5 (needs 2 - sqrt(3) = 0.268 at the upper contacts) and not at 0.1.
    d = 0.1
    y0 = -HALF + 0.5 * d
    centres = np.array([[-0.5 * d, y0, 0.0], [0.5 * d, y0, 0.0], [0.0, y0 + np.sqrt(3) / 2 * d, 0.0]])
    radii = np.full(3, 0.5 * d)
    a, b, _ = frictional_balance(centres, radii, d, 1e-6, 0.5)
    assert highs_worst_residual(a, b, 6) <= 1e-9
    a, b, _ = frictional_balance(centres, radii, d, 1e-6, 0.1)
    assert highs_worst_residual(a, b, 6) > 1e-3


def crossing_pairs(centres, radii, d, tolerance):
    """Contacts whose minimum image lies across an x or z face of the periodic cell."""
    return sum(1 for i, j, delta in contact_pairs(centres, radii, 2 * radii.max() + tolerance * d,
                                                  periodic=True)
               if np.linalg.norm(delta) - radii[i] - radii[j] <= tolerance * d
               and not np.allclose(delta, centres[i] - centres[j]))


@pytest.mark.cli
def test_highs_certifies_a_periodic_frictionless_blend(tmp_path):
    # A bimodal blend (1 : 0.5, equal volumes) in the periodic cell: the certificate's
    # contacts include the minimum-image pairs across the faces, and no side walls.
    out = tmp_path / "periodic.xyz"
    r = subprocess.run([str(SGMP), "pack", "--count", "600", "--arrangement", "loose-random",
                        "--seed", "4", "--sides", "periodic", "--size-modes", "1:0.5,0.5:0.5",
                        "--fraction-basis", "volume", "--relax", "frictionless",
                        "--out", str(out)], capture_output=True, text=True, check=False)
    assert r.returncode == 0, r.stderr
    header, centres, radii = read_xyz(out)
    assert header["sides"] == "periodic" and header["certified"] == "true"
    d = float(header["diameter"])
    tolerance = float(header["certificate_gap_tolerance"])
    a, b = balance_matrix(centres, radii, d, tolerance, periodic=True)
    assert a.shape[1] == int(header["certificate_contacts"])
    across = crossing_pairs(centres, radii, d, tolerance)
    print(f"{a.shape[1]} contacts, {across} across the faces")
    assert across > 0
    # Every centre inside the cell; no minimum-image pair overlaps beyond 10^-12 d.
    assert np.all(np.abs(centres[:, [0, 2]]) <= HALF)
    gaps = [np.linalg.norm(delta) - radii[i] - radii[j]
            for i, j, delta in contact_pairs(centres, radii, 2 * radii.max(), periodic=True)]
    assert min(gaps) >= -1e-12 * d
    n_rows, n_cols = a.shape
    from scipy.sparse import eye, hstack
    a_eq = hstack([a, eye(n_rows), -eye(n_rows)]).tocsc()
    lp = linprog(np.concatenate([np.zeros(n_cols), np.ones(2 * n_rows)]), A_eq=a_eq, b_eq=b,
                 bounds=(0, None), method="highs")
    assert lp.status == 0
    s = lp.x[n_cols:n_cols + n_rows] - lp.x[n_cols + n_rows:]
    assert np.linalg.norm(s.reshape(-1, 3), axis=1).max() <= float(
        header["certificate_residual_tolerance"])


@pytest.mark.cli
def test_highs_certifies_a_periodic_frictional_pack(tmp_path):
    # 60 spheres at phi target 0.3 (d = 0.306, under the cell's limit of 0.3125), mu = 0.5.
    out = tmp_path / "periodic-frictional.xyz"
    r = subprocess.run([str(SGMP), "pack", "--count", "60", "--phi-target", "0.3",
                        "--arrangement", "loose-random", "--seed", "4", "--sides", "periodic",
                        "--relax", "frictional", "--out", str(out)],
                       capture_output=True, text=True, check=False)
    assert r.returncode == 0, r.stderr
    header, centres, radii = read_xyz(out)
    d = float(header["diameter"])
    tolerance = float(header["certificate_gap_tolerance"])
    a, b, contacts = frictional_balance(centres, radii, d, tolerance, 0.5, periodic=True)
    assert contacts == int(header["certificate_contacts"])
    assert crossing_pairs(centres, radii, d, tolerance) > 0
    assert header["certified"] == "true"
    assert highs_worst_residual(a, b, 6) <= float(header["certificate_residual_tolerance"])


@pytest.mark.cli
def test_highs_certifies_the_contact_dynamics_settling(tmp_path):
    # `--relax-settle dynamics` ends with contact dynamics, certified by its own forces (no
    # LP); HiGHS, on scipy's contacts of the same positions, reaches the same decision.
    out = tmp_path / "dynamics.xyz"
    r = subprocess.run([str(SGMP), "pack", "--count", "300", "--arrangement", "loose-random",
                        "--seed", "4", "--relax", "frictionless", "--relax-settle", "dynamics",
                        "--keep-uncertified", "--out", str(out)],
                       capture_output=True, text=True, check=False)
    assert r.returncode == 0, r.stderr
    header, centres, radii = read_xyz(out)
    d = float(header["diameter"])
    a, b = balance_matrix(centres, radii, d, float(header["certificate_gap_tolerance"]))
    assert a.shape[1] == int(header["certificate_contacts"])
    worst = highs_worst_residual(a, b, 3)
    print(f"worst residual: the settling's forces {header['certificate_residual_max']}, "
          f"HiGHS {worst:.3g} m*g over {a.shape[1]} contacts")
    assert header["certified"] == "true"
    assert header["certificate_forces"] == "settling-witness"
    assert worst <= float(header["certificate_residual_tolerance"])
