# Types of the compiled extension sgmp._sgmp (pybind11; sgmp/python/src/). Checked by mypy
# in tests/python/test_typing.py against sgmp/__init__.py and a user's script.
import os
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy
import numpy.typing

__version__: str

_Path = Union[str, "os.PathLike[str]"]

class Pack:
    def __init__(
        self,
        positions: numpy.typing.ArrayLike,
        radii: numpy.typing.ArrayLike,
        bins: Optional[numpy.typing.ArrayLike] = ...,
        ids: Optional[numpy.typing.ArrayLike] = ...,
        header: Optional[Mapping[str, Any]] = ...,
        species: Optional[numpy.typing.ArrayLike] = ...,
    ) -> None: ...
    @property
    def positions(self) -> numpy.ndarray: ...
    @property
    def radii(self) -> numpy.ndarray: ...
    @property
    def bins(self) -> numpy.ndarray: ...
    @property
    def ids(self) -> numpy.ndarray: ...
    @property
    def species(self) -> numpy.ndarray: ...
    @property
    def header_text(self) -> Dict[str, str]: ...
    # The typed header: a property sgmp/__init__.py adds.
    @property
    def header(self) -> Dict[str, Any]: ...
    def __len__(self) -> int: ...

def header_kinds() -> Dict[str, str]: ...
def metric_table() -> List[Dict[str, Any]]: ...
def pack(
    count: int,
    arrangement: str,
    seed: Optional[int] = ...,
    progress: Optional[Callable[[str, int, int], None]] = ...,
    **options: Any,
) -> Pack: ...
def arrange(count: int, arrangement: str, seed: Optional[int] = ..., **options: Any) -> Pack: ...
def read(path: _Path, frame: Optional[int] = ..., radius: Optional[float] = ...) -> Pack: ...
def write(
    pack: Pack,
    path: _Path,
    force: bool = ...,
    format: Optional[str] = ...,
    *,
    up: str = ...,
    length_scale: Optional[float] = ...,
    length_unit: Optional[str] = ...,
    density: Optional[float] = ...,
) -> None: ...
def measure(
    pack: Pack,
    region: Optional[Sequence[float]] = ...,
    slab: float = ...,
    gr_bin: float = ...,
    gr_range: float = ...,
    gr_density: str = ...,
    gr_container_space: bool = ...,
    voronoi: bool = ...,
    q6_cutoff: float = ...,
    overlap_floor: float = ...,
    threads: int = ...,
) -> Dict[str, Any]: ...
