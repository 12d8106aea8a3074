"""Tail-underflow class: at e2 = 1e300 the tail formed tt*tt = 0, status 4 on a finite input."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
rho = e1**2 + e2**2

name = "c2_log_log"
f = sp.log(1 + sp.log(1 + rho))
gains = {"circle": dict(k1=0.25, k2=0.7, lam=0.3, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0)}
