"""`make bench`: proving against checking, per design (issue 9's goal: checking a
certificate takes at most 10 % of proving it).

For every design of designs/ and tests/designs/ whose P1-P8 the verifier
proves, in one process after import, median of three:

* prove  -- `verify_design` (the search, plus the proposer's kernel steps)
            less the check below, which `verify_design` also runs once;
* check  -- `design_certificate.check` of its certificate (kernel only, no search);

each run with the verifier's and the kernel's memos emptied first (`_forget`);

and how much of the report the kernel has checked (properties and kf with
nothing left to the search)."""
from __future__ import annotations

import json
import statistics
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from uwmr_symbolic import certify, design_certificate as DC  # noqa: E402
from uwmr_symbolic.kernel import certificate as kernel_certificate, core  # noqa: E402
from uwmr_symbolic.verify import verify_design      # noqa: E402


def _forget():
    """Empty the memos that would make a second run cheaper than a first:
    the proposer's proved lemmas, the checker's checked steps, and every cache
    of the kernel (parsed and printed expressions, root isolation, zero tests,
    domains), so that the check does not reuse what the proof computed.
    SymPy's own cache stays warm, as in any long process."""
    certify._FOUND.clear()
    kernel_certificate._CHECKED.clear()
    for value in vars(core).values():      # `parse` among them
        if hasattr(value, "cache_clear"):
            value.cache_clear()


def _median(fn, n=3):
    times, out = [], None
    for _ in range(n):
        _forget()
        t = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t)
    return statistics.median(times), out


def main() -> int:
    files = sorted((ROOT / "designs").glob("*.py")) + sorted((ROOT / "tests" / "designs").glob("*.py"))
    print(f"{'design':34} {'prove s':>8} {'check s':>8} {'check/prove':>11}  kernel-checked")
    ratios, total_check = [], 0.0
    for path in files:
        prove, report = _median(lambda: verify_design(path))
        if report.error is not None:
            continue
        text = json.dumps(DC.build(report))
        check, checks = _median(lambda: DC.check(text))
        prove = max(prove - check, 1e-3)        # verify_design re-checks its own certificate once
        total_check += check
        ratios.append(check / prove)
        done = [c.name for c in checks if c.kernel_checked]
        proved = [c.name for c in checks if c.status == "proved"]
        print(f"{path.stem[:34]:34} {prove:8.3f} {check:8.3f} {check / prove:10.1%}  "
              f"{len(done)}/{len(proved)} {' '.join(done)}")
    print(f"check/prove: median {statistics.median(ratios):.1%}, worst {max(ratios):.1%} (goal <= 10 %); "
          f"checking all {len(ratios)} certificates: {total_check:.2f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
