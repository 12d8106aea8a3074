"""C^2 join at rho = b = R^2, R = 88776683/2^26: b = 7881299444482489/2^52 is a double whose last bit is 1.

Inside (rho <= b): G(rho) = rho/2 + ((b - rho)^(5/2) - b^(5/2) + 5 b^(3/2) rho/2)/10,
G'(rho) = 1/2 + (b^(3/2) - (b - rho)^(3/2))/4 > 0, G''(rho) = 3 (b - rho)^(1/2)/8 -> 0 at b.
Outside, in s = |e|: F(s) = A s + B/s + C with F, F', F'' equal to those of G(s^2) at s = R:
F'(R) = 2 R G'(b) = A - B/R^2, F''(R) = 2 G'(b) + 4 R^2 G''(b) = 2 G'(b) = 2 B/R^3, so B = R^3 G'(b) > 0,
A = 3 R G'(b); F' = A - B/s^2 >= A - B/R^2 > 0 and F' < A = kf.  Only (b - rho)^(1/2) is C^0 at b,
so f is C^2 (P7), and every property holds.  The rounding of e1*e1 + e2*e2 can cross b (its last bit
is odd), where b - rho < 0 would make (b - rho)^(3/2) imaginary in the inner formula."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
name = "C2 join at a boundary with an odd last bit"
rho = e1**2 + e2**2
R = sp.Rational(88776683, 2**26)
b = R**2
inner = rho / 2 + ((b - rho)**sp.Rational(5, 2) - b**sp.Rational(5, 2) + 5 * b**sp.Rational(3, 2) * rho / 2) / 10
G1 = sp.Rational(1, 2) + b**sp.Rational(3, 2) / 4       # G'(b)
A, B = 3 * R * G1, R**3 * G1
C = inner.subs({e1: R, e2: 0}) - A * R - B / R
s = sp.sqrt(rho)
f = sp.Piecewise((inner, rho <= b), (A * s + B / s + C, True))
gains = {"circle": dict(k1=0.25, k2=0.7, lam=0.01, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0)}
