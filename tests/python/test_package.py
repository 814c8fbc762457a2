"""The Python package behaves like one: pack()'s signature names every option the extension
takes, headers are typed, arrays refuse writes, packs pickle, and a progress callback is
called (and checked)."""
import inspect
import math
import pickle

import numpy as np
import pytest

import sgmp


def test_pack_signature_names_every_option_of_the_extension():
    extension = sgmp._options_of_the_extension()
    assert extension, "the extension no longer lists its options"
    parameters = inspect.signature(sgmp.pack).parameters
    assert set(extension) <= set(parameters), set(extension) - set(parameters)
    assert set(parameters) - set(extension) == {"progress"}
    assert "relax_friction" in sgmp.pack.__doc__ and "progress" in sgmp.pack.__doc__


def test_header_values_are_typed():
    p = sgmp.pack(150, "loose-random", seed=7, size_modes="1:0.5,0.5:0.5")
    h = p.header
    assert h["count"] == 150 and isinstance(h["count"], int)
    assert isinstance(h["diameter"], float) and h["diameter"] > 0.0
    assert h["generator"] == "sgmp" and h["arrangement"] == "loose-random"
    assert h["species_counts"] == (75, 75)
    box = h["container"]
    assert isinstance(box, sgmp.Container)
    assert box.origin == (-0.625, -0.625, -0.625)
    assert box.lengths[0] == 1.25 and box.lengths[2] == 1.25 and math.isinf(box.lengths[1])
    assert p.header_text["count"] == "150"  # the strings as written
    assert list(h) == list(p.header_text)  # header order kept


def test_arrays_refuse_writes_instead_of_losing_them():
    p = sgmp.pack(50, "small-dense", seed=1)
    for name in ("positions", "radii", "bins", "ids", "species"):
        array = getattr(p, name)
        with pytest.raises(ValueError):
            array[0] = array[0]
    copy = p.positions.copy()  # a copy is the user's to change
    copy[0, 0] = 99.0
    assert p.positions[0, 0] != 99.0


def test_packs_pickle_with_species_and_header():
    p = sgmp.pack(120, "loose-random", seed=5, size_modes="1:0.5,0.6:0.5")
    q = pickle.loads(pickle.dumps(p))
    for name in ("positions", "radii", "bins", "ids", "species"):
        assert np.array_equal(getattr(q, name), getattr(p, name)), name
    assert q.header_text == p.header_text


def test_progress_is_called_and_checked():
    calls = []
    sgmp.pack(2500, "loose-random", seed=1, progress=lambda *a: calls.append(a))
    assert calls[0] == ("deposition", 1000, 2500) and calls[-1] == ("deposition", 2500, 2500)
    with pytest.raises(ValueError, match="progress"):
        sgmp.pack(10, "loose-random", progress=3)


def test_unknown_and_bad_options_raise_one_line_value_errors():
    with pytest.raises(TypeError):
        sgmp.pack(10, "loose-random", no_such_option=1)
    with pytest.raises(ValueError, match=r"^relax_friction = -1: "):
        sgmp.pack(10, "loose-random", relax="frictional", relax_friction=-1)
    with pytest.raises(ValueError, match="species"):
        sgmp.Pack(np.zeros((2, 3)), np.ones(2), species=np.array([1, -2]))


