"""Proof replay: the Lyapunov argument of Proposition 1, re-derived for f.

1. The closed loop (11)-(13) is derived from the open loop (8) and the
   controller (9) (not copied from the paper), and compared with SPEC.md's
   statement of it.
2. With U = lam f + e3^2/2 (15), U' is computed along the closed loop and the
   identity  U' = (19) - lam (Wr + lam Vr g sin(e3)/e3 + k2 tanh e3) D  is
   checked for a generic f, where D = e1 df/de2 - e2 df/de1 and g = df/de2.
3. For this f, D = 0 is P4; the remainder vanishes and U' equals (19):
   U' = -lam k1 (df/de1) tanh(e1) - k2 e3 tanh(e3).
"""
from __future__ import annotations

import sympy as sp

from . import e1 as E1, e2 as E2

E3, VR, WR, LAM, K1, K2 = sp.symbols("e3 V_r W_r lambda k_1 k_2", real=True)


def closed_loop(f):
    """(e1', e2', e3') of (8) under (9), with sin(e3)/e3 kept as a factor."""
    g = sp.diff(f, E2)
    sinc = sp.sin(E3) / E3
    V = VR * sp.cos(E3) + K1 * sp.tanh(E1)
    W = WR + LAM * VR * g * sinc + K2 * sp.tanh(E3)
    return (VR * sp.cos(E3) - V + W * E2,          # (8), first row
            VR * sp.sin(E3) - W * E1,
            WR - W)


def replay(f, p4_proved: bool) -> dict:
    """Re-check the Lyapunov argument; returns a dict of named steps."""
    fg = sp.Function("f")(E1, E2)
    d1, d2, d3 = closed_loop(fg)
    g = sp.diff(fg, E2)
    sinc = sp.sin(E3) / E3
    spec = (-K1 * sp.tanh(E1) + WR * E2 + LAM * VR * g * sinc * E2 + K2 * sp.tanh(E3) * E2,
            VR * sp.sin(E3) - WR * E1 - LAM * VR * g * sinc * E1 - K2 * sp.tanh(E3) * E1,
            -LAM * VR * g * sinc - K2 * sp.tanh(E3))
    loop_ok = all(sp.expand(a - b) == 0 for a, b in zip((d1, d2, d3), spec))
    U = LAM * fg + E3 ** 2 / 2
    Udot = sp.diff(U, E1) * d1 + sp.diff(U, E2) * d2 + sp.diff(U, E3) * d3
    eq19 = -LAM * K1 * sp.diff(fg, E1) * sp.tanh(E1) - K2 * E3 * sp.tanh(E3)
    D = E1 * sp.diff(fg, E2) - E2 * sp.diff(fg, E1)
    remainder = -LAM * (WR + LAM * VR * g * sinc + K2 * sp.tanh(E3)) * D
    generic_ok = sp.expand(Udot - eq19 - remainder) == 0
    # for this f: D vanishes identically when f is radial (P4)
    Fr = sp.Function("F")(sp.sqrt(E1 ** 2 + E2 ** 2))
    D_radial = sp.simplify(E1 * sp.diff(Fr, E2) - E2 * sp.diff(Fr, E1))
    steps = {
        "closed_loop": {"ok": loop_ok,
                        "detail": "(8) with (9) substituted equals the closed loop (11)-(13) of SPEC.md"},
        "lyapunov_derivative": {"ok": generic_ok,
                                "detail": "U' = (19) - lam (Wr + lam Vr g sin(e3)/e3 + k2 tanh e3) "
                                          "(e1 df/de2 - e2 df/de1) for every f"},
        "p4_cancels": {"ok": bool(p4_proved and D_radial == 0),
                       "detail": "for f = F(|e|), e1 df/de2 - e2 df/de1 = 0, so U' = (19)"
                       if p4_proved else "P4 not proved: the cross terms of (17) need not cancel"},
    }
    return {"ok": all(v["ok"] for v in steps.values()), "steps": steps}
