"""Design 2 of the paper, after reference [46]: f (29), controller (30)."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "Design 2"
description = "f = sqrt(1 + e1^2 + e2^2) - 1, equation (29)"
f = sp.sqrt(1 + e1**2 + e2**2) - 1

gains = {
    "circle": dict(k1=0.25, k2=0.7, lam=0.6, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
    "lemniscate": dict(k1=0.1178, k2=0.15, lam=0.0285, Vmax=0.75, Wmax=2.0, Vr_max=0.6322, Wr_max=1.8320),
}
