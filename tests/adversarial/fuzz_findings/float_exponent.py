"""FALSE PROOF of P6 and P7 (a float exponent read with 15 digits).

f = rho ** (0.3/(0.1*3)),  rho = e1^2 + e2^2,  and 0.3/(0.1*3) is the double
0.9999999999999998 = 1 - 2^-52 =: q.

So f = |e|^(2q) = F(|e|) with 2q - 2 = -2^-51 < 0:
  F'(s)/s = 2q s^(2q-2) = 2q s^(-2^-51) -> oo as s -> 0+, so no constant k with
  df/de1 = k e1 h, 0 <= h <= 1 exists: P6 is FALSE;
  F''(s) = 2q(2q-1) s^(2q-2) -> oo as s -> 0+, so d2f/de2^2 (= F''(|e2|) on e1 = 0) is
  unbounded near the origin: P7 is FALSE.
(The growth is astronomically slow -- s^(-2^-51) at s = 1e-300 is 1 + 3.1e-13 -- so this
is decided by the exponent's exact sign, not by sampling.)
The verifier reads the exponent as 1.00000000000000, i.e. checks f = rho, and answers
P6 proved (k = 2, h = 1) and P7 proved.  With (0.1+0.2)/0.3 = 1 + 2^-52 instead, P6
(F'/s = 2q s^(2^-51) -> oo as s -> oo) is proved the same way though false.
Found by the fuzzer's float-power family; the mechanism is issue 9's 15-digit floats.
"""
import sympy as sp
from uwmr_symbolic import e1, e2

rho = e1**2 + e2**2
f = rho ** (0.3 / (0.1 * 3))
