"""Unusable: f is not real-valued for |e1| < 1 (sqrt of a negative number)."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
f = sp.sqrt(e1**2 - 1)
gains = {"circle": dict(k1=0.25, k2=0.7, lam=1.2, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0)}
