"""`make demo`: verify every design in a folder and print a summary table."""
from __future__ import annotations

import sys
from pathlib import Path

from .report import render_text
from .verify import verify_design

LETTER = {"proved": "P", "refuted": "R", "unknown": "?"}


def main(argv=None) -> int:
    folder = Path((argv or sys.argv[1:] or ["designs"])[0])
    files = sorted(folder.glob("*.py"))
    reports = []
    for i, path in enumerate(files, 1):
        print(f"[{i}/{len(files)}] {path.name} ...", file=sys.stderr, flush=True)
        r = verify_design(path)
        reports.append(r)
        print(render_text(r))
        print()
    print("Summary (P proved, R refuted, ? unknown; kf certified; bound (10) per scenario)")
    print(f"{'design':<28} P1..P8    {'kf':<22} {'gains':<34} exit  time")
    for r in reports:
        if r.error:
            print(f"{r.path.name:<28} unusable: {r.error}")
            continue
        row = "".join(LETTER[v.status] for v in r.properties.values())
        kf = r.kf
        if kf is None or (kf.upper is None and not kf.unbounded_witness):
            kf_s = "undecided"
        elif kf.upper is None:
            kf_s = "infinite"
        else:
            kf_s = str(kf.exact) if kf.exact is not None else f"~{float(kf.upper):.9g}"
        gains = " ".join(f"{n}:{'ok' if g.V_ok and g.W_ok else ('FAIL' if g.W_ok is False or not g.V_ok else '?')}"
                         for n, g in r.gains.items())
        print(f"{r.path.name:<28} {row}  {kf_s:<22} {gains:<34} {r.exit_status:>4}  {r.seconds:5.2f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
