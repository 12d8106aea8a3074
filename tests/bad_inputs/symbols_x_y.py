"""f written in x, y instead of the error coordinates e1, e2."""
import sympy as sp

x, y = sp.symbols("x y", real=True)
f = sp.log(1 + x**2 + y**2) / 2
