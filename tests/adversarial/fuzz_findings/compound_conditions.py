"""UNKNOWN where the answer is easy: Piecewise conditions written with Xor,
ITE and Contains.

f = log(1 + rho) where Xor(e1 > 0, e2 > 0); else log(1 + rho) + e1^2 where
ITE(e2 > 0, Contains(e1, [0, 1]), e1 < 5); else log(1 + rho) + 2 e1^2.  On
the circle of radius 1/3: at (1/3, 0) Xor(True, False) holds, f = log(10/9);
at (-1/3, 0) Xor fails and ITE gives e1 < 5, true, f = log(10/9) + 1/9.  So
f is not radial: P4 is false.  Before 2026-11-28 the certificate's design
expression held Xor, which the checker's reader does not accept, so nothing
re-checked and every verdict, P4's refutation included, was reported
unknown.  The loader now writes such conditions with relations, And, Or and
Not.  Found by an adversarial helper.
"""
import sympy as sp
from uwmr_symbolic import e1, e2

rho = e1**2 + e2**2
f = sp.Piecewise((sp.log(1 + rho), sp.Xor(e1 > 0, e2 > 0)),
                 (sp.log(1 + rho) + e1**2, sp.ITE(e2 > 0, sp.Contains(e1, sp.Interval(0, 1)), e1 < 5)),
                 (sp.log(1 + rho) + 2 * e1**2, True))
