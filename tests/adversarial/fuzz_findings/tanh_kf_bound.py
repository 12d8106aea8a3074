"""UNKNOWN where the answer is easy: the bound on df/de2 of a saturating
f = tanh(e1^2 + e2^2) rested on the search alone.

F(s) = tanh(s^2), F'(s) = 2 s (1 - tanh(s^2)^2) > 0 for s > 0.  F'' =
2 (1 - tanh^2)(1 - 4 s^2 tanh(s^2)) vanishes where 4 u tanh(u) = 1, u = s^2
= 0.52181344779576860447..., so kf = 2 sqrt(u) (1 - tanh(u)^2) =
1.11311587212026790027... (mpmath, 30 digits).  P1, P2, P4-P8 hold; P3
fails (F -> 1: not radially unbounded).  Before 2026-11-28 the kernel had no
proof of U - F' >= 0 beyond some R: F' is decreasing there, but the
proposer spent its budget before it factored F'' over tanh, and it could
not show tanh(s^2) - 1 < 0 (the rule `sign_below_sup` had only the sign +).
"""
import sympy as sp
from uwmr_symbolic import e1, e2

f = sp.tanh(e1**2 + e2**2)
