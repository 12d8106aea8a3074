"""Wall-clock limits for SymPy calls that may run for a long time.

`time_limit(seconds)` raises `TimeLimit` inside the block when the time is
up.  Limits nest: an inner limit never extends an outer one.

Two ways of interrupting the block, with the same meaning:

* SIGALRM, in a process's main thread on POSIX, when `signals_allowed()`:
  the command line and its worker processes, which own their process.
* otherwise a watchdog thread that raises `TimeLimit` in the limited thread
  (CPython's `PyThreadState_SetAsyncExc`): any thread, any OS, and no signal
  handler of the caller's process is touched.  The library (`api.verify`
  in-process) uses this one, inside `no_signals()`.

A TimeLimit can be swallowed where Python ignores exceptions (a weakref or
`__del__` callback run by the garbage collector inside the block).  Both ways
therefore raise it again every `REFIRE` seconds until the block is left.

Neither can interrupt one long call inside C code (the exception is raised
when the interpreter runs Python code again); `api.verify` therefore runs in
a worker process by default, which is killed when it outlives its limit."""
from __future__ import annotations

import ctypes
import os
import queue
import signal
import threading
import time
from contextlib import contextmanager

#: How many limits set by `attempt` have expired in this process (a result
#: computed while one expired depends on the time it was given: the cache
#: serves it only to runs with the same or a shorter --timeout).
expired = 0

#: Seconds between two raises of one expired limit (one may be swallowed).
REFIRE = 0.25


class TimeLimit(BaseException):
    """A time limit expired (a BaseException, so that design files and
    broad `except Exception` clauses cannot swallow it)."""


_local = threading.local()      # per thread: .deadlines (list), .signals (bool), .no_signals (int)


def _stack() -> list:
    if not hasattr(_local, "deadlines"):
        _local.deadlines = []
    return _local.deadlines


def signals_allowed() -> bool:
    """SIGALRM may be used: POSIX, the main thread, and not inside `no_signals()`."""
    return (hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread()
            and not getattr(_local, "no_signals", 0))


@contextmanager
def no_signals():
    """Limits opened inside this block use the watchdog thread, never SIGALRM."""
    _local.no_signals = getattr(_local, "no_signals", 0) + 1
    try:
        yield
    finally:
        _local.no_signals -= 1


# ---------------------------------------------------------------- SIGALRM

def _arm_signal(deadlines):
    if deadlines:
        remaining = max(min(deadlines) - time.monotonic(), 1e-3)
        signal.setitimer(signal.ITIMER_REAL, remaining)
    else:
        signal.setitimer(signal.ITIMER_REAL, 0)


def _on_alarm(signum, frame):
    now = time.monotonic()
    if any(d <= now for d in _stack()):
        signal.setitimer(signal.ITIMER_REAL, REFIRE)    # again, unless the block is left first
        raise TimeLimit()
    _arm_signal(_stack())           # early (a stale timer): wait for the nearest deadline


# ---------------------------------------------------------------- watchdog thread

_set_async_exc = ctypes.pythonapi.PyThreadState_SetAsyncExc
_set_async_exc.argtypes = (ctypes.c_ulong, ctypes.py_object)
_set_async_exc.restype = ctypes.c_int


def _raise_in(tid: int, exc) -> None:
    """Raise `exc` in thread `tid` at its next Python instruction (None: cancel
    a pending one)."""
    _set_async_exc(ctypes.c_ulong(tid), ctypes.py_object(exc) if exc is not None else ctypes.py_object())


class _Watchdog:
    """One daemon thread; `armed[tid]` is the nearest deadline of thread tid
    (set and removed by that thread with single dict operations, and a
    wake-up through a C-level queue: the limited thread never takes a lock
    that an exception could leave held)."""

    def __init__(self):
        self.armed: dict[int, tuple] = {}
        self.fired: dict[int, tuple] = {}     # tid -> (entry, when) of its last raise (watchdog's own)
        self.wake: queue.SimpleQueue = queue.SimpleQueue()
        self.thread: threading.Thread | None = None

    def arm(self, tid: int, deadline: float | None):
        if deadline is None:
            self.armed.pop(tid, None)
        else:
            self.armed[tid] = (deadline, object())    # a fresh token: re-armed, fires again
        if self.thread is None:      # never ends (reset in a forked child)
            self.thread = threading.Thread(target=self._run, name="uwmr-time-limit", daemon=True)
            self.thread.start()
        self.wake.put(None)

    def _run(self):
        while True:
            try:
                self._fire_and_wait()
            except Exception:  # noqa: BLE001 - the watchdog must outlive any surprise
                time.sleep(1e-3)

    def _fire_and_wait(self):
        now = time.monotonic()
        waiting = []
        for tid, entry in list(self.armed.items()):       # list(): one C call, no concurrent change
            last = self.fired.get(tid)
            due = last[1] + REFIRE if last is not None and last[0] is entry else entry[0]
            if due > now:
                waiting.append(due)
                continue
            _raise_in(tid, TimeLimit)
            self.fired[tid] = (entry, now)
            waiting.append(now + REFIRE)
            if self.armed.get(tid) is not entry:
                _raise_in(tid, None)                       # the block ended meanwhile: take it back
        for tid in list(self.fired):
            if tid not in self.armed:
                del self.fired[tid]
        try:
            self.wake.get(timeout=max(min(waiting) - time.monotonic(), 0.0) if waiting else None)
        except queue.Empty:
            pass


_watchdog = _Watchdog()


def _reset_after_fork():
    global _watchdog
    _watchdog = _Watchdog()


if hasattr(os, "register_at_fork"):
    os.register_at_fork(after_in_child=_reset_after_fork)


def _arm_thread(deadlines):
    _watchdog.arm(threading.get_ident(), min(deadlines) if deadlines else None)


# ---------------------------------------------------------------- the limit

@contextmanager
def time_limit(seconds: float):
    deadlines = _stack()
    if not deadlines:
        _local.signals = signals_allowed()
    use_signals = _local.signals
    previous = signal.signal(signal.SIGALRM, _on_alarm) if use_signals and not deadlines else None
    arm = _arm_signal if use_signals else _arm_thread
    depth = len(deadlines)
    deadlines.append(time.monotonic() + seconds)
    try:
        arm(deadlines)
        yield
    finally:
        del deadlines[depth:]      # also what a TimeLimit raised between append and try left
        arm(deadlines)
        if not use_signals:
            _raise_in(threading.get_ident(), None)    # the block is over: drop a TimeLimit not yet raised
        if previous is not None:
            signal.signal(signal.SIGALRM, previous)


def attempt(fn, seconds: float, default=None):
    """fn() within `seconds`, or `default` if it times out or fails."""
    depth = len(_stack())
    try:
        with time_limit(seconds):
            return fn()
    except TimeLimit:
        global expired
        expired += 1
        deadlines = _stack()
        if len(deadlines) > depth:       # a second raise cut time_limit's own cleanup short
            del deadlines[depth:]
            (_arm_signal if _local.signals else _arm_thread)(deadlines)
        return default   # an outer limit that also expired fires again at once
    except Exception:  # noqa: BLE001 - SymPy failures mean 'not found'
        return default


def quiet_on_interrupt() -> None:
    """In a forked child process (a pool's or a batch's): Ctrl-C, which
    reaches the whole process group, ends it at once with status 130 and no
    traceback; the parent says it once.  Where the parent ignores SIGINT (a
    job started in the background by a shell), the child ignores it too."""
    if signal.getsignal(signal.SIGINT) is not signal.SIG_IGN:
        signal.signal(signal.SIGINT, lambda *_: os._exit(130))
