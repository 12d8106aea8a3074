"""The Python API: verify a candidate f of the controller family (9), generate
its code, simulate it.  Everything the command line does, without files::

    import sympy as sp
    from uwmr_symbolic import e1, e2, verify, generate, simulate

    report = verify(sp.log(1 + e1**2 + e2**2) / 2,
                    gains={"circle": dict(k1=0.25, k2=0.7, lam=1.2, Vmax=0.75, Wmax=2.0,
                                          Vr_max=0.5, Wr_max=1.0)})
    report.exit_status          # 0: P1-P8 proved, kf certified, bound (10) holds
    report.plot_profile()       # F, F' and F'/s with the certified kf
    generate(report, "out/")    # C99, Python and CasADi
    sim = simulate(report, "circle")
    sim.plot_inputs()           # V, W with the limits of (6), as Figures 6 and 9

Time limits work from any thread and on any OS: by default the verifier runs
in a worker process (``python -m uwmr_symbolic._worker``, started once and
reused) that is killed when it outlives its limit; with ``worker=False`` it runs in the calling thread,
limited by a watchdog thread (`timeouts`), never by a signal handler."""
from __future__ import annotations

import atexit
import contextlib
import os
import pickle
import queue
import re
import shutil
import subprocess
import sys
import tempfile
import threading
import time
import warnings
from pathlib import Path
from typing import TYPE_CHECKING, Iterable, Mapping

import sympy as sp

from .design import DesignError, design_from_namespace
from .properties import PROPERTIES
from .timeouts import TimeLimit, no_signals, time_limit
from .verdict import unknown
from .verify import DEFAULT_TIMEOUT, Report, _timed_out, verify_loaded

if TYPE_CHECKING:
    from .simulation.reference import Reference
    from .simulation.result import SimulationResult

__all__ = ["verify", "verify_file", "generate", "simulate", "DEFAULT_TIMEOUT", "IN_MEMORY"]

#: The folder named in the path of a design given in memory (no such folder
#: exists; generated files are named after the design's stem).
IN_MEMORY = Path("<in-memory>")
TARGETS = ("c", "python", "casadi")
WORKER_START = 10.0     # seconds allowed for a new worker process to start, beyond the limit


def _stem(name: str) -> str:
    stem = re.sub(r"\W+", "_", name).strip("_").lower()
    return stem if stem and not stem[0].isdigit() else f"design_{stem}".rstrip("_")


def _stopped(path: Path, timeout: float, seconds: float) -> Report:
    props = {p: unknown(f"the verifier's worker process was stopped after {seconds:g} s "
                        f"(timeout {timeout:g} s)") for p in PROPERTIES}
    return Report(path, None, props, None, seconds=seconds, timed_out=True)


def _verify_here(namespace: dict, path: Path, timeout: float, kernel_only: bool = True) -> Report:
    """verify() in this thread: check the names, then P1-P8, kf, replay, gains."""
    start = time.monotonic()
    try:
        with time_limit(timeout):
            design = design_from_namespace(namespace, path)
    except DesignError as exc:
        return Report(path, None, {}, None, error=str(exc), seconds=time.monotonic() - start)
    except TimeLimit:
        props = {p: _timed_out("checking f, params and gains", timeout) for p in PROPERTIES}
        return Report(path, None, props, None, seconds=time.monotonic() - start, timed_out=True)
    return verify_loaded(design, timeout, start, kernel_only)


def _verify_file_here(path, timeout: float, kernel_only: bool = True) -> Report:
    from .verify import verify_design      # looked up at each call (tests may replace it)
    return verify_design(path, timeout=timeout, kernel_only=kernel_only)


def verify_job(job: dict) -> Report:
    """Run a job of `_run` in this thread (here, or in the worker process)."""
    if job["kind"] == "file":
        return _verify_file_here(job["path"], job["timeout"], job.get("kernel_only", True))
    return _verify_here(job["namespace"], job["path"], job["timeout"], job.get("kernel_only", True))


def _run(job: dict, worker: bool) -> Report:
    """Run a verification job in a worker process, or here (`worker=False`)."""
    if worker and sys.executable:
        try:
            data = pickle.dumps({**job, "cwd": os.getcwd()})     # relative paths as here
        except Exception as exc:  # noqa: BLE001 - e.g. a lambda among the params
            warnings.warn(f"the design cannot be sent to a worker process ({type(exc).__name__}: {exc}); "
                          f"verifying in this process", RuntimeWarning, stacklevel=3)
        else:
            report = _in_worker(data, job)
            if report is not None:
                return report
    with no_signals():
        return verify_job(job)


