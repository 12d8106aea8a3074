"""The unsaturated controller (38) of reference [49], written as a member of (9).

With f = (e1^2 + e2^2)/2, df/de2 = e2 and (9) becomes (38) with tanh replaced
by the identity in V and W; it is here as the paper's baseline."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "Unsaturated baseline (38)"
description = "f = (e1^2 + e2^2)/2, the controller of reference [49]"
f = (e1**2 + e2**2) / 2

gains = {
    "circle": dict(k1=0.25, k2=0.7, lam=1.0, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
    "lemniscate": dict(k1=0.1178, k2=0.15, lam=1.0, Vmax=0.75, Wmax=2.0, Vr_max=0.6322, Wr_max=1.8320),
}
