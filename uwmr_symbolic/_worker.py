"""The worker process of `api.verify` and `api.verify_file`.

``python -m uwmr_symbolic._worker`` reads jobs from stdin and answers each on
stdout, one after the other, until stdin closes; each message is an 8-byte
length and a pickle.  A job is verified in this process's main thread (the
process belongs to the verifier, so its limits may use SIGALRM); the answer
is ``(status, value, output)``: ``("report", Report, text)``, ``("error",
exception, text)`` or ``("unreadable", message, "")`` when the job could not
be unpickled (a SymPy class defined in the caller's session, say); ``text``
is what the job printed.  The caller (`api._Worker`) kills the process when
a job outlives its limit and starts a new one for the next job."""
from __future__ import annotations

import contextlib
import io
import os
import pickle
import struct
import sys

HEADER = struct.Struct("<Q")


def read_message(stream) -> bytes | None:
    """One length-prefixed message, or None at the end of the stream."""
    header = stream.read(HEADER.size)
    if len(header) < HEADER.size:
        return None
    size = HEADER.unpack(header)[0]
    data = stream.read(size)
    return data if len(data) == size else None


def write_message(stream, data: bytes) -> None:
    stream.write(HEADER.pack(len(data)) + data)
    stream.flush()


def _answer(data: bytes) -> tuple:
    from . import api
    try:
        job = pickle.loads(data)
    except Exception as exc:  # noqa: BLE001 - e.g. a SymPy class defined in the caller's session
        return "unreadable", f"{type(exc).__name__}: {exc}", ""
    captured = io.StringIO()
    try:
        os.chdir(job["cwd"])
        with contextlib.redirect_stdout(captured), contextlib.redirect_stderr(captured):
            report = api.verify_job(job)
    except Exception as exc:  # noqa: BLE001 - a verifier bug is the caller's exception
        return "error", RuntimeError(f"the verifier failed: {type(exc).__name__}: {exc}"), captured.getvalue()
    return "report", report, captured.getvalue()


def main() -> int:
    source, sink = sys.stdin.buffer, sys.stdout.buffer
    sys.stdout = sys.stderr          # nothing but the answers goes to stdout
    while True:
        data = read_message(source)
        if data is None:
            return 0
        answer = _answer(data)
        try:
            out = pickle.dumps(answer)
        except Exception as exc:  # noqa: BLE001 - an object of the user's that cannot travel back
            out = pickle.dumps(("error", RuntimeError(f"the report could not be sent back from the worker "
                                                      f"process ({type(exc).__name__}: {exc}); call with "
                                                      f"worker=False"), answer[2]))
        write_message(sink, out)


if __name__ == "__main__":
    try:
        sys.exit(main())
    except KeyboardInterrupt:       # Ctrl-C reaches the whole process group: the caller says it, once
        sys.exit(130)
