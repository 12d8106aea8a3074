"""Project settings from ``[tool.uwmr-symbolic]`` in a ``pyproject.toml``.

Read the way ruff reads ``[tool.ruff]``: starting in the current directory and
walking up to the filesystem root, the first ``pyproject.toml`` that has a
``[tool.uwmr-symbolic]`` table is used (a ``pyproject.toml`` without one is
passed over).  Command-line flags override every setting.  Example::

    [tool.uwmr-symbolic]
    timeout = 120                  # seconds per design (--timeout)
    jobs = 2                       # worker processes (--jobs)
    designs = ["designs/*.py"]     # checked when no FILE is given
    cache-dir = ".uwmr-cache"      # result cache (--cache-dir)

Relative paths in ``designs`` and ``cache-dir`` are taken from the folder of
that ``pyproject.toml``, not from the current directory.  For the cache the
order is ``--cache-dir``, then ``$UWMR_CACHE_DIR``, then ``cache-dir``, then
``~/.cache/uwmr-symbolic``.  An unknown key, a value of the wrong type or a
file that is not valid TOML is a `SettingsError` (the command prints its one
line and exits 2).
"""
from __future__ import annotations

import os
import sys
from dataclasses import dataclass, field
from pathlib import Path

if sys.version_info >= (3, 11):
    import tomllib
else:                                   # pragma: no cover - Python 3.10
    import tomli as tomllib

TABLE = "uwmr-symbolic"
KNOWN_KEYS = ("cache-dir", "designs", "jobs", "timeout")
#: the largest --timeout: the workers' waits take whole milliseconds in a C int (about 24 days)
MAX_TIMEOUT = 1e6


class SettingsError(Exception):
    """A ``[tool.uwmr-symbolic]`` table that cannot be used; the message is one
    line naming the file, the key and the problem."""


@dataclass
class Settings:
    """The settings in force; ``source`` is the ``pyproject.toml`` they came
    from (None: no file, every field at its default)."""
    timeout: float | None = None
    jobs: int | None = None
    designs: list[str] = field(default_factory=list)
    cache_dir: str | None = None
    source: Path | None = None


def find_pyproject(start: Path | str | None = None) -> Path | None:
    """The nearest ``pyproject.toml`` at or above `start` (default: the current
    directory) with a ``[tool.uwmr-symbolic]`` table, or None."""
    here = Path(start if start is not None else os.getcwd()).resolve()
    for folder in (here, *here.parents):
        candidate = folder / "pyproject.toml"
        if candidate.is_file() and _table(candidate) is not None:
            return candidate
    return None


def _table(path: Path) -> dict | None:
    try:
        with open(path, "rb") as fh:
            data = tomllib.load(fh)
    except OSError as exc:
        raise SettingsError(f"{path}: cannot read: {exc.strerror or exc}") from None
    except tomllib.TOMLDecodeError as exc:
        raise SettingsError(f"{path}: not valid TOML: {exc}") from None
    except UnicodeDecodeError as exc:
        raise SettingsError(f"{path}: not valid TOML: not UTF-8 text ({exc.reason} at byte {exc.start}); "
                            f"save it as UTF-8") from None
    table = data.get("tool", {}).get(TABLE) if isinstance(data.get("tool"), dict) else None
    if table is not None and not isinstance(table, dict):
        raise SettingsError(f"{path}: tool.{TABLE} must be a table")
    return table


def load(start: Path | str | None = None) -> Settings:
    """The settings for a command run in `start` (default: the current directory)."""
    path = find_pyproject(start)
    if path is None:
        return Settings()
    table = _table(path)
    where = f"{path}: [tool.{TABLE}]"
    unknown = sorted(set(table) - set(KNOWN_KEYS))
    if unknown:
        raise SettingsError(f"{where} unknown setting {unknown[0]!r} (known: {', '.join(KNOWN_KEYS)})")
    out = Settings(source=path)
    base = path.parent
    if "timeout" in table:
        value = table["timeout"]
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not 0 < value <= MAX_TIMEOUT:
            raise SettingsError(f"{where} timeout must be a number of seconds above 0 and at most "
                                f"{MAX_TIMEOUT:g}, not {value!r}")
        out.timeout = float(value)
    if "jobs" in table:
        value = table["jobs"]
        if isinstance(value, bool) or not isinstance(value, int) or value < 1:
            raise SettingsError(f"{where} jobs must be an integer of at least 1, not {value!r}")
        out.jobs = value
    if "designs" in table:
        value = table["designs"]
        if isinstance(value, str):
            value = [value]
        if not isinstance(value, list) or not value or not all(isinstance(v, str) and v for v in value):
            raise SettingsError(f"{where} designs must be a list of glob patterns, not {value!r}")
        out.designs = [v if os.path.isabs(v) else str(base / v) for v in value]
    if "cache-dir" in table:
        value = table["cache-dir"]
        if not isinstance(value, str) or not value:
            raise SettingsError(f"{where} cache-dir must be a folder name, not {value!r}")
        out.cache_dir = _folder(value, f"{where} cache-dir", relative_to=base)
    return out


def _folder(value: str, what: str, relative_to=None) -> str:
    """A folder's absolute path, ~ expanded (the same folder whatever the
    working directory is when it is used: a design file may chdir)."""
    try:
        folder = Path(value).expanduser()
    except RuntimeError as exc:         # ~someone who does not exist, or no home folder
        raise SettingsError(f"{what} {value!r}: {str(exc).rstrip('.')}; give the folder's full path") from None
    return os.path.abspath(folder if folder.is_absolute() or relative_to is None else relative_to / folder)


def apply(args, default_timeout: float) -> Settings:
    """Fill the options of parsed `uwmr-verify` arguments that the command line
    left unset (None) from the settings: ``timeout``, ``jobs``, ``cache_dir``
    and, when no FILE was given, ``files`` from ``designs``."""
    settings = load()
    if args.timeout is None:
        args.timeout = settings.timeout if settings.timeout is not None else default_timeout
    if args.jobs is None:
        args.jobs = settings.jobs
    if args.cache_dir is None:
        env = os.environ.get("UWMR_CACHE_DIR")
        args.cache_dir = _folder(env, "$UWMR_CACHE_DIR") if env else settings.cache_dir
    elif args.cache_dir:
        args.cache_dir = _folder(args.cache_dir, "--cache-dir")
    if args.cache_dir is None and not getattr(args, "no_cache", False):
        from .cache import default_dir
        try:
            args.cache_dir = str(default_dir())
        except RuntimeError as exc:     # $XDG_CACHE_HOME of ~nobody, or no home folder (red team 28)
            raise SettingsError(f"no cache folder: {str(exc).rstrip('.')}; set --cache-dir, $UWMR_CACHE_DIR or "
                                f"--no-cache") from None
    if not args.files and settings.designs and not getattr(args, "check_certificate", None):
        args.files = list(settings.designs)     # (--check-certificate takes no design file: red team 28)
    return settings
