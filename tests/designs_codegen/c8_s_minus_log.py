"""Not one of issue 8's seven classes (found after them): F(s) = s - log(1 + s),
F'(s) = s/(1 + s) = s - s^2 + ..., whose series at 0 has a next term only s
smaller than the leading one.  The tiny region was refused (next term above
1e-20 relative at the float TINY = 1e-12), the mid form sqrt(rho)/(sqrt(rho) + rho)
was used down to s = 0, and rho = 0 gave 0/0: status 4 at e = (0, 1e-300)."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
rho = e1**2 + e2**2

name = "c8_s_minus_log"
f = sp.sqrt(rho) - sp.log(1 + sp.sqrt(rho))
gains = {"circle": dict(k1=0.25, k2=0.7, lam=0.3, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0)}
