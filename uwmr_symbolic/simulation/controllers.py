"""The generated controllers, loaded for simulation.

Both back-ends of the code generator drive the loop: the Python module
`<stem>.py` (imported from its file) and the C99 source `<stem>.c`, compiled
with `codegen.harness.build_library` (gcc, the generator's strict flags, -O2)
into a shared library called through ctypes.  The SymPy formula is never
used to compute a command, and the errors (7) that the loop feeds the law
come from the same generated code (`Backend.errors`): what is simulated is
what is deployed.

By default the files are generated afresh from the design file into a
private temporary directory (`codegen.generate(..., force=True)`), so they
always match the design as it is now; `generated_dir` uses an existing
directory such as `generated/<stem>/` instead."""
from __future__ import annotations

import atexit
import ctypes
import importlib.util
import shutil
import tempfile
import types
from dataclasses import dataclass
from pathlib import Path

import numpy as np

_TMP: list[str] = []


def _tmpdir(prefix: str) -> Path:
    d = tempfile.mkdtemp(prefix=prefix)
    if not _TMP:
        atexit.register(lambda: [shutil.rmtree(p, ignore_errors=True) for p in _TMP])
    _TMP.append(d)
    return Path(d)


class _Gains(ctypes.Structure):
    _fields_ = [("k1", ctypes.c_double), ("k2", ctypes.c_double), ("lam", ctypes.c_double)]


_ERRORS: list = []


def generated_errors():
    """errors (7) exactly as every generated Python module has them (the
    codegen's `python_tracking.py.j2`, rendered on its own): the errors of a
    controller that has no generated module, such as the baseline (38)."""
    if not _ERRORS:
        from ..codegen.python_backend import errors_source
        mod = types.ModuleType("_uwmr_generated_errors")
        exec(compile(errors_source(), "<generated errors (7)>", "exec"), mod.__dict__)   # noqa: S102
        _ERRORS.append(mod.errors)
    return _ERRORS[0]


class Backend:
    """A controller as the simulation loop calls it: `backend(e1, e2, e3, vr,
    wr, k1, k2, lam) -> (v, w)` is law (9) and `backend.errors(x, y, th, xr,
    yr, thr) -> (e1, e2, e3)` errors (7), both from the same generated code
    (errors None: the generated Python errors, `generated_errors`)."""

    def __init__(self, control, errors=None, name=""):
        self.control = control
        self._errors = errors
        self.name = name

    @property
    def errors(self):
        return self._errors if self._errors is not None else generated_errors()

    def __call__(self, e1, e2, e3, vr, wr, k1, k2, lam):
        return self.control(e1, e2, e3, vr, wr, k1, k2, lam)


