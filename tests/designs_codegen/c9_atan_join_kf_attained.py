"""A C^1 join at rho = 49 whose |df/de2| reaches kf = 21 exactly, at s = 10.5
(found by checking generated code against bound (10) near that radius).

F(s) = s^2 for s <= 7, 7 s + 49 atan(2 s/7 - 3) + 49 pi/4 beyond: F(7) = 49
on both sides; F'(s) = 2 s (14 at 7) and 7 + 14/(1 + (2 s/7 - 3)^2) (14 at 7,
largest at 2 s/7 = 3, s = 10.5, where it is 21, and -> 7 as s -> oo), so
kf = sup F' = 21, attained on the circle s = 10.5."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
rho = e1**2 + e2**2
s = sp.sqrt(rho)
name = "atan join, kf attained"
f = sp.Piecewise((rho, rho <= 49), (7*s + 49*sp.atan(2*s/7 - 3) + 49*sp.pi/4, True))
gains = {"circle": dict(k1=0.25, k2=0.7, lam=0.01, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0)}
