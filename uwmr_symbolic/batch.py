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
from concurrent.futures import ProcessPoolExecutor, as_completed
from concurrent.futures.process import BrokenProcessPool
from pathlib import Path

from .cache import ResultCache, design_key, source_hash
from .report import design_fields, to_dict
from .verify import Report, load_with_limit, verify_loaded

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


def check_file(path: str, timeout: float, cache_dir: str | None, use_cache: bool = True) -> dict:
    """Verify one file, or serve its result from the cache."""
    start = time.monotonic()
    loaded = load_with_limit(path, timeout, start)
    if isinstance(loaded, Report):          # unusable, or loading timed out
        return {**to_dict(loaded), "cached": False} if loaded.error is None else to_dict(loaded)
    design = loaded
    cache = ResultCache(cache_dir) if use_cache else None
    key = design_key(design) if use_cache else None
    if cache is not None:
        hit = cache.get(key)
        if hit is not None and isinstance(hit.get("exit_status"), int):
            return {**hit, **design_fields(design), "cached": True}
    report = verify_loaded(design, timeout, start)
    result = to_dict(report)
    if cache is not None and not report.timed_out:
        cache.put(key, result)
    return {**result, "cached": False}


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


def _pool(workers: int) -> ProcessPoolExecutor:
    methods = multiprocessing.get_all_start_methods()
    # fork: the workers start with SymPy and the verifier already imported
    ctx = multiprocessing.get_context("fork" if "fork" in methods else "spawn")
    return ProcessPoolExecutor(max_workers=workers, mp_context=ctx)


def check_files(paths: list[str], timeout: float, use_cache: bool = True, jobs: int | None = None,
                cache_dir: str | None = None, progress: Progress | None = None) -> list[dict]:
    """Results for `paths`, in order.  One file (or jobs=1) runs in this
    process; more run in min(jobs, files) worker processes."""
    jobs = jobs or os.cpu_count() or 1
    cache_dir = str(ResultCache(cache_dir).directory) if use_cache else None
    progress = progress or Progress(0)
    results: list[dict | None] = [None] * len(paths)
    if use_cache:
        source_hash()      # computed once, inherited by forked workers
    if len(paths) <= 1 or jobs <= 1:
        for i, p in enumerate(paths):
            try:
                results[i] = check_file(p, timeout, cache_dir, use_cache)
            except Exception as exc:  # noqa: BLE001 - a verifier bug must not hide the other files
                results[i] = _internal_error(p, exc)
            progress.step(p)
        return results
    pending = list(range(len(paths)))
    with _pool(min(jobs, len(paths))) as pool:
        futures = {pool.submit(check_file, paths[i], timeout, cache_dir, use_cache): i for i in pending}
        broken = []
        for fut in as_completed(futures):
            i = futures[fut]
            try:
                results[i] = fut.result()
            except BrokenProcessPool:
                broken.append(i)
                continue
            except Exception as exc:  # noqa: BLE001
                results[i] = _internal_error(paths[i], exc)
            progress.step(paths[i])
    # A worker died (a design file that kills its process takes the pool with
    # it): check those files again one at a time, each in its own process, so
    # that only the culprit is reported.
    for i in sorted(broken):
        with _pool(1) as pool:
            try:
                results[i] = pool.submit(check_file, paths[i], timeout, cache_dir, use_cache).result()
            except BrokenProcessPool:
                results[i] = {"design": paths[i], "error": "the process checking this file died "
                                                           "(does the file call os._exit or crash Python?)",
                              "exit_status": 2}
            except Exception as exc:  # noqa: BLE001
                results[i] = _internal_error(paths[i], exc)
        progress.step(paths[i])
    return results


def worst_status(statuses) -> int:
    """Worst exit status of a set: 0 < 3 < 1 < 2."""
    order = {0: 0, 3: 1, 1: 2, 2: 3}
    return max(statuses, key=lambda s: order[s], default=0)
