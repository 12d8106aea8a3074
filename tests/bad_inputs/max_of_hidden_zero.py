"""Max of a constant that is 0 in disguise (atan(1/2) + atan(1/3) = pi/4):
SymPy's rewrite of it as a Piecewise does not return."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
hidden_zero = sp.atan(sp.Rational(1, 2)) + sp.atan(sp.Rational(1, 3)) - sp.pi / 4
f = sp.log(1 + e1**2 + e2**2) + sp.Max(0, hidden_zero, evaluate=False)
