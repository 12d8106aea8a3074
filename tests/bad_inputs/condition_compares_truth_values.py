# a relation between two conditions: SymPy builds it, but it is not a relation between numbers
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
f = sp.Piecewise((e1**2 + e2**2, e1 > 1), (2*(e1**2 + e2**2), sp.Eq(e1 > 0, e2 > 0)), (3*(e1**2 + e2**2), True))
