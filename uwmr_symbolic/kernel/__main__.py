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
            where = f" for {parse(c.var)} in {'(' if c.lo_open else '['}{parse(c.lo)}, " \
                    f"{parse(c.hi)}{')' if c.hi_open else ']'}" if c.var else ""
            print(f"{path}: checked {c.kind} {parse(c.expr)} want={c.want} strict={c.strict}"
                  f"{' other=' + str(parse(c.other)) if c.other else ''}{where}")
        print(f"{path}: rests on {', '.join(sorted(set().union(*[t.assumptions for t in theorems])))}")
    return status


if __name__ == "__main__":
    sys.exit(main())
