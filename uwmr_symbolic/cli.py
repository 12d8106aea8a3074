"""Command line: `uwmr-verify FILE... [--format text|json|junit|github] [--timeout S]`."""
from __future__ import annotations

import argparse
import contextlib
import functools
import json
import os
import signal
import sys
import threading
from pathlib import Path

from . import __version__, settings
from .batch import Progress, check_files, expand_paths, hard_limit, worst_status
from .cache import ResultCache
from .files import write_text_atomic
from .report import (render_github, render_json, render_junit, render_markdown_summary, render_summary,
                     render_text, shown)
from .verify import DEFAULT_TIMEOUT, SEARCH_ONLY


def render_simulation_text(sim) -> str:
    from .simulation import render_simulation_text as render
    return render(sim)

EPILOG = """\
who decides:
  a verdict counts when the trusted kernel (uwmr_symbolic/kernel) re-checked the search's
  proof or witness; one resting on the search alone is reported unknown (--trust-search
  counts it).

certificates:
  --certificate OUT.json writes what the trusted kernel (uwmr_symbolic/kernel) has checked of
  each property; --check-certificate OUT.json re-checks it with no search.  A cached result
  is used only when its certificate re-checks.

exit status:
  0  every property P1-P8 proved, proof replay ok, every gain scenario within bound (10)
  1  a property refuted (with a witness) or a gain check fails
  2  unusable input: the design file is missing, broken or not a valid design; an
     option or setting that cannot be used; an output that cannot be written
  3  inconclusive: some verdict is unknown, nothing refuted
  130  interrupted (Ctrl-C); the files written before it are complete
  141  the output pipe closed early (`uwmr-verify ... | head`), as for other tools
With several files the status is the worst one (2 > 1 > 3 > 0).

FILE may be a glob ('designs/*.py', quoted or not) or a directory (its *.py files).
Several files are checked in parallel (--jobs, default: one per CPU core).

formats:
  text    the report of each design, then a summary table when there are several
  json    one JSON object for one file, a JSON array for several
  junit   JUnit XML as pytest writes it: a test case per design and property P1-P8,
          proof replay and gain scenario (refuted/unknown are failures)
  github  GitHub Actions annotations (::error at the line defining f for a refuted
          property or at the gains line for a failing bound (10), ::warning for an
          unknown one, ::notice for a design proved in full), then the summary
          table; also appended as Markdown to $GITHUB_STEP_SUMMARY when that is set

cache:
  Results are cached by the design's canonical expression, parameters, gains,
  the tool's version and the verifier's source, in --cache-dir, else
  $UWMR_CACHE_DIR, else cache-dir in [tool.uwmr-symbolic], else
  $XDG_CACHE_HOME/uwmr-symbolic or ~/.cache/uwmr-symbolic; --no-cache
  recomputes everything and stores nothing.  A result in which a time limit
  expired answers only runs with the same or a shorter --timeout.  A hit is
  used only when its certificate re-checks; bound (10), the proof replay and
  the exit status are derived again from it.

settings:
  [tool.uwmr-symbolic] in the nearest pyproject.toml with that table (searched
  from the current folder upwards) may set timeout, jobs, designs (globs checked
  when no FILE is given) and cache-dir; paths are relative to that file.
  Command-line flags override them; an unknown key or a wrong value exits 2.

A design file defines f (a SymPy expression in real symbols e1, e2) and
optionally params, gains, name, description: see the README."""


class _Parser(argparse.ArgumentParser):
    """argparse, but a usage mistake is one line on stderr (exit 2), not the
    usage block followed by the error."""

    def error(self, message):
        self.exit(2, f"{self.prog}: {message} (uwmr-verify --help lists the options)\n")


