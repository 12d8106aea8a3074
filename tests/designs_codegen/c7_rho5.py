"""Float-overflow class: rho**5 overflows float for |e| > 6.9e3, below the fixed far threshold 1e4."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
rho = e1**2 + e2**2

name = "c7_rho5"
f = sp.log(1 + rho**5) / 10
gains = {"circle": dict(k1=0.25, k2=0.7, lam=0.3, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0)}
