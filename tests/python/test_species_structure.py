"""Per-species coordination of a blend, computed a second way: `sgmp-compare measure`'s
Z_IJ(delta) and Z_I(delta) (metrics.json, "species") against scipy's cKDTree on the same
pack, and its partial g_I_J columns (g_r.csv) checked for range and far-field value."""
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


# Two blends: sizes within a factor 2 (one contact search), and a wide trimodal blend
# (1 : 0.25 : 0.15, whose small and large spheres are searched apart).
@pytest.mark.cli
@pytest.mark.parametrize("count,modes,basis", [
    ("1500", "1:0.5,0.6:0.5", "number"),
    ("4000", "1:0.6,0.25:0.2,0.15:0.2", "volume"),
])
def test_blend_coordination_equals_a_kd_tree_count(tmp_path, count, modes, basis):
    path = tmp_path / "blend.xyz"
    made = subprocess.run([str(SGMP), "pack", "--count", count, "--arrangement", "loose-random",
                           "--seed", "4", "--size-modes", modes, "--fraction-basis", basis,
                           "--out", str(path)],
                          capture_output=True, text=True, check=False)
    assert made.returncode == 0, made.stderr
    result = subprocess.run([str(COMPARE), "measure", str(path), "--out", str(tmp_path / "m"),
                             "--no-voronoi"], capture_output=True, text=True, check=False)
    assert result.returncode == 0, result.stderr
    metrics = json.loads((tmp_path / "m" / "blend.metrics.json").read_text())
    species_block = metrics["species"]

    # Columns of the extended XYZ file (Properties=id:I:1:pos:R:3:radius:R:1:bin:I:1:
    # species_id:I:1), read with numpy alone.
    table = np.loadtxt(path, skiprows=2)
    centres, radii, species = table[:, 1:4], table[:, 4], table[:, 6].astype(int)
    assert "species_id:I:1" in path.read_text().splitlines()[1]
    d = 2.0 * radii.mean()
    region = (np.abs(centres) <= 0.5).all(axis=1)  # the control volume, the default region
    tree = cKDTree(centres)
    names = list(species_block["pairs"][0]["z_ij"].keys())
    tolerances = [float(name) for name in names]
    reach = 2.0 * radii.max() + max(tolerances) * d
    neighbours = tree.query_ball_point(centres, reach)
    count = {}
    for a in np.flatnonzero(region):
        for b in neighbours[a]:
            if b == a:
                continue
            gap = np.linalg.norm(centres[a] - centres[b]) - radii[a] - radii[b]
            key = (int(species[a]), int(species[b]))
            counts = count.setdefault(key, np.zeros(len(tolerances)))
            counts += np.array([gap <= t * d for t in tolerances])
    origins = {int(s): int(np.sum(region & (species == s))) for s in np.unique(species)}
    for pair in species_block["pairs"]:
        i, j = pair["i"], pair["j"]
        for t, name in enumerate(names):
            # Integer counts over the same origins: equal up to the division's rounding.
            assert pair["z_ij"][name] == pytest.approx(
                count.get((i, j), np.zeros(len(names)))[t] / origins[i], rel=1e-12, abs=0)
            assert pair["z_ji"][name] == pytest.approx(
                count.get((j, i), np.zeros(len(names)))[t] / origins[j], rel=1e-12, abs=0)
    # The whole pack's Z(delta): every pair counted from each origin.
    for t, name in enumerate(names):
        total = sum(c[t] for (a, _), c in count.items())
        assert metrics[f"z_mean_tol_{name}"] == pytest.approx(
            total / int(region.sum()), rel=1e-12, abs=0)
    for one in species_block["species"]:
        s = one["species"]
        assert one["origins"] == origins[s]
        for t, name in enumerate(names):
            total = sum(c[t] for (a, _), c in count.items() if a == s)
            assert one["z_mean"][name] == pytest.approx(total / origins[s], rel=1e-12, abs=0)

    rows = [line for line in (tmp_path / "m" / "blend.g_r.csv").read_text().splitlines()
            if not line.startswith("#")]
    header = rows[0].split(",")
    table = np.array([[float(v) for v in row.split(",")] for row in rows[1:]])
    diameter = {one["species"]: one["diameter_over_d"] for one in species_block["species"]}
    for pair in species_block["pairs"]:
        column = table[:, header.index(pair["column"])]
        assert (column >= 0.0).all()
        # g_IJ -> 1 far from contact when the sizes are within a factor 2. In the wide
        # blend the range of 5 d (d the number-mean diameter) ends before its coarse
        # spheres (5.7 d) stop shaping the small ones' neighbourhoods: g_3_3 is 0.94 there.
        narrow = max(diameter.values()) <= 2.0 * min(diameter.values())
        if narrow:
            far = table[:, header.index("r_over_d")] >= 3.0
            assert abs(column[far].mean() - 1.0) < 0.05
