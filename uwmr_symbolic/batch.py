"""Checking many design files: argument expansion, the cache, and parallel
workers.

Every file is checked by `check_file`, which returns the JSON-able result
dict of `report.to_dict` (plus ``"cached"``).  With several files the work
runs in a pool of processes — the verifier's time limits use SIGALRM, which
only works in a process's main thread — and the results come back in the
order the files were given."""
from __future__ import annotations

import glob
import multiprocessing
import os
import sys
import time
from fractions import Fraction
import multiprocessing.connection
from pathlib import Path

import sympy as sp

from . import design_certificate as certificates
from .cache import ResultCache, design_key, source_hash
from .gains import check_gains
from .interval import Interval
from .report import design_fields, gains_dict, kf_numbers, to_dict
from .profile import float_of
from .properties import PROPERTIES
from .replay import replay
from .timeouts import quiet_on_interrupt
from .verdict import Status, Verdict, unknown
from .verify import Report, kernel_summary, kf_checked, load_with_limit, verify_loaded

GLOB_CHARS = set("*?[")
# what `report.to_dict` gives (and a served entry, nothing else), and its kf
RESULT_KEYS = ("design", "name", "f", "properties", "kf", "gains", "proof_replay", "kernel", "seconds", "exit_status",
               "f_line", "gains_line", "certificate")
KF_FIELDS = {"exact", "exact_digits", "lower", "upper", "enclosure", "attained", "unbounded", "kernel_checked", "reason"}
PROPERTY_FIELDS, P6_FIELDS = {"verdict", "reason", "witness", "unchecked"}, {"k", "k_float", "h"}


def expand_paths(args: list[str]) -> list[str]:
    """Files from the command line: a glob (when the shell did not expand it)
    becomes the files it matches, a directory its ``*.py`` files (regular
    files, not hidden: not a sub-folder, a broken link or an editor's
    ``.#x.py``); anything else is kept as given (a missing file is reported
    by the loader).  Duplicates are dropped, the order is kept."""
    out: list[str] = []
    for arg in args:
        if os.path.isdir(arg):
            out.extend(sorted(str(p) for p in Path(arg).glob("*.py") if p.is_file() and not p.name.startswith(".")))
        elif not os.path.exists(arg) and GLOB_CHARS & set(arg):
            matches = sorted(p for p in glob.glob(arg, recursive=True) if os.path.isfile(p))
            out.extend(matches or [arg])
        else:
            out.append(arg)
    seen, unique = set(), []
    for path in out:            # a.py and ./a.py are one file (red team 28)
        key = os.path.realpath(path)
        if key not in seen:
            seen.add(key)
            unique.append(path)
    return unique


def check_file(path: str, timeout: float, cache_dir: str | None, use_cache: bool = True,
               kernel_only: bool = True, want_report: bool = False) -> dict:
    """Verify one file, or serve its result from the cache.  `want_report`
    (--codegen, --simulate: they need the verifier's whole `Report`, which
    an entry does not hold): verify it, store the result, and return the
    Report as well, under "report", so that the command verifies it once."""
    start = time.monotonic()
    loaded = load_with_limit(path, timeout, start)
    if isinstance(loaded, Report):          # unusable, or loading timed out
        return {**to_dict(loaded), "cached": False} if loaded.error is None else to_dict(loaded)
    design = loaded
    cache = ResultCache(cache_dir) if use_cache else None
    key = (design_key(design) | ({} if kernel_only else {"trust_search": True})) if use_cache else None
    if cache is not None and not want_report:
        hit = cache.get(key, timeout)     # not if computed with less time while a limit expired
        hit = served(hit, design, kernel_only) if hit is not None else None
        if hit is not None:
            hit |= design_fields(design)
            return {**{key: hit[key] for key in RESULT_KEYS}, "cached": True}       # in `to_dict`'s order
    report = verify_loaded(design, timeout, start, kernel_only)
    result = {**to_dict(report), "certificate": report.certificate}
    if cache is not None and report.certificate is not None and not {"error", "stopped", "failed", "refuted_by"} & set(report.kernel):
        cache.put(key, result, timeout=timeout, timed_out=report.timed_out)
    return {**result, "cached": False} | ({"report": report} if want_report else {})


