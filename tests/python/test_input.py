"""Points from Python: any (N, D) array-like of real numbers converted without surprise
(float32 and float64, C and Fortran order, lists, integer arrays), and NaN, wrong shapes,
empty sets, points outside [0,1) and non-real arrays refused with ValueError naming the
argument."""

import numpy as np
import pytest

import samplescope


def ref():
    return np.random.default_rng(5).random((50, 3))


def test_float32_is_converted_exactly():
    x32 = ref().astype(np.float32)
    assert samplescope.discrepancy(x32, "CD") == samplescope.discrepancy(
        x32.astype(np.float64), "CD"
    )


def test_fortran_order_and_views_give_the_c_order_numbers():
    x = ref()
    f = np.asfortranarray(x)
    assert not f.flags.c_contiguous
    assert samplescope.discrepancy(f, "WD") == samplescope.discrepancy(x, "WD")
    wide = np.random.default_rng(2).random((50, 6))
    view = wide[:, ::2]  # strided, neither C nor Fortran contiguous
    assert samplescope.discrepancy(view, "MD") == samplescope.discrepancy(
        np.ascontiguousarray(view), "MD"
    )
    # The transpose of a (3, 50) array is the (50, 3) set, not its transpose.
    assert samplescope.discrepancy(np.ascontiguousarray(x.T).T, "MD") == (
        samplescope.discrepancy(x, "MD")
    )


def test_lists_and_tuples():
    x = ref()
    assert samplescope.discrepancy(x.tolist(), "CD") == samplescope.discrepancy(x, "CD")
    assert samplescope.discrepancy(tuple(map(tuple, x)), "CD") == (
        samplescope.discrepancy(x, "CD")
    )


def test_zeros_as_integers():
    assert samplescope.discrepancy([[0, 0], [0, 0]], "L2-star") == (
        samplescope.discrepancy(np.zeros((2, 2)), "L2-star")
    )


@pytest.mark.parametrize(
    "bad, message",
    [
        (np.array([[0.1, np.nan]]), r"points: point 0, x1 = NaN: must be a number in \[0, 1\)"),
        (np.array([[0.1, 1.0]]), r"points: point 0, x1 = 1: must be a number in \[0, 1\)"),
        (np.array([[0.2, 0.3], [-0.1, 0.5]]), r"point 1, x0 = -0.1: must be a number in \[0, 1\)"),
        (np.array([[0.1, np.inf]]), r"x1 = inf: must be a number in \[0, 1\)"),
        (np.array([0.1, 0.2]), r"points: expected an array of shape \(N, D\), got shape \(2,\)"),
        (np.zeros((2, 2, 2)), r"got shape \(2, 2, 2\)"),
        (np.zeros((0, 2)), r"points: holds no points"),
        (np.zeros((3, 0)), r"points: 0 columns"),
        (np.zeros((2, 2), dtype=complex), r"points: expected an array of real numbers.*complex"),
        (np.zeros((2, 2), dtype=bool), r"points: expected an array of real numbers.*bool"),
        ([[0.1, 0.2], [0.3]], r"points: expected an array of real numbers"),
        ([["a", "b"]], r"points: expected an array of real numbers"),
        (5, r"got shape \(\)"),
    ],
)
def test_bad_points_are_refused_naming_the_argument(bad, message):
    with pytest.raises(ValueError, match=message):
        samplescope.discrepancy(bad, "CD")


def test_the_same_checks_for_every_function_that_takes_points():
    bad = np.array([[0.5, 1.5]])
    for call in (
        lambda: samplescope.analyze(bad),
        lambda: samplescope.periodogram(bad, size=8),
        lambda: samplescope.reconstruct(points=bad, size=8),
    ):
        with pytest.raises(ValueError, match=r"points: point 0, x1 = 1.5: must be a number"):
            call()
