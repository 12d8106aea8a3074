# f is written with a function SymPy knows nothing about
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
g = sp.Function("g")
f = g(e1**2 + e2**2)
