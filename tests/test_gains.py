"""Bound (10) in exact arithmetic (`gains.check_gains`), with kf exact or
only enclosed: a violation is claimed only when kf's lower bound proves it."""
import sympy as sp

from uwmr_symbolic.gains import check_gains

Q = sp.Rational
CIRCLE = {"c": dict(k1=Q(1, 4), k2=Q(7, 10), lam=Q(6, 5), Vmax=Q(3, 4), Wmax=Q(2), Vr_max=Q(1, 2), Wr_max=Q(1))}
# W bound = 1 + (6/5)(1/2) kf + 7/10 = 17/10 + (3/5) kf: exactly Wmax at kf = 1/2


def test_exact_kf_on_the_limit_passes_and_above_fails():
    assert check_gains(CIRCLE, Q(1, 2))["c"].W_ok is True
    assert check_gains(CIRCLE, Q(1, 2) + Q(1, 10 ** 9))["c"].W_ok is False


def test_enclosed_kf_straddling_the_limit_is_undecided():
    # kf in [1/2, 1/2 + 1e-9]: the true kf may be 1/2 (passes) or above (fails)
    g = check_gains(CIRCLE, Q(1, 2) + Q(1, 10 ** 9), kf_lower=Q(1, 2))["c"]
    assert g.W_ok is None and g.V_ok is True


def test_enclosed_kf_below_or_above_the_limit_decides():
    assert check_gains(CIRCLE, Q(49, 100), kf_lower=Q(48, 100))["c"].W_ok is True
    assert check_gains(CIRCLE, Q(52, 100), kf_lower=Q(51, 100))["c"].W_ok is False
