"""The size moments of a blend and the random-close-packing fraction they predict
(metrics.json "size_distribution"), computed a second way: numpy and scipy.stats from the
radii in the file, and the Desmond & Weeks (2014) formula in closed form for the bimodal
blend 1 : 0.5 at equal volumes (number fractions 1/9 and 8/9)."""
import json
import os
import pathlib
import subprocess

import numpy as np
import pytest
from scipy import stats

SOURCE = pathlib.Path(os.environ.get("SGMP_SOURCE_DIR", pathlib.Path(__file__).parents[2]))
SGMP = os.environ.get("SGMP_EXECUTABLE", SOURCE / "build" / "sgmp" / "sgmp")
COMPARE = os.environ.get("SGMP_COMPARE_EXECUTABLE", SOURCE / "build" / "compare" / "sgmp-compare")


def desmond_weeks(delta, skew):
    return 0.634 + 0.0658 * delta + 0.0857 * skew * delta ** 2


def test_the_formula_for_the_bimodal_blend_in_closed_form():
    # r = 1 with probability 1/9, 1/2 with 8/9: mean 5/9, variance 2/81, third central
    # moment 7/729; delta = sqrt(2)/5, S = (7/729) / (2/81)^(3/2) = 7 / (2 sqrt 2).
    delta = np.sqrt(2.0) / 5.0
    skew = 7.0 / (2.0 * np.sqrt(2.0))
    radii = np.array([1.0] + [0.5] * 8)
    assert np.std(radii) / np.mean(radii) == pytest.approx(delta, rel=1e-14)
    assert stats.skew(radii) == pytest.approx(skew, rel=1e-13)
    assert desmond_weeks(delta, skew) == pytest.approx(0.66957, abs=1e-5)


@pytest.mark.cli
@pytest.mark.parametrize("modes,basis", [("1:0.5,0.5:0.5", "volume"),
                                         ("1:0.6,0.25:0.2,0.15:0.2", "volume")])
def test_measure_reports_the_moments_and_the_prediction(tmp_path, modes, basis):
    path = tmp_path / "blend.xyz"
    for command in ([SGMP, "pack", "--count", "3000", "--seed", "1", "--arrangement",
                     "loose-random", "--size-modes", modes, "--fraction-basis", basis, "--out",
                     path],
                    [COMPARE, "measure", path, "--out", tmp_path / "m", "--no-voronoi"]):
        result = subprocess.run([str(c) for c in command], capture_output=True, text=True,
                                check=False)
        assert result.returncode == 0, result.stderr
    block = json.loads((tmp_path / "m" / "blend.metrics.json").read_text())["size_distribution"]
    radii = np.loadtxt(path, skiprows=2)[:, 4]
    delta = np.std(radii) / np.mean(radii)  # population sd, by number
    skew = stats.skew(radii)                # biased (population) skewness, as defined
    # Sums of 3000 terms in another order: equal to 10^-12.
    assert block["polydispersity"] == pytest.approx(delta, rel=1e-12)
    assert block["skewness"] == pytest.approx(skew, rel=1e-10)
    if delta <= 0.4 and -2.0 <= skew <= 4.0:
        assert block["phi_rcp_desmond_weeks"] == pytest.approx(desmond_weeks(delta, skew),
                                                               rel=1e-12)
        # A physical random close packing: above the one-size 0.634, below 1.
        assert 0.634 < block["phi_rcp_desmond_weeks"] < 1.0
    else:  # the trimodal blend: delta 0.48, S 7.8, beyond the fitted range
        assert block["phi_rcp_desmond_weeks"] is None


@pytest.mark.cli
def test_equal_spheres_have_no_size_block(tmp_path):
    path = tmp_path / "equal.xyz"
    for command in ([SGMP, "pack", "--count", "300", "--seed", "1", "--arrangement",
                     "loose-random", "--out", path],
                    [COMPARE, "measure", path, "--out", tmp_path / "m", "--no-voronoi"]):
        result = subprocess.run([str(c) for c in command], capture_output=True, text=True,
                                check=False)
        assert result.returncode == 0, result.stderr
    assert "size_distribution" not in json.loads((tmp_path / "m" / "equal.metrics.json").read_text())
