"""Compile generated C and call it from Python (tests and benchmarks).

`build_library` compiles `<stem>.c` with a small batch driver into a shared
library and wraps it with ctypes; `build_executable` compiles the same driver
as a program (used for the -fsanitize=address,undefined run, whose runtime
cannot be loaded into a Python process)."""
from __future__ import annotations

import ctypes
import os
import subprocess
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .c_backend import c_identifier

STRICT = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-Wdouble-promotion"]

DRIVER = r"""
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "{stem}.h"

void uwmr_batch(long n, const double *x, double *out, int *st)
{{
    long i;
    for (i = 0; i < n; ++i) {{
        const double *a = x + 8 * i;
        uwmr_{ident}_gains g;
        g.k1 = a[5];
        g.k2 = a[6];
        g.lam = a[7];
        st[i] = uwmr_{ident}_control(a[0], a[1], a[2], a[3], a[4], &g, out + 2 * i, out + 2 * i + 1);
    }}
}}

#ifndef UWMR_HARNESS_NO_F32
void uwmr_batch_f32(long n, const float *x, float *out, int *st)
{{
    long i;
    for (i = 0; i < n; ++i) {{
        const float *a = x + 8 * i;
        uwmr_{ident}_gains_f32 g;
        g.k1 = a[5];
        g.k2 = a[6];
        g.lam = a[7];
        st[i] = uwmr_{ident}_control_f32(a[0], a[1], a[2], a[3], a[4], &g, out + 2 * i, out + 2 * i + 1);
    }}
}}
#endif

/* Errors (7): rows of 6 (x, y, th, xr, yr, thr) -> 3 outputs and a status. */
void uwmr_batch_errors(long n, const double *x, double *out, int *st)
{{
    long i;
    for (i = 0; i < n; ++i) {{
        const double *a = x + 6 * i;
        st[i] = uwmr_{ident}_errors(a[0], a[1], a[2], a[3], a[4], a[5], out + 3 * i, out + 3 * i + 1, out + 3 * i + 2);
    }}
}}

#ifndef UWMR_HARNESS_NO_F32
void uwmr_batch_errors_f32(long n, const float *x, float *out, int *st)
{{
    long i;
    for (i = 0; i < n; ++i) {{
        const float *a = x + 6 * i;
        st[i] = uwmr_{ident}_errors_f32(a[0], a[1], a[2], a[3], a[4], a[5], out + 3 * i, out + 3 * i + 1, out + 3 * i + 2);
    }}
}}
#endif

/* One tracker (reset first) along a sequence of rows of 6 (pose, ref). */
void uwmr_batch_track(long n, const double *x, double *out, int *st)
{{
    long i;
    uwmr_{ident}_tracker s;
    uwmr_{ident}_reset(&s);
    for (i = 0; i < n; ++i) {{
        const double *a = x + 6 * i;
        uwmr_{ident}_pose p, r;
        p.x = a[0]; p.y = a[1]; p.th = a[2];
        r.x = a[3]; r.y = a[4]; r.th = a[5];
        st[i] = uwmr_{ident}_track(&s, &p, &r, out + 3 * i, out + 3 * i + 1, out + 3 * i + 2);
    }}
}}

#ifndef UWMR_HARNESS_NO_F32
void uwmr_batch_track_f32(long n, const float *x, float *out, int *st)
{{
    long i;
    uwmr_{ident}_tracker_f32 s;
    uwmr_{ident}_reset_f32(&s);
    for (i = 0; i < n; ++i) {{
        const float *a = x + 6 * i;
        uwmr_{ident}_pose_f32 p, r;
        p.x = a[0]; p.y = a[1]; p.th = a[2];
        r.x = a[3]; r.y = a[4]; r.th = a[5];
        st[i] = uwmr_{ident}_track_f32(&s, &p, &r, out + 3 * i, out + 3 * i + 1, out + 3 * i + 2);
    }}
}}
#endif

/* _step along a sequence (one tracker): rows of 11 (pose, ref, vr, wr, k1, k2, lam) -> v, w, status. */
void uwmr_batch_step(long n, const double *x, double *out, int *st)
{{
    long i;
    uwmr_{ident}_tracker s;
    uwmr_{ident}_reset(&s);
    for (i = 0; i < n; ++i) {{
        const double *a = x + 11 * i;
        uwmr_{ident}_pose p, r;
        uwmr_{ident}_gains g;
        p.x = a[0]; p.y = a[1]; p.th = a[2];
        r.x = a[3]; r.y = a[4]; r.th = a[5];
        g.k1 = a[8]; g.k2 = a[9]; g.lam = a[10];
        st[i] = uwmr_{ident}_step(&s, &p, &r, a[6], a[7], &g, out + 2 * i, out + 2 * i + 1);
    }}
}}

#ifdef UWMR_DRIVER_MAIN
/* driver d|f N IN OUT: N rows of 8 inputs from IN, 2 outputs + status to OUT;
   then the NULL-pointer calls, which must return nonzero. */
int main(int argc, char **argv)
{{
    long n;
    int f32, *st, rc = 0;
    size_t size;
    void *x, *out;
    FILE *fin, *fout;
    if (argc != 5) {{
        return 2;
    }}
    f32 = argv[1][0] == 'f';
#ifdef UWMR_HARNESS_NO_F32
    if (f32) {{
        return 2;
    }}
#endif
    n = atol(argv[2]);
    size = f32 ? sizeof(float) : sizeof(double);
    x = malloc((size_t)n * 8 * size);
    out = malloc((size_t)n * 2 * size);
    st = (int *)malloc((size_t)n * sizeof(int));
    fin = fopen(argv[3], "rb");
    if (!x || !out || !st || !fin || fread(x, size, (size_t)n * 8, fin) != (size_t)n * 8) {{
        return 2;
    }}
    fclose(fin);
#ifndef UWMR_HARNESS_NO_F32
    if (f32) {{
        uwmr_batch_f32(n, (const float *)x, (float *)out, st);
    }} else
#endif
    {{
        uwmr_batch(n, (const double *)x, (double *)out, st);
    }}
    fout = fopen(argv[4], "wb");
    if (!fout) {{
        return 2;
    }}
    fwrite(out, size, (size_t)n * 2, fout);
    fwrite(st, sizeof(int), (size_t)n, fout);
    fclose(fout);
    /* the error functions and the tracker on the same numbers (the first 6 of
       every row as a pose pair), for the sanitizers: nothing is compared */
#ifndef UWMR_HARNESS_NO_F32
    if (f32) {{
        float *e = (float *)malloc((size_t)n * 8 * sizeof(float));
        float *xs = (float *)malloc((size_t)n * 6 * sizeof(float));
        long i;
        for (i = 0; e && xs && i < n; ++i) {{
            memcpy(xs + 6 * i, (const float *)x + 8 * i, 6 * sizeof(float));
        }}
        if (e && xs) {{
            uwmr_batch_errors_f32(n, xs, e, st);
            uwmr_batch_track_f32(n, xs, e, st);
        }}
        free(e);
        free(xs);
    }} else
#endif
    {{
        double *e = (double *)malloc((size_t)n * 8 * sizeof(double));
        double *xs = (double *)malloc((size_t)n * 11 * sizeof(double));
        long i;
        for (i = 0; e && xs && i < n; ++i) {{
            memcpy(xs + 6 * i, (const double *)x + 8 * i, 6 * sizeof(double));
        }}
        if (e && xs) {{
            uwmr_batch_errors(n, xs, e, st);
            uwmr_batch_track(n, xs, e, st);
            for (i = 0; i < n; ++i) {{
                memcpy(xs + 11 * i, (const double *)x + 8 * i, 8 * sizeof(double));
                memcpy(xs + 11 * i + 8, (const double *)x + 8 * i + 5, 3 * sizeof(double));
            }}
            uwmr_batch_step(n, xs, e, st);
        }}
        free(e);
        free(xs);
    }}
    {{
        double v = 1.0, w = 1.0;
#ifndef UWMR_HARNESS_NO_F32
        float vf = 1.0F, wf = 1.0F;
#endif
        uwmr_{ident}_gains g = {{1.0, 1.0, 1.0}};
#ifndef UWMR_HARNESS_NO_F32
        uwmr_{ident}_gains_f32 gf = {{1.0F, 1.0F, 1.0F}};
#endif
        rc |= uwmr_{ident}_control(1.0, 1.0, 1.0, 1.0, 1.0, NULL, &v, &w) == 0 || v != 0.0 || w != 0.0;
        rc |= uwmr_{ident}_control(1.0, 1.0, 1.0, 1.0, 1.0, &g, NULL, &w) == 0 || w != 0.0;
        rc |= uwmr_{ident}_control(1.0, 1.0, 1.0, 1.0, 1.0, &g, &v, NULL) == 0 || v != 0.0;
#ifndef UWMR_HARNESS_NO_F32
        rc |= uwmr_{ident}_control_f32(1.0F, 1.0F, 1.0F, 1.0F, 1.0F, NULL, &vf, &wf) == 0 || vf != 0.0F;
        rc |= uwmr_{ident}_control_f32(1.0F, 1.0F, 1.0F, 1.0F, 1.0F, &gf, NULL, NULL) == 0;
#endif
        {{
            double e1 = 1.0, e2 = 1.0, e3 = 1.0;
            uwmr_{ident}_tracker s;
            uwmr_{ident}_pose p = {{1.0, 1.0, 1.0}};
            uwmr_{ident}_reset(&s);
            uwmr_{ident}_reset(NULL);
            rc |= uwmr_{ident}_errors(1.0, 1.0, 1.0, 1.0, 1.0, 1.0, NULL, &e2, &e3) != 1 || e2 != 0.0 || e3 != 0.0;
            rc |= uwmr_{ident}_track(NULL, &p, &p, &e1, &e2, &e3) != 1 || e1 != 0.0;
            rc |= uwmr_{ident}_track(&s, &p, NULL, &e1, &e2, &e3) != 1 || s.started;
            rc |= uwmr_{ident}_step(&s, &p, &p, 1.0, 1.0, NULL, &v, &w) != 1 || v != 0.0 || w != 0.0;
            rc |= uwmr_{ident}_step(&s, NULL, &p, 1.0, 1.0, &g, &v, NULL) != 1 || v != 0.0;
#ifndef UWMR_HARNESS_NO_F32
            rc |= uwmr_{ident}_step_f32(NULL, NULL, NULL, 1.0F, 1.0F, NULL, NULL, NULL) != 1;
#endif
        }}
    }}
    free(x);
    free(out);
    free(st);
    return rc ? 3 : 0;
}}
#endif
"""


