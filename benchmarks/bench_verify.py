"""`make bench`: wall time of `uwmr-verify` per design, after import.

Goal (issue): every paper design decided in <= 2 s, all of designs/ in <= 10 s
on a 2-core machine.  Each design runs in a fresh process (so no cache is
shared), timed from after the package import; the median of three runs is
printed with its ratio to the 2 s goal."""
from __future__ import annotations

import json
import statistics
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CHILD = """
import sys, time, json
import uwmr_symbolic.verify as v
t = time.perf_counter(); r = v.verify_design(sys.argv[1]); dt = time.perf_counter() - t
print(json.dumps({"seconds": dt, "exit": r.exit_status}))
"""


def time_design(path: Path, repeats: int = 3) -> tuple[float, int]:
    runs = []
    for _ in range(repeats):
        out = subprocess.run([sys.executable, "-c", CHILD, str(path)], capture_output=True, text=True,
                             check=True, cwd=ROOT)
        runs.append(json.loads(out.stdout.strip().splitlines()[-1]))
    return statistics.median(r["seconds"] for r in runs), runs[0]["exit"]


def main() -> int:
    files = sorted((ROOT / "designs").glob("*.py"))
    total = 0.0
    print(f"{'design':<28} {'median s':>9} {'vs 2 s goal':>12} exit")
    for path in files:
        sec, status = time_design(path)
        total += sec
        print(f"{path.name:<28} {sec:9.3f} {sec / 2.0:11.2f}x {status:>4}")
    print(f"{'all of designs/':<28} {total:9.3f} {total / 10.0:11.2f}x  (goal 10 s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
