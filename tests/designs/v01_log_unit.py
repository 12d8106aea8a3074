"""Valid design: f = log(1 + e1^2 + e2^2); kf = 1, attained at |e| = 1.

Hand derivation (rho = e1^2 + e2^2, s = sqrt(rho), f = F(s), F(s) = log(1 + s^2)):
  F'(s) = 2s/(1 + s^2),  F'(s)/s = 2/(1 + rho).
  df/de1 = 2 e1/(1 + rho),  df/de2 = 2 e2/(1 + rho)   (rational, smooth on R^2).
P1 proved: the partials are rational with denominator >= 1, hence C^inf.
   |df/de2| <= 2 s/(1 + s^2) <= 1 by AM-GM (1 + s^2 >= 2s), equality at s = 1
   with e1 = 0, e.g. (0, 1).  kf = 1, attained.
P2 proved: log(1) = 0.
P3 proved: 1 + rho > 1 for e != 0, so f > 0; f -> oo as |e| -> oo.
P4 proved: e1 df/de2 = 2 e1 e2/(1+rho) = e2 df/de1.
P5 proved: df/de1 tanh(e1) = 2 e1 tanh(e1)/(1+rho) > 0 for e1 != 0.
P6 proved: df/de1 = k e1 h with k = 2, h = 1/(1 + rho) in (0, 1].
P7 proved: second partials are rational with denominator (1+rho)^2 >= 1.
P8 proved: df/de2 = 2 e2/(1 + rho) -> 0 as e2 -> 0 for every e1.
Gains (bound (10): V = Vr_max + k1, W = Wr_max + lam Vr_max kf + k2):
  exact_margin_zero: V = 0.5 + 0.25 = 0.75 <= 0.75 (ok, margin 0);
                     W = 1.0 + 0.5*0.5*1 + 0.5 = 1.75 <= 1.75 (ok, margin exactly 0).
  over_by_1e-5:      W = 1.0 + 0.25 + 0.50001 = 1.75001 > 1.75 (FAILS by 1e-5).
Exit status 1 (all properties proved, but one gain check fails).
"""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)

name = "log(1 + |e|^2)"
description = "f = log(1 + e1^2 + e2^2), kf = 1 attained at |e| = 1"
f = sp.log(1 + e1**2 + e2**2)

gains = {
    "exact_margin_zero": dict(k1=0.25, k2=0.5, lam=0.5, Vmax=0.75, Wmax=1.75, Vr_max=0.5, Wr_max=1.0),
    "over_by_1e-5": dict(k1=0.25, k2=0.50001, lam=0.5, Vmax=0.75, Wmax=1.75, Vr_max=0.5, Wr_max=1.0),
}
