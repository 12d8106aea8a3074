"""python -m uwmr_symbolic.kernel CERT.json ...: re-check certificates.

Prints each conclusion and the assumptions it rests on; exit 0 if every
certificate checks, 1 if one does not (with the first failing step)."""
import json
import sys

from .certificate import CertificateError, check_certificate
from .parse import parse


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    if not argv:
        print(__doc__.strip())
        return 2
    status = 0
    for path in argv:
        try:
            with open(path, encoding="utf-8") as fh:
                theorems = check_certificate(json.load(fh))
        except (OSError, json.JSONDecodeError, CertificateError) as exc:
            print(f"{path}: REJECTED: {exc}")
            status = 1
            continue
        for c in [t.claim for t in theorems]:
            x, lo, hi = c.var and parse(c.var), c.lo and parse(c.lo), parse(c.hi or "oo")
            span = f" for {x} in {'(['[not c.lo_open]}{lo}, {hi}{')]'[not c.hi_open]}" if c.lo else f" for all {x}"
            where = "" if not x else f" as {x} -> oo" if c.kind == "limit_oo" else span
            print(f"{path}: checked {c.kind} {parse(c.expr)} want={c.want} strict={c.strict}"
                  f"{' other=' + str(parse(c.other)) if c.other else ''}{where}")
        print(f"{path}: rests on {', '.join(sorted(set().union(*[t.assumptions for t in theorems])))}")
    return status


if __name__ == "__main__":
    sys.exit(main())
