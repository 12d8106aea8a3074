"""How verification time grows with the size of f (issue 9): three families
of designs whose every property holds, n = 1, 2, 4, 8, 16, each timed as the
whole command `uwmr-verify FILE --no-cache --format json` in a fresh process.

    sum     f = sum_{k=1..n} log(1 + rho/k)/(k n)
    nested  f = log(1 + log(1 + ... log(1 + rho)))          (n logs)
    chain   f = log(1 + rho) + sum_{k=1..n} h(rho - k)/10 [rho > k],
            h(x) = x^3/(1 + x^3): a Piecewise with n C^2 joins

Prints one row per family: seconds and how many of P1-P8 were proved (and,
where fewer, how many the search alone proved: --trust-search counts them).
Goal of the issue: every family fully proved at n = 16 within 10 s.

    python benchmarks/bench_scaling.py [--sizes 1 2 4 8 16] [--repeat 3] [--timeout 120]
"""
import argparse
import json
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from uwmr_symbolic.verify import SEARCH_ONLY

HEADER = 'import sympy as sp\nfrom sympy import log, Piecewise\ne1, e2 = sp.symbols("e1 e2", real=True)\n' \
         'rho = e1**2 + e2**2\n'


def family_sum(n):
    return "f = " + " + ".join(f"log(1 + rho/{k})/({k}*{n})" for k in range(1, n + 1))


def family_nested(n):
    inner = "rho"
    for _ in range(n):
        inner = f"log(1 + {inner})"
    return f"f = {inner}"


def family_chain(n):
    pieces, extra = [], ""
    for k in range(n + 1):
        upper = f"rho <= {k + 1}" if k < n else "True"
        pieces.append(f"(log(1 + rho){extra}, {upper})")
        extra += f" + (rho - {k + 1})**3/(10*(1 + (rho - {k + 1})**3))"
    return "f = Piecewise(" + ", ".join(pieces) + ")"


FAMILIES = {"sum": family_sum, "nested": family_nested, "chain": family_chain}
PROVED_BY_SEARCH = SEARCH_ONLY + "proved"      # the reason of a proof the kernel did not re-check


def time_once(path, timeout):
    t0 = time.perf_counter()
    run = subprocess.run([sys.executable, "-m", "uwmr_symbolic.cli", str(path), "--no-cache", "--format", "json",
                          "--timeout", str(timeout)], capture_output=True, text=True)
    seconds = time.perf_counter() - t0
    try:
        props = json.loads(run.stdout)["properties"].values()
        proved = sum(v["verdict"] == "proved" for v in props)
        searched = proved + sum(v["reason"].startswith(PROVED_BY_SEARCH) for v in props)
    except (ValueError, KeyError):
        proved = searched = -1
    return seconds, f"{proved}/8" if searched == proved else f"{proved}/8, search {searched}"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--sizes", type=int, nargs="+", default=[1, 2, 4, 8, 16])
    ap.add_argument("--repeat", type=int, default=3, help="runs per point (median); 1 beyond n = 4")
    ap.add_argument("--timeout", type=float, default=120)
    args = ap.parse_args()
    print(f"verification time (s, whole process, median) and P1-P8 proved (by the kernel, the default; "
          f"'search k': k with --trust-search), --timeout {args.timeout:g}")
    print("family  " + "".join(f"{'n = ' + str(n):>26}" for n in args.sizes))
    with tempfile.TemporaryDirectory() as tmp:
        for name, build in FAMILIES.items():
            cells = []
            for n in args.sizes:
                path = Path(tmp) / f"{name}{n}.py"
                path.write_text(HEADER + build(n) + "\n")
                runs = [time_once(path, args.timeout) for _ in range(args.repeat if n <= 4 else 1)]
                seconds = statistics.median(r[0] for r in runs)
                cells.append(f"{seconds:6.1f} s ({runs[0][1]})")
            print(f"{name:<8}" + "".join(f"{c:>26}" for c in cells), flush=True)


if __name__ == "__main__":
    main()
