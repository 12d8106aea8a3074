"""Unusable: Subs(x/y, (x, y), (e1, e1)) is e1/e1, which has no value on the line e1 = 0
(red team 27); carried out with SymPy's evaluation it was the number 1."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
x, y = sp.symbols("x y", real=True)
f = sp.log(1 + e1**2 + e2**2) * sp.Subs(x / y, (x, y), (e1, e1))
