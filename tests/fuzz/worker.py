"""The verifier in a process of its own, so that a hang or a crash cannot
block the fuzzer.

`Verifier().verify(path, timeout)` sends the path to a long-lived child
(`python -m fuzz.worker`, which imports the verifier once) and reads one JSON
line back: each property's status, reason and witness, and kf with its
bounds as exact fractions.  When the child does not answer within
timeout + HARD_MARGIN seconds it is killed (its process group only) and
restarted, and the result is {"hang": True}."""
from __future__ import annotations

import json
import os
import select
import signal
import subprocess
import sys
import traceback
from pathlib import Path

HARD_MARGIN = 20.0
HERE = Path(__file__).resolve().parent


def _frac(x):
    """A bound of kf as exact text: a Fraction, or the SymPy number that
    `kf.scale` puts there when it claims an exact value."""
    if x is None:
        return None
    if hasattr(x, "numerator") and not hasattr(x, "free_symbols"):
        return f"{x.numerator}/{x.denominator}"
    return __import__("sympy").srepr(x)


def _fresh_recheck(report) -> str | None:
    """Re-check the report's certificate as a fresh process does: with the
    kernel's parse cache, step memo and printer memo emptied first.  (A claim
    printed from what the prover had read once differed from the checker's.)"""
    from uwmr_symbolic import design_certificate as DC
    from uwmr_symbolic.kernel import certificate, core, parse
    text = json.dumps(report.certificate if report.certificate is not None else DC.build(report))
    parse.parse.cache_clear()
    certificate._CHECKED.clear()
    core._PRINTER.memo.clear()
    try:
        DC.check(text)
    except DC.CertificateError as exc:
        return f"in a fresh process: {exc}"
    return None


def _answer(path: str, timeout: float) -> dict:
    from uwmr_symbolic.report import _jsonable
    from uwmr_symbolic.verify import verify_design
    try:
        # the search's verdicts (--trust-search), so that they are checked too; r.kernel: what the kernel checked
        r = verify_design(path, timeout=timeout, kernel_only=False)
    except BaseException as exc:    # the CLI reports this as exit 2, "internal error"
        return {"crash": f"{exc.__class__.__name__}: {exc}", "traceback": traceback.format_exc()[-4000:]}
    if r.error is not None:
        return {"error": r.error}
    kf = r.kf
    kernel = r.kernel or {"checked": [], "search": []}
    # every certificate the prover emits must re-check (oracle: "certificate"), in this process and in a fresh one
    cert = kernel.get("error") or _fresh_recheck(r)
    checked = [p for p in kernel["checked"] if p == "kf" or r.properties[p].proved]
    refutations = [p for p in kernel["checked"] if p != "kf" and r.properties[p].refuted]
    return {
        "certificate_error": cert, "kernel_checked": checked, "refutations_checked": refutations,
        "properties": {p: {"status": v.status, "reason": v.reason, "witness": _jsonable(v.witness)}
                       for p, v in r.properties.items()},
        "kf": None if kf is None else {
            "lower": _frac(kf.lower), "upper": _frac(kf.upper),
            "exact": None if kf.exact is None else str(kf.exact),
            "exact_srepr": None if kf.exact is None else __import__("sympy").srepr(kf.exact),
            "unbounded": kf.upper is None and bool(kf.unbounded_witness), "reason": kf.reason},
        "timed_out": r.timed_out, "seconds": r.seconds, "exit_status": r.exit_status,
    }


def main():
    for line in sys.stdin:
        req = json.loads(line)
        try:
            text = json.dumps(_answer(req["path"], req["timeout"]))
        except BaseException as exc:      # a bug of this harness, not of the verifier
            text = json.dumps({"harness": f"{exc.__class__.__name__}: {exc}"})
        sys.stdout.write(text + "\n")
        sys.stdout.flush()


class Verifier:
    def __init__(self):
        self.proc = None

    def _start(self):
        env = dict(os.environ, PYTHONPATH=str(HERE.parent) + os.pathsep + os.environ.get("PYTHONPATH", ""))
        self.proc = subprocess.Popen([sys.executable, "-m", "fuzz.worker"], cwd=HERE.parent, env=env,
                                     stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                                     text=True, start_new_session=True)

    def close(self):
        if self.proc is not None:
            try:
                os.killpg(self.proc.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            self.proc.wait()
            self.proc = None

    def verify(self, path, timeout: float) -> dict:
        if self.proc is None or self.proc.poll() is not None:
            self._start()
        self.proc.stdin.write(json.dumps({"path": str(path), "timeout": timeout}) + "\n")
        self.proc.stdin.flush()
        ready, _, _ = select.select([self.proc.stdout], [], [], timeout + HARD_MARGIN)
        line = self.proc.stdout.readline() if ready else ""
        if not line:
            code = self.proc.poll()
            self.close()
            return {"hang": code is None, "crash": None if code is None else f"worker process died (status {code})"}
        try:
            out = json.loads(line)
        except json.JSONDecodeError:      # a native library wrote to stdout as it aborted ("FLINT exception ...")
            self.close()
            return {"hang": False, "crash": f"worker process wrote {line.strip()[:200]!r} and stopped"}
        if out.get("timed_out"):
            # the verifier's SIGALRM limits are per process state: after one
            # expired, start afresh (the CLI runs one process per file anyway)
            self.close()
        return out

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


if __name__ == "__main__":
    main()
