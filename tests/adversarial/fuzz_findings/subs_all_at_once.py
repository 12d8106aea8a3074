"""WRONG: a substitution of several variables carried out one at a time.

f = Subs(log(1 + e1^2 + e2^2) + e1, (e1, e2), (e2, e1)) is log(1 + rho) + e2.
SymPy's Subs.doit substitutes the variables one after another, so the
loader read log(1 + 2 e1^2) + e1, and the kernel then correctly checked the
wrong function: P8 "proved" (true f: df/de2 -> 1 as e2 -> 0), P5 and P6
"refuted" (true f: df/de1 = 2 e1/(1 + rho), so P5 holds, and P6 with k = 2,
h = 1/(1 + rho)).  For the true f, P3 fails (f(0, -2) = log 5 - 2 < 0), P4
fails, P8 fails.  The loader now substitutes all variables at once.  Found
by an adversarial helper (2026-11-28).
"""
import sympy as sp
from uwmr_symbolic import e1, e2

f = sp.Subs(sp.log(1 + e1**2 + e2**2) + e1, (e1, e2), (e2, e1))