def served(hit: dict, design, kernel_only: bool = True) -> dict | None:
    """The cached result to serve, or None (a miss).  Its design certificate
    must re-check in the kernel, be about this design's f and agree with the
    cached verdicts (each the certificate's, or, with `kernel_only`, unknown
    where the kernel did not check it) on all of P1-P8, P6's k must be the
    one the kernel checked h <= 1 with, and kf must be the one the kernel
    checked (exact, enclosed, or infinite by a checked witness) or none.  A
    kf resting on the search, or with --trust-search any verdict resting on
    it, is computed again: what an entry says the search found could be
    anybody's.  Bound (10) per scenario, the proof replay (11)-(19), the exit
    status and kf's digits or enclosure are derived again from the
    certificate and the design, and an entry's other fields are dropped.
    The texts that explain the verdicts (reasons, witnesses' descriptions,
    P6's h, whether kf is attained) are served as stored."""
    cert = hit.get("certificate")
    try:
        checks = certificates.check(cert)
    except certificates.CertificateError:
        return None
    kernel = kernel_summary(checks)
    if not kernel_only and kernel["search"]:      # --trust-search trusts the search, not an entry's notes
        return None
    statuses = {p: e.get("status") for p, e in cert["properties"].items() if p in PROPERTIES}
    expected = {p: "unknown" if kernel_only and p in kernel["search"] else s for p, s in statuses.items()}
    props, shown_kf, seconds = hit.get("properties"), hit.get("kf"), hit.get("seconds")
    if not (isinstance(props, dict) and all(isinstance(v, dict) and isinstance(v.get("reason"), str) and set(v) <= (
            PROPERTY_FIELDS | (P6_FIELDS if (p, v.get("verdict")) == ("P6", "proved") else set())) for p, v in props.items())
            and isinstance(shown_kf, dict) and set(shown_kf) == KF_FIELDS and shown_kf["attained"] in (True, False, None)
            and isinstance(shown_kf["reason"], str) and type(seconds) in (int, float) and 0 <= seconds < 1e7):
        return None
    verdicts = {p: str(v.get("verdict")) for p, v in props.items()}
    if cert["design"]["f"] != sp.srepr(design.f) or hit.get("kernel") != kernel or verdicts != expected \
            or set(verdicts) != set(PROPERTIES):        # (a property left out is no property proved)
        return None
    k6 = next(c.value for c in checks if c.name == "P6")
    if verdicts["P6"] == "proved" and (k6 is None or props["P6"].get("k") != str(k6)):
        return None             # P6's k is the one the kernel checked h <= 1 with
    props = {p: dict(props[p], **({"k_float": float_of(k6)} if "k" in props[p] else {})) for p in PROPERTIES}
    checked = _checked_kf(cert, kernel, shown_kf)
    if checked is None:
        return None
    kf, numbers = checked
    gains = check_gains(design.gains, *kf)
    proof = replay(design.f, statuses.get("P4") == "proved")
    status = Report(design.path, design, {p: Verdict(Status(v), "") for p, v in verdicts.items()}, None, gains,
                    proof).exit_status
    here = {**cert, "design": {**cert["design"], "file": str(design.path), "name": design.name}}   # (a copy's entry)
    shown_kf = dict(shown_kf, **numbers, kernel_checked=kf[1])      # kf's numbers as checked, not as stored
    return {"properties": props, "kf": shown_kf, "kernel": kernel, "seconds": hit["seconds"], "certificate": here,
            "gains": gains_dict(gains), "proof_replay": proof, "exit_status": status}


def _checked_kf(cert: dict, kernel: dict, shown: dict) -> tuple | None:
    """((kf_upper, kf_known, kf_lower) for `gains.check_gains`, kf's numbers
    as `report.kf_numbers` gives them) from what the kernel checked of kf,
    if the cached `shown` kf has those numbers; else None."""
    entry = cert["properties"].get("kf") or {}
    if "kf" in kernel["checked"] and entry.get("exact") is not None:
        exact = certificates.parse(entry["exact"])
        box = Interval.point(exact)         # (as `kf.exact_certificate` and `report.to_dict` print it)
        out = (exact, True, None), kf_numbers(exact, box.lower_fraction(), box.upper_fraction(), False)
    elif "kf" in kernel["checked"]:
        L, U = certificates.parse(entry["lower"]), certificates.parse(entry["upper"])
        out = (U, True, L), kf_numbers(None, Fraction(str(L)), Fraction(str(U)), False)
    elif kf_checked(cert, kernel):        # infinite, by a checked P1 witness df/de2 -> oo
        out = (None, True, None), kf_numbers(None, None, None, True)
    else:   # kf undecided, or resting on the search: what an entry says the search found could be anybody's
        # (bound (10) does not use it by default, but the report shows it), so such an entry is computed again
        out = (None, False, None), kf_numbers(None, None, None, False)
    return out if all(shown.get(key) == out[1][key] for key in ("exact", "lower", "upper", "unbounded")) else None


def _internal_error(path: str, exc: BaseException) -> dict:
    return {"design": path, "error": f"internal error of uwmr-verify ({exc.__class__.__name__}: {exc}); "
                                     f"please report it", "exit_status": 2}


