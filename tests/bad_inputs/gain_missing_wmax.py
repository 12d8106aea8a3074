"""Unusable: a gain scenario without Wmax."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
f = sp.log(1 + e1**2 + e2**2)
gains = {"circle": dict(k1=0.25, k2=0.7, lam=1.2, Vmax=0.75, Vr_max=0.5, Wr_max=1.0)}
