"""python -m uwmr_symbolic.codegen [--force] [--out DIR] DESIGN.py ...

Writes generated/<stem>/ (or DIR/<stem>/) for each design; the same as
`uwmr-verify FILE --codegen`.  Exit status 1 when a design is refused, 2
when a design file is unusable or the output folder cannot take the files
(one line on stderr each; nothing written for that design)."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from . import CodegenRefused, OutputError, generate
from ..verify import verify_design


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="python -m uwmr_symbolic.codegen", description=__doc__.splitlines()[0])
    ap.add_argument("designs", nargs="+", type=Path)
    ap.add_argument("--out", type=Path, default=Path("generated"), help="parent directory (default generated/)")
    ap.add_argument("--force", action="store_true", help="also generate unverified designs, with a NOT VERIFIED banner")
    args = ap.parse_args(argv)
    status = 0
    for path in args.designs:
        report = verify_design(path)
        if report.error is not None:
            print(f"{path}: {report.error}", file=sys.stderr)
            status = 2
            continue
        try:
            written = generate(path, args.out / path.stem, force=args.force, report=report)
        except CodegenRefused as exc:
            print(f"{path}: refused: {'; '.join(exc.reasons)}", file=sys.stderr)
            status = max(status, 1)
            continue
        except OutputError as exc:
            print(f"{path}: no code generated: {exc}", file=sys.stderr)
            status = 2
            continue
        print(f"{path}: " + ", ".join(str(p) for p in written))
    return status


if __name__ == "__main__":
    sys.exit(main())
