"""Valid design: f = log(cosh(sqrt(e1^2 + e2^2))); kf = 1, not attained.

Hand derivation (s = |e|, F(s) = log cosh s, F'(s) = tanh s, F''(s) = 1/cosh(s)^2):
  Smoothness at the origin: cosh(sqrt(rho)) = sum_n rho^n/(2n)! is an entire
  function of rho = e1^2 + e2^2 and is >= 1, so f = log(cosh(sqrt(rho))) is
  analytic on all of R^2 even though sqrt(rho) is not differentiable at 0.
  df/de2 = tanh(s) e2/s (:= 0 at the origin), |df/de2| <= tanh(s) < 1.
P1 proved: f analytic; sup |df/de2| = sup tanh(s) = 1, approached as s -> oo along
   e1 = 0, never attained.  kf = 1, attained = False.
P2 proved: log cosh 0 = log 1 = 0.
P3 proved: cosh s > 1 for s > 0; f >= s - log 2 -> oo.
P4 proved: radial (e1 df/de2 = tanh(s) e1 e2/s = e2 df/de1).
P5 proved: df/de1 = tanh(s) e1/s has the sign of e1 for e1 != 0.
P6 proved: df/de1 = e1 * tanh(s)/s; tanh(s)/s in (0, 1] (-> 1 at s = 0), so k = 1,
   h = tanh(s)/s.
P7 proved: f analytic.
P8 proved: |df/de2| <= |e2| tanh(s)/s <= |e2| -> 0.
Gains: tight: V = 0.5 + 0.25 = 0.75 <= 0.75; W = 1.0 + 1.0*0.5*1 + 0.5 = 2.0 <= 2.0
   (margin exactly 0, ok).  Exit status 0.
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "log cosh |e|"
description = "f = log(cosh(sqrt(e1^2 + e2^2))), kf = 1 not attained"
f = sp.log(sp.cosh(sp.sqrt(e1**2 + e2**2)))

gains = {
    "tight": dict(k1=0.25, k2=0.5, lam=1.0, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0),
}