def build_parser() -> argparse.ArgumentParser:
    p = _Parser(
        prog="uwmr-verify",
        description="Prove or refute properties P1-P8 of f(e1, e2) for the saturated "
                    "controller family (9) of Moreno-Valenzuela et al. (2020), certify kf, "
                    "replay the Lyapunov proof and check gains against bound (10).",
        epilog=EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("files", nargs="*", metavar="FILE", help="design file(s), globs or directories")
    p.add_argument("--format", choices=("text", "json", "junit", "github"), default="text",
                   help="output format (default text)")
    p.add_argument("--junit-xml", metavar="PATH",
                   help="also write the JUnit XML report to PATH (whatever --format is)")
    p.add_argument("--timeout", type=float, default=None,
                   help=f"seconds per design before undecided properties become 'unknown' "
                        f"(default {DEFAULT_TIMEOUT:g}, or timeout in [tool.uwmr-symbolic])")
    p.add_argument("-j", "--jobs", type=int, default=None,
                   help="worker processes for several files (default: the number of CPU cores)")
    p.add_argument("--no-cache", action="store_true", help="neither read nor write the result cache")
    p.add_argument("--cache-dir", metavar="DIR", default=None,
                   help="folder of the result cache (default $UWMR_CACHE_DIR, else cache-dir in "
                        "[tool.uwmr-symbolic], else $XDG_CACHE_HOME/uwmr-symbolic or ~/.cache/uwmr-symbolic)")
    p.add_argument("-q", "--quiet", action="store_true",
                   help="text format: with several files print only the summary table")
    p.add_argument("--codegen", nargs="?", const="", metavar="DIR",
                   help="after verifying, write the controller (Python, C99 double and float) into DIR "
                        "(default generated/<stem>/; with several files DIR/<stem>/); only for designs "
                        "whose P1-P8 are all proved")
    p.add_argument("--force", action="store_true",
                   help="with --codegen: generate unverified designs too, every file headed by a "
                        "NOT VERIFIED banner with the reasons")
    p.add_argument("--simulate", action="store_true",
                   help="after verifying, run the generated C and Python controllers in closed loop on "
                        "each gain scenario (circle, lemniscate or --reference), continuous time and "
                        "100 Hz, beside the unsaturated baseline (38), within max(--timeout, 600 s) per design; "
                        "exit 1 if a check fails, 3 if a simulation does not finish")
    p.add_argument("--monte-carlo", type=int, default=None, metavar="N",
                   help="simulate (implies --simulate) and also N random initial poses per scenario "
                        "(100 Hz, vectorised; at most 100000)")
    p.add_argument("--seed", type=int, default=None,
                   help="with --simulate: seed for --monte-carlo and pose noise (default 0)")
    p.add_argument("--delay", type=int, default=0, metavar="SAMPLES",
                   help="with --simulate: command delay of the 100 Hz loop in samples (default 0, at most 1000)")
    p.add_argument("--reference", action="append", default=[], metavar="SCENARIO=FILE",
                   help="with --simulate: the reference for a gain scenario, from a CSV of waypoints "
                        "(columns t,x,y) or a Python file defining pose(t) -> (xr, yr, thr, vr, wr) "
                        "(numpy arrays, continuous heading) and duration")
    p.add_argument("--check-generated", action="store_true",
                   help="check that generated/ matches what the design files (default designs/*.py) "
                        "and this tool generate; exit 1 when stale")
    p.add_argument("--certificate", metavar="PATH",
                   help="write the design certificate (JSON: the kernel's theorems per property and what still "
                        "rests on the search) to PATH; with several files PATH is a directory of STEM.cert.json")
    p.add_argument("--check-certificate", nargs="+", metavar="CERT",
                   help="re-check certificate file(s) in the kernel without any search (in parallel, --jobs) and "
                        "say what each property rests on (exit 0 all check, 1 one does not or its check outlives "
                        "--timeout, 2 unreadable)")
    p.add_argument("--trust-search", action="store_true",
                   help="also count verdicts the search proved or refuted but the trusted kernel could not "
                        "re-check (by default they are 'unknown' and a gain check needs a kernel-checked kf); "
                        "the report's kernel line names them")
    p.add_argument("--kernel-only", dest="kernel_only_flag", action="store_true",
                   help="count only the kernel's verdicts (the default; kept for scripts)")
    p.add_argument("--version", action="version", version=f"uwmr-verify {__version__}")
    return p


def check_generated(args) -> int:
    """`--check-generated`: 0 when generated/ is up to date, 1 when stale, 3
    when it did not finish in time (UsageError when there is no design file
    or one is unusable).  The designs run in a child process, as in a check:
    one that calls os._exit or ignores SIGALRM ends or outlives the child,
    never the command (red team 28: os._exit(0) read as "up to date")."""
    from .codegen import CodegenRefused
    from .codegen.staleness import stale_files
    designs = [Path(p) for p in expand_paths(args.files)] if args.files else sorted(Path("designs").glob("*.py"))
    if not designs:
        raise UsageError("--check-generated found no design files (run it from the repository root or name them)")

    def stale():
        try:
            return "stale", stale_files(designs, Path("generated"), orphans=not args.files)   # named: only theirs
        except CodegenRefused as exc:       # (only an unusable design: stale_files generates with force)
            return "unusable", f"{exc.path}: {'; '.join(exc.reasons)}"
    seconds = len(designs) * hard_limit(args.timeout)
    kind, answer = in_fork(stale, seconds)
    if kind == "late":
        print(f"uwmr-verify: --check-generated did not finish within {seconds:g} s (--timeout {args.timeout:g} s "
              f"per design, with its grace)", file=sys.stderr)
        return 3
    if kind != "ok":
        what = f"the process exited with code {answer}" if kind == "died" else answer
        raise UsageError(f"--check-generated: a design file ended the check ({what}); run each design "
                         f"file with `uwmr-verify FILE` to see which")
    if answer[0] == "unusable":
        raise UsageError(f"--check-generated: {answer[1]}")
    problems = answer[1]
    for line in problems:
        print(line)
    if not problems:
        print(f"generated/ is up to date for {len(designs)} design(s)")
    return 1 if problems else 0


MAX_DELAY = 1000            # samples: 10 s of the 100 Hz loop
SIMULATION_SECONDS = 600    # a design's simulations stop after the larger of this and --timeout
MAX_MONTE_CARLO = 100_000   # random initial poses per scenario
MAX_WAYPOINT_BYTES = 20_000_000     # a --reference CSV


class UsageError(Exception):
    """A command-line argument cannot be used (exit 2, one line)."""


def in_fork(fn, seconds: float):
    """fn() in a forked child process, whose answer alone crosses back:
    ("ok", value); ("raised", "SystemExit: 0") for anything it raised,
    SystemExit and KeyboardInterrupt included; ("died", exit code) when it
    ended without an answer (os._exit, a crash in C code); ("late", None)
    when it outlived `seconds` and was killed.  A --reference file's code
    runs so, so that its exit cannot end (or pass off as) the command."""
    import multiprocessing

    from .timeouts import quiet_on_interrupt
    ctx = multiprocessing.get_context("fork")
    recv, send = ctx.Pipe(duplex=False)

    def child():
        quiet_on_interrupt()
        try:
            answer = ("ok", fn())
        except BaseException as exc:        # noqa: BLE001 - whatever the user's code raises, even exit()
            answer = ("raised", f"{type(exc).__name__}: {exc}".rstrip(": "))
        try:
            send.send(answer)
        except Exception as exc:            # noqa: BLE001 - a value that cannot be pickled
            send.send(("raised", f"the result could not be sent back ({type(exc).__name__}: {exc})"))
    proc = ctx.Process(target=child)
    proc.start()
    send.close()
    try:
        answer = recv.recv() if recv.poll(seconds) else ("late", None)
    except EOFError:
        answer = None
    finally:
        if proc.is_alive():
            proc.kill()
        proc.join()
        recv.close()
    return answer or ("died", proc.exitcode)


def load_references(specs, timeout: float) -> dict:
    """--reference SCENARIO=FILE: waypoints (CSV t,x,y) or pose(t) from a Python file,
    each read (and checked against (2)) within `timeout` seconds."""
    from .simulation import ReferenceError
    from .timeouts import TimeLimit, time_limit
    refs = {}
    names = [spec.partition("=")[0] for spec in specs]
    twice = next((n for n in names if names.count(n) > 1), None)
    if twice is not None:
        raise UsageError(f"--reference {twice}=... is given twice; give one file per scenario")
    for spec in specs:
        name, sep, file = spec.partition("=")
        if not sep or not name or not file:
            raise UsageError(f"--reference {spec!r}: expected SCENARIO=FILE")
        path = Path(file)
        if path.suffix != ".csv":       # the user's code: first in a child process (exit(), os._exit)
            _probe_reference(path, name, timeout)
        try:
            with time_limit(timeout):
                refs[name] = _read_reference(path, name)
        except TimeLimit:
            raise UsageError(f"{path}: the reference did not load within --timeout ({timeout:g} s)") from None
        except UsageError:
            raise
        except (OSError, ValueError, ReferenceError) as exc:
            raise UsageError(f"{path}: {exc}") from None
        except Exception as exc:  # the user's file raised
            raise UsageError(f"{path}: raised {exc.__class__.__name__}: {exc}") from None
    return refs


def _probe_reference(path, name, timeout):
    """Load a Python --reference file and check its pose() (as `load_references`
    does) in a child process first: UsageError if the file ends the process,
    raises or does not finish, so that its exit() or os._exit() ends neither
    the command nor passes for its status."""
    def load():
        from .timeouts import time_limit
        with time_limit(timeout):
            _read_reference(path, name)
    kind, what = in_fork(load, timeout + 5)
    if kind == "died":
        raise UsageError(f"{path}: the reference file ended the process (exit code {what}) while loading or in "
                         f"pose(); it must define pose(t) and duration and return")
    if kind == "late":
        raise UsageError(f"{path}: the reference did not load within --timeout ({timeout:g} s)")
    if kind == "raised" and what.startswith(("SystemExit", "KeyboardInterrupt")):
        raise UsageError(f"{path}: the reference file raised {what} while loading or in pose(); it must define "
                         f"pose(t) and duration and return")


def _number(text: str) -> bool:
    try:
        float(text)
        return True
    except ValueError:
        return False


def _read_reference(path, name):
    """One --reference file as a Reference (see `load_references`): a CSV's
    columns checked by name (finite numbers, some rows) before the spline."""
    import runpy
    import warnings

    import numpy as np

    from .simulation import from_function, from_waypoints
    if path.is_dir():
        raise UsageError(f"{path}: is a folder; give a CSV of waypoints or a Python file defining pose(t)")
    if path.suffix != ".csv":
        with contextlib.redirect_stdout(sys.stderr):    # its prints (red team 28: 224 kB before the JSON)
            ns = runpy.run_path(str(path))
        pose = ns.get("pose")
        if not callable(pose) or "duration" not in ns:
            raise UsageError(f"{path}: define pose(t) -> (xr, yr, thr, vr, wr) and duration")

        def pose_printing_to_stderr(t):
            with contextlib.redirect_stdout(sys.stderr):
                return pose(t)
        return from_function(pose_printing_to_stderr, 0.0, float(ns["duration"]), name=name)
    if (size := path.stat().st_size) > MAX_WAYPOINT_BYTES:       # (98 MB of text took 2.8 GB to read)
        raise UsageError(f"{path}: {size / 1e6:.0f} MB of waypoints, and at most "
                         f"{MAX_WAYPOINT_BYTES // 10**6} MB are read; give fewer (the path is a spline through them)")
    try:
        lines = path.read_text(encoding="utf-8-sig").splitlines()      # (a byte-order mark is no column name)
    except UnicodeDecodeError as exc:
        raise UsageError(f"{path}: not UTF-8 text ({exc.reason} at byte {exc.start}); save it as UTF-8") from None
    header = next((i for i, line in enumerate(lines) if line.strip() and not line.startswith("#")), 0)
    named = lines and "".join(lines[header].split()).lower() == "t,x,y"    # the columns' names
    if lines and not named and not any(_number(field) for field in lines[header].split(",")):     # names
        raise UsageError(f"{path}: the header {lines[header].strip()!r} is not t,x,y: the columns are the "
                         f"time, then x and y, in that order")
    rows = [line for line in (lines[header + 1:] if named else lines) if line.strip() and not line.startswith("#")]
    if not rows:
        raise UsageError(f"{path}: no waypoints: expected rows t,x,y (numbers) after the optional header")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")         # numpy's and scipy's warnings: the checks below say it in one line
        try:
            data = np.loadtxt(rows, delimiter=",", ndmin=2, comments="#")
        except ValueError as exc:   # (numpy's hint about `usecols` does not apply here)
            raise UsageError(f"{path}: expected comma-separated numbers t,x,y in every waypoint row: "
                             f"{str(exc).split('; use ')[0].rstrip('.')}") from None
        if data.shape[1] != 3:
            raise UsageError(f"{path}: expected three columns t,x,y, found {data.shape[1]}")
        for j, column in enumerate("txy"):
            bad = np.flatnonzero(~np.isfinite(data[:, j]))
            if bad.size:
                raise UsageError(f"{path}: column {column} is not a finite number in waypoint {bad[0] + 1}")
        return from_waypoints(data[:, 0], data[:, 1], data[:, 2], name=name)


class Reports:
    """The verifier's `Report` of each design file for --simulate and
    --codegen: the one the batch's process sent back with its result (it
    verified the file once, `check_files(want_reports=True)`), else (that
    process was killed) computed here, with the command's --timeout."""

    def __init__(self, timeout: float, results=()):
        self.timeout = timeout
        self._reports = {str(d["design"]): d.pop("report") for d in results if "report" in d}

    def __call__(self, path):
        from .api import verify_file
        key = str(path)
        if key not in self._reports:    # in a worker process, killed past --timeout like the batch's
            self._reports[key] = verify_file(path, timeout=self.timeout, worker=True)
        return self._reports[key]


def run_simulations(results, args, refs: dict, reports: Reports) -> int:
    """--simulate: attach result["simulation"]; 1 if a check failed, 3 if a
    design's simulations did not finish within the larger of --timeout and
    SIMULATION_SECONDS, 2 if a --reference leaves a scenario's Vr_max or
    Wr_max (that design is not simulated)."""
    from .codegen import CodegenInvalid
    from .simulation import simulate_design
    from .simulation.api import reference_speeds
    from .timeouts import TimeLimit, time_limit
    status = 0
    for d in results:
        if d.get("error") is not None:
            continue
        if d.get("f") is None:              # loading it did not finish within --timeout (not tried again)
            print(f"{d['design']}: not simulated: the design file did not load within --timeout", file=sys.stderr)
            continue
        report = reports(d["design"])
        if report.design is None or not report.design.gains:
            print(f"{d['design']}: not simulated: the design has no gain scenarios", file=sys.stderr)
            continue
        speeds = {n: reference_speeds(refs[n], g) for n, g in report.design.gains.items() if n in refs}
        beyond = [f"--reference {n}: {v['beyond']}" for n, v in speeds.items() if not v["within"]]
        if beyond:      # bound (10) was checked for references within the scenario's Vr_max and Wr_max
            print(f"{d['design']}: not simulated: {'; '.join(beyond)} (bound (10) holds only for a reference "
                  f"within the scenario's Vr_max and Wr_max: raise them in the design's gains or slow the "
                  f"reference)", file=sys.stderr)
            status = worst_status([status, 2])
            continue
        limit = max(args.timeout, SIMULATION_SECONDS)

        def simulate(path=d["design"], report=report):
            try:
                with time_limit(limit):
                    return "sim", simulate_design(path, report=report, monte_carlo=args.monte_carlo or 0,
                                                  seed=args.seed or 0, references=refs or None, delay=args.delay)
            except CodegenInvalid as exc:
                return "invalid", f"{exc.what}: {exc.reasons[0]}"
            except TimeLimit:
                return "late", None
        # in a child process: a --reference's pose() that calls exit() or os._exit, or generated code
        # that crashes, ends that child, not the command
        kind, value = in_fork(simulate, limit + 30)
        if kind == "ok":
            kind, value = value
        if kind == "invalid":       # the simulator runs the generated code, which the validation gate refused
            print(f"{d['design']}: not simulated, {value}", file=sys.stderr)
            status = 1
            continue
        if kind == "late":
            print(f"{d['design']}: the simulation did not finish within {limit:g} s "
                  f"(the larger of --timeout and {SIMULATION_SECONDS} s)", file=sys.stderr)
            status = worst_status([status, 3])
            continue
        if kind != "sim":
            why = f"ended without a result (exit code {value})" if kind == "died" else f"raised {value}"
            blame = ("a --reference file's pose() must return five arrays shaped like t, and never exit" if refs
                     else "an internal error of uwmr-verify: please report it")
            print(f"{d['design']}: not simulated: the simulation {why} ({blame})", file=sys.stderr)
            status = worst_status([status, 2])
            continue
        d["simulation"] = sim = value
        if not all(entry.get("ok", True) for entry in sim.values()):
            status = 1
            d["exit_status"] = worst_status([d["exit_status"], 1])     # the summary, JUnit, GitHub say so too
    return status


def write_code(paths, results, out, force, reports: Reports) -> int:
    """`--codegen`: generate each usable design; 1 if one was refused, 2 if
    the output folder cannot take the files (nothing written there)."""
    from .codegen import CodegenInvalid, CodegenRefused, OutputError, generate
    status = 0
    for d in results:                       # (in the order of paths)
        path = Path(d["design"])
        if d.get("error") is not None:
            continue
        if d.get("f") is None:              # loading it did not finish within --timeout (not tried again)
            print(f"{path}: no code generated: the design file did not load within --timeout", file=sys.stderr)
            continue
        target = None if out == "" else (Path(out) / path.stem if len(paths) > 1 else Path(out))
        unproved = [f"{p} {v['verdict']}: {v['reason']}" for p, v in d["properties"].items() if v["verdict"] != "proved"]
        try:
            if unproved and not force:      # refused as `generate` would, without verifying it again
                raise CodegenRefused(unproved)
            written = generate(path, target, force=force, report=reports(path))
        except CodegenInvalid as exc:
            print(f"{path}: no code generated, {exc.what}: {exc.reasons[0]}",
                  file=sys.stderr)
            status = 1
            continue
        except CodegenRefused as exc:
            hint = "" if force else "; use --force for a NOT VERIFIED build"
            search = [r.split()[0] for r in exc.reasons if SEARCH_ONLY in r]
            if search and not unproved:     # --trust-search counted them, the code generator does not
                print(f"{path}: no code generated: code is generated from the kernel's verdicts only, and "
                      f"{', '.join(search)} rest on the search alone (--trust-search does not extend to --codegen; "
                      f"--certificate FILE says why){hint}", file=sys.stderr)
                status = 1
                continue
            print(f"{path}: no code generated, the design is not verified ({len(exc.reasons)} "
                  f"reason(s): {exc.reasons[0]} ...){hint}", file=sys.stderr)
            status = 1
            continue
        except OutputError as exc:
            print(f"{path}: no code generated: {exc}", file=sys.stderr)
            status = worst_status([status, 2])
            continue
        print(f"{path}: wrote " + ", ".join(str(p) for p in written), file=sys.stderr)
    return status


def _check_one_certificate(name: str, timeout: float = DEFAULT_TIMEOUT) -> tuple[int, str, str]:
    """(status, stdout text, stderr text) of `--check-certificate` for one file."""
    from .design_certificate import CertificateError, check, parse, read_json
    from .timeouts import TimeLimit, time_limit
    from .verdict import PROPERTIES
    path = Path(name)
    if path.exists() and not path.is_file():     # a FIFO blocks, /dev/zero never ends (red team 28)
        return 2, "", f"{name}: not a regular file: give the certificate's .json file"
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        return 2, "", f"{name}: cannot read the certificate: {exc}"
    try:
        with time_limit(timeout):
            data = read_json(text)
            checks = check(data)
    except CertificateError as exc:
        return 1, "", f"{name}: the certificate does not check: {exc}"
    except TimeLimit:
        return 1, "", (f"{name}: the certificate does not check: not finished within --timeout {timeout:g} s "
                       "(a step ran that long; a larger --timeout gives it more time)")
    present = {c.name for c in checks}
    lines = [c.line() for c in checks] + [f"{p}: absent (this certificate says nothing about it)"
                                          for p in PROPERTIES if p not in present]
    if "kf" not in present:
        lines.append("kf: absent (a certificate holds kf only when the verifier certified a finite kf)")
    design = data["design"]                     # (read by `check`: f parses)
    try:
        f = str(parse(design["f"], design=True))
    except ValueError:                          # an integer beyond sys.get_int_max_str_digits
        f = "(a formula with a number too long to print)"
    head = (f"{name}: certificate re-checked for the f it holds, f = {f} "
            f"(it names the design {design.get('name')!r}, file {design.get('file')!r})")
    return 0, "\n".join([head, *("  " + line for line in lines)]), ""


def check_certificates(files, jobs: int | None = None, timeout: float = DEFAULT_TIMEOUT) -> int:
    """`--check-certificate`: re-check each file in the kernel, one process
    per core (forked: the kernel is imported once), reported in order; a
    file whose check outlives `timeout` seconds does not check."""
    import multiprocessing

    jobs = max(1, min(jobs or os.cpu_count() or 1, len(files)))
    one = functools.partial(_check_one_certificate, timeout=timeout)
    if jobs > 1 and "fork" in multiprocessing.get_all_start_methods():
        # the workers ignore Ctrl-C and the pool's exit terminates them: a worker that ended itself
        # at Ctrl-C could hold the pool's task lock, and the pool's exit then waited forever (red team 28)
        with multiprocessing.get_context("fork").Pool(jobs, initializer=signal.signal,
                                                      initargs=(signal.SIGINT, signal.SIG_IGN)) as pool:
            results = pool.map(one, files, chunksize=1)
    else:
        results = [one(name) for name in files]
    for _, out, err in results:
        if err:
            print(err, file=sys.stderr)
        if out:
            print(out)
    return max((status for status, _, _ in results), default=0)


def write_certificates(paths, results, target) -> int:
    """`--certificate PATH`: one file, or STEM.cert.json per design in PATH."""
    out = Path(target)
    status = 0
    for d in results:
        cert = d.get("certificate")
        if cert is None:
            if d.get("error") is None:      # (an unusable file has its one line already)
                print(f"{d['design']}: no certificate written: nothing was decided (see the verdicts)",
                      file=sys.stderr)
            continue
        if len(paths) > 1 and out.exists() and not out.is_dir():
            print(f"uwmr-verify: --certificate {out}: with several design files it names a folder, and {out} is a "
                  f"file", file=sys.stderr)
            return 2
        dest = out / (Path(d["design"]).stem + ".cert.json") if len(paths) > 1 else out
        try:
            dest.parent.mkdir(parents=True, exist_ok=True)
            write_text_atomic(dest, json.dumps(cert, indent=1) + "\n")
        except OSError as exc:
            print(f"uwmr-verify: cannot write {dest}: {exc.strerror or exc}", file=sys.stderr)
            status = 2
    return status


_NUMBERS = ("--timeout", "-j", "--jobs", "--monte-carlo")     # options whose value may start with "-" (-inf, -1)


def main(argv=None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    for i in range(len(argv) - 1, 0, -1):      # argparse reads "-inf" after --timeout as an option: join them
        if argv[i - 1] in _NUMBERS and argv[i][:1] == "-" and argv[i][1:2] not in ("-", ""):
            argv[i - 1:i + 1] = [f"{argv[i - 1]}={argv[i]}"]
    args = build_parser().parse_args(argv)
    args.kernel_only = not args.trust_search
    try:
        settings.apply(args, DEFAULT_TIMEOUT)   # [tool.uwmr-symbolic] in pyproject.toml; flags win
        return _main(args)
    except (settings.SettingsError, UsageError) as exc:     # one line, exit 2
        print(f"uwmr-verify: {exc}", file=sys.stderr)
        return 2


def _given(args) -> set[str]:
    """The options given that change what a command does, as typed
    ({"--format", ...}; "FILE" for design files): not the cache's, --quiet,
    --kernel-only (the default), nor --timeout and --jobs (which
    [tool.uwmr-symbolic] may set for every command)."""
    given = {"FILE"} if args.files else set()
    for action in build_parser()._actions:
        if action.option_strings and action.dest not in ("help", "version", "no_cache", "cache_dir", "timeout",
                                                         "jobs", "kernel_only_flag", "quiet") \
                and getattr(args, action.dest, action.default) not in (action.default, None, False):
            given.add(max(action.option_strings, key=len))
    return given


def _main(args) -> int:
    if not 0 < args.timeout <= settings.MAX_TIMEOUT:        # (nan fails both)
        raise UsageError(f"--timeout must be a number of seconds above 0 and at most {settings.MAX_TIMEOUT:g}, "
                         f"not {args.timeout:g}")
    if args.jobs is not None and args.jobs < 1:
        raise UsageError("--jobs must be at least 1")
    designs = [c for c in args.check_certificate or () if c.endswith(".py")]
    if designs:
        raise UsageError(f"--check-certificate takes certificate files (.json), and {designs[0]} looks like a design "
                         f"file; verify it with `uwmr-verify {designs[0]}`")
    for mode, flag, takes in (("check_certificate", "--check-certificate", "--timeout and --jobs"),
                              ("check_generated", "--check-generated", "design files")):
        given = _given(args) - {flag} - ({"FILE"} if mode == "check_generated" else set())
        if getattr(args, mode) and given:
            raise UsageError(f"{flag} does not go with {sorted(given)[0]} (it takes {takes} only); "
                             f"run the two separately")
    if args.check_certificate:
        return check_certificates(args.check_certificate, args.jobs, args.timeout)
    if args.check_generated:
        return check_generated(args)
    if args.force and args.codegen is None:
        raise UsageError("--force only makes sense with --codegen")
    if args.codegen and args.codegen.endswith(".py") and Path(args.codegen).is_file():
        raise UsageError(f"--codegen takes a folder, and {args.codegen} is a design file; name the design files "
                         f"before the option (uwmr-verify {args.codegen} --codegen) or write --codegen=DIR")
    if not args.files:
        raise UsageError("no design file given (try: uwmr-verify designs/*.py)")
    empty = [flag for flag, value in (("--cache-dir", args.cache_dir), ("--certificate", args.certificate),
                                      ("--junit-xml", args.junit_xml)) if value == ""]
    if empty:
        raise UsageError(f"{empty[0]} needs a path, not an empty text")
    if not 0 <= (args.monte_carlo or 0) <= MAX_MONTE_CARLO or not 0 <= args.delay <= MAX_DELAY:
        raise UsageError(f"--monte-carlo must be in 0..{MAX_MONTE_CARLO} and --delay in 0..{MAX_DELAY} "
                         f"(samples of the 100 Hz loop)")
    simulate = args.simulate or args.monte_carlo is not None      # (--monte-carlo 0 simulates too)
    if args.seed is not None and args.seed < 0:
        raise UsageError(f"--seed must be a non-negative integer, not {args.seed}")
    if not simulate and (args.reference or args.delay or args.seed is not None):
        raise UsageError("--reference, --delay and --seed only make sense with --simulate")
    if args.trust_search and args.kernel_only_flag:
        raise UsageError("--trust-search and --kernel-only contradict each other; give one")
    paths = expand_paths(args.files)
    if not paths:
        raise UsageError(f"no design files in {', '.join(args.files)} (a folder is read for its *.py files)")
    inputs = {Path(p).resolve() for p in paths}
    for flag, target in (("--certificate", args.certificate if len(paths) == 1 else None),
                         ("--junit-xml", args.junit_xml)):
        if target and Path(target).resolve() in inputs:     # (red team 28: the design became the JSON)
            raise UsageError(f"{flag} {target} is a design file to be checked; write the {flag[2:]} to another file")
    if len(paths) > 1 and (args.codegen is not None or args.certificate):
        stems = {}
        for path in paths:
            other = stems.setdefault(Path(path).stem, path)
            if other != path:
                raise UsageError(f"{other} and {path} have the same name {Path(path).stem!r}, and --codegen and "
                                 f"--certificate write one folder or file per name; rename one")
    refs = load_references(args.reference, args.timeout) if simulate else {}  # before anything is verified or written
    cache = None if args.no_cache else ResultCache(args.cache_dir)
    why = cache and cache.unwritable()
    if why:
        print(f"uwmr-verify: warning: the cache folder {cache.directory} cannot be written "
              f"({why}); results are not cached (--cache-dir DIR or --no-cache)", file=sys.stderr)
    progress = Progress(len(paths))
    try:
        results = check_files(paths, args.timeout, use_cache=not args.no_cache, jobs=args.jobs,
                              cache_dir=args.cache_dir, progress=progress, kernel_only=args.kernel_only,
                              want_reports=(simulate or args.codegen is not None) and args.kernel_only)
    finally:
        progress.close()
    # (with --trust-search the batch's reports count the search's verdicts: code is generated from
    # the kernel's only, so `Reports` verifies again, kernel only)
    reports = Reports(args.timeout, results)
    scenarios = {name for d in results for name in (d.get("gains") or {})}
    unused = sorted(set(refs) - scenarios)
    if unused:
        raise UsageError(f"--reference {unused[0]}=...: no design has a gain scenario {unused[0]!r} "
                         f"(theirs: {', '.join(sorted(scenarios)) or 'none'})")
    cert_status = write_certificates(paths, results, args.certificate) if args.certificate else 0
    for d in results:
        d.pop("certificate", None)
        if d.get("error") is not None:
            print(f"{shown(d['design'])}: {d['error']}", file=sys.stderr)
    sim_status = 0
    if simulate:
        sim_status = run_simulations(results, args, refs, reports)
    good = [d for d in results if d.get("error") is None]
    many = len(paths) > 1
    if args.format == "json":
        if not many:
            if good:
                print(render_json(good[0]))
        else:
            print(json.dumps(results, indent=2))
    elif args.format == "junit":
        print(render_junit(results))
    elif args.format == "github":
        annotations = render_github(results)
        if annotations:
            print(annotations)
        print(render_summary(results))
        step_summary = os.environ.get("GITHUB_STEP_SUMMARY")
        if step_summary:
            try:
                with open(step_summary, "a", encoding="utf-8") as fh:
                    fh.write(render_markdown_summary(results))
            except OSError as exc:  # the job summary is a nicety; the annotations and exit status are what count
                print(f"uwmr-verify: warning: the job summary GITHUB_STEP_SUMMARY={step_summary} cannot be "
                      f"written ({exc.strerror or exc})", file=sys.stderr)
    else:
        if good and not (many and args.quiet):
            print("\n\n".join(render_text(d) + (("\n\n" + render_simulation_text(d["simulation"]))
                                                 if "simulation" in d else "") for d in good))
        if many:
            if good and not args.quiet:
                print()
            print(render_summary(results))
    if args.junit_xml:
        try:        # (its folder made, as --certificate's; the error names the file asked for: red team 28)
            Path(args.junit_xml).parent.mkdir(parents=True, exist_ok=True)
            write_text_atomic(args.junit_xml, render_junit(results) + "\n")
        except OSError as exc:
            print(f"uwmr-verify: cannot write {args.junit_xml}: {exc.strerror or exc}", file=sys.stderr)
            return 2
    status = worst_status([*(d["exit_status"] for d in results), sim_status, cert_status])
    if args.codegen is not None:
        status = worst_status([status, write_code(paths, results, args.codegen, args.force, reports)])
    return status


def run() -> None:
    """Console entry point: `main`, and a reader that closes the pipe early
    (`uwmr-verify ... | head`) ends the command quietly with status 141, as
    if killed by SIGPIPE; Ctrl-C ends it with one line and status 130; an
    output that cannot be written (a full disk, a closed stdout) with one
    line and status 2."""
    if sys.stdout is None:          # started with stdout closed (`uwmr-verify d.py >&-`): nothing could be reported
        print("uwmr-verify: cannot write the output: standard output is closed", file=sys.stderr)
        sys.exit(2)
    try:
        status = main()
        if sys.stdout is not None:
            sys.stdout.flush()
    except BrokenPipeError:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        status = 141
    except KeyboardInterrupt:
        print("uwmr-verify: interrupted (Ctrl-C); the files written before are complete, the others were "
              "not written", file=sys.stderr)
        status = 130
    except OSError as exc:          # stdout on a full disk
        with contextlib.suppress(OSError, ValueError):
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        print(f"uwmr-verify: cannot write the output: {exc.strerror or exc}", file=sys.stderr)
        status = 2
    if any(t is not threading.main_thread() and not t.daemon and t.is_alive() for t in threading.enumerate()):
        # a thread that a --reference file started would hold the exit (red team 28): the work is done
        with contextlib.suppress(OSError, ValueError):
            sys.stdout.flush()
            sys.stderr.flush()
        os._exit(status)
    sys.exit(status)


if __name__ == "__main__":
    run()
