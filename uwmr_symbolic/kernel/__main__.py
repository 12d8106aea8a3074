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
        for t in theorems:
            c = t.claim
            x, span = c.var and parse(c.var), f"{'(['[not c.lo_open]}{c.lo and parse(c.lo)}, {parse(c.hi or 'oo')}{')]'[not c.hi_open]}"
            where = "" if not c.var else f" as {x} -> oo" if c.kind == "limit_oo" else f" for {x} in {span}" if c.lo else f" for all {x}"
            print(f"{path}: checked {c.kind} {parse(c.expr)} want={c.want} strict={c.strict}"
                  f"{' other=' + str(parse(c.other)) if c.other else ''}{where}")
        print(f"{path}: rests on {', '.join(sorted(set().union(*[t.assumptions for t in theorems])))}")
    return status


if __name__ == "__main__":
    sys.exit(main())
