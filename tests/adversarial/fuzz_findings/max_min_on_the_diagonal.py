"""WRONG (with --trust-search): kf "infinite" along a line where Max and Min
switch branches.

f = log(1 + rho) + e1 (Max(e1^2, e2^2) + Min(e1^2, e2^2) - rho) is
log(1 + rho) everywhere (Max + Min of two numbers is their sum), so
df/de2 = 2 e2/(1 + rho), bounded by 1.  The search differentiated the
Piecewise that the loader writes branch by branch and followed the ray
through (1, 1), the line where both switch: the branches' formula there is
-2 e1 e2 + ..., unbounded, but it is not f's derivative.  A refutation
through a derivative's formula of an f with Piecewise, Max, Min or sign now
stands only where the kernel checks its witness.  Found by an adversarial
helper.
"""
import sympy as sp
from uwmr_symbolic import e1, e2

rho = e1**2 + e2**2
f = sp.log(1 + rho) + e1 * (sp.Max(e1**2, e2**2) + sp.Min(e1**2, e2**2) - rho)