class _Worker:
    """A running ``python -m uwmr_symbolic._worker``: reused from one job to
    the next (the verifier stays imported and warm), killed when a job
    outlives its limit."""

    def __init__(self):
        env = dict(os.environ)
        package_parent = str(Path(__file__).resolve().parents[1])
        env["PYTHONPATH"] = os.pathsep.join(p for p in (package_parent, env.get("PYTHONPATH")) if p)
        # -P: a design folder's random.py or math.py is not imported in place of Python's own; a session
        # of its own: Ctrl-C reaches the caller only, which kills the worker (red team 28: a worker still
        # importing printed a traceback)
        self.proc = subprocess.Popen([sys.executable, "-P", "-m", "uwmr_symbolic._worker"], stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE, env=env, start_new_session=True)

    def ask(self, data: bytes, limit: float) -> bytes | None:
        """The answer to one job, or None when the process was killed at `limit`
        seconds or died."""
        from ._worker import read_message, write_message
        answers: queue.SimpleQueue = queue.SimpleQueue()
        reader = threading.Thread(target=lambda: answers.put(read_message(self.proc.stdout)), daemon=True)
        try:
            write_message(self.proc.stdin, data)
        except OSError:
            self.close()
            return None
        reader.start()
        try:
            answer = answers.get(timeout=limit)
        except queue.Empty:
            answer = None
        except KeyboardInterrupt:
            self.close()
            raise
        if answer is None:
            self.close()
        return answer

    def close(self):
        self.proc.kill()
        self.proc.wait()
        for stream in (self.proc.stdin, self.proc.stdout):
            with contextlib.suppress(OSError):
                stream.close()


_idle: list[_Worker] = []           # workers waiting for a job (several threads may verify at once)
_idle_lock = threading.Lock()


@atexit.register
def _close_idle_workers():
    with _idle_lock:
        while _idle:
            _idle.pop().close()


def _in_worker(data: bytes, job: dict) -> Report | None:
    """The report computed by a worker process (None: the worker could not
    read the job, e.g. a SymPy class defined in a notebook)."""
    from .batch import hard_limit
    with _idle_lock:
        worker = _idle.pop() if _idle else None
    if worker is not None and worker.proc.poll() is not None:    # it died while idle
        worker.close()
        worker = None
    fresh = worker is None
    if fresh:
        worker = _Worker()
    limit = hard_limit(job["timeout"]) + (WORKER_START if fresh else 0.0)
    start = time.monotonic()
    answer = worker.ask(data, limit)
    if answer is None:
        elapsed = time.monotonic() - start
        if elapsed < limit and job["kind"] == "file":
            return Report(Path(job["path"]), None, {}, None, seconds=elapsed,
                          error="the process checking this file died (does the file call os._exit or crash Python?)")
        if elapsed < limit:
            raise RuntimeError("the verifier's worker process died (see the messages above)")
        return _stopped(Path(job["path"]), job["timeout"], elapsed)
    with _idle_lock:
        _idle.append(worker)
    status, value, output = pickle.loads(answer)
    if output:
        sys.stderr.write(output)
    if status == "unreadable":
        warnings.warn(f"the worker process could not read the design ({value}); verifying in this process",
                      RuntimeWarning, stacklevel=4)
        return None
    if status == "error":
        raise value
    return value


