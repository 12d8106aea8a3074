"""HANG: a run that ignored --timeout.

f = log(1 + rho) + (erf(rho) + erfc(rho) - 1) e1, which is log(1 + rho)
(erf + erfc = 1).  Proposing an elliptic ratio, the verifier asked SymPy for
the series of f(t, 0) at t = 0, which did not return; the first call was cut
off by P1's time limit, but the kf stage asked again outside any limit, so
only the parent's hard kill ended the run (75 s with --timeout 60, always
timeout + 10 s).  The series now has 2 s of its own and the kf stage is
inside its limit.  Found by an adversarial helper (2026-11-28).
"""
import sympy as sp
from uwmr_symbolic import e1, e2

rho = e1**2 + e2**2
f = sp.log(1 + rho) + (sp.erf(rho) + sp.erfc(rho) - 1) * e1