class Progress:
    """`[done/total] file` on stderr, rewritten in place — only when stderr is
    a terminal and there is more than one file, so logs and pipes stay clean."""

    def __init__(self, total: int, stream=None):
        self.stream = stream if stream is not None else sys.stderr
        self.total = total
        self.done = 0
        self.enabled = total > 1 and hasattr(self.stream, "isatty") and self.stream.isatty()

    def step(self, path: str):
        self.done += 1
        if self.enabled:
            self.stream.write(f"\r\033[K[{self.done}/{self.total}] {path}")
            self.stream.flush()

    def close(self):
        if self.enabled:
            self.stream.write("\r\033[K")
            self.stream.flush()


HARD_GRACE = 10.0     # seconds past --timeout before a stuck check is killed


def hard_limit(timeout: float) -> float:
    """Wall-clock limit of one file's process: the verifier's own SIGALRM
    limits cannot interrupt a long call inside C code (big-integer or Arb
    arithmetic, say), so the parent kills the process after this long."""
    return timeout + max(HARD_GRACE, 0.25 * timeout)


def _timed_out_result(path: str, timeout: float) -> dict:
    props = {p: unknown(f"the check of this file was stopped after {hard_limit(timeout):g} s "
                        f"(--timeout {timeout:g} s)") for p in PROPERTIES}
    return to_dict(Report(Path(path), None, props, None, seconds=hard_limit(timeout), timed_out=True))


def _child(conn, path, timeout, cache_dir, use_cache, kernel_only, want_report):
    quiet_on_interrupt()
    try:
        result = check_file(path, timeout, cache_dir, use_cache, kernel_only, want_report)
    except Exception as exc:  # noqa: BLE001 - a verifier bug must not hide the other files
        result = _internal_error(path, exc)
    conn.send(result)
    conn.close()
    # not a normal exit, which waits for every thread the design file started (red team 28: a
    # thread sleeping 1000 s held the whole batch); the result is sent, nothing else is left to do
    sys.stdout.flush()
    sys.stderr.flush()
    os._exit(0)


def check_files(paths: list[str], timeout: float, use_cache: bool = True, jobs: int | None = None,
                cache_dir: str | None = None, progress: Progress | None = None,
                kernel_only: bool = True, want_reports: bool = False) -> list[dict]:
    """Results for `paths`, in order.  Each file is checked in a process of
    its own (forked: SymPy and the verifier are already imported), at most
    `jobs` at a time; a process that outlives `hard_limit(timeout)` is killed
    and its file reported as timed out, one that dies is reported unusable.
    `want_reports`: as `check_file`'s `want_report`."""
    jobs = max(1, min(jobs or os.cpu_count() or 1, len(paths) or 1))
    cache_dir = str(ResultCache(cache_dir).directory) if use_cache else None
    progress = progress or Progress(0)
    results: list[dict | None] = [None] * len(paths)
    if use_cache:
        source_hash()      # computed once, inherited by the forked children
    methods = multiprocessing.get_all_start_methods()
    ctx = multiprocessing.get_context("fork" if "fork" in methods else "spawn")
    pending = list(range(len(paths)))
    active = {}            # connection -> (index, process, deadline)
    while pending or active:
        while pending and len(active) < jobs:
            i = pending.pop(0)
            recv, send = ctx.Pipe(duplex=False)
            proc = ctx.Process(target=_child, args=(send, paths[i], timeout, cache_dir, use_cache, kernel_only,
                                                    want_reports))
            proc.start()
            send.close()
            active[recv] = (i, proc, time.monotonic() + hard_limit(timeout))
        nearest = min(deadline for _, _, deadline in active.values())
        ready = multiprocessing.connection.wait(list(active), timeout=max(0.0, nearest - time.monotonic()))
        now = time.monotonic()
        for conn in list(active):
            i, proc, deadline = active[conn]
            if conn in ready:
                try:
                    results[i] = conn.recv()
                except EOFError:
                    results[i] = {"design": paths[i], "error": "the process checking this file died "
                                                               "(does the file call os._exit or crash Python?)",
                                  "exit_status": 2}
            elif now >= deadline:
                proc.kill()
                results[i] = _timed_out_result(paths[i], timeout)
            else:
                continue
            proc.join()
            conn.close()
            del active[conn]
            progress.step(paths[i])
    return results


def worst_status(statuses) -> int:
    """Worst exit status of a set: 0 < 3 < 1 < 2."""
    order = {0: 0, 3: 1, 1: 2, 2: 3}
    return max(statuses, key=lambda s: order[s], default=0)
