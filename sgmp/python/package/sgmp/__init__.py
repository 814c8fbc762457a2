"""SGMP sphere packs: make them (pack, arrange), read and write pack files (read, write) and
measure them (measure).

Axes: X left-right, Y up, Z front-back; lengths in units of the control volume's side. The
work is done by the compiled extension sgmp._sgmp (the testbed's pack, engine and metrics
libraries); this module gives its functions their signatures and docstrings, and packs
their typed headers.
"""
import math
import os
import re
from typing import Any, Callable, Dict, List, NamedTuple, Optional, Sequence, Tuple, Union

from . import _sgmp
from ._sgmp import Pack, __version__

HeaderValue = Union[bool, int, float, str, Tuple[Union[int, float], ...], "Container"]
Progress = Callable[[str, int, int], None]
PathLike = Union[str, "os.PathLike[str]"]

__all__ = ["Pack", "Container", "pack", "arrange", "read", "write", "measure", "metric_table",
           "__version__"]


class Container(NamedTuple):
    """The container of a pack header's `container` key: walls at x_min, x_max and z_min,
    z_max, the floor at `floor`, open at the top (so its height is infinite)."""
    x_min: float
    x_max: float
    z_min: float
    z_max: float
    floor: float

    @property
    def origin(self) -> Tuple[float, float, float]:
        """The corner (x_min, floor, z_min)."""
        return (self.x_min, self.floor, self.z_min)

    @property
    def lengths(self) -> Tuple[float, float, float]:
        """Side lengths along x, y, z (y: infinite, no lid)."""
        return (self.x_max - self.x_min, math.inf, self.z_max - self.z_min)


_INTEGER = re.compile(r"[+-]?\d+\Z")
_REAL = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\Z")


def _number(text: str) -> Optional[Union[int, float]]:
    if _INTEGER.match(text):
        return int(text)
    if _REAL.match(text):
        return float(text)
    return None


# The kind of each pack parameter (the engine's parameter table): a parameter's value has
# one Python type whatever its text ("0" and "0.3" are both floats for momentum; "120" and
# "8,120,720" are both tuples for sweep_stages).
_KINDS: Dict[str, str] = _sgmp.header_kinds()


def _by_kind(kind: str, text: str) -> Optional[HeaderValue]:
    """`text` as its parameter's kind gives it, or None when it does not read so."""
    if kind == "number" and _number(text) is not None:
        return float(text)
    if kind == "integer" and _INTEGER.match(text):
        return int(text)
    if kind == "list":
        items = [_number(part) for part in text.split(",")]
        if all(item is not None for item in items):
            return tuple(item for item in items if item is not None)
    if kind in ("choice", "text"):
        return text
    return None


def _typed(key: str, text: str) -> HeaderValue:
    """A header value as Python sees it. A pack parameter takes its kind from the parameter
    table (number: float, integer: int, list: tuple, choice and text: str); `container` is a
    Container; any other key: bools, whole numbers, reals, tuples of numbers for
    comma-separated lists, else the string."""
    if key == "container":
        numbers = [_number(part) for part in text.split()]
        if len(numbers) == 5 and all(n is not None for n in numbers):
            return Container(*(float(n) for n in numbers if n is not None))
        return text
    if key in _KINDS:
        typed = _by_kind(_KINDS[key], text)
        if typed is not None:
            return typed
    if text in ("true", "false"):
        return text == "true"
    number = _number(text)
    if number is not None:
        return number
    if "," in text:
        items = [_number(part) for part in text.split(",")]
        if all(item is not None for item in items):
            return tuple(item for item in items if item is not None)
    return text


def _header(self: Pack) -> Dict[str, HeaderValue]:
    """The header's key=value pairs, typed (header_text has them as strings), in order."""
    return {key: _typed(key, value) for key, value in self.header_text.items()}


setattr(Pack, "header", property(_header, doc=_header.__doc__))  # the stub types it


def _given(options: Dict[str, Any]) -> Dict[str, Any]:
    return {key: value for key, value in options.items() if value is not None}


