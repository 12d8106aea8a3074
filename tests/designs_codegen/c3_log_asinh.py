"""Silent-zero class: beyond |e| ~ 1.3e154 asinh(1/(tt*tt)) = inf gave g = 0 with status 0."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
rho = e1**2 + e2**2

name = "c3_log_asinh"
f = sp.log(1 + sp.asinh(rho))
gains = {"circle": dict(k1=0.25, k2=0.7, lam=0.3, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0)}
