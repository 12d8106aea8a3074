"""Tail-underflow class: at e = (0, 2e154) the t = 1/s tail formed tt*tt = 0 and log(x1/x0) = inf, status 4 on a finite input."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
rho = e1**2 + e2**2

name = "c2_log_squared"
f = sp.log(1 + rho)**2 / 4
gains = {"circle": dict(k1=0.25, k2=0.7, lam=0.3, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0)}
