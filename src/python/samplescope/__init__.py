"""samplescope: sample patterns, their Fourier spectra, discrepancy, reconstruction filters and
integration error for image synthesis, computed by the samplescope Rust library on NumPy arrays.

Every function takes the command line's parameter names as keyword arguments, validated by the
same descriptors; bad input raises ``ValueError`` with the command line's one-line message, and
the numbers are the command line's (``samplescope points``, ``analyze``, ...).
"""

from . import _native
from ._native import *  # noqa: F401,F403  (every function of the extension module)

__version__ = _native.__version__
__all__ = [name for name in dir(_native) if not name.startswith("_")]


def _pattern_list() -> str:
    lines = []
    for p in _native.patterns():
        dims = "2D only" if p["max_dims"] == 2 else "dims 1..%d" % p["max_dims"]
        params = ", ".join(s["name"] for s in p["params"]) or "no parameters"
        lines.append("    %-20s %s (%s; %s)" % (p["name"], p["summary"], dims, params))
    return "\n".join(lines)


def points(pattern, n, *, dims=2, seed=None, allow_fewer=False, **params):
    return _native.points(pattern, n, dims=dims, seed=seed, allow_fewer=allow_fewer, **params)


points.__doc__ = (_native.points.__doc__ or "") + "\n\nPatterns:\n" + _pattern_list() + "\n"
