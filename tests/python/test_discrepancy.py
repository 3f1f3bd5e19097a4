"""discrepancy() against scipy.stats.qmc.discrepancy (L2-star, CD, WD, MD at D = 2, 5, 8),
against the formula of the symmetric discrepancy (SD; scipy has none), and the exact 2D star
discrepancy against a brute-force count over the critical boxes."""

import numpy as np
import pytest
from scipy.stats import qmc

import samplescope


def sets(d):
    """A scrambled Sobol' set, a random set and a small Halton set in d dimensions."""
    rng = np.random.default_rng(d)
    return [
        qmc.Sobol(d, scramble=True, seed=7).random(256),
        rng.random((300, d)),
        qmc.Halton(d, scramble=False).random(33),
    ]


# The largest pair factor h of each method: the terms of its sums are at most BOUND^d.
BOUND = {"L2-star": 1.0, "CD": 1.5, "WD": 1.5, "MD": 2.0}


def close_to_scipy(ours, theirs, method, d):
    """scipy sums N² products in a plain running f64 sum and loses ~ε per term of the terms'
    scale to the final cancellation (ours is summed in double-double and is the closer to the
    exact value; tests/it/cube_discrepancy.rs holds both against a 50-digit evaluation):
    agreement to 1e-13 of the terms' scale, 3·BOUND^d, and 1e-12 relative. L2-star is compared
    on its square (the sum)."""
    if method == "L2-star":
        ours, theirs = ours**2, theirs**2
    return abs(ours - theirs) <= 1e-13 * 3 * BOUND[method] ** d + 1e-12 * abs(theirs)


@pytest.mark.parametrize("d", [2, 5, 8])
@pytest.mark.parametrize("method", ["L2-star", "CD", "WD", "MD"])
def test_equals_scipy(d, method):
    for x in sets(d):
        ours = samplescope.discrepancy(x, method)
        theirs = qmc.discrepancy(x, method=method)
        assert close_to_scipy(ours, theirs, method, d), (method, d, ours, theirs)
        # A wrong formula misses by far more than the tolerance.
        assert not close_to_scipy(ours * (1 + 1e-6), theirs, method, d)


def test_default_method_is_l2_star():
    x = sets(3)[0]
    assert samplescope.discrepancy(x) == samplescope.discrepancy(x, "L2-star")


def symmetric_squared(x):
    """SD² = (4/3)^d − (2/N) Σ_i Π_k (1 + 2x − 2x²) + (2^d/N²) Σ_i Σ_j Π_k (1 − |a − b|)."""
    n, d = x.shape
    single = np.prod(1 + 2 * x - 2 * x * x, axis=1).sum()
    double = np.prod(1 - np.abs(x[:, None, :] - x[None, :, :]), axis=2).sum()
    return (4 / 3) ** d - 2 / n * single + 2**d / n**2 * double


@pytest.mark.parametrize("d", [2, 5, 8])
def test_symmetric_is_the_formula_squared(d):
    for x in sets(d):
        assert samplescope.discrepancy(x, "SD") == pytest.approx(
            symmetric_squared(x), rel=1e-9
        )


def star_brute_force(p):
    """D*_N: the largest |area − fraction| over boxes [0,u)×[0,v) with u, v at the points'
    coordinates or 1, counting open and closed boxes."""
    n = len(p)
    us = np.append(np.unique(p[:, 0]), 1.0)
    vs = np.append(np.unique(p[:, 1]), 1.0)
    worst = 0.0
    for u in us:
        for v in vs:
            area = u * v
            inside_open = np.count_nonzero((p[:, 0] < u) & (p[:, 1] < v)) / n
            inside_closed = np.count_nonzero((p[:, 0] <= u) & (p[:, 1] <= v)) / n
            worst = max(worst, area - inside_open, inside_closed - area)
    return worst


def test_star_is_the_exact_sup_over_boxes():
    rng = np.random.default_rng(1)
    for x in [rng.random((40, 2)), qmc.Halton(2, scramble=False).random(64)]:
        assert samplescope.discrepancy(x, "star") == pytest.approx(
            star_brute_force(x), rel=1e-12
        )


def test_star_is_2d_only_and_methods_are_named():
    with pytest.raises(ValueError, match="star discrepancy is 2D.*5 columns"):
        samplescope.discrepancy(np.full((4, 5), 0.5), "star")
    with pytest.raises(ValueError, match="method = cd: must be one of star, L2-star, CD"):
        samplescope.discrepancy(np.full((4, 2), 0.5), "cd")


def test_over_budget_is_refused_naming_the_budget():
    x = np.random.default_rng(0).random((20000, 64))
    with pytest.raises(ValueError, match="budget"):
        samplescope.discrepancy(x, "CD", budget=0.01)
