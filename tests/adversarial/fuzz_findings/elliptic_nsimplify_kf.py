"""WRONG EXACT kf (nsimplify after the proof, on top of the 15-digit float).

f = a log(1 + e1^2 + 2 e2^2),  a = 0.7071067811865476 (the double
0.70710678118654757273731...).

f = F(sqrt(e1^2 + 2 e2^2)) with F(s) = a log(1 + s^2), so df/de2 = 2 a 2 e2/(1 + e1^2 + 2 e2^2)
and kf = sup |df/de2| = sqrt(2) a sup 2t/(1 + t^2) = sqrt(2) a = 1.00000000000000006836...
(attained at e1 = 0, e2 = 1/sqrt(2); mpmath at 50 and 100 digits).
The verifier reports kf = 1 EXACTLY (lower = upper = 1): kf.scale multiplies the
certified sup 176776695296637/250000000000000 (a read with 15 digits) by sqrt(2) and
runs sp.nsimplify, which turns 1.00000000000000059 into 1.  The enclosure [1, 1]
excludes the true value.  Found by the fuzzer's elliptic family; known from issue 9.
"""
import sympy as sp
from uwmr_symbolic import e1, e2

f = 0.7071067811865476 * sp.log(1 + e1**2 + 2 * e2**2)
