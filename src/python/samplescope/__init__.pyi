# Type stubs of the samplescope package (the functions of the extension module
# samplescope._native, re-exported). One block per area, in the order of src/python/mod.rs.
import os
import pathlib
from typing import Any, Dict, List, Literal, Mapping, Optional, Sequence, Tuple, Union

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
    budget: Optional[float] = None,
    budget_memory: Optional[float] = None,
    **params: ParamValue,
) -> npt.NDArray[np.float64]:
    """The first n points of a pattern in [0,1)^dims, shape (n, dims), float64: the numbers
    `samplescope points` writes."""

def patterns() -> List[Dict[str, Any]]:
    """The catalogue of patterns: name, summary, max_dims, random, params (name, doc, kind,
    default, allowed, min/max, options, length)."""

# discrepancy.rs
def discrepancy(
    points: npt.ArrayLike,
    method: Literal["star", "L2-star", "CD", "WD", "MD", "SD"] = "L2-star",
    *,
    budget: Optional[float] = None,
    budget_memory: Optional[float] = None,
) -> float:
    """One discrepancy of an (N, D) point set in [0,1)^D, scipy.stats.qmc.discrepancy's
    conventions: "L2-star" (default) the root T_N; "CD", "WD", "MD" squared (as scipy's); "SD"
    squared; "star" the exact 2D star discrepancy D*_N."""

# analyze.rs
def analyze(
    points: npt.ArrayLike,
    *,
    size: int = 256,
    tolerance: Optional[float] = None,
    exact: bool = False,
    project: Optional[Tuple[int, int]] = None,
    budget: Optional[float] = None,
    budget_memory: Optional[float] = None,
) -> Dict[str, Any]:
    """The dict `samplescope analyze --points FILE --json` prints for these points, plus (2D
    points) the arrays "periodogram" (M, M), "raps" (K, 2), "anisotropy" (K, 2), "rdf" (B, 4)."""

def periodogram(
    points: Union[npt.ArrayLike, str],
    size: int = 256,
    tolerance: Optional[float] = None,
    exact: bool = False,
    realizations: Optional[int] = None,
    *,
    n: Optional[int] = None,
    seed: Optional[int] = None,
    budget: Optional[float] = None,
    budget_memory: Optional[float] = None,
    **params: ParamValue,
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64]]:
    """(P, raps): the M×M periodogram P[ky + M//2, kx + M//2] of an (N, 2) array, of a
    (K, N, 2) array of realizations (averaged) or of a pattern (name, n, realizations, seed,
    parameters), and its radial average (rows radius, power)."""

# filter.rs
def filter_response(
    kernel: str,
    *,
    mode: Literal["separable", "radial"] = "separable",
    budget: Optional[float] = None,
    budget_memory: Optional[float] = None,
    **params: ParamValue,
) -> Tuple[
    npt.NDArray[np.float64], npt.NDArray[np.float64], npt.NDArray[np.float64], Dict[str, Any]
]:
    """(omega, magnitude, phase, metrics): the response from 0 to 2 cycles per sample (513
    values, as `filter --response` writes) and the dict `samplescope filter --json` prints."""

# recon.rs
def reconstruct(
    signal: str = "zone-plate",
    pattern: Optional[str] = None,
    points: Optional[npt.ArrayLike] = None,
    filter: str = "gaussian",
    size: int = 512,
    *,
    n: Optional[int] = None,
    spp: Optional[int] = None,
    seed: Optional[int] = None,
    mode: Literal["separable", "radial"] = "separable",
    signal_params: Optional[Mapping[str, ParamValue]] = None,
    pattern_params: Optional[Mapping[str, ParamValue]] = None,
    filter_params: Optional[Mapping[str, ParamValue]] = None,
    allow_fewer: bool = False,
    budget: Optional[float] = None,
    budget_memory: Optional[float] = None,
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.float64], Dict[str, Any]]:
    """(image, reference, report): size×size arrays (row 0 at the bottom) and the dict
    `samplescope recon --json` prints."""

# converge.rs
def converge(
    pattern: str,
    integrand: str,
    n: Sequence[int],
    realizations: int,
    dims: int = 2,
    *,
    seed: Optional[int] = None,
    no_shift: bool = False,
    randomize: bool = False,
    pattern_params: Optional[Mapping[str, ParamValue]] = None,
    integrand_params: Optional[Mapping[str, ParamValue]] = None,
    budget: Optional[float] = None,
    budget_memory: Optional[float] = None,
) -> Dict[str, Any]:
    """The dict `samplescope converge --json` prints, plus the rows as arrays "n" (int64),
    "mse", "mse_stderr" (NaN where undefined), "variance", "bias2"."""

# render.rs
def render(
    scene: Union[str, "os.PathLike[str]"],
    out_dir: Union[str, "os.PathLike[str]"],
    formats: Optional[Sequence[Literal["png", "svg", "pdf", "csv"]]] = None,
    *,
    scale: Optional[int] = None,
    aspect: Optional[str] = None,
    no_cache: bool = False,
    budget: Optional[float] = None,
    budget_memory: Optional[float] = None,
) -> List[pathlib.Path]:
    """Writes every figure of a scene (a file's path or RON text) into out_dir, as
    `samplescope render` does; the files written, in order."""
