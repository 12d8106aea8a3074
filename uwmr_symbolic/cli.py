"""Command line: `uwmr-verify FILE... [--format text|json] [--timeout S]`."""
from __future__ import annotations

import argparse
import json
import sys

from . import __version__
from .report import render_json, render_text, to_dict
from .verify import DEFAULT_TIMEOUT, verify_design

EPILOG = """\
exit status:
  0  every property P1-P8 proved, proof replay ok, every gain scenario within bound (10)
  1  a property refuted (with a witness) or a gain check fails
  2  unusable input: the design file is missing, broken or not a valid design
  3  inconclusive: some verdict is unknown, nothing refuted
With several files the status is the worst one (2 > 1 > 3 > 0).

A design file defines f (a SymPy expression in real symbols e1, e2) and
optionally params, gains, name, description: see the README."""


def build_parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="uwmr-verify",
        description="Prove or refute properties P1-P8 of f(e1, e2) for the saturated "
                    "controller family (9) of Moreno-Valenzuela et al. (2020), certify kf, "
                    "replay the Lyapunov proof and check gains against bound (10).",
        epilog=EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("files", nargs="+", metavar="FILE", help="design file(s)")
    p.add_argument("--format", choices=("text", "json"), default="text", help="output format (default text)")
    p.add_argument("--timeout", type=float, default=DEFAULT_TIMEOUT,
                   help=f"seconds per design before undecided properties become 'unknown' "
                        f"(default {DEFAULT_TIMEOUT:g})")
    p.add_argument("--version", action="version", version=f"uwmr-verify {__version__}")
    return p


def _worst(statuses):
    order = {0: 0, 3: 1, 1: 2, 2: 3}
    return max(statuses, key=lambda s: order[s]) if statuses else 0


def main(argv=None) -> int:
    args = build_parser().parse_args(argv)
    if args.timeout <= 0:
        print("uwmr-verify: --timeout must be positive", file=sys.stderr)
        return 2
    reports = [verify_design(f, timeout=args.timeout) for f in args.files]
    for r in reports:
        if r.error is not None:
            print(f"{r.path}: {r.error}", file=sys.stderr)
    good = [r for r in reports if r.error is None]
    if args.format == "json":
        if len(args.files) == 1:
            if good:
                print(render_json(good[0]))
        else:
            print(json.dumps([to_dict(r) for r in reports], indent=2))
    else:
        print("\n\n".join(render_text(r) for r in good))
    return _worst([r.exit_status for r in reports])


if __name__ == "__main__":
    sys.exit(main())
