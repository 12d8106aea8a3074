"""Unusable: sqrt(e1^2 - 2) and sqrt(e2^2 - 2) have no real value near the origin (red team 22).  At
(0, 0) SymPy multiplies them as I sqrt(2) I sqrt(2) = -2, so f(0, 0) came out as the real
sqrt(4) + 2 = 4 and P2 was refuted with a value f does not have."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
f = sp.sqrt((e1**2 - 2)*(e2**2 - 2)) - sp.sqrt(e1**2 - 2)*sp.sqrt(e2**2 - 2) + sp.log(1 + e1**2 + e2**2)
