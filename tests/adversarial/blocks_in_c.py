"""Loading this file blocks SIGALRM and then sleeps: the same situation as a
long call inside C that never returns to the interpreter (the verifier's
SIGALRM time limit cannot fire).  Only the per-file process watchdog stops it."""
import signal
import time

import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
signal.pthread_sigmask(signal.SIG_BLOCK, [signal.SIGALRM])
time.sleep(3600)
f = sp.log(1 + e1**2 + e2**2) / 2
