"""Run the verifier CLI in a subprocess, the way a user runs it."""
import os
import signal
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

#: f in rho = e1^2 + e2^2 that the search proves P1-P8 for and the kernel does not yet
#: re-check in full (P1, P6, kf): F = log(1 + L^2), L = log(1 + s^2), F' = 4 s L/((1 + s^2)(1 + L^2)).
#: The bound of F' on the tail is not found: F'(1/t) is not defined at t = 0 (log of 1/t), and
#: as a product A B (`sign_below_product`) the factor L/(1 + L^2) <= 1/2 is not bounded by 1 the
#: way the proposer splits it (1 - L >= 0 fails).  (Four nested logs served here until the kernel
#: proved them, through that rule.)
SEARCH_ONLY = "log(1 + log(1 + rho)**2)"

#: Seconds one verifier run may take in the verdict tests (override with UWMR_TEST_TIMEOUT).
DESIGN_TIMEOUT = float(os.environ.get("UWMR_TEST_TIMEOUT", "900"))


@dataclass
class Run:
    argv: list
    returncode: int | None
    stdout: str
    stderr: str
    elapsed: float
    timed_out: bool

    def describe(self) -> str:
        tail = self.stderr[-3000:]
        return (f"command: {' '.join(self.argv)}\nexit: {self.returncode} "
                f"(timed out: {self.timed_out}, {self.elapsed:.1f} s)\n"
                f"stderr (tail):\n{tail}\nstdout (head):\n{self.stdout[:3000]}")


def run_cli(args, timeout=DESIGN_TIMEOUT) -> Run:
    """`python -m uwmr_symbolic.cli *args` from the repository root.

    The child gets its own session so that on timeout the whole process group it
    started (and only that) is killed."""
    argv = [sys.executable, "-m", "uwmr_symbolic.cli", *map(str, args)]
    t0 = time.monotonic()
    proc = subprocess.Popen(argv, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            stdin=subprocess.DEVNULL, text=True, start_new_session=True)
    timed_out = False
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        timed_out = True
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        out, err = proc.communicate()
    return Run(argv, None if timed_out else proc.returncode, out, err,
               time.monotonic() - t0, timed_out)
