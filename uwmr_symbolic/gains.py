"""Gain check against bound (10), in exact rational arithmetic.

  |V| <= |Vr|max + k1                 must be <= Vmax
  |W| <= |Wr|max + lam |Vr|max kf + k2  must be <= Wmax

Inputs are exact rationals (decimals read as written), kf is its certified
upper bound (the exact value when it is proved).  A violation by 1e-5 is a
violation."""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from .limits import interval_sign


@dataclass
class GainCheck:
    scenario: str
    V_bound: sp.Expr
    W_bound: sp.Expr | None     # None: kf infinite
    V_margin: sp.Expr
    W_margin: sp.Expr | None
    lam_max: sp.Expr | None     # largest lam keeping the W bound within Wmax
    kf_known: bool = True       # False: kf undecided, the W bound cannot be checked
    W_margin_lower: sp.Expr | None = None   # the margin with kf's certified lower bound

    @property
    def V_ok(self) -> bool | None:
        """|V| bound within Vmax; None when the margin's sign is undecided
        (gains such as pi/8 whose margin is 0 in disguise)."""
        return _nonnegative(self.V_margin)

    @property
    def W_ok(self) -> bool | None:
        if not self.kf_known:
            return None
        if self.W_margin is None:       # kf infinite
            return False
        ok = _nonnegative(self.W_margin)
        if ok is not False:             # (None: the margin's sign undecided)
            return ok
        if self.W_margin_lower is not None and _nonnegative(self.W_margin_lower) is not False:
            return None         # the limit lies inside kf's enclosure: undecided, not a violation
        return False


def _nonnegative(x) -> bool | None:
    """x >= 0 for an exact real number: SymPy's comparison, else the sign of
    x's Arb enclosure (`limits.interval_sign`); None when neither decides (a
    zero in disguise: no simplification is taken on faith for a margin)."""
    r = x >= 0
    if r in (sp.true, sp.false):
        return bool(r)
    sign = interval_sign(x)
    return None if sign is None else sign > 0


def check_gains(gains: dict, kf_upper, kf_known: bool = True, kf_lower=None) -> dict[str, GainCheck]:
    """Bound (10) for every scenario.  kf_upper: exact SymPy number, or None
    with kf_known=True for an infinite kf (the W bound is then infinite and
    only lam = 0 would do), or kf_known=False when kf is undecided.
    kf_lower: kf's certified lower bound when kf is only enclosed; a W bound
    that fails with kf_upper but holds with kf_lower is undecided (W_ok None),
    not failed: only the lower bound proves a violation."""
    out = {}
    for name, g in gains.items():
        V_bound = g["Vr_max"] + g["k1"]
        V_margin = g["Vmax"] - V_bound
        if kf_upper is None:
            W_bound = W_margin = None
            lam_max = sp.Integer(0) if kf_known else None
        else:
            W_bound = g["Wr_max"] + g["lam"] * g["Vr_max"] * kf_upper + g["k2"]
            W_margin = g["Wmax"] - W_bound
            room = g["Wmax"] - g["Wr_max"] - g["k2"]
            lam_max = sp.Max(0, room / (g["Vr_max"] * kf_upper)) if kf_upper != 0 else sp.oo
        lower = None
        if kf_upper is not None and kf_lower is not None:
            lower = g["Wmax"] - (g["Wr_max"] + g["lam"] * g["Vr_max"] * kf_lower + g["k2"])
        out[name] = GainCheck(name, V_bound, W_bound, V_margin, W_margin, lam_max, kf_known, lower)
    return out
