"""UNKNOWN where the answer is easy: P5 of f = tanh(4 (e1^2 + e2^2)).

F'(s) = 8 s (1 - tanh(4 s^2)^2) > 0 for s > 0 (|tanh| < 1), so P5 holds.
The search sampled F' at 64 bits, where 1 - tanh(44)^2 (s = 3.3) cancels to
an interval holding 0, took that for a failed sample and never asked the
kernel; its own bisection then got stuck at s = 3.33025.  Samples are now
taken again at 256 bits before they count against asking the kernel.  P3
fails (F -> 1); kf = 4 sqrt(u) (1 - tanh(u)^2) = 2.22623174424053580054...
with 4 u tanh(u) = 1 (twice tanh(rho)'s kf, mpmath).
"""
import sympy as sp
from uwmr_symbolic import e1, e2

f = sp.tanh(4 * (e1**2 + e2**2))
