"""Writing a report file (a certificate, JUnit XML) whole or not at all."""
from __future__ import annotations

import contextlib
import os
from pathlib import Path


def write_text_atomic(path, text: str) -> None:
    """Write `text` to `path` (UTF-8) as one piece: into a temporary file
    beside the target, then renamed over it, so a full disk or an
    interruption leaves the old file (or none) and no temporary file.  A
    symbolic link is written through (its target is replaced); a FIFO or a
    device is written to directly (renaming over it would replace it with a
    plain file).  Raises OSError, naming the target."""
    path = Path(path)
    if path.is_symlink():
        path = path.resolve()
    if path.is_dir():
        raise IsADirectoryError(21, "is a folder; name a file", str(path))
    if path.exists() and not path.is_file():        # /dev/stdout, a FIFO: no rename
        with open(path, "w", encoding="utf-8") as fh:
            fh.write(text)
        return
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    try:
        with open(tmp, "x", encoding="utf-8") as fh:
            fh.write(text)
        os.replace(tmp, path)
    except BaseException:
        with contextlib.suppress(OSError):
            tmp.unlink()
        raise
