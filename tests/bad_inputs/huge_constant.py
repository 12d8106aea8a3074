"""Unusable: a constant of 5,001 digits, which Python does not print (its limit is 4,300 digits),
so no certificate or code could name it (it crashed the verifier with a ValueError)."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
f = sp.Integer(10) ** 5000 * sp.log(1 + e1**2 + e2**2)
