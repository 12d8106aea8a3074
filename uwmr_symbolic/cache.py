"""Result cache: a verified design's result (the dict of `report.to_dict`),
stored as JSON and found again by what the result depends on.

The key holds the canonical form of what is verified — ``sympy.srepr`` of f
with the parameters substituted, the parameter values and the gain scenarios
(exact SymPy numbers, also as ``srepr``) — together with the tool's version, a
hash of the verifier's own source files (see `source_hash`) and the versions of SymPy,
python-flint, mpmath and Python.  Editing the verifier, upgrading a
dependency or changing f, a parameter or a gain therefore never reuses an old
result.  The file name, the design's ``name`` and the line numbers are not
part of the key: they are filled in from the file being checked.

Entries live in ``$UWMR_CACHE_DIR``, else ``$XDG_CACHE_HOME/uwmr-symbolic``,
else ``~/.cache/uwmr-symbolic``; one file ``<sha256 of the key>.json`` each,
written to a temporary file and renamed into place (atomic), so a reader sees
either nothing or a whole entry.  An entry that does not parse, or whose
stored key differs from the one asked for, is treated as missing.

The ``--timeout`` is not part of the key but of the entry, with whether a time
limit expired while the result was computed (``timed_out``).  Time matters
only there: the verdicts depend on the time given only through limits that
expire (the kernel proposer's budget counts work, not time, and never changes
a verdict), so a result in which none expired is what any timeout
gives and is served to every run, while one in which a limit expired (some
verdict may be "unknown" for lack of time) is served only to a run with no
more time than it had (`serves`); a run with more time verifies again and
replaces the entry.

A hit touches its entry; after each write the least recently used entries
beyond `MAX_ENTRIES` are deleted, so results of old verifier versions do not
pile up."""
from __future__ import annotations

import hashlib
import json
import os
import re
import sys
import tempfile
from functools import lru_cache
from pathlib import Path

import sympy as sp

from . import __version__

#: Bump when the layout of an entry changes.
CACHE_FORMAT = 2
#: Entries kept (least recently used ones beyond this are evicted).
MAX_ENTRIES = 2000
_ENTRY_NAME = re.compile(r"[0-9a-f]{64}\.json")
PACKAGE_DIR = Path(__file__).resolve().parent


def default_dir() -> Path:
    env = os.environ.get("UWMR_CACHE_DIR")
    if env:
        return Path(env).expanduser()
    xdg = os.environ.get("XDG_CACHE_HOME")
    base = Path(xdg).expanduser() if xdg else Path.home() / ".cache"
    return base / "uwmr-symbolic"


@lru_cache(maxsize=1)
def source_hash() -> str:
    """sha256 over the verifier's Python sources: every top-level module of
    the package, and every module of a subpackage that has been imported by
    now (the verifier is imported before the first key is made).  Subpackages
    the verifier does not use, such as the code generator, are left out, so
    editing them keeps the cache."""
    from . import verify  # noqa: F401  (make sure the verifier's modules are loaded)
    files = set(PACKAGE_DIR.glob("*.py"))
    for name, module in list(sys.modules.items()):
        file = getattr(module, "__file__", None)
        if (name == "uwmr_symbolic" or name.startswith("uwmr_symbolic.")) and file and file.endswith(".py"):
            path = Path(file).resolve()
            if PACKAGE_DIR in path.parents:
                files.add(path)
    h = hashlib.sha256()
    for path in sorted(files):
        rel = path.relative_to(PACKAGE_DIR).as_posix()
        h.update(rel.encode() + b"\0")
        h.update(path.read_bytes())
        h.update(b"\0")
    return h.hexdigest()


@lru_cache(maxsize=1)
def _dependency_versions() -> dict:
    from importlib.metadata import PackageNotFoundError, version
    out = {"python": ".".join(map(str, sys.version_info[:3]))}
    for dist in ("sympy", "python-flint", "mpmath"):
        try:
            out[dist] = version(dist)
        except PackageNotFoundError:
            out[dist] = None
    return out


