"""`make bench`: proving against checking, per design (issue 9's goal: checking a
certificate takes at most 10 % of proving it).

For every design of designs/ and tests/designs/ that the verifier decides,
each side in a fresh process (as `uwmr-verify FILE` and `uwmr-verify
--check-certificate CERT` run), timed after the import, median of `--repeat`:

* prove  -- `verify_design` (the search, plus the proposer's kernel steps)
            less the re-check of its own certificate that it runs once;
* steps  -- the part of prove spent in kernel rule applications (reading
            their data included), failed attempts too: the least a check of
            the same steps could cost if it found every SymPy object built;
* check  -- `design_certificate.check` of that certificate (kernel only, no
            search), with nothing cached from the proof;

and how much of the report the kernel has checked (properties and kf with
nothing left to the search)."""
from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

PROVE = """
import json, sys, time
import uwmr_symbolic.verify as V
from uwmr_symbolic import design_certificate as DC
from uwmr_symbolic.kernel import core
own, steps, depth = [0.0], [0.0], [0]
kernel_check = V._kernel_check
def timed(*args, **kw):
    t, before = time.perf_counter(), steps[0]
    try:
        return kernel_check(*args, **kw)
    finally:
        own[0] += time.perf_counter() - t
        steps[0] = before
V._kernel_check = timed
def step_timer(fn):
    def timed_step(*args, **kw):
        depth[0] += 1
        t = time.perf_counter()
        try:
            return fn(*args, **kw)
        finally:
            depth[0] -= 1
            if depth[0] == 0:
                steps[0] += time.perf_counter() - t
    return timed_step
core._apply, core._encode = step_timer(core._apply), step_timer(core._encode)
t = time.perf_counter()
report = V.verify_design(sys.argv[1])
seconds = time.perf_counter() - t - own[0]
if report.error is None:
    open(sys.argv[2], "w").write(json.dumps(DC.build(report)))
print(json.dumps({"seconds": seconds, "steps": steps[0], "error": report.error}))
"""

CHECK = """
import json, sys, time
from uwmr_symbolic import design_certificate as DC
text = open(sys.argv[1]).read()
t = time.perf_counter()
checks = DC.check(text)
print(json.dumps({"seconds": time.perf_counter() - t,
                  "checked": [c.name for c in checks if c.kernel_checked],
                  "proved": [c.name for c in checks if c.status == "proved"]}))
"""


def _child(code, *args) -> dict:
    out = subprocess.run([sys.executable, "-c", code, *map(str, args)], capture_output=True, text=True,
                         check=True, cwd=ROOT)
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--repeat", type=int, default=3, help="fresh processes per side and design (median)")
    args = ap.parse_args()
    files = sorted((ROOT / "designs").glob("*.py")) + sorted((ROOT / "tests" / "designs").glob("*.py"))
    print(f"{'design':34} {'prove s':>8} {'steps s':>8} {'check s':>8} {'check/prove':>11} {'check/steps':>11}  "
          f"kernel-checked")
    ratios, shares, total_check = [], [], 0.0
    with tempfile.TemporaryDirectory() as tmp:
        cert = Path(tmp) / "certificate.json"
        for path in files:
            proofs = [_child(PROVE, path, cert) for _ in range(args.repeat)]
            if proofs[0]["error"] is not None:
                continue
            checks = [_child(CHECK, cert) for _ in range(args.repeat)]
            prove = statistics.median(p["seconds"] for p in proofs)
            steps = statistics.median(p["steps"] for p in proofs)
            check = statistics.median(c["seconds"] for c in checks)
            total_check += check
            ratios.append(check / prove)
            shares.append(steps / prove)
            done, proved = checks[0]["checked"], checks[0]["proved"]
            print(f"{path.stem[:34]:34} {prove:8.3f} {steps:8.3f} {check:8.3f} {check / prove:10.1%} "
                  f"{check / steps:10.1f}x  {len(done)}/{len(proved)} {' '.join(done)}", flush=True)
    print(f"check/prove: median {statistics.median(ratios):.1%}, worst {max(ratios):.1%} (goal <= 10 %); "
          f"checking all {len(ratios)} certificates: {total_check:.2f} s")
    print(f"kernel steps within proving: median {statistics.median(shares):.1%} of prove, "
          f"worst {max(shares):.1%}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
