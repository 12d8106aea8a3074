"""math.sqrt applied to a SymPy expression."""
import math

import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
f = math.sqrt(1 + e1**2 + e2**2) - 1
