"""UNKNOWN where the answer is easy: f(0, 0) is a sum of logarithms that is
exactly 0 without being SymPy's literal 0.

f = log(4 + e1^2 + e2^2)/2 - log 2, so F(s) = log(1 + s^2/4)/2: f(0, 0) =
log(4)/2 - log(2) = 0 since log 4 = 2 log 2; F > 0 for s > 0, F -> oo;
F'(s) = s/(4 + s^2) <= 1/4 with equality at s = 2, so kf = 1/4; F'(s)/s =
1/(4 + s^2) <= 1/4 (P6 with k = 1/4); F is analytic (P7, P8).  P1-P8 all hold.
Before 2026-11-28 the search proved P2 by simplify, the kernel's value_sign
wanted the literal 0 and refused, and the certificate held a "proved" P2
with neither kernel theorems nor unchecked facts: it did not re-check, so
every verdict was reported unknown.  Found by an adversarial helper.
"""
import sympy as sp
from uwmr_symbolic import e1, e2

f = sp.log(4 + e1**2 + e2**2) / 2 - sp.log(2)
