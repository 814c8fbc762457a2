"""SGMP sphere packs: make them (pack, arrange), read and write pack files (read, write) and
measure them (measure).

Axes: X left-right, Y up, Z front-back; lengths in units of the control volume's side. The
work is done by the compiled extension sgmp._sgmp (the testbed's pack, engine and metrics
libraries); this module gives its functions their signatures and docstrings, and packs
their typed headers.
"""
import math
import re
from typing import NamedTuple, Optional

from . import _sgmp
from ._sgmp import Pack, __version__, measure, read, write

__all__ = ["Pack", "Container", "pack", "arrange", "read", "write", "measure", "__version__"]


class Container(NamedTuple):
    """The container of a pack header's `container` key: walls at x_min, x_max and z_min,
    z_max, the floor at `floor`, open at the top (so its height is infinite)."""
    x_min: float
    x_max: float
    z_min: float
    z_max: float
    floor: float

    @property
    def origin(self):
        """The corner (x_min, floor, z_min)."""
        return (self.x_min, self.floor, self.z_min)

    @property
    def lengths(self):
        """Side lengths along x, y, z (y: infinite, no lid)."""
        return (self.x_max - self.x_min, math.inf, self.z_max - self.z_min)


_INTEGER = re.compile(r"[+-]?\d+\Z")
_REAL = re.compile(r"[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?\Z")


def _number(text):
    if _INTEGER.match(text):
        return int(text)
    if _REAL.match(text):
        return float(text)
    return None


def _typed(key, text):
    """A header value as Python sees it: bools, whole numbers, reals, tuples of numbers for
    comma-separated lists, a Container for `container`; anything else stays a string."""
    if key == "container":
        numbers = [_number(part) for part in text.split()]
        if len(numbers) == 5 and all(n is not None for n in numbers):
            return Container(*(float(n) for n in numbers))
        return text
    if text in ("true", "false"):
        return text == "true"
    number = _number(text)
    if number is not None:
        return number
    if "," in text:
        items = [_number(part) for part in text.split(",")]
        if all(item is not None for item in items):
            return tuple(items)
    return text


def _header(self):
    """The header's key=value pairs, typed (header_text has them as strings), in order."""
    return {key: _typed(key, value) for key, value in self.header_text.items()}


Pack.header = property(_header, doc=_header.__doc__)


def _given(options):
    return {key: value for key, value in options.items() if value is not None}


def pack(count, arrangement, seed=None, *, phi_target=None, size_modes=None,
         size_distribution=None, fraction_basis=None, drop_order=None, sides=None,
         circle_factor=None, sweep_positions=None, sweep_stages=None,
         lower_neighbours=None, gap=None, fall=None, fall_step=None, contact=None,
         momentum=None, walls=None, stall_moves=None, max_moves=None, relax=None,
         relax_stiffness=None, relax_stiffness_factor=None, relax_stages=None,
         relax_shell=None, relax_force_tolerance=None, relax_time=None, relax_crossings=None,
         relax_friction=None, relax_settle_limit=None, relax_tangential_ratio=None,
         relax_settle=None, progress=None):
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
        fraction_basis=fraction_basis, drop_order=drop_order, sides=sides,
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


def arrange(count, arrangement, seed=None, *, phi_target=None, size_modes=None,
            size_distribution=None, fraction_basis=None, drop_order=None, sides=None):
    """The starting arrangement itself (as `sgmp arrange`): `count` spheres of
    `arrangement` before the protocol; options as sgmp.pack."""
    return _sgmp.arrange(count, arrangement, seed, **_given(dict(
        phi_target=phi_target, size_modes=size_modes, size_distribution=size_distribution,
        fraction_basis=fraction_basis, drop_order=drop_order, sides=sides)))


def _options_of_the_extension() -> Optional[list]:
    """The keyword options the compiled sgmp.pack takes (from its refusal of an unknown
    one): the tests check that pack()'s signature names every one of them."""
    try:
        _sgmp.pack(1, "loose-random", None, None, no_such_option=1)
    except ValueError as error:
        found = re.search(r"\(options: (.*)\)", str(error))
        return [name.strip() for name in found.group(1).split(",")] if found else None
    return None