def driver_source(stem: str) -> str:
    return DRIVER.format(stem=stem, ident=c_identifier(stem))


def has_float_variant(src_dir, stem: str) -> bool:
    """Whether the generated header declares the float (_f32) variant."""
    return f"uwmr_{c_identifier(stem)}_control_f32(" in (Path(src_dir) / f"{stem}.h").read_text()


def _compile(src_dir: Path, stem: str, out: Path, flags, cc="gcc"):
    driver = out.parent / f"{stem}_driver.c"
    driver.write_text(driver_source(stem))
    no_f32 = [] if has_float_variant(src_dir, stem) else ["-DUWMR_HARNESS_NO_F32"]
    cmd = [cc, *flags, *no_f32, "-I", str(src_dir), str(src_dir / f"{stem}.c"), str(driver), "-o", str(out), "-lm"]
    res = subprocess.run(cmd, capture_output=True, text=True)
    if res.returncode != 0:
        raise RuntimeError(f"compilation failed: {' '.join(cmd)}\n{res.stderr}")
    return res


@dataclass
class Compiled:
    lib: ctypes.CDLL
    ident: str
    path: Path

    def run(self, x: np.ndarray, f32=False):
        """(v, w, status) for rows of 8 inputs."""
        dt = np.float32 if f32 else np.float64
        x = np.ascontiguousarray(x, dtype=dt)
        n = len(x)
        out = np.zeros((n, 2), dtype=dt)
        st = np.zeros(n, dtype=np.int32)
        fn = self.lib.uwmr_batch_f32 if f32 else self.lib.uwmr_batch
        fn(ctypes.c_long(n), x.ctypes.data_as(ctypes.c_void_p), out.ctypes.data_as(ctypes.c_void_p),
           st.ctypes.data_as(ctypes.c_void_p))
        return out[:, 0], out[:, 1], st

    def _rows(self, name, x, width, n_out, f32):
        dt = np.float32 if f32 else np.float64
        x = np.ascontiguousarray(np.reshape(x, (-1, width)), dtype=dt)
        n = len(x)
        out = np.zeros((n, n_out), dtype=dt)
        st = np.zeros(n, dtype=np.int32)
        getattr(self.lib, name + ("_f32" if f32 else ""))(
            ctypes.c_long(n), x.ctypes.data_as(ctypes.c_void_p), out.ctypes.data_as(ctypes.c_void_p),
            st.ctypes.data_as(ctypes.c_void_p))
        return out, st

    def errors(self, x, f32=False):
        """(e1, e2, e3, status) of `_errors` for rows (x, y, th, xr, yr, thr)."""
        out, st = self._rows("uwmr_batch_errors", x, 6, 3, f32)
        return out[:, 0], out[:, 1], out[:, 2], st

    def track(self, x, f32=False):
        """(e1, e2, e3, status) of one tracker along the rows (x, y, th, xr, yr, thr)."""
        out, st = self._rows("uwmr_batch_track", x, 6, 3, f32)
        return out[:, 0], out[:, 1], out[:, 2], st

    def step(self, x):
        """(v, w, status) of `_step` (double) along rows (x, y, th, xr, yr, thr, vr, wr, k1, k2, lam)."""
        out, st = self._rows("uwmr_batch_step", x, 11, 2, False)
        return out[:, 0], out[:, 1], st

    def function(self, f32=False):
        return getattr(self.lib, f"uwmr_{self.ident}_control{'_f32' if f32 else ''}")


