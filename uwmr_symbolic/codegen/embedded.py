"""Embedded check: the float variant of every generated controller compiles
for a Cortex-M4F and needs no double-precision code.

    python -m uwmr_symbolic.codegen.embedded [DIR ...]      (default: generated/*/)

Compiles `<stem>.c` with -DUWMR_NO_DOUBLE (the float variant alone) using
Debian's arm-none-eabi-gcc and the flags below, lists the object's undefined
symbols with arm-none-eabi-nm -u and fails on any double-precision one (a
double libm function or an EABI/libgcc double helper), and prints the .text
size.  `make embedded` installs the toolchain when it is missing."""
from __future__ import annotations

import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

CC, NM, SIZE = "arm-none-eabi-gcc", "arm-none-eabi-nm", "arm-none-eabi-size"
FLAGS = ["-mcpu=cortex-m4", "-mthumb", "-mfloat-abi=hard", "-mfpu=fpv4-sp-d16", "-O2",
         "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-Wdouble-promotion", "-DUWMR_NO_DOUBLE"]
DOUBLE_LIBM = {"sin", "cos", "tan", "tanh", "sinh", "cosh", "sqrt", "exp", "expm1", "log", "log1p", "pow",
               "atan", "atan2", "asin", "acos", "asinh", "acosh", "atanh", "fabs", "frexp", "ldexp",
               "scalbn", "hypot", "fmod", "floor", "ceil", "round"}
DOUBLE_HELPER = re.compile(r"^__aeabi_(d\w*|[fil]2d|ui2d|ul2d)$|^__\w*df\d$|^__(extend|trunc)\w*df\w*$")


def available() -> bool:
    return all(shutil.which(t) for t in (CC, NM, SIZE))


def check(src_dir: Path, work: Path) -> tuple[int, list[str]]:
    """(.text size in bytes, forbidden undefined symbols) for one generated dir."""
    stem = src_dir.name
    obj = work / f"{stem}.o"
    subprocess.run([CC, *FLAGS, "-c", str(src_dir / f"{stem}.c"), "-o", str(obj)],
                   check=True, capture_output=True, text=True)
    undefined = subprocess.run([NM, "-u", str(obj)], check=True, capture_output=True, text=True).stdout.split()
    names = [u for u in undefined if u not in ("U", "w")]
    bad = [u for u in names if u in DOUBLE_LIBM or DOUBLE_HELPER.match(u)]
    size_out = subprocess.run([SIZE, "-A", str(obj)], check=True, capture_output=True, text=True).stdout
    text = sum(int(line.split()[1]) for line in size_out.splitlines() if line.startswith(".text"))
    return text, bad


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    dirs = [Path(a) for a in argv] or sorted(p for p in Path("generated").iterdir() if p.is_dir())
    if not available():
        print(f"{CC} not found: run `make embedded` (installs gcc-arm-none-eabi and libnewlib-arm-none-eabi)",
              file=sys.stderr)
        return 2
    status = 0
    with tempfile.TemporaryDirectory() as tmp:
        for d in dirs:
            try:
                text, bad = check(d, Path(tmp))
            except subprocess.CalledProcessError as exc:
                print(f"{d.name}: compilation failed\n{exc.stderr}", file=sys.stderr)
                status = 1
                continue
            verdict = "ok, no double-precision symbol" if not bad else "DOUBLE SYMBOLS: " + " ".join(bad)
            print(f"{d.name}: Cortex-M4F float variant .text = {text} bytes; {verdict}")
            status |= bool(bad)
    return status


if __name__ == "__main__":
    sys.exit(main())
