"""f = log(1 + rho) + (e2^4 - 4)/(e2^2 - 2) - e2^2 - 2: log(1 + rho) wherever it
has a value, and none on the lines e2 = +-sqrt(2) (0/0), irrational roots of a
denominator over Q (red team 18b: --trust-search proved P1-P8 for such an f)."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
f = sp.log(1 + e1**2 + e2**2) + (e2**4 - 4)/(e2**2 - 2) - e2**2 - 2
