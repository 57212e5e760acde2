"""A map's distance transform and connected components, in C (``_map_transforms.c``).

The costmap's obstacle distances, AMCL's likelihood field and the planner's components are
computed from the whole map once per map version (then read from the map cache). scipy's
``distance_transform_edt`` and ``label`` compute the same arrays, but importing
``scipy.ndimage`` costs about a quarter of a CPU-second, the largest single part of a first
start on a new map. The extension is built with the package (``pyproject.toml``, optional:
where it is missing, ``available()`` says so and scipy computes them, the same values).
"""

from __future__ import annotations

import ctypes
import logging
from functools import cache

import numpy as np
import numpy.typing as npt

logger = logging.getLogger(__name__)

_ADDRESS = ctypes.c_void_p


@cache
def _library() -> ctypes.CDLL | None:
    try:
        from assistantx.nav import _map_transforms  # type: ignore[attr-defined]
    except ImportError:
        logger.info("the compiled map transforms are not built; scipy.ndimage computes them")
        return None
    library = ctypes.CDLL(_map_transforms.__file__)
    int32 = ctypes.c_int32
    library.map_distance.restype = ctypes.c_int
    library.map_distance.argtypes = [_ADDRESS, int32, int32, _ADDRESS]
    library.map_components.restype = int32
    library.map_components.argtypes = [_ADDRESS, int32, int32, _ADDRESS]
    return library


def available() -> bool:
    """Whether the compiled transforms were built with this installation."""
    return _library() is not None


def distance_to(marked: npt.NDArray[np.bool_]) -> npt.NDArray[np.float64]:
    """Each cell's exact Euclidean distance (cells) to the nearest marked cell (0 on one):
    ``scipy.ndimage.distance_transform_edt(~marked)``. No marked cell: every cell ``inf``."""
    library = _library()
    if library is None:
        if not marked.any():
            return np.full(marked.shape, np.inf)
        from scipy.ndimage import distance_transform_edt

        return np.asarray(distance_transform_edt(~marked), dtype=np.float64)
    cells = np.ascontiguousarray(marked, dtype=np.bool_)
    height, width = cells.shape
    out = np.empty(cells.shape, dtype=np.float64)
    if library.map_distance(cells.ctypes.data, height, width, out.ctypes.data) != 0:
        raise MemoryError(f"no memory for the distance transform of a {width} x {height} map")
    return out


def components(cells: npt.NDArray[np.bool_]) -> npt.NDArray[np.int32]:
    """Each set cell's 4-connected component, numbered from 1 in row-major order of the
    components' first cells, 0 elsewhere: ``scipy.ndimage.label(cells)``'s labels."""
    library = _library()
    labels = np.empty(cells.shape, dtype=np.int32)
    if library is None:
        from scipy.ndimage import label

        label(cells, output=labels)
        return labels
    flat = np.ascontiguousarray(cells, dtype=np.bool_)
    height, width = flat.shape
    library.map_components(flat.ctypes.data, height, width, labels.ctypes.data)
    return labels
