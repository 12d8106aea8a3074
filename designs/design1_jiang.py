"""Design 1 of the paper, after Jiang et al.: f (26), controller (28)."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "Design 1 (Jiang et al.)"
description = "f = 1/2 log(1 + e1^2 + e2^2), equation (26)"
f = sp.log(1 + e1**2 + e2**2) / 2

# Table 1 of the paper.
gains = {
    "circle": dict(k1=0.25, k2=0.7, lam=1.2, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
    "lemniscate": dict(k1=0.1178, k2=0.15, lam=0.0569, Vmax=0.75, Wmax=2.0, Vr_max=0.6322, Wr_max=1.8320),
}