def verify(f: sp.Expr, params: Mapping | None = None, gains: Mapping | None = None, *, name: str | None = None,
           timeout: float = DEFAULT_TIMEOUT, worker: bool = True, kernel_only: bool = True) -> Report:
    """Verify a candidate ``f(e1, e2)`` for the controller family (9).

    Decides P1-P8 (proved, refuted with a witness, or unknown), certifies
    kf >= sup |df/de2| of P1, replays the Lyapunov argument (15)-(19) and
    checks each gain scenario against bound (10).

    Parameters
    ----------
    f:
        A SymPy expression in the real symbols ``e1``, ``e2``
        (``from uwmr_symbolic import e1, e2``); other symbols take their
        values from `params`.
    params:
        ``{symbol or name: number}``; floats are read as the decimal they
        print as (0.1 is 1/10).
    gains:
        ``{scenario: dict(k1=, k2=, lam=, Vmax=, Wmax=, Vr_max=, Wr_max=)}``,
        the gains of (9), the limits of (6) and the reference bounds of (3).
        A scenario named ``circle`` or ``lemniscate`` can be simulated on the
        paper's path.  Without gains bound (10) is not checked.
    name:
        A name for the report and the generated files (default ``design``).
    timeout:
        Seconds for the whole verification; a property still undecided then
        is ``unknown`` (and ``report.timed_out`` is true).
    worker:
        Verify in a worker process (default), killed if it outlives the time
        limit even inside a long C call; ``False`` verifies in the calling
        thread (faster to start; limited by a watchdog thread, any thread).
    kernel_only:
        Count only the verdicts the trusted kernel re-checked (default): a
        proof or refutation resting on the search alone becomes
        ``unknown``, and bound (10) needs a kernel-checked kf.  ``False``
        also counts the search's (``--trust-search``); ``report.kernel``
        says which verdicts the kernel re-checked, in either mode.

    Returns a `Report` (``exit_status``, ``properties``, ``kf``, ``gains``;
    ``to_dict()``, rich display in a notebook, ``plot_profile()``).

    Raises `DesignError` (one line naming the fix) when f, params or gains
    cannot be used."""
    if not timeout > 0:
        raise ValueError(f"timeout must be positive, got {timeout!r}")
    if isinstance(f, bool) or not isinstance(f, sp.Expr):
        raise DesignError(f"f is a {type(f).__name__}, not a SymPy expression in e1, e2 "
                          f"(from uwmr_symbolic import e1, e2; f = sympy.log(1 + e1**2 + e2**2) / 2)")
    name = name or "design"
    path = IN_MEMORY / f"{_stem(name)}.py"
    namespace = {"f": f, "params": dict(params) if params is not None else None,
                 "gains": {k: dict(v) if isinstance(v, Mapping) else v for k, v in gains.items()}
                 if isinstance(gains, Mapping) else gains, "name": name}
    report = _run({"kind": "memory", "namespace": namespace, "path": path, "timeout": float(timeout),
                   "kernel_only": bool(kernel_only)}, worker)
    if report.error is not None:
        raise DesignError(report.error)
    return report


def verify_file(path: str | os.PathLike, *, timeout: float = DEFAULT_TIMEOUT, worker: bool = True,
                kernel_only: bool = True) -> Report:
    """Verify a design file (Python defining ``f`` and optionally ``params``,
    ``gains``, ``name``, ``description``), as ``uwmr-verify FILE`` does.

    Never raises for a bad file: ``report.error`` then holds the one-line
    reason and ``report.exit_status`` is 2.  `timeout`, `worker` and
    `kernel_only` as in `verify`."""
    if not timeout > 0:
        raise ValueError(f"timeout must be positive, got {timeout!r}")
    return _run({"kind": "file", "path": Path(path), "timeout": float(timeout),
                 "kernel_only": bool(kernel_only)}, worker)


def generate(report: Report, out_dir: str | os.PathLike, targets: Iterable[str] = TARGETS, *,
             force: bool = False) -> list[Path]:
    """Write the controller (9) of a verified design into `out_dir`.

    `targets`: any of ``"c"`` (``<stem>.h``, ``<stem>.c``: C99, double and
    float, with the errors (7) and ``_step``; plus ``example_main.c`` and a
    ``CMakeLists.txt``, see docs/deploy.md), ``"python"`` (``<stem>.py``, numpy) and ``"casadi"``
    (``<stem>.casadi``, a serialised ``casadi.Function``
    ``control(e1, e2, e3, vr, wr, k1, k2, lam) -> (v, w)``).  The C and Python
    files are checked against the exact law before anything is written.

    Raises ``codegen.CodegenRefused`` unless P1-P8 are all proved and the
    proof replay succeeded; ``force=True`` writes the C and Python files of an
    unverified design, each headed by a NOT VERIFIED banner (no CasADi file:
    it could not carry the banner).  Returns the paths written."""
    from .codegen import build
    from .codegen import generate as write_checked
    targets = tuple(targets)
    bad = sorted(set(targets) - set(TARGETS))
    if bad:
        raise ValueError(f"unknown target {bad[0]!r}; choose among {', '.join(TARGETS)}")
    out = Path(out_dir)
    written: list[Path] = []
    if "c" in targets or "python" in targets:
        with tempfile.TemporaryDirectory() as tmp:
            for p in write_checked(report.path, Path(tmp) / "out", force=force, report=report):
                c_file = p.suffix in (".c", ".h") or p.name == "CMakeLists.txt"   # the C package, example included
                if ("c" in targets and c_file) or ("python" in targets and p.suffix == ".py"):
                    out.mkdir(parents=True, exist_ok=True)
                    written.append(Path(shutil.copyfile(p, out / p.name)))
    if "casadi" in targets:
        from .codegen import casadi_function      # validated against the exact law, like the files
        model, _ = build(report.path, force=force, report=report)
        if model.verified:
            fn = casadi_function(report.path, report=report)
            out.mkdir(parents=True, exist_ok=True)
            target = out / f"{model.stem}.casadi"
            fn.save(str(target))
            written.append(target)
        else:
            warnings.warn("no CasADi file for a NOT VERIFIED design", RuntimeWarning, stacklevel=2)
    return written


