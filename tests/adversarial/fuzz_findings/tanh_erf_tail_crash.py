"""CRASH (TypeError out of the search) in the proposer's Taylor step.

f = |e|^(5/2)/2 + tanh(erf(rho)) erf(4 rho)/2 (rho = e1^2 + e2^2): every term is
increasing in rho and vanishes at 0, so P2-P5 and P7, P8 hold, P3 (f ~ |e|^(5/2)/2)
and P6 fails (F'(s)/s ~ (5/4) s^(1/2) -> oo), and P1 fails (kf = sup F' is infinite).
At --timeout 10 the proposer's sign proof for F's growth reached the tail form at
t = 0, where SymPy's subs of -8 exp(-1327105/64)/(sqrt(pi) t^4 cosh(erf(t^-2))^2)
compares nan and raises TypeError; the run ended with "internal error" (3 of 4
runs: which step is reached depends on the time left).  Found by make fuzz,
2026-11-27 (seed 3189202835, family 'power').
"""
import sympy as sp
from uwmr_symbolic import e1, e2

rho = e1**2 + e2**2
f = rho**sp.Rational(5, 4)/2 + sp.tanh(sp.erf(rho))*sp.erf(4*rho)/2
