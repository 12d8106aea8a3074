"""Design 4 of the paper (new), exactly as printed: f (33), controller (34).

With s = sqrt(e1^2 + e2^2 + 1) - 1 the paper switches from 1 - cos(s) to
s - pi + 1 at s = pi.  See the README for what the verifier finds."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "Design 4 (as printed)"
description = "f = s - pi + 1 if s > pi, 1 - cos(s) otherwise, s = sqrt(e1^2+e2^2+1) - 1, equation (33)"
s = sp.sqrt(e1**2 + e2**2 + 1) - 1
f = sp.Piecewise((s - sp.pi + 1, s > sp.pi), (1 - sp.cos(s), True))

gains = {
    "circle": dict(k1=0.25, k2=0.7, lam=0.6, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
    "lemniscate": dict(k1=0.1178, k2=0.15, lam=0.0285, Vmax=0.75, Wmax=2.0, Vr_max=0.6322, Wr_max=1.8320),
}
