"""^ (exclusive or) written for a power."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
f = sp.log(1 + e1^2 + e2^2) / 2
