"""c declared positive but given -1: SymPy folds |c| - c to 0 while the file
builds f, so f with c = -1, log(1 + rho) + 2 e1 e2 (f(1, -1) < 0), is not the
log(1 + rho) SymPy holds."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
c = sp.Symbol("c", positive=True)
f = sp.log(1 + c**2 * (e1**2 + e2**2)) + (sp.Abs(c) - c) * e1 * e2
params = {c: -1}
