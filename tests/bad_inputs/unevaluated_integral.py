"""Unusable: f holds an unevaluated Integral (red team 20: it was reported as
"a division by zero in the formula?")."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
t = sp.Symbol("t")
f = sp.Integral(sp.exp(-t**2), (t, 0, sp.oo)) * (e1**2 + e2**2)