@dataclass
class Controllers:
    """`python` and `c`: Backends (law (9) and errors (7)) of the generated
    Python module and of the C compiled from the same design, both
    broadcasting over numpy arrays and returning (v, w) / (e1, e2, e3)."""
    stem: str
    directory: Path
    module: object
    compiled: object          # codegen.harness.Compiled

    def __post_init__(self):
        fn = self.compiled.function()
        fn.argtypes = [ctypes.c_double] * 5 + [ctypes.POINTER(_Gains),
                                                ctypes.POINTER(ctypes.c_double),
                                                ctypes.POINTER(ctypes.c_double)]
        fn.restype = ctypes.c_int
        self._cfn = fn
        err = getattr(self.compiled.lib, f"uwmr_{self.compiled.ident}_errors")
        err.argtypes = [ctypes.c_double] * 6 + [ctypes.POINTER(ctypes.c_double)] * 3
        err.restype = ctypes.c_int
        self._cerr = err
        self._v, self._w = ctypes.c_double(), ctypes.c_double()
        self._pv, self._pw = ctypes.byref(self._v), ctypes.byref(self._w)
        self._e = [ctypes.c_double() for _ in range(3)]
        self._pe = [ctypes.byref(e) for e in self._e]
        self._g = _Gains()
        self._pg = ctypes.byref(self._g)
        self.python = Backend(self.module.control, self.module.errors, "python")
        self.c = Backend(self.c_control, self.c_errors, "c")

    def c_scalar(self, e1, e2, e3, vr, wr, k1, k2, lam):
        g = self._g
        g.k1, g.k2, g.lam = k1, k2, lam
        self._cfn(e1, e2, e3, vr, wr, self._pg, self._pv, self._pw)
        return self._v.value, self._w.value

    def c_control(self, e1, e2, e3, vr, wr, k1, k2, lam):
        if np.ndim(e1) == 0 and np.ndim(e2) == 0 and np.ndim(e3) == 0 and np.ndim(vr) == 0:
            return self.c_scalar(float(e1), float(e2), float(e3), float(vr), float(wr),
                                 float(k1), float(k2), float(lam))
        args = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in (e1, e2, e3, vr, wr, k1, k2, lam)))
        shape = args[0].shape
        x = np.stack([a.ravel() for a in args], axis=1)
        v, w, _ = self.compiled.run(x)
        return v.reshape(shape), w.reshape(shape)

    def c_errors(self, x, y, th, xr, yr, thr):
        """errors (7) by the generated C `uwmr_<stem>_errors` (0 where its status is not 0)."""
        args = (x, y, th, xr, yr, thr)
        if all(np.ndim(a) == 0 for a in args):
            self._cerr(*(float(a) for a in args), *self._pe)
            return tuple(e.value for e in self._e)
        arrays = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in args))
        shape = arrays[0].shape
        e1, e2, e3, _ = self.compiled.errors(np.stack([a.ravel() for a in arrays], axis=1))
        return e1.reshape(shape), e2.reshape(shape), e3.reshape(shape)

    def backend(self, name: str) -> Backend:
        return {"python": self.python, "c": self.c}[name]


def _law_38(e1, e2, e3, vr, wr, k1, k2, lam):
    """The paper's unsaturated controller (38) of reference [49], as printed:

        V = Vr cos(e3) + k1 e1,   W = Wr + lam Vr e2 sin(e3)/e3 + k2 e3.

    Not generated code: the generated controller of
    designs/unsaturated_baseline.py is law (9) with f = rho/2, which keeps
    tanh in V and in the k2 term (so its V obeys |V| <= |Vr| + k1), and is
    simulated beside this one as "baseline_generated"."""
    e3 = np.asarray(e3, dtype=float)
    sinc = np.sinc(e3 / np.pi)
    v = vr * np.cos(e3) + k1 * np.asarray(e1)
    w = wr + lam * vr * np.asarray(e2) * sinc + k2 * e3
    if np.ndim(v) == 0:
        return float(v), float(w)
    return v, w


#: the baseline (38) with the generated errors (7)
unsaturated_38 = Backend(_law_38, None, "(38) as printed")


_CACHE: dict = {}


def load_controllers(design_path, report=None, generated_dir=None) -> Controllers:
    """Generate (unless `generated_dir` is given), compile and load the design's controller."""
    from ..codegen import generate
    from ..codegen.harness import build_library
    design_path = Path(design_path).resolve()
    stem = design_path.stem
    if generated_dir is None:
        # keyed by what the generated code depends on, not by the file's time: a design file may
        # take f from a helper module that changed since
        from ..codegen import not_verified_reasons
        if report is None:
            from ..verify import verify_design
            report = verify_design(design_path)
        d, kf = report.design, report.kf
        key = (str(design_path), d.name, repr(d.f), repr(d.f_source), repr(sorted(d.params.items())),
               None if kf is None else (str(kf.exact), str(kf.upper)), tuple(not_verified_reasons(report)))
        if key in _CACHE:
            return _CACHE[key]
        src = _tmpdir(f"uwmr-sim-{stem}-")
        generate(design_path, src, force=True, report=report)
    else:
        src = Path(generated_dir)
        key = (str(src.resolve()), (src / f"{stem}.c").stat().st_mtime_ns,
               (src / f"{stem}.py").stat().st_mtime_ns)
        if key in _CACHE:
            return _CACHE[key]
    work = _tmpdir(f"uwmr-sim-{stem}-build-")
    compiled = build_library(src, stem, work)
    spec = importlib.util.spec_from_file_location(f"_uwmr_generated_{stem}_{len(_CACHE)}", src / f"{stem}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    ctl = Controllers(stem, src, module, compiled)
    _CACHE[key] = ctl
    return ctl
