"""Embedded check: the float variant of every generated controller compiles
for a Cortex-M4F and needs no double-precision code.

    python -m uwmr_symbolic.codegen.embedded [DIR ...]      (default: generated/*/)

Compiles `<stem>.c` with -DUWMR_NO_DOUBLE (the float variant alone) using
Debian's arm-none-eabi-gcc and the flags below, lists the object's undefined
symbols with arm-none-eabi-nm -u and fails on any double-precision one (a
double libm function or an EABI/libgcc double helper), and prints the .text
size.  Then it builds the example loop `example_main.c` with the float
variant (-DUWMR_NO_DOUBLE) and links it against newlib with
--specs=nosys.specs (and once more with newlib-nano, --specs=nano.specs):
flash = text + data, static RAM = data + bss (arm-none-eabi-size), and the
stack from -fstack-usage: the sum of the frames of main and of every
function of <stem>.c, an upper bound of any call chain through them (none
is recursive); the frames of libm and libc (printf) are not counted.
`make embedded` installs the toolchain when it is missing."""
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


SPECS = {"newlib": ["--specs=nosys.specs"], "newlib-nano": ["--specs=nano.specs", "--specs=nosys.specs"]}


def example(src_dir: Path, work: Path) -> dict:
    """Flash, static RAM and stack [bytes] of the example loop for the
    Cortex-M4F (see the module doc): {"newlib": (flash, ram), "newlib-nano":
    (flash, ram), "stack": bytes, "frames": {function: bytes}}."""
    stem = src_dir.name
    objs = []
    for name in (f"{stem}.c", "example_main.c"):
        obj = work / (Path(name).stem + ".o")
        subprocess.run([CC, *FLAGS, "-fstack-usage", "-ffunction-sections", "-fdata-sections", "-c",
                        str(src_dir / name), "-o", str(obj)], check=True, capture_output=True, text=True)
        objs.append(obj)
    frames = {}
    for su in (work / f"{stem}.su", work / "example_main.su"):
        for line in su.read_text().splitlines():
            where, size, _kind = line.rsplit("\t", 2)
            fn = where.rsplit(":", 1)[-1]
            if su.stem == stem or fn == "main":
                frames[fn] = frames.get(fn, 0) + int(size)
    out = {"stack": sum(frames.values()), "frames": frames}
    for label, specs in SPECS.items():
        elf = work / f"{stem}_{label}.elf"
        subprocess.run([CC, *FLAGS, *specs, "-Wl,--gc-sections", *map(str, objs), "-lm", "-o", str(elf)],
                       check=True, capture_output=True, text=True)
        text, data, bss = (int(v) for v in subprocess.run([SIZE, "-B", str(elf)], check=True, capture_output=True,
                                                           text=True).stdout.splitlines()[1].split()[:3])
        out[label] = (text + data, data + bss)
    return out


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
            if not (d / "example_main.c").exists():
                continue
            try:
                ex = example(d, Path(tmp))
            except subprocess.CalledProcessError as exc:
                print(f"{d.name}: the example loop does not build or link\n{exc.stderr}", file=sys.stderr)
                status = 1
                continue
            sizes = "; ".join(f"{k}: flash {ex[k][0]} B, static RAM {ex[k][1]} B" for k in SPECS)
            print(f"{d.name}: example loop (float variant, --specs=nosys.specs) {sizes}; "
                  f"stack <= {ex['stack']} B (main + {d.name}.c, -fstack-usage; libm/libc not counted)")
    return status


if __name__ == "__main__":
    sys.exit(main())