def design_key(design) -> dict:
    """Everything a verification result depends on, as JSON-able data."""
    return {
        "format": CACHE_FORMAT,
        "tool": __version__,
        "source": source_hash(),
        "deps": _dependency_versions(),
        "f": sp.srepr(design.f),
        "params": {name: sp.srepr(v) for name, v in sorted(design.params.items())},
        "gains": {scen: {k: sp.srepr(v) for k, v in sorted(vals.items())}
                  for scen, vals in sorted(design.gains.items())},
    }


def serves(entry: dict, timeout: float | None) -> bool:
    """Whether a stored entry answers a run with `timeout` (seconds; None:
    a run whose timeout is not known): always when no time limit expired
    while its result was computed, else only when the entry's run had at
    least `timeout` seconds."""
    if entry.get("timed_out") is False:
        return True
    had = entry.get("timeout")
    return (entry.get("timed_out") is True and timeout is not None and type(had) in (int, float)
            and had >= timeout)


def digest(key: dict) -> str:
    return hashlib.sha256(json.dumps(key, sort_keys=True, separators=(",", ":")).encode()).hexdigest()


class ResultCache:
    def __init__(self, directory: Path | str | None = None, max_entries: int = MAX_ENTRIES):
        self.directory = Path(directory) if directory is not None else default_dir()
        self.max_entries = max_entries

    def unwritable(self) -> str | None:
        """Why results cannot be stored in the folder (None: they can)."""
        try:
            self.directory.mkdir(parents=True, exist_ok=True)
            with tempfile.TemporaryFile(dir=self.directory):
                return None
        except OSError as exc:
            return exc.strerror or str(exc)

    def path_for(self, key: dict) -> Path:
        return self.directory / f"{digest(key)}.json"

    def get(self, key: dict, timeout: float | None = None) -> dict | None:
        """The stored result for `key`, or None (missing, unreadable, corrupt,
        or computed with less time than `timeout` while a time limit expired:
        see `serves`)."""
        path = self.path_for(key)
        if not path.is_file():      # (missing; a FIFO would block the read)
            return None
        try:
            entry = json.loads(path.read_text())
        except (OSError, UnicodeDecodeError, ValueError, RecursionError):      # (a nested edit: red team 19)
            return None
        if not isinstance(entry, dict) or entry.get("key") != key or not isinstance(entry.get("result"), dict) \
                or not serves(entry, timeout):
            return None
        try:
            os.utime(path)      # recently used: evicted last
        except OSError:
            pass
        return entry["result"]

    def evict(self) -> int:
        """Delete the least recently used entries beyond `max_entries`; how many.
        Only the cache's own entries (named by a sha256, `path_for`): a folder
        given as the cache may hold other files (red team 28: a user's
        data1.json was deleted)."""
        try:
            entries = sorted((p for p in self.directory.glob("*.json") if _ENTRY_NAME.fullmatch(p.name)),
                             key=lambda p: p.stat().st_mtime_ns, reverse=True)
        except OSError:
            return 0
        removed = 0
        for path in entries[self.max_entries:]:
            try:
                path.unlink()
                removed += 1
            except OSError:
                pass
        return removed

    def put(self, key: dict, result: dict, timeout: float | None = None, timed_out: bool = False) -> bool:
        """Store atomically (replacing an entry of the same key), with the
        run's `timeout` and whether a time limit expired in it; False (and
        no exception) when the cache is not writable."""
        target = self.path_for(key)
        tmp = None
        try:
            self.directory.mkdir(parents=True, exist_ok=True)
            fd, tmp = tempfile.mkstemp(dir=self.directory, prefix=".tmp-", suffix=".json")
            with os.fdopen(fd, "w") as fh:
                json.dump({"key": key, "timeout": timeout, "timed_out": bool(timed_out), "result": result},
                          fh, indent=1)  # key order kept: output order
                fh.flush()
                os.fsync(fh.fileno())
            os.replace(tmp, target)
            self.evict()
            return True
        except OSError:
            if tmp is not None:
                try:
                    os.unlink(tmp)
                except OSError:
                    pass
            return False
