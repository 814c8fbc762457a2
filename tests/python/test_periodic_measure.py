"""`sgmp-compare measure` of packs with periodic sides, computed a second way.

- phi over the whole cell across: with no lateral boundary each sphere counts by its
  height alone, so phi is the sum of exact ball-slab volumes over the cell's area (a closed
  form, no images).
- Z(delta) and Z_IJ(delta): a minimum-image count with scipy's periodic cKDTree.
- The Voronoi cells of the particles tile the cell from the floor to the lid: their volumes
  sum to the cell's area times (lid - floor), the lid one mean diameter above the top.
- Every metric is unchanged when the pack is shifted across by any amount and wrapped.
"""
import json
import os
import pathlib
import subprocess

import numpy as np
import pytest
from scipy.spatial import cKDTree

SOURCE = pathlib.Path(os.environ.get("SGMP_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
SGMP = os.environ.get("SGMP_EXECUTABLE", SOURCE / "build" / "sgmp" / "sgmp")
COMPARE = os.environ.get("SGMP_COMPARE_EXECUTABLE", SOURCE / "build" / "compare" / "sgmp-compare")


def run(*args):
    result = subprocess.run([str(a) for a in args], capture_output=True, text=True, check=False)
    assert result.returncode == 0, result.stderr
    return result


def read_xyz(path):
    lines = path.read_text().splitlines()
    header = lines[1]
    table = np.loadtxt(lines[2:], ndmin=2)
    return header, table


def container_of(header):
    text = header.split('container="')[1].split('"')[0]
    return [float(v) for v in text.split()]


def ball_below(r, u):
    """Volume of a ball of radius r below the plane at height u from its centre."""
    u = np.clip(u, -r, r)
    return np.pi * (r + u) ** 2 * (2.0 * r - u) / 3.0


def measure(tmp_path, path, name, *extra):
    out = tmp_path / name
    run(COMPARE, "measure", path, "--out", out, *extra)
    return json.loads((out / (path.stem + ".metrics.json")).read_text())


def pack(tmp_path, name, *options):
    path = tmp_path / f"{name}.xyz"
    run(SGMP, "pack", "--arrangement", "loose-random", "--sides", "periodic", "--out", path,
        *options)
    return path


def min_image_counts(centres, radii, cell, lo, origins, tolerances, d):
    """Neighbours j != i with minimum-image gap <= t*d, per origin, per tolerance."""
    shifted = centres.copy()
    shifted[:, 0] -= lo[0]
    shifted[:, 2] -= lo[2]
    shifted[:, 1] -= shifted[:, 1].min()
    box = [cell[0], 1e9, cell[2]]  # y not periodic: a period far beyond the pack
    tree = cKDTree(np.mod(shifted, box), boxsize=box)
    reach = 2.0 * radii.max() + max(tolerances) * d
    counts = np.zeros((len(origins), len(tolerances)))
    for row, a in enumerate(origins):
        for b in tree.query_ball_point(np.mod(shifted[a], box), reach):
            if b == a:
                continue
            delta = shifted[a] - shifted[b]
            delta[0] -= cell[0] * np.round(delta[0] / cell[0])
            delta[2] -= cell[2] * np.round(delta[2] / cell[2])
            gap = np.linalg.norm(delta) - radii[a] - radii[b]
            counts[row] += [gap <= t * d for t in tolerances]
    return counts


# N = 150: d = 0.29, so g(r)'s reach of 5 d is wider than the cell (images several
# periods away).
@pytest.mark.cli
@pytest.mark.parametrize("seed,count", [(1, 1500), (2, 1500), (3, 150)])
def test_periodic_phi_z_and_voronoi_volume_a_second_way(tmp_path, seed, count):
    path = pack(tmp_path, f"p{seed}", "--count", str(count), "--seed", str(seed))
    header, table = read_xyz(path)
    assert 'pbc="T F T"' in header and "sides=periodic" in header
    x_min, x_max, z_min, z_max, floor = container_of(header)
    centres, radii = table[:, 1:4], table[:, 4]
    d = 2.0 * radii.mean()
    cell = np.array([x_max - x_min, 0.0, z_max - z_min])
    metrics = measure(tmp_path, path, "m")
    # The default region: the whole cell across, the control volume's heights.
    assert metrics["region"]["lo"] == [x_min, -0.5, z_min]
    assert metrics["region"]["hi"] == [x_max, 0.5, z_max]
    slab = ball_below(radii, 0.5 - centres[:, 1]) - ball_below(radii, -0.5 - centres[:, 1])
    phi = slab.sum() / (cell[0] * cell[2] * 1.0)
    # Exact volumes both ways: equal to rounding (10⁻¹² of a sum of 1500 terms).
    assert metrics["phi"] == pytest.approx(phi, rel=1e-12)
    origins = np.flatnonzero(np.abs(centres[:, 1]) <= 0.5)
    assert metrics["origins"] == len(origins)
    # Z(0) counts exact contacts, which the shift to the tree's box decides by rounding.
    names = ["1e-6", "1e-3", "1e-2", "2e-2", "5e-2"]
    counts = min_image_counts(centres, radii, cell, [x_min, floor, z_min], origins,
                              [float(n) for n in names], d)
    for t, name in enumerate(names):
        # Integer counts over the same origins: equal up to the division's rounding.
        assert metrics[f"z_mean_tol_{name}"] == pytest.approx(counts[:, t].mean(), rel=1e-12)
    # Only the floor is a wall: floor contacts alone, none at the faces.
    near_floor = np.sum(centres[origins, 1] - radii[origins] - floor <= 1e-2 * d)
    assert metrics["wall_contacts_tol_1e-2"] == near_floor

    # Voronoi: every particle's cell, region from the floor to above the top.
    top = (centres[:, 1] + radii).max()
    everything = measure(tmp_path, path, "all", "--region", x_min, x_max, floor, top + 1.0,
                         z_min, z_max)
    assert everything["origins"] == len(radii)
    spheres = (4.0 / 3.0 * np.pi * radii ** 3).sum()
    tiled = cell[0] * cell[2] * (top + d - floor)
    # voro++ cell volumes summed: exact to about 10⁻¹⁰ of the cell's volume.
    assert everything["voronoi_detail"]["global"] == pytest.approx(spheres / tiled, rel=1e-9)


@pytest.mark.cli
def test_periodic_g_r_counts_every_image_within_its_range(tmp_path):
    # N = 150: d = 0.29, so g(r)'s range of 5 d (1.44) exceeds the period 1.25 and a pair
    # meets several images of the same partner, as in the infinite periodic pack. Brute
    # force over every image shift up to 3 periods: the same pair count in every bin.
    path = pack(tmp_path, "g", "--count", "150", "--seed", "3")
    header, table = read_xyz(path)
    x_min, x_max, z_min, z_max, _ = container_of(header)
    centres, radii = table[:, 1:4], table[:, 4]
    d = 2.0 * radii.mean()
    measure(tmp_path, path, "m")
    g = np.genfromtxt(tmp_path / "m" / "g.g_r.csv", comments="#", names=True, delimiter=",")
    upper = g["r_hi_over_d"] * d
    assert upper[-1] > (x_max - x_min) / 2.0
    counts = np.zeros(len(g))
    for i in np.flatnonzero(np.abs(centres[:, 1]) <= 0.5):  # the region's origins
        for kx in range(-3, 4):
            for kz in range(-3, 4):
                shift = np.array([kx * (x_max - x_min), 0.0, kz * (z_max - z_min)])
                dist = np.linalg.norm(centres - centres[i] + shift, axis=1)
                if kx == 0 and kz == 0:
                    dist[i] = np.inf  # not itself
                dist = dist[dist < upper[-1]]
                np.add.at(counts, np.searchsorted(upper, dist, side="right"), 1)
    # Integer counts: equal exactly.
    assert np.array_equal(counts, g["pairs"])


@pytest.mark.cli
def test_periodic_metrics_do_not_move_with_the_pack(tmp_path):
    path = pack(tmp_path, "p", "--count", "1500", "--seed", "3",
                "--size-modes", "1:0.5,0.6:0.5")
    lines = path.read_text().splitlines()
    x_min, x_max, z_min, z_max, _ = container_of(lines[1])
    table = np.loadtxt(lines[2:], ndmin=2)
    moved = table.copy()
    moved[:, 1] = x_min + np.mod(table[:, 1] + 0.37 * (x_max - x_min) - x_min, x_max - x_min)
    moved[:, 3] = z_min + np.mod(table[:, 3] + 0.81 * (z_max - z_min) - z_min, z_max - z_min)
    shifted = path.with_name("shifted.xyz")
    with shifted.open("w") as out:
        out.write(lines[0] + "\n" + lines[1] + "\n")
        for row in moved:
            out.write(" ".join(repr(int(v)) if k in (0, 5, 6) else repr(float(v))
                               for k, v in enumerate(row)) + "\n")
    a = measure(tmp_path, path, "a")
    b = measure(tmp_path, shifted, "b")
    # Sums over the same spheres in another order: equal to 10⁻¹⁰ (rounding of the shift).
    for key in ["phi", "z_mean_tol_1e-3", "z_mean_tol_1e-2", "split_ratio", "voronoi_phi_mean",
                "voronoi_phi_sd", "q6_global", "origins"]:
        assert b[key] == pytest.approx(a[key], rel=1e-9, abs=1e-12), key
    for pa, pb in zip(a["species"]["pairs"], b["species"]["pairs"]):
        for name, value in pa["z_ij"].items():
            if name == "0":  # exact contacts: the shift's rounding decides them
                continue
            assert pb["z_ij"][name] == pytest.approx(value, rel=1e-9), name
    ga = np.genfromtxt(tmp_path / "a" / "p.g_r.csv", delimiter=",", names=True, comments="#")
    gb = np.genfromtxt(tmp_path / "b" / "shifted.g_r.csv", delimiter=",", names=True,
                       comments="#")
    for column in ga.dtype.names:
        assert np.allclose(ga[column], gb[column], rtol=1e-9, atol=1e-9), column
    # Far from contact g -> 1 with no lateral edge: each bin within 0.1 (1500 spheres, 0.02 d
    # bins: about 5 % noise per bin) and their mean within 0.03 on [3, 5] d.
    far = (ga["r_over_d"] >= 3.0) & (ga["r_over_d"] <= 5.0)
    assert np.all(np.abs(ga["g"][far] - 1.0) < 0.1)
    assert abs(ga["g"][far].mean() - 1.0) < 0.03
