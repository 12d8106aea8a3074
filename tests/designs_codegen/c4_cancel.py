"""Cancellation class: g = e2 (1/sqrt(1+rho) - 1/(1+rho)) ... lost every digit for small rho (x0 - sqrt(x0), log(1+rho) without log1p)."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
rho = e1**2 + e2**2

name = "c4_cancel"
f = 2*sp.sqrt(1 + rho) - 2 - sp.log(1 + rho)
gains = {"circle": dict(k1=0.25, k2=0.7, lam=0.3, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0)}