def test_size_distributions_from_a_file_or_lognormal(tmp_path):
    table = tmp_path / "blend.csv"
    table.write_text("diameter,fraction,density\n10,0.51,1.95\n5,0.17,1.95\n6,0.18,2.7\n")
    # Mass fractions 0.86 in all (the rest binder): normalised, with a UserWarning as the
    # command line's warning line.
    with pytest.warns(UserWarning, match=r"fractions sum to 0\.86\d*; normalised to 1$"):
        p = sgmp.pack(2000, "loose-random", seed=1, size_distribution=str(table),
                      fraction_basis="mass")
    with pytest.warns(UserWarning, match="^size_modes = 1:0.3,0.5:0.3: fractions sum to 0.6"):
        sgmp.pack(50, "loose-random", size_modes="1:0.3,0.5:0.3")
    assert p.header["size_distribution"] == str(table)
    assert len(p.header["species_counts"]) == 3 and set(np.unique(p.species)) == {1, 2, 3}
    q = sgmp.pack(400, "loose-random", seed=1, size_distribution="lognormal:200:0.3:4",
                  fraction_basis="volume")
    counts = q.header["species_counts"]
    assert len(counts) == 4 and sum(counts) == 400
    assert counts[0] > counts[-1]  # equal volumes: more of the small spheres
    with pytest.raises(ValueError, match="^size_distribution = lognormal:200:-1: SIGMA"):
        sgmp.pack(10, "loose-random", size_distribution="lognormal:200:-1")
    with pytest.raises(ValueError, match="not both"):
        sgmp.pack(10, "loose-random", size_distribution="lognormal:200:0.3", size_modes="1:1")
    with pytest.raises(ValueError, match="readable file"):
        sgmp.pack(10, "loose-random", size_distribution=str(tmp_path / "missing.csv"))


def test_header_values_take_their_parameters_kind():
    # The type comes from the parameter table, not the text: momentum is a float whether
    # it reads 0 or 0.3, sweep_stages a tuple whether it lists one stage or three.
    plain = sgmp.pack(60, "loose-random", seed=2)
    staged = sgmp.pack(60, "loose-random", seed=2, momentum=0.3, sweep_stages="8,120,720")
    assert plain.header["momentum"] == 0.0 and isinstance(plain.header["momentum"], float)
    assert isinstance(staged.header["momentum"], float)
    assert plain.header["sweep_stages"] == (120,)
    assert staged.header["sweep_stages"] == (8, 120, 720)
    assert isinstance(plain.header["circle_factor"], float)  # "50" in the file
    assert isinstance(plain.header["lower_neighbours"], int)


def test_signatures_are_readable_by_inspect():
    for function in (sgmp.measure, sgmp.read, sgmp.write, sgmp.pack, sgmp.arrange):
        signature = inspect.signature(function)
        assert signature.return_annotation is not inspect.Signature.empty, function
    assert list(inspect.signature(sgmp.measure).parameters)[:2] == ["pack", "region"]


def test_write_refuses_header_entries_that_do_not_read_back(tmp_path):
    positions = np.array([[0.0, -0.5, 0.0], [0.2, -0.5, 0.0]])
    radii = np.array([0.05, 0.05])
    # "a b" read back as {'a': 'T', 'b': '1'} and "x=y" as {'x': 'y=1'}; a line break or
    # an ESC byte wrote a file that sgmp.read refuses.
    for header in ({"a b": "1"}, {"x=y": "1"}, {"a\nb": "1"}, {"k": "v\x1b[31m"}, {"k": 'a"b'}):
        with pytest.raises(ValueError, match="header"):
            sgmp.Pack(positions, radii, header=header)
    with pytest.raises(ValueError, match="must be a string"):
        sgmp.Pack(positions, radii, header={3: "x"})
    good = sgmp.Pack(positions, radii, header={"lab": "glass beads", "k": "1"})
    sgmp.write(good, tmp_path / "g.xyz")
    assert sgmp.read(tmp_path / "g.xyz").header_text["lab"] == "glass beads"


def test_ids_and_bins_must_be_whole_numbers():
    positions = np.array([[0.0, -0.5, 0.0], [0.2, -0.5, 0.0]])
    radii = np.array([0.05, 0.05])
    # NaN ids became INT64_MIN and 2.7 was truncated to 2, silently.
    with pytest.raises(ValueError, match="ids: entry 1 = nan must be a whole number"):
        sgmp.Pack(positions, radii, ids=np.array([1.0, np.nan]))
    with pytest.raises(ValueError, match="bins: entry 0 = 2.7 must be a whole number"):
        sgmp.Pack(positions, radii, bins=np.array([2.7, 1.0]))
    with pytest.raises(ValueError, match="must be whole numbers"):
        sgmp.Pack(positions, radii, ids=np.array(["1", "2"]))
    exact = sgmp.Pack(positions, radii, ids=np.array([7.0, 9.0]), bins=np.array([3, 4]))
    assert list(exact.ids) == [7, 9] and list(exact.bins) == [3, 4]
