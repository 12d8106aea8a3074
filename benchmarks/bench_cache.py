"""`make bench` (second part): wall time of `uwmr-verify designs/*.py` cold and
served from the result cache.

Each figure is the median of three runs of the whole command in a fresh
process (interpreter start and imports included: what CI waits for):

* cold, one worker    -- empty cache, `--jobs 1`
* cold, parallel      -- empty cache, one worker per core (the default)
* cached              -- the same command again, every result from the cache

and, in one process after import, the cost per design of a cache hit
(executing the design file, canonical key, reading the entry)."""
from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CHILD = """
import json, sys, time
from uwmr_symbolic.batch import check_file
out = {}
for path in sys.argv[2:]:
    t = time.perf_counter(); d = check_file(path, 60.0, sys.argv[1], True); dt = time.perf_counter() - t
    out[path] = {"seconds": dt, "cached": d.get("cached")}
print(json.dumps(out))
"""


def _run(files, cache_dir, extra=()) -> tuple[float, list]:
    env = {**os.environ, "UWMR_CACHE_DIR": str(cache_dir)}
    t = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "uwmr_symbolic.cli", *files, "--format", "json", *extra],
                          cwd=ROOT, env=env, capture_output=True, text=True)
    dt = time.perf_counter() - t
    if proc.returncode not in (0, 1, 3):
        sys.exit(f"uwmr-verify failed ({proc.returncode}):\n{proc.stderr}")
    return dt, json.loads(proc.stdout)


def main() -> int:
    files = [str(p.relative_to(ROOT)) for p in sorted((ROOT / "designs").glob("*.py"))]
    cold1, cold, warm = [], [], []
    with tempfile.TemporaryDirectory(prefix="uwmr-bench-cache-") as tmp:
        for i in range(3):
            cold1.append(_run(files, Path(tmp) / f"seq{i}", ["--jobs", "1"])[0])
            cache_dir = Path(tmp) / f"par{i}"
            dt, results = _run(files, cache_dir)
            assert not any(d["cached"] for d in results)
            cold.append(dt)
            dt, results = _run(files, cache_dir)
            assert all(d["cached"] for d in results), "second run not served from the cache"
            warm.append(dt)
        hits = json.loads(subprocess.run([sys.executable, "-c", CHILD, str(cache_dir), *files], cwd=ROOT,
                                         capture_output=True, text=True, check=True).stdout)
    c1, c, w = (statistics.median(x) for x in (cold1, cold, warm))
    print(f"uwmr-verify designs/*.py ({len(files)} designs, {os.cpu_count()} cores), median of 3, wall time:")
    print(f"  cold, --jobs 1          {c1:7.3f} s")
    print(f"  cold, parallel          {c:7.3f} s")
    print(f"  cached                  {w:7.3f} s   ({c / w:.1f}x faster than cold parallel, "
          f"{c1 / w:.1f}x than cold --jobs 1)")
    print("cache hit per design, in process after import (load the file + key + read the entry):")
    for path, h in hits.items():
        assert h["cached"], path
        print(f"  {Path(path).name:<28} {1000 * h['seconds']:7.1f} ms")
    print(f"  {'all of designs/':<28} {1000 * sum(h['seconds'] for h in hits.values()):7.1f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
