"""UNKNOWN where the answer is easy: a certificate the checker rejected, so
that every verdict was reported unknown.

f = rho/(2 + log(1 + rho)), F(s) = s^2/(2 + log(1 + s^2)).  F'(s) = 2 s
[(2 + L) - s^2/(1 + s^2)]/(2 + L)^2 with L = log(1 + s^2) >= 0, and
s^2/(1 + s^2) < 1, so F' > 0 for s > 0: P5 holds; P2, P3, P4, P8 hold too.
The proposer returned a weaker theorem than asked (F' >= 0), the verdict
attached it as P5's kernel proof, and the checker refused the whole
certificate ("P5: the kernel's conclusion is not dF/ds > 0").  A weak claim
is now left to the search, visibly, and the other verdicts are checked.
Found by an adversarial helper.
"""
import sympy as sp
from uwmr_symbolic import e1, e2

rho = e1**2 + e2**2
f = rho / (2 + sp.log(1 + rho))
