"""numpy's log applied to a SymPy expression."""
import numpy as np
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
f = np.log(1 + e1**2 + e2**2) / 2
