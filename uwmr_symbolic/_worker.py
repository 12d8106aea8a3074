"""The worker process of `api.verify` and `api.verify_file`.

Reads one pickled job from stdin, verifies it in this process's main thread
(the process belongs to the verifier, so its limits may use SIGALRM), writes
the pickled `Report` to stdout.  Run as ``python -m uwmr_symbolic._worker``."""
from __future__ import annotations

import pickle
import sys


def main() -> int:
    try:
        job = pickle.load(sys.stdin.buffer)
    except Exception as exc:  # noqa: BLE001 - e.g. a SymPy class defined in the caller's session
        print(f"cannot read the job: {type(exc).__name__}: {exc}", file=sys.stderr)
        return 3
    out = sys.stdout.buffer
    sys.stdout = sys.stderr          # nothing but the result goes to stdout
    from . import api
    if job["kind"] == "file":
        report = api._verify_file_here(job["path"], job["timeout"])
    else:
        report = api._verify_here(job["namespace"], job["path"], job["timeout"])
    try:
        data = pickle.dumps(report)
    except Exception as exc:  # noqa: BLE001 - an object of the user's that cannot travel
        data = pickle.dumps(RuntimeError(f"the report could not be sent back from the worker process "
                                         f"({type(exc).__name__}: {exc}); call with worker=False"))
    out.write(data)
    out.flush()
    return 0


if __name__ == "__main__":
    sys.exit(main())