def simulate(report: Report, scenario: "str | Reference" = "circle", *, gains: Mapping | str | None = None,
             kinds: Iterable[str] = ("continuous", "digital"), backends: Iterable[str] = ("c", "python"),
             baseline: bool = False, delay: int = 0, noise: tuple | None = None, seed: int = 0,
             pose0: tuple | None = None) -> "SimulationResult":
    """Run the generated controller (9) of `report`'s design in closed loop
    with the unicycle (1) along a reference (2).

    `scenario`: ``"circle"`` or ``"lemniscate"`` (the paper's Section 5
    experiments: path, initial pose, duration, RMS window), or a
    `simulation.Reference` (from ``from_waypoints``, ``from_path``,
    ``from_function``; the robot starts 0.5 m beside it unless `pose0`).
    `gains`: a dict ``k1, k2, lam, Vmax, Wmax, Vr_max, Wr_max`` or the name of
    one of the design's scenarios (default: the scenario of the same name).
    `kinds`: ``continuous`` (an adaptive integrator) and/or ``digital`` (100 Hz
    zero-order hold, `delay` samples of delay, pose `noise` = (sigma_xy,
    sigma_theta) seeded by `seed`).  `backends`: the generated C (compiled
    with gcc) and Python code, the first drives the reported run and the
    second is compared with it.  `baseline`: also the unsaturated
    controller (38) on the paper's paths.

    Returns a `SimulationResult` with the trajectories, the checks (limits
    (6), convergence, U = lam f + e3^2/2 of (15) non-increasing) and plots."""
    from .simulation.api import Scenario, scenario_for, simulate_38, simulate_scenario, _load, _verified, BASELINE
    from .simulation.controllers import load_controllers
    from .simulation.result import SimulationResult
    if report.design is None:
        raise ValueError(f"the report is of an unusable design: {report.error}")
    design = report.design
    name = scenario if isinstance(scenario, str) else getattr(scenario, "name", "reference")
    if isinstance(scenario, str):
        sc = scenario_for(scenario)
        if sc is None:
            raise ValueError(f"no built-in path {scenario!r}: use 'circle', 'lemniscate' or a Reference")
    else:
        sc = scenario if isinstance(scenario, Scenario) else scenario_for(name, {name: scenario})
    if pose0 is not None:
        sc = Scenario(sc.name, sc.reference, tuple(float(a) for a in pose0), sc.window, sc.description)
    if gains is None or isinstance(gains, str):
        key = name if gains is None else gains
        if key not in design.gains:
            have = ", ".join(design.gains) or "none"
            raise ValueError(f"the design has no gain scenario {key!r} (it has: {have}); pass gains=dict(...)")
        chosen = design.gains[key]
    else:
        from .design import _parse_gains
        chosen = _parse_gains({name: dict(gains)})[name]
    kinds, backends = tuple(kinds), tuple(backends)
    verified = _verified(report)
    ctl = load_controllers(report.path, report=report)
    runs = simulate_scenario(ctl, design, sc, chosen, verified=verified, backends=backends, delay=delay,
                             noise=noise, seed=seed, kinds=kinds, keep=True)
    if baseline and sc.name in ("circle", "lemniscate") and BASELINE.exists():
        base = _load(BASELINE)
        runs["baseline"] = simulate_38(base.design, sc, base.design.gains[sc.name], keep=True)
    trajectories = {kind: m.pop("_trajectory") for kind, m in runs.items()}
    return SimulationResult(name=design.name, scenario=sc, gains={k: float(v) for k, v in chosen.items()},
                            runs=runs, trajectories=trajectories, f=design.f, verified=verified)
