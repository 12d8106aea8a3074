"""WRONG REFUTATION of P7 (a radicand's double zero taken as a singularity).

f = (rho^2 - 8 rho + 16)^(3/2) = |rho - 4|^3,  rho = e1^2 + e2^2.

u -> |u|^3 is C^2 (second derivative 6|u|), and rho is a polynomial, so f is C^2 on R^2:
d2f/de2^2 = 6|rho-4|(rho-4) + 36 |rho-4| e2^2 ... all continuous, and every second partial
tends to 0 at the circle rho = 4 from both sides (at (0, 2 -+ 1e-12) the values are
~1e-10 at 50 and 100 digits).  P7 is TRUE.
The verifier refutes P7: "F is singular at s = 2: s**4 - 8*s**2 + 16 violates
'nonnegative' at s = 2" -- the radicand is 0 there, which is allowed.
(Its refutations of P1 (kf infinite: F' = 6 s (s^2-4)|s^2-4| is unbounded), P2 (f(0) = 64),
P3, P5 (F' < 0 on (0, 2)) and P6 are right, but P1/P5/P6 cite the same non-witness.)
Found by the fuzzer's 'classic' family; known from issue 9.
"""
import sympy as sp
from uwmr_symbolic import e1, e2

rho = e1**2 + e2**2
f = (rho**2 - 8 * rho + 16) ** sp.Rational(3, 2)
