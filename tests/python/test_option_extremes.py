"""Every numeric option of sgmp.pack, sgmp.arrange and sgmp.measure at the extremes (±1e308,
NaN, ±inf, 2⁶⁴, −2⁶³−1, the smallest doubles): the call returns or raises ValueError,
TypeError or OverflowError naming the option; it never takes the interpreter down. (The
command-line tools get the same property test: tests/cli/option_extremes.py.)"""

import math

import pytest

import sgmp

EXTREMES = [1e308, -1e308, math.nan, math.inf, -math.inf, 2**64, -(2**63) - 1, 1e-308,
            5e-324, 0, -1]
PACK_NUMBERS = ["phi_target", "circle_factor", "sweep_positions", "lower_neighbours",
                "fall_step", "momentum", "stall_moves", "max_moves", "relax_stiffness",
                "relax_stiffness_factor", "relax_stages", "relax_shell",
                "relax_force_tolerance", "relax_time", "relax_crossings", "relax_friction"]
MEASURE_NUMBERS = ["slab", "gr_bin", "gr_range", "q6_cutoff", "overlap_floor", "threads"]
REFUSALS = (ValueError, TypeError, OverflowError)


def spelled(name):
    """The names a message may use for a keyword: as given, or as its command-line option."""
    return (name, name.replace("_", "-"))


@pytest.mark.parametrize("name", PACK_NUMBERS + ["count", "seed"])
@pytest.mark.parametrize("value", EXTREMES, ids=repr)
def test_pack_options_at_the_extremes(name, value):
    options = {"count": 40, "arrangement": "loose-random", name: value}
    try:
        pack = sgmp.pack(**options)
    except REFUSALS as error:
        assert any(s in str(error) for s in spelled(name)), str(error)
        assert "\n" not in str(error)
        return
    assert len(pack) == options["count"]


@pytest.mark.parametrize("name", ["count", "phi_target"])
@pytest.mark.parametrize("value", EXTREMES, ids=repr)
def test_arrange_options_at_the_extremes(name, value):
    options = {"count": 40, "arrangement": "loose-random", name: value}
    try:
        sgmp.arrange(**options)
    except REFUSALS as error:
        assert any(s in str(error) for s in spelled(name)), str(error)


@pytest.fixture(scope="module")
def small_pack():
    return sgmp.pack(40, "loose-random", seed=1)


@pytest.mark.parametrize("name", MEASURE_NUMBERS)
@pytest.mark.parametrize("value", EXTREMES, ids=repr)
def test_measure_options_at_the_extremes(small_pack, name, value):
    try:
        metrics = sgmp.measure(small_pack, **{name: value})
    except REFUSALS as error:
        assert any(s in str(error) for s in spelled(name)), str(error)
        return
    assert 0.0 <= metrics["phi"] <= 0.74048


@pytest.mark.parametrize("value", EXTREMES, ids=repr)
def test_measure_region_at_the_extremes(small_pack, value):
    try:
        metrics = sgmp.measure(small_pack, region=[value, 0.5, -0.5, 0.5, -0.5, 0.5])
    except REFUSALS as error:
        assert "region" in str(error), str(error)
        return
    assert -0.5 <= value < 0.5 and 0.0 <= metrics["phi"] <= 0.74048
