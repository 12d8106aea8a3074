"""FALSE PROOF of P2 and P3 (floats read with 15 digits).

f = sqrt(1 + rho) - (0.1 + 0.2)/0.3,  rho = e1^2 + e2^2.

(0.1 + 0.2)/0.3 is the double 1.0000000000000002 = 4503599627370497/4503599627370496,
so f(0, 0) = 1 - 4503599627370497/4503599627370496 = -2^-52 = -2.2204460492503131e-16
(exact rational arithmetic; mpmath at 50 and 100 digits agrees), and f < 0 for
rho < 4.44e-16.  P2 (f(0,0) = 0) and P3 (f > 0 off the origin) are false.
The verifier reads the Float as the decimal 1.00000000000000 (str() keeps 15 digits),
i.e. checks sqrt(1 + rho) - 1, and answers P2 proved, P3 proved.
Found by the fuzzer's float-offset family (tests/fuzz/grammar.py), known from issue 9.
"""
import sympy as sp
from uwmr_symbolic import e1, e2

rho = e1**2 + e2**2
f = sp.sqrt(1 + rho) - (0.1 + 0.2) / 0.3
