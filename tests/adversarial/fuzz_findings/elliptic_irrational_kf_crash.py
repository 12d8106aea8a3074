"""CRASH (exit 2, internal error) on an elliptic design whose radial sup is irrational.

f = asinh(e1^2/3 + e2^2).

f = F(sqrt(e1^2 + 3 e2^2)) with F(s) = asinh(s^2/3); the verifier finds the elliptic
reduction (r = 3), certifies sup F' = sqrt(6)/3 EXACTLY, and then kf.scale calls
sp.Rational(cert.lower) on that irrational number:
"TypeError: invalid input: sqrt(6)/3" -> uwmr-verify exits 2, "internal error".
Truth: df/de2 = 2 e2/sqrt(1 + q^2), q = e1^2/3 + e2^2, largest on e1 = 0:
kf = sup 2t/sqrt(1 + t^4) = sqrt(2) at t = 1 (= sqrt(3) * sqrt(6)/3); P1, P2, P3, P5-P8 true,
P4 false.  Any elliptic design with an irrational exact sup crashes the same way (the fuzzer
hit 2*asinh(e1**2/3 + e2**2)/7, seed 201, design 89; atan, erf, ratio blocks do too).
Not in issue 9's list.
"""
import sympy as sp
from uwmr_symbolic import e1, e2

f = sp.asinh(e1**2 / 3 + e2**2)
