"""CRASH (exit 2, internal error) on 0**rho.

f = log(1 + rho) (1 - 0**rho): 0**rho is 1 at the origin and 0 elsewhere, so f equals
log(1 + rho) everywhere (f(0, 0) = 0 * 0 = 0) and every property is that of design 1
(P1-P8 true, kf = 1 at |e| = 1).
The verifier crashes in certify_kf: `neg.upper <= ...` compares SymPy's nan
("TypeError: Invalid NaN comparison"); uwmr-verify exits 2 with "internal error".
Found by the fuzzer's 'classic' family; known from issue 9.
"""
import sympy as sp
from uwmr_symbolic import e1, e2

rho = e1**2 + e2**2
f = sp.log(1 + rho) * (1 - 0**rho)
