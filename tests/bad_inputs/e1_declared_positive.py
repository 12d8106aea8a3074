"""e1, e2 declared positive: SymPy folds sqrt(e1**2) to e1 while the file
builds f, so for real e1 the f written here, log(1 + (|e1| + e1)^2/4 + e2^2),
is not the f SymPy holds, log(1 + e1^2 + e2^2) (f(-1, 0) = 0: P3 fails)."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", positive=True)
f = sp.log(1 + (sp.sqrt(e1**2) + e1)**2 / 4 + e2**2)
