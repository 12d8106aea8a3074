"""One fuzzing profile: draw designs from the grammar, verify each in the
worker process, check every verdict against the oracle, and tabulate.

    python -m fuzz.run --examples 500 [--seed N] [--timeout 10] [--keep DIR]

(from tests/, as `make fuzz` does).  Every design with a contradiction is
written to --keep (default: a temporary folder) with the evidence in its
docstring."""
from __future__ import annotations

import argparse
import collections
import sys
import tempfile
import time
import warnings
from dataclasses import dataclass, field
from pathlib import Path

from hypothesis import HealthCheck, Phase, given, seed as hseed, settings

from .grammar import FAMILIES, PROPS, designs, design_source
from .oracle import check
from .worker import Verifier


@dataclass
class Stats:
    tried: int = 0
    by_family: collections.Counter = field(default_factory=collections.Counter)
    verdicts: dict = field(default_factory=lambda: {p: collections.Counter() for p in PROPS})
    truth_verdicts: dict = field(default_factory=lambda: {p: collections.Counter() for p in PROPS})
    true_known: int = 0
    true_proved: int = 0
    true_kernel: int = 0        # of those, kernel-checked: proved by default
    proved_total: int = 0       # proved properties plus finite kf claims (exact or enclosed)
    kernel_checked: int = 0     # of those, checked by the kernel with nothing left to the search
    refuted_total: int = 0
    refutations_checked: int = 0    # refuted properties whose witness the kernel checked
    false_known: int = 0
    false_refuted: int = 0
    contradictions: list = field(default_factory=list)     # (path, case, Contradiction)
    seconds: float = 0.0
    state_leaks: list = field(default_factory=list)   # failed in a used worker, fine in a fresh one

    def unexplained(self):
        return [(p, case, c) for p, case, c in self.contradictions if c.known is None]

    def count(self, kind, known=None):
        return sum(1 for _, _, c in self.contradictions if c.kind == kind and (known is None or
                                                                              (c.known is not None) == known))

    def table(self) -> str:
        rows = [f"designs tried: {self.tried} in {self.seconds:.0f} s  "
                f"({', '.join(f'{k} {v}' for k, v in sorted(self.by_family.items()))})",
                "property  proved  refuted  unknown   true: proved/known   false: refuted/known"]
        for p in PROPS:
            v, t = self.verdicts[p], self.truth_verdicts[p]
            rows.append(f"{p:8}  {v['proved']:6}  {v['refuted']:7}  {v['unknown']:7}   "
                        f"{t['T proved']:5}/{t['T']:<5}          {t['F refuted']:5}/{t['F']:<5}")
        share = self.true_proved / self.true_known if self.true_known else float("nan")
        rshare = self.false_refuted / self.false_known if self.false_known else float("nan")
        rows += [
            f"false proofs:       {self.count('false proof')}",
            f"wrong refutations:  {self.count('wrong refutation')}",
            f"bad witnesses:      {self.count('bad witness')}",
            f"wrong kf claims:    {self.count('wrong kf')}",
            f"certificates that do not re-check: {self.count('certificate')}",
            f"proved properties and finite kf claims kernel-checked: {self.kernel_checked}/{self.proved_total}",
            f"refuted properties with a kernel-checked witness: {self.refutations_checked}/{self.refuted_total}",
            f"crashes / hangs / rejected: {self.count('crash')} / {self.count('hang')} / {self.count('unusable')}",
            f"hang/death only in a reused process (fine in a fresh one): {len(self.state_leaks)}",
            f"true properties (known by construction) proved by the search (--trust-search): "
            f"{self.true_proved}/{self.true_known} = {share:.1%}",
            f"  of which kernel-checked (proved by default): {self.true_kernel}/{self.true_known}",
            f"false properties refuted: {self.false_refuted}/{self.false_known} = {rshare:.1%}",
        ]
        for path, case, c in self.contradictions:
            rows.append(f"  {path.name}: {c.line()}")
        return "\n".join(rows)


def write_finding(path: Path, case, contradictions):
    text = design_source(case)
    doc = "\n".join(c.line() for c in contradictions).replace('"""', "'''").replace("\\", "\\\\")
    text = text.replace('"""', '"""' + doc + "\n\n", 1)
    path.write_text(text)


