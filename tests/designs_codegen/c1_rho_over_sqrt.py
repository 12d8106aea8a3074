"""Printer class: F = rho/sqrt(1+rho); H holds (rho+1)**(3/2), printed as (rho + 1.0*sqrt(rho + 1.0)) before the fix."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
rho = e1**2 + e2**2

name = "c1_rho_over_sqrt"
f = rho / sp.sqrt(1 + rho)
gains = {"circle": dict(k1=0.25, k2=0.7, lam=0.3, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0)}
