"""HANG, found by `make fuzz` (seed 1747139665, family radial), 2026-11-25: the
verifier outlived --timeout 10 by more than the fuzzer's 20-s margin (the
command line killed it at 20 s, every property unknown).

f = 2.5 (e1^2 + e2^2)^2 - 2.5 exp(exp(-4 (e1^2 + e2^2)) - 1) + 2.5

Cause: the proposer's substitution step (u - sin(u) style) called SymPy's
`subs` of a subterm, whose `powdenest` asked assumption queries that
factored a huge polynomial inside FLINT, holding the interpreter where no
time limit reaches.  The step now replaces the subterm structurally.

Truth: F(s) = 2.5 s^4 + 2.5 (1 - exp(exp(-4 s^2) - 1)), F(0) = 0 (P2);
F'(s) = 10 s^3 + 20 s exp(-4 s^2) exp(exp(-4 s^2) - 1) > 0 for s > 0, and
F'(s) >= 10 s^3 is unbounded, so kf is infinite and P1 fails."""
from sympy import exp, symbols

e1, e2 = symbols("e1 e2", real=True)
rho2 = e1 ** 2 + e2 ** 2
f = 2.5 * rho2 ** 2 - 2.5 * exp(exp(-4 * rho2) - 1) + 2.5
