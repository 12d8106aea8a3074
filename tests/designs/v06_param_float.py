"""Valid design with a float parameter: f = log(1 + c (e1^2 + e2^2)), c = 0.5.

kf = sqrt(c) = sqrt(2)/2, attained at |e| = 1/sqrt(c) = sqrt(2).

Hand derivation (rho = e1^2 + e2^2, s = |e|, F(s) = log(1 + c s^2)):
  df/de1 = 2c e1/(1 + c rho), df/de2 = 2c e2/(1 + c rho), F'(s) = 2 c s/(1 + c s^2).
  With t = sqrt(c) s: F'(s) = sqrt(c) * 2t/(1+t^2) <= sqrt(c), equality at t = 1.
  c = 1/2: kf = sqrt(1/2) = sqrt(2)/2 ~= 0.7071068, attained at (0, sqrt(2)).
P1 proved (rational partials, denominator >= 1).  P2 proved (log 1 = 0).
P3 proved (1 + c rho > 1 for e != 0, unbounded).  P4 proved (radial).
P5 proved: 2c e1 tanh(e1)/(1 + c rho) > 0 for e1 != 0.
P6 proved: k = 2c = 1, h = 1/(1 + c rho) in (0, 1].
P7 proved (rational).  P8 proved (df/de2 -> 0 as e2 -> 0).
Gains: W = 1.0 + 1.0*0.5*sqrt(2)/2 + 0.5 = 1.5 + sqrt(2)/4 = 1.853553390593...
  pass:          Wmax = 1.85356 >= W (ok by ~6.6e-6).
  over_by_1e-5:  Wmax = 1.85354 <  W (FAILS by ~1.34e-5).
  V = 0.5 + 0.25 = 0.75 <= 0.75 in both.
Exit status 1 (a gain check fails).
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
c = sp.symbols("c", positive=True)

name = "log(1 + c |e|^2), c = 0.5"
description = "parameter given as a float in params; kf = sqrt(c)"
f = sp.log(1 + c * (e1**2 + e2**2))
params = {c: 0.5}

gains = {
    "pass": dict(k1=0.25, k2=0.5, lam=1.0, Vmax=0.75, Wmax=1.85356, Vr_max=0.5, Wr_max=1.0),
    "over_by_1e-5": dict(k1=0.25, k2=0.5, lam=1.0, Vmax=0.75, Wmax=1.85354, Vr_max=0.5, Wr_max=1.0),
}