def pack(count: int, arrangement: str, seed: Optional[int] = None, *,
         phi_target: Optional[float] = None, size_modes: Optional[str] = None,
         size_distribution: Optional[str] = None, fraction_basis: Optional[str] = None,
         largest_diameter: Optional[str] = None,
         drop_order: Optional[str] = None, sides: Optional[str] = None,
         circle_factor: Optional[float] = None, sweep_positions: Optional[int] = None,
         sweep_stages: Optional[Union[str, Sequence[int]]] = None,
         lower_neighbours: Optional[int] = None, gap: Optional[str] = None,
         fall: Optional[str] = None, fall_step: Optional[float] = None,
         contact: Optional[str] = None, momentum: Optional[float] = None,
         walls: Optional[str] = None, stall_moves: Optional[int] = None,
         max_moves: Optional[int] = None, relax: Optional[str] = None,
         relax_stiffness: Optional[float] = None,
         relax_stiffness_factor: Optional[float] = None, relax_stages: Optional[int] = None,
         relax_shell: Optional[float] = None, relax_force_tolerance: Optional[float] = None,
         relax_time: Optional[float] = None, relax_crossings: Optional[int] = None,
         relax_friction: Optional[float] = None, relax_settle_limit: Optional[int] = None,
         relax_tangential_ratio: Optional[float] = None,
         relax_settle: Optional[str] = None,
         progress: Optional[Progress] = None) -> Pack:
    """Packs `count` spheres from `arrangement` (single-column, small-dense, large-dense,
    loose-random) with the Spin Gap Move Protocol and returns an sgmp.Pack.

    Every option is the `sgmp pack` option of the same name (dashes as underscores); one
    left at None keeps the engine's default, so the same options give the same pack as
    `sgmp pack`, bit for bit:

    - seed: whole number (default: the engine's default seed)
    - phi_target: the sizing rule's target packing fraction (0.63)
    - size_modes: 'a:f[:rho],...' relative diameter, fraction, density ('1:0.7,0.5:0.3')
    - size_distribution: a CSV file (header diameter,fraction[,density], one row per
      species) or 'lognormal:MEDIAN:SIGMA[:CLASSES[:QLO:QHI]]' (not with size_modes)
    - fraction_basis: what the fractions mean: 'number', 'volume' or 'mass'
    - largest_diameter: the largest species' diameter in a physical unit, '200 um' (set
      by a size_distribution CSV whose diameter column names its unit, diameter_um)
    - drop_order: a blend's drop order: 'stratified' (the default: each species at its
      share in every run of drops) or 'shuffled'
    - sides: 'walls' (the thesis' container) or 'periodic' (x and z periodic, the floor
      kept)
    - circle_factor, sweep_positions, sweep_stages ('8,120,720' or a list), lower_neighbours,
      gap ('largest'|'random'), fall, fall_step, contact, momentum, walls, stall_moves,
      max_moves: the protocol (see `sgmp pack --help`)
    - relax: 'none', 'frictionless' or 'frictional', and relax_stiffness,
      relax_stiffness_factor, relax_stages, relax_shell, relax_force_tolerance, relax_time,
      relax_crossings, relax_friction (mu of 'frictional', default 0.5),
      relax_settle_limit, relax_tangential_ratio (k_t/k of 'frictional'), relax_settle
      ('lp', the default, or 'dynamics': how 'frictionless' settles): the relaxation (a relaxed pack is returned whether or not it is
      certified: read pack.header['certified']); relax_stiffness, relax_stages and
      relax_time default by mode (frictionless 2e4, 1, 200; frictional 2e3, 5, 5), and the
      header records the values run
    - progress: called as progress(phase, done, total) with phase 'deposition' (spheres
      placed of total, every 1000), 'relaxation' or 'clearing' (minimiser steps) or
      'settling' (LP iterations); total is 0 where none is known.

    Ctrl-C raises KeyboardInterrupt at the next progress point. A bad value raises
    ValueError in one line naming the keyword, the value and the rule.
    """
    return _sgmp.pack(count, arrangement, seed, progress, **_given(dict(
        phi_target=phi_target, size_modes=size_modes, size_distribution=size_distribution,
        fraction_basis=fraction_basis, largest_diameter=largest_diameter,
        drop_order=drop_order, sides=sides,
        circle_factor=circle_factor,
        sweep_positions=sweep_positions,
        sweep_stages=sweep_stages, lower_neighbours=lower_neighbours, gap=gap, fall=fall,
        fall_step=fall_step, contact=contact, momentum=momentum, walls=walls,
        stall_moves=stall_moves, max_moves=max_moves, relax=relax,
        relax_stiffness=relax_stiffness, relax_stiffness_factor=relax_stiffness_factor,
        relax_stages=relax_stages, relax_shell=relax_shell,
        relax_force_tolerance=relax_force_tolerance, relax_time=relax_time,
        relax_crossings=relax_crossings, relax_friction=relax_friction,
        relax_settle_limit=relax_settle_limit, relax_tangential_ratio=relax_tangential_ratio,
        relax_settle=relax_settle)))


