"""Design 5 of the paper (new): f (35), controller (37)."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "Design 5"
description = "f = 1 - 1/(e1^2 + e2^2 + 1), equation (35)"
f = 1 - 1 / (e1**2 + e2**2 + 1)

gains = {
    "circle": dict(k1=0.25, k2=0.7, lam=0.9238, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
    "lemniscate": dict(k1=0.1178, k2=0.15, lam=0.0438, Vmax=0.75, Wmax=2.0, Vr_max=0.6322, Wr_max=1.8320),
}
