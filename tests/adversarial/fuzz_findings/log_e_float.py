"""FALSE PROOF of P3 and a WRONG kf (floats read with 15 digits).

f = log(math.e + rho) - 1 with math.e = 2.718281828459045090795598... (the double),
which is below e by 1.4456e-16.

f(0, 0) = log(math.e) - 1 = -5.318e-17 < 0 (mpmath, 50 and 100 digits), so P2 and P3
are false (f < 0 for rho < e - math.e = 1.4456e-16).  The verifier refutes P2 but
proves P3: it reads math.e as 2.71828182845905 = 54365636569181/20000000000000,
which is ABOVE e.
kf: the true kf is sup 2s/(math.e + s^2) = 1/sqrt(math.e) = 0.60653065971263343973...;
the verifier claims kf = 2000000*sqrt(271828182845905)/54365636569181
= 0.60653065971263289204... exactly (enclosure [x, x]), 5.5e-16 too small: the
certified upper bound is below the true supremum (attained at |e| = sqrt(math.e)).
Found by the fuzzer's 'classic' family; the mechanism is known from issue 9.
"""
import math

import sympy as sp
from uwmr_symbolic import e1, e2

rho = e1**2 + e2**2
f = sp.log(math.e + rho) - 1
