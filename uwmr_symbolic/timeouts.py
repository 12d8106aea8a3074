"""Wall-clock limits for SymPy calls that may run for a long time.

`time_limit(seconds)` raises `TimeLimit` inside the block when the time is
up (SIGALRM; main thread only).  Limits nest: an inner limit never extends
an outer one."""
from __future__ import annotations

import signal
import time
from contextlib import contextmanager

_deadlines: list[float] = []

#: How many limits set by `attempt` have expired in this process (a result
#: computed while one expired depends on the time it was given: not cached).
expired = 0


class TimeLimit(BaseException):
    """A time limit expired (a BaseException, so that design files and
    broad `except Exception` clauses cannot swallow it)."""


def _arm():
    if _deadlines:
        remaining = max(min(_deadlines) - time.monotonic(), 1e-3)
        signal.setitimer(signal.ITIMER_REAL, remaining)
    else:
        signal.setitimer(signal.ITIMER_REAL, 0)


def _on_alarm(signum, frame):
    raise TimeLimit()


@contextmanager
def time_limit(seconds: float):
    previous = signal.signal(signal.SIGALRM, _on_alarm)
    _deadlines.append(time.monotonic() + seconds)
    _arm()
    try:
        yield
    finally:
        _deadlines.pop()
        _arm()
        if not _deadlines:
            signal.signal(signal.SIGALRM, previous)


def attempt(fn, seconds: float, default=None):
    """fn() within `seconds`, or `default` if it times out or fails."""
    try:
        with time_limit(seconds):
            return fn()
    except TimeLimit:
        global expired
        expired += 1
        return default   # an outer limit that also expired fires again at once
    except Exception:  # noqa: BLE001 - SymPy failures mean 'not found'
        return default
