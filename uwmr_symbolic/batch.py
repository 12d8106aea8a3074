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
import multiprocessing.connection
from pathlib import Path

import sympy as sp

from . import design_certificate as certificates
from .cache import ResultCache, design_key, source_hash
from .report import design_fields, to_dict
from .properties import PROPERTIES
from .verdict import unknown
from .verify import Report, kernel_summary, load_with_limit, verify_loaded

GLOB_CHARS = set("*?[")


def expand_paths(args: list[str]) -> list[str]:
    """Files from the command line: a glob (when the shell did not expand it)
    becomes the files it matches, a directory its ``*.py`` files; anything
    else is kept as given (a missing file is reported by the loader).
    Duplicates are dropped, the order is kept."""
    out: list[str] = []
    for arg in args:
        if os.path.isdir(arg):
            out.extend(sorted(str(p) for p in Path(arg).glob("*.py")))
        elif not os.path.exists(arg) and GLOB_CHARS & set(arg):
            matches = sorted(p for p in glob.glob(arg, recursive=True) if os.path.isfile(p))
            out.extend(matches or [arg])
        else:
            out.append(arg)
    return list(dict.fromkeys(out))


def check_file(path: str, timeout: float, cache_dir: str | None, use_cache: bool = True,
               kernel_only: bool = True) -> dict:
    """Verify one file, or serve its result from the cache."""
    start = time.monotonic()
    loaded = load_with_limit(path, timeout, start)
    if isinstance(loaded, Report):          # unusable, or loading timed out
        return {**to_dict(loaded), "cached": False} if loaded.error is None else to_dict(loaded)
    design = loaded
    cache = ResultCache(cache_dir) if use_cache else None
    key = (design_key(design) | ({} if kernel_only else {"trust_search": True})) if use_cache else None
    if cache is not None:
        hit = cache.get(key, timeout)     # not if computed with less time while a limit expired
        if hit is not None and isinstance(hit.get("exit_status"), int) and rechecks(hit, design, kernel_only):
            return {**hit, **design_fields(design), "cached": True}
    report = verify_loaded(design, timeout, start, kernel_only)
    result = {**to_dict(report), "certificate": report.certificate}
    if cache is not None and report.certificate is not None and not {"error", "stopped"} & set(report.kernel):
        cache.put(key, result, timeout=timeout, timed_out=report.timed_out)
    return {**result, "cached": False}


def rechecks(hit: dict, design, kernel_only: bool = True) -> bool:
    """A cached result is used only if its design certificate re-checks in
    the kernel, is about this design's f, and agrees with the cached verdicts
    (each the certificate's, or, with `kernel_only`, unknown where the kernel
    did not check it)."""
    cert = hit.get("certificate")
    try:
        kernel = kernel_summary(certificates.check(cert))
    except certificates.CertificateError:
        return False
    verdicts = {p: str(v.get("verdict")) for p, v in hit.get("properties", {}).items()}
    statuses = {p: e.get("status") for p, e in cert["properties"].items() if p in PROPERTIES}
    expected = {p: "unknown" if kernel_only and p in kernel["search"] else s for p, s in statuses.items()}
    return cert["design"]["f"] == sp.srepr(design.f) and hit.get("kernel") == kernel and verdicts == expected


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


def _child(conn, path, timeout, cache_dir, use_cache, kernel_only):
    try:
        result = check_file(path, timeout, cache_dir, use_cache, kernel_only)
    except Exception as exc:  # noqa: BLE001 - a verifier bug must not hide the other files
        result = _internal_error(path, exc)
    conn.send(result)
    conn.close()


def check_files(paths: list[str], timeout: float, use_cache: bool = True, jobs: int | None = None,
                cache_dir: str | None = None, progress: Progress | None = None,
                kernel_only: bool = True) -> list[dict]:
    """Results for `paths`, in order.  Each file is checked in a process of
    its own (forked: SymPy and the verifier are already imported), at most
    `jobs` at a time; a process that outlives `hard_limit(timeout)` is killed
    and its file reported as timed out, one that dies is reported unusable."""
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
            proc = ctx.Process(target=_child, args=(send, paths[i], timeout, cache_dir, use_cache, kernel_only))
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
