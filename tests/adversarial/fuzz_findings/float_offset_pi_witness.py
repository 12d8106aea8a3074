"""BAD WITNESS of a P3 refutation (float read with 15 digits).

f = 3 log(1 + tanh(rho)) - pi + math.pi,  rho = e1^2 + e2^2,
math.pi = 3.141592653589793115997963... (the double), pi - math.pi = 1.2246e-16.

P3 is false (f(0, 0) = math.pi - pi = -1.2246e-16 < 0), and the verifier says
refuted -- but with the witness |e| = 1/32000000 ("F(s) > 0 fails at s = 1/32000000"),
where the user's f is POSITIVE: rho = 9.765625e-16, f = 3 log(1 + tanh(rho)) - 1.2246e-16
= +2.8072228200853e-15 (mpmath, 50 and 100 digits agree).  The witness holds only for
the f the verifier reads, with math.pi as 3.14159265358979 (offset -3.2e-15).  A
refutation's witness must be a counterexample for the design as written.
Found by the fuzzer's float-offset family (seed 201, design 36); mechanism of issue 9.
Now math.pi is read as repr(math.pi) = 3.141592653589793 (README), pi minus that is
2.3846e-16, and the verifier's witness |e| = 1/128000000 gives f = 1.83e-16 - 2.38e-16 < 0:
a counterexample for the design as the verifier documents reading it.
"""
import math

import sympy as sp
from uwmr_symbolic import e1, e2

rho = e1**2 + e2**2
f = 3 * sp.log(1 + sp.tanh(rho)) - sp.pi + math.pi
