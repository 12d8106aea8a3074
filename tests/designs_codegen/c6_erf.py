"""Python-crash class: F(s) = s erf(s) + (exp(-s^2) - 1)/sqrt(pi), F'(s) = erf(s); the module called math.erf without importing math."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
rho = e1**2 + e2**2

name = "c6_erf"
f = (sp.sqrt(rho)*sp.erf(sp.sqrt(rho)) + (sp.exp(-rho) - 1)/sp.sqrt(sp.pi))
gains = {"circle": dict(k1=0.25, k2=0.7, lam=0.3, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0)}
