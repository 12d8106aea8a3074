"""Run the verifier CLI in a subprocess, the way a user runs it."""
import os
import signal
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

#: f in rho = e1^2 + e2^2 whose P1 the search proves and the kernel does not yet re-check:
#: F = sqrt(s^2 + eps^2) - eps, eps = 10^-20, F' = s/sqrt(s^2 + eps^2) < 1 -> 1 (kf = 1, not
#: attained).  The proposer's cover of 1 - F' near s = 0 would need boxes of width about eps.
#: (log(1 + log(1 + rho)^2) and four nested logs served here until the kernel proved them.)
SEARCH_ONLY = "sqrt(rho + Rational(1, 10**40)) - Rational(1, 10**20)"

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
