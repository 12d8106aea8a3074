"""Hangs at import: the verifier must give up after --timeout and report unknown (exit 3)."""
import time

import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
while True:
    time.sleep(3600)
f = sp.log(1 + e1**2 + e2**2)
