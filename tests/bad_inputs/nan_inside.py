"""Unusable: adding nan collapses f to SymPy's nan."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
f = sp.log(1 + e1**2 + e2**2) + sp.nan * e1
assert f is sp.nan
gains = {"circle": dict(k1=0.25, k2=0.7, lam=1.2, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0)}
