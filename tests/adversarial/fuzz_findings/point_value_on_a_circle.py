"""UNKNOWN where the answer is easy: a value of its own on one circle, equal to
the formula there.

f = log(10) on e1^2 + e2^2 = 9, log(1 + e1^2 + e2^2) elsewhere: that is
log(1 + e1^2 + e2^2) everywhere (log(1 + 9) = log 10), so P1-P8 hold as for
F(s) = log(1 + s^2) (kf = sup 2s/(1 + s^2) = 1 at s = 1).  Before 2026-11-25 the
kernel had no rule for a branch taken at points only, and P1, P5, P6, P7 rested
on the search alone (reported unknown).  The 'point-value' family of the fuzzer.
"""
import sympy as sp
from uwmr_symbolic import e1, e2

rho = e1**2 + e2**2
f = sp.Piecewise((sp.log(10), sp.Eq(rho, 9)), (sp.log(1 + rho), True))
