"""Unusable: raises while being imported."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
f = sp.log(1 + e1**2 + e2**2)
raise RuntimeError("this design file fails at import on purpose")
