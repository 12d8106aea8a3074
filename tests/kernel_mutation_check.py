"""Hand-written mutants of the kernel: each must be killed by the fast
kernel tests.  Run:  .venv/bin/python tests/kernel_mutation_check.py
(about 30 mutants x 20 s; not collected by pytest).  Survivors today, all
equivalent: the explicit log-domain check in arb.py (Arb's log of a ball
reaching <= 0 is nan, which the evaluator refuses anyway); sign_on_tail's
check that E is defined for s > 0 (the same check on E(1/t) catches every
case we could construct); join_at_zero's exact E(m) = 0 (E defined at m
and continuous there already gives the weak sign)."""
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MUTANTS = [
 ("arb.py", "return Iv(x.lo + y.lo, x.hi + y.hi)", "return Iv(x.hi + y.lo, x.hi + y.hi)"),
 ("arb.py", "if not (x.positive() or x.negative()):", "if False:"),
 ("arb.py", "if not x.positive():\n        raise Undefined(\"log", "if False:\n        raise Undefined(\"log"),
 ("arb.py", "if not x.nonnegative():\n        raise Undefined(f\"x**({e}) needs x >= 0\")", "pass"),
 ("arb.py", "lo, hi = lo.min(q), hi.max(q)", "lo, hi = lo.max(q), hi.max(q)"),
 ("arb.py", "return Iv(g(arb(0)), g(-x.lo).max(g(x.hi)))", "return Iv(g(x.lo), g(-x.lo).max(g(x.hi)))"),
 ("arb.py", "_BOUNDED = {sp.sin: arb.sin, sp.cos: arb.cos}", "_BOUNDED = {sp.sin: arb.sin, sp.cos: arb.sin}"),
 ("core.py", "        return v.positive() if want > 0 else v.negative()\n    return v.nonnegative()", "        return v.nonnegative() if want > 0 else v.negative()\n    return v.nonnegative()"),
 ("core.py", "_need(_lt(a, b), lambda: f\"cut points not increasing", "_need(True, lambda: f\"cut points not increasing"),
 ("core.py", "_need(at_c == 0, lambda:", "_need(True, lambda:"),
 ("core.py", "sigma * side ** order, True)", "sigma, True)"),
 ("core.py", "n -= sum(1 for v, op in ((lo_f, lo_open), (hi_f, hi_open)) if v is not None and op and q.eval(v) == 0)", "n -= at_ends"),
 ("core.py", "        elif m % 2 == 0:\n            continue", "        elif True:\n            continue"),
 ("core.py", "_need(n > 0 or p.claim.strict,", "_need(True,"),
 ("core.py", "_need(s in (0, want), lambda:", "_need(True, lambda:"),
 ("core.py", "_need(not (l.hi_open and r.lo_open),", "_need(True,"),
 ("core.py", "_need(l.hi == r.lo, \"not adjacent\")\n    _need(not", "_need(True, \"not adjacent\")\n    _need(not"),
 ("core.py", "_need(defined_for_positive(e, var), lambda: f\"{e} not shown defined for all {var} > 0\")\n    _need(defined_for_positive(e.subs", "_need(True, \"\")\n    _need(defined_for_positive(e.subs"),
 ("core.py", "_need(sp.cancel(sp.together(d)) == 0,", "_need(True,"),
 ("core.py", "_need(v.contains(0), lambda:", "_need(True, lambda:"),
 ("core.py", "_need(c.strict or not strict,", "_need(True,"),
 ("core.py", "_need(e.subs(var, m) == 0,", "_need(True,"),
 ("core.py", "_need(at_r.positive() if d.want > 0 else at_r.negative(),", "_need(True,"),
 ("core.py", "_need(et.subs(t, 0) - c == 0 and at0.hull().contains(0),", "_need(True,"),
 ("core.py", "_need(bool(v.hi <= ub.lo),", "_need(True,"),
 ("core.py", "_need(bool(v.lo >= evaluate(L, bits=256).hi),", "_need(True,"),
 ("core.py", "object.__setattr__(self, \"_token\", None)", "pass"),
 ("certificate.py", "if t.claim != claimed:", "if False:"),
 ("certificate.py", "if data.get(\"version\") != VERSION:", "if False:"),
 ("certificate.py", "if rests != sorted(data[\"assumptions\"]):", "if False:"),
]


def main():
    tmp = tempfile.mkdtemp(prefix="kernel-mutants-")
    for d in ("uwmr_symbolic", "tests"):
        shutil.copytree(os.path.join(ROOT, d), os.path.join(tmp, d))
    kdir = os.path.join(tmp, "uwmr_symbolic", "kernel") + "/"
    killed = 0
    for i, (f, old, new) in enumerate(MUTANTS):
        src = open(os.path.join(ROOT, "uwmr_symbolic", "kernel", f)).read()
        assert src.count(old) == 1, (f, old)
        open(kdir + f, "w").write(src.replace(old, new))
        r = subprocess.run([sys.executable, "-m", "pytest", "-q", "-x", "-p", "no:cacheprovider",
                            "tests/test_kernel.py", "tests/test_kernel_fuzz.py"], cwd=tmp,
                           env={**os.environ, "PYTHONPATH": tmp}, capture_output=True, text=True)
        open(kdir + f, "w").write(src)
        ok = r.returncode != 0
        killed += ok
        print(("KILLED  " if ok else "SURVIVED"), f, old[:70].replace("\n", " "), flush=True)
    print(f"{killed}/{len(MUTANTS)} killed")
    shutil.rmtree(tmp)
    return 0 if killed >= len(MUTANTS) - 3 else 1


if __name__ == "__main__":
    sys.exit(main())
