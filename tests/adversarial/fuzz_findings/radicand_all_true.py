"""WRONG REFUTATION of P1 for a design with P1-P8 all true.

f = log(1 + rho (1 + (rho^2 - 2 rho + 1)^(3/2))) = log(1 + G(rho)),
G(rho) = rho (1 + |rho - 1|^3).

Truth by construction: |rho - 1|^3 is C^2, so G and f are C^2 (P1 continuity, P7);
G(0) = 0 (P2); G' = 1 + |rho-1|^3 + 3 rho |rho-1|(rho-1), which for rho > 1 is > 1 and
for rho < 1 is 1 + x^2 (4x - 3) with x = 1 - rho in (0, 1], at least 1 - 1/4 (the minimum
of x^2 (4x - 3) is -1/4 at x = 1/2); so G is increasing: P3 (G ~ rho^4, f -> oo), P5; F'(s) = 2 s G'/(1+G)
is continuous and ~ 8/s at infinity, so kf is finite (P1) and G'/(1+G) is bounded (P6);
F'(0+) = 0 (P8); radial (P4).
The verifier refutes P1 (and, given time, P7): "F' is singular at s = 2:
s**2*((s**4 - 2*s**2 + 1)**(3/2) + 1) + 1 violates 'nonzero' at s = 2 inside (0, oo)" --
but that expression is 1 + G >= 1 everywhere, 1 + 4 (1 + 27) = 113 at s = 2.  The verdict
depends on the time budget: with --timeout 10 on a loaded machine P1 is 'unknown', with
30 or 60 s it is 'refuted' (53 s run: P1 and P7 refuted, P3, P5, P6, P8 unknown).  This is
the 'continuous_on guards refute what is true' class of issue 9 (a radicand with a
double zero, rho^2 - 2 rho + 1, inside a denominator).
Found by the fuzzer's dip family ('|rho - c|^3 as a 3/2 power'); same cause as
radicand_cube4.py (issue 9).
"""
import sympy as sp
from uwmr_symbolic import e1, e2

rho = e1**2 + e2**2
f = sp.log(1 + rho * (1 + (rho**2 - 2 * rho + 1) ** sp.Rational(3, 2)))
