# Type stubs of the samplescope package (the functions of the extension module
# samplescope._native, re-exported). One block per area, in the order of src/python/mod.rs.
from typing import Any, Dict, List, Optional, Union

import numpy as np
import numpy.typing as npt

__version__: str

# points.rs
ParamValue = Union[int, float, bool, str, List[float]]

def points(
    pattern: str,
    n: int,
    *,
    dims: int = 2,
    seed: Optional[int] = None,
    allow_fewer: bool = False,
    **params: ParamValue,
) -> npt.NDArray[np.float64]:
    """The first n points of a pattern in [0,1)^dims, shape (n, dims), float64: the numbers
    `samplescope points` writes."""

def patterns() -> List[Dict[str, Any]]:
    """The catalogue of patterns: name, summary, max_dims, random, params (name, doc, kind,
    default, allowed, min/max, options, length)."""
