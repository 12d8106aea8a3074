"""Time limits outside the main thread (the watchdog thread of `timeouts`):
they fire, they nest as SIGALRM limits do, and a limit that ends in time
never leaves a stray TimeLimit behind; one that is swallowed (as Python
does in a garbage-collector callback) is raised again."""
import threading
import time

from uwmr_symbolic.timeouts import TimeLimit, _stack, attempt, no_signals, signals_allowed, time_limit


def _busy():
    while True:
        pass


def _busy_until(end):
    while time.monotonic() < end:
        pass


def _exercise(out):
    start = time.monotonic()
    try:
        with time_limit(0.3):
            _busy()
    except TimeLimit:
        out["single"] = time.monotonic() - start
    start = time.monotonic()
    try:
        with time_limit(0.3):
            out["inner"] = attempt(_busy, 5.0, "gave up")     # the outer limit ends the inner one...
            _busy()                                             # ...and fires again at once outside it
    except TimeLimit:
        out["nested"] = time.monotonic() - start
    start = time.monotonic()
    try:
        with time_limit(0.1):
            try:
                _busy_until(start + 5)
            except TimeLimit:              # swallowed, as a garbage-collector callback does
                out["swallowed"] = time.monotonic() - start
            _busy_until(start + 5)
    except TimeLimit:
        out["again"] = time.monotonic() - start
    fired = 0
    for i in range(5000):
        try:
            with time_limit(0.0005 if i % 2 else 10):
                sum(range(200))
        except TimeLimit:
            fired += 1
    out["fired"] = fired
    end = time.monotonic() + 0.3
    while time.monotonic() < end:      # a stray TimeLimit would be raised here
        sum(range(100))
    out["stack"] = list(_stack())
    out["signals"] = signals_allowed()


def _check(out):
    assert 0.3 <= out["single"] < 1.5, out
    assert out["inner"] == "gave up" and 0.3 <= out["nested"] < 1.5, out
    assert out["stack"] == [] and out["fired"] <= 2500, out
    # a swallowed TimeLimit is raised again REFIRE = 0.25 s later
    assert 0.1 <= out["swallowed"] < 1.0 and out["swallowed"] + 0.2 < out["again"] < 2.0, out


def test_limits_in_another_thread():
    out = {}
    thread = threading.Thread(target=_exercise, args=(out,))
    thread.start()
    thread.join(60)
    assert not thread.is_alive()
    _check(out)
    assert out["signals"] is False


def test_limits_in_the_main_thread_without_signals():
    out = {}
    with no_signals():
        _exercise(out)
    _check(out)
    assert out["signals"] is False


def test_limits_in_the_main_thread_with_signals():
    out = {}
    _exercise(out)
    _check(out)
    assert out["signals"] is True


def test_stages_after_the_deadline_share_one_grace_inside_the_kill_limit():
    from uwmr_symbolic.batch import HARD_GRACE
    from uwmr_symbolic.verify import AFTER_DEADLINE, stage_seconds
    assert stage_seconds(100.0, 5.0, 90.0) == 10.0          # before the deadline: what --timeout leaves
    assert stage_seconds(100.0, 5.0, 99.0) == 5.0           # at least the stage's own share
    assert stage_seconds(100.0, 5.0, 100.0 + AFTER_DEADLINE - 2) == 2.0   # cut at the shared grace
    now = 100.5                      # kf, the kernel re-check and the replay all use their whole slice, past the deadline
    for least in (1.0, 5.0, 5.0):
        now += stage_seconds(100.0, least, now)
    assert now == 100.0 + AFTER_DEADLINE < 100.0 + HARD_GRACE   # the old max(left, 5 s) slices ended at 111.5