def run_profile(examples: int, seed: int | None = 0, timeout: float = 10.0, keep: Path | None = None,
                progress=None, family: str | None = None) -> Stats:
    keep = Path(keep or tempfile.mkdtemp(prefix="uwmr-fuzz-"))
    keep.mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp(prefix="uwmr-fuzz-work-"))
    stats = Stats()
    t0 = time.monotonic()
    with Verifier() as verifier:
        @settings(max_examples=examples, deadline=None, database=None, derandomize=seed is None,
                  phases=[Phase.generate], suppress_health_check=list(HealthCheck))
        @given(designs(family))
        def one(case):
            n = stats.tried
            path = work / f"d{n:05d}.py"
            path.write_text(design_source(case))
            result = verifier.verify(path, timeout)
            if result.get("hang") or result.get("crash") or result.get("seconds", 0) > timeout / 2:
                verifier.close()                 # a fresh process for the next design (see worker.py)
            if result.get("hang") or (result.get("crash") or "").startswith("worker process died"):
                # does it hang or die on its own, or only after earlier designs in the same process?
                retry = verifier.verify(path, timeout)
                verifier.close()
                if not retry.get("hang") and not (retry.get("crash") or "").startswith("worker process died"):
                    stats.state_leaks.append((path.name, "hang" if result.get("hang") else result["crash"]))
                    result = retry
            found = check(case, result)
            stats.tried += 1
            stats.by_family[case.family] += 1
            stats.proved_total += sum(1 for v in (result.get("properties") or {}).values()
                                      if v.get("status") == "proved")
            stats.proved_total += (result.get("kf") or {}).get("upper") is not None
            stats.kernel_checked += len(result.get("kernel_checked") or [])
            stats.refuted_total += sum(1 for v in (result.get("properties") or {}).values()
                                       if v.get("status") == "refuted")
            stats.refutations_checked += len(result.get("refutations_checked") or [])
            for p in PROPS:
                st = (result.get("properties") or {}).get(p, {}).get("status", "none")
                stats.verdicts[p][st] += 1
                if case.truth.get(p) is not None:
                    tv = "T" if case.truth[p] else "F"
                    stats.truth_verdicts[p][tv] += 1
                    stats.truth_verdicts[p][f"{tv} {st}"] += 1
                if case.truth.get(p) is True:
                    stats.true_known += 1
                    stats.true_proved += st == "proved"
                    stats.true_kernel += st == "proved" and p in (result.get("kernel_checked") or [])
                elif case.truth.get(p) is False:
                    stats.false_known += 1
                    stats.false_refuted += st == "refuted"
            if found:
                kept = keep / f"{case.family}_{n:05d}.py"
                write_finding(kept, case, found)
                stats.contradictions += [(kept, case, c) for c in found]
            if progress:
                progress(n, case, result, found)

        if seed is not None:
            one = hseed(seed)(one)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            one()
    stats.seconds = time.monotonic() - t0
    return stats


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--examples", type=int, default=500)
    ap.add_argument("--seed", type=int, default=None, help="default: a fresh random seed")
    ap.add_argument("--timeout", type=float, default=10.0)
    ap.add_argument("--keep", type=Path, default=None)
    ap.add_argument("--family", choices=sorted(FAMILIES), default=None, help="draw from this family only")
    a = ap.parse_args(argv)
    import random
    seed = a.seed if a.seed is not None else random.randrange(2 ** 32)
    print(f"seed {seed}", flush=True)

    def progress(n, case, result, found):
        checked = set(result.get("kernel_checked") or []) | set(result.get("refutations_checked") or [])
        tags = " ".join(f"{p}:{(result.get('properties') or {}).get(p, {}).get('status', '-')[0]}"
                        f"{'*' if p in checked else ' '}" for p in PROPS)     # *: the kernel has checked it
        print(f"[{n}] {case.family:16} {tags} {result.get('seconds', 0) or 0:5.1f}s "
              + ("; ".join(c.line()[:160] for c in found)), flush=True)
    stats = run_profile(a.examples, seed, a.timeout, a.keep, progress, a.family)
    print(stats.table())
    return 1 if stats.unexplained() else 0


if __name__ == "__main__":
    sys.exit(main())
