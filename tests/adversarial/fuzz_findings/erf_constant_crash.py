"""CRASH (a KernelError out of the search) on a constant Arb cannot sign.

f = 1 + rho^2 erf(rho)/1000 off the origin, 0 at it (rho = e1^2 + e2^2): f jumps
from 0 to 1 at the origin, so P1, P5, P6, P7 are false (the jump), P2 and P4 true,
P3 true (F(s) = 1 + s^4 erf(s^2)/1000 > 0 for s > 0 and -> oo), P8 true (F'(0+) = 0).
The proposer's sum rule met 3 u exp(-u^2)/(125 sqrt(pi)) + 3 (erf(18687/64) - 1)/250
on [292, oo) and asked the kernel for the sign of the constant, about -10^-37000;
the kernel's refusal ("sign ... not decided") ended the run.  Found by the fuzzer's
'origin' family, 2026-11-25 (seed 99001).
"""
import sympy as sp
from uwmr_symbolic import e1, e2

rho = e1**2 + e2**2
f = sp.Piecewise((0, sp.Eq(rho, 0)), (rho**2 * sp.erf(rho) / 1000 + 1, True))
