"""WRONG (with --trust-search): a slope at the origin that is 0 in disguise.

f = log(1 + rho) + (log 6 - log 2 - log 3) e1 is log(1 + rho): P1-P8 all
hold (kf = 1 at |e| = 1).  The search read F'(0+) = log 6 - log 2 - log 3
as nonzero because it is not SymPy's literal 0, and refuted P1, P5-P8
("df/de2(0, h) -> c as h -> 0+ but -> -c as h -> 0-").  By default the
kernel refused the witness (unknown); with --trust-search the refutations
counted.  F'(0+) is now 0 when `exact_sign` shows it 0, and no refutation
rests on a value not shown nonzero.  Found by an adversarial helper.
"""
import sympy as sp
from uwmr_symbolic import e1, e2

f = sp.log(1 + e1**2 + e2**2) + (sp.log(6) - sp.log(2) - sp.log(3)) * e1
