"""Design 3 of the paper (new): f (31), controller (32)."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
alpha, beta = sp.symbols("alpha beta", positive=True)

name = "Design 3"
description = "f = (1/alpha) log cosh(sqrt(beta e1^2 + beta e2^2 + 1) - 1), equation (31)"
f = sp.log(sp.cosh(sp.sqrt(beta * e1**2 + beta * e2**2 + 1) - 1)) / alpha
params = {alpha: 1.0, beta: 4.0}

gains = {
    "circle": dict(k1=0.25, k2=0.7, lam=0.3, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
    "lemniscate": dict(k1=0.1178, k2=0.15, lam=0.0142, Vmax=0.75, Wmax=2.0, Vr_max=0.6322, Wr_max=1.8320),
}