def build_library(src_dir, stem: str, work_dir, extra=("-O2",)) -> Compiled:
    """Compile with the strict flags into a shared library loaded by ctypes."""
    src_dir, work_dir = Path(src_dir), Path(work_dir)
    out = work_dir / f"lib{stem}.so"
    _compile(src_dir, stem, out, [*STRICT, *extra, "-fPIC", "-shared"])
    lib = ctypes.CDLL(str(out))
    f32 = has_float_variant(src_dir, stem)
    for name in ("uwmr_batch", "uwmr_batch_f32", "uwmr_batch_errors", "uwmr_batch_errors_f32", "uwmr_batch_track",
                 "uwmr_batch_track_f32", "uwmr_batch_step"):
        if f32 or not name.endswith("_f32"):
            getattr(lib, name).restype = None
    return Compiled(lib, c_identifier(stem), out)


def build_executable(src_dir, stem: str, work_dir, extra=()) -> Path:
    src_dir, work_dir = Path(src_dir), Path(work_dir)
    out = work_dir / f"{stem}_driver"
    _compile(src_dir, stem, out, [*STRICT, *extra, "-DUWMR_DRIVER_MAIN"])
    return out


def run_executable(exe: Path, x: np.ndarray, work_dir, f32=False, env=None):
    """(v, w, status, completed process) from the driver program."""
    dt = np.float32 if f32 else np.float64
    x = np.ascontiguousarray(x, dtype=dt)
    work_dir = Path(work_dir)
    fin, fout = work_dir / "in.bin", work_dir / "out.bin"
    x.tofile(fin)
    res = subprocess.run([str(exe), "f" if f32 else "d", str(len(x)), str(fin), str(fout)],
                         capture_output=True, text=True, env={**os.environ, **(env or {})})
    if res.returncode != 0:
        return None, None, None, res
    raw = fout.read_bytes()
    n = len(x)
    size = np.dtype(dt).itemsize
    out = np.frombuffer(raw[:n * 2 * size], dtype=dt).reshape(n, 2)
    st = np.frombuffer(raw[n * 2 * size:], dtype=np.int32)
    return out[:, 0], out[:, 1], st, res