def arrange(count: int, arrangement: str, seed: Optional[int] = None, *,
            phi_target: Optional[float] = None, size_modes: Optional[str] = None,
            size_distribution: Optional[str] = None, fraction_basis: Optional[str] = None,
            largest_diameter: Optional[str] = None,
            drop_order: Optional[str] = None, sides: Optional[str] = None) -> Pack:
    """The starting arrangement itself (as `sgmp arrange`): `count` spheres of
    `arrangement` before the protocol; options as sgmp.pack."""
    return _sgmp.arrange(count, arrangement, seed, **_given(dict(
        phi_target=phi_target, size_modes=size_modes, size_distribution=size_distribution,
        fraction_basis=fraction_basis, largest_diameter=largest_diameter,
        drop_order=drop_order, sides=sides)))


def read(path: PathLike, frame: Optional[int] = None, radius: Optional[float] = None) -> Pack:
    """Reads a pack file: extended XYZ (frame: counted from 1, default the last),
    LAMMPS/LIGGGHTS dump custom or a LAMMPS data file; .gz transparently. radius replaces
    every radius (for species-only files). Raises ValueError ("file:line: reason") for
    malformed files."""
    return _sgmp.read(path, frame, radius)


def write(pack: Pack, path: PathLike, force: bool = False, format: Optional[str] = None, *,
          up: str = "y", length_scale: Optional[float] = None,
          length_unit: Optional[str] = None, density: Optional[float] = None) -> None:
    """Writes a pack file atomically in the format named by format (xyz, xyz.gz, data, dump,
    vtk, vtp) or by the path's ending; vtk and vtp also write NAME.container.vtk/.vtp.
    up='z' writes z up; length_scale with length_unit writes lengths in that unit, one
    control-volume side being length_scale; density is a data file's density column (as
    sgmp convert --up, --length-scale, --length-unit, --density). An existing file is
    replaced only with force=True (else FileExistsError); a format that cannot carry the
    pack, a header key that is not one word or a value with a quote or control character
    raises ValueError."""
    _sgmp.write(pack, path, force, format, up=up, length_scale=length_scale,
                length_unit=length_unit, density=density)


def measure(pack: Pack, region: Optional[Sequence[float]] = None,
            slab: Optional[float] = None, gr_bin: Optional[float] = None,
            gr_range: Optional[float] = None, gr_density: Optional[str] = None,
            gr_container_space: Optional[bool] = None, voronoi: Optional[bool] = None,
            q6_cutoff: Optional[float] = None, overlap_floor: Optional[float] = None,
            threads: Optional[int] = None) -> Dict[str, Any]:
    """Every metric of one pack, as `sgmp-compare measure` (options named as its
    command-line options, dashes as underscores; one left at None keeps its default;
    region = [xlo, xhi, ylo, yhi, zlo, zhi], default the control volume). Returns the dict
    of its metrics.json (phi, overlaps, z_mean_tol_*, split_ratio, q6_*, voronoi_phi_*, ...)
    plus the curves as numpy arrays: g_r (rows r/d, g), phi_y (rows y_mid, phi), p_z (rows z,
    then P(Z) at each tolerance of p_z_tolerances); for a blend also g_r_partial and
    phi_y_species."""
    return _sgmp.measure(pack, region, **_given(dict(
        slab=slab, gr_bin=gr_bin, gr_range=gr_range, gr_density=gr_density,
        gr_container_space=gr_container_space, voronoi=voronoi, q6_cutoff=q6_cutoff,
        overlap_floor=overlap_floor, threads=threads)))


def metric_table() -> List[Dict[str, Any]]:
    """The metric table sgmp-compare judges and writes by, one dict per metric: name (the
    key of measure()'s dict and of metrics.json), label, unit, definition (a link into
    compare/docs/definitions.md), kind ("scalar", "curve" or "distribution"), margin (the
    declared equivalence margin), judged (False: information only), contact_tolerance (δ/d
    of a contact metric, else None), summary_column (its `sgmp batch` summary.csv column, or
    None), in_report (a row of every comparison) and in_metrics_json."""
    return _sgmp.metric_table()


def _options_of_the_extension() -> Optional[list]:
    """The keyword options the compiled sgmp.pack takes (from its refusal of an unknown
    one): the tests check that pack()'s signature names every one of them."""
    try:
        _sgmp.pack(1, "loose-random", None, None, no_such_option=1)
    except ValueError as error:
        found = re.search(r"\(options: (.*)\)", str(error))
        return [name.strip() for name in found.group(1).split(",")] if found else None
    return None
