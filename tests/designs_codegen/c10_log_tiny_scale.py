"""log(1 + c rho) with c = 1e-30 (the double nearest): F'(s)/s = 2c/(1 + c s^2),
so H = F'(s)/s is about 2e-30 on the whole fast region.  Proved P1-P8 with
kf = sqrt(c) (at s = 1/sqrt(c)), yet code generation once stopped with an
OverflowError: the a priori range of lam vr for the fast path divided by
H's tiny range."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
c = sp.Symbol("c", positive=True)
rho = e1**2 + e2**2
name = "log(1 + 1e-30 rho)"
f = sp.log(1 + c*rho)
params = {c: 1e-30}
