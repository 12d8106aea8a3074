"""f = log(1 + rho) + e2/(e2 - 2) - 2/(e2 - 2): log(1 + rho) wherever it has a
value, and none on the line e2 = 2 (0/0), which no fixed sample point meets."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
f = sp.log(1 + e1**2 + e2**2) + e2/(e2 - 2) - 2/(e2 - 2)
