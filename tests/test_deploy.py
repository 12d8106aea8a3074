"""From a proved design to a robot (issue 11): errors (7), the heading
tracker, `_step` in C and Python, the example loop and its CMake package.

* errors (7) and the tracker of the committed generated C (double, float)
  and Python against (7) evaluated with mpmath at 200 bits, along heading
  sequences that arrive wrapped and jump by multiples of 2 pi;
* C and Python `step` agree to 1e-12 along a whole closed-loop trajectory;
* the example loop, configured and built with CMake through
  add_subdirectory, converges on the paper's circle within Vmax, Wmax and
  bound (10), as the Python simulation does;
* the validation at generation time refuses an error function that wraps e3.
"""
from __future__ import annotations

import math
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from uwmr_symbolic.codegen import build, reference, validate
from uwmr_symbolic.codegen.harness import STRICT, build_library
from uwmr_symbolic.design import load_design

ROOT = Path(__file__).resolve().parent.parent
STEMS = sorted(p.name for p in (ROOT / "generated").iterdir() if p.is_dir())
TWO_PI = 2 * math.pi


@pytest.fixture(scope="module")
def compiled(tmp_path_factory):
    work = tmp_path_factory.mktemp("deploy")
    return {stem: build_library(ROOT / "generated" / stem, stem, work) for stem in ("design1_jiang", "design3_logcosh")}


@pytest.fixture(scope="module")
def modules():
    return {stem: validate.load_module(ROOT / "generated" / stem / f"{stem}.py", f"_deploy_{stem}")
            for stem in ("design1_jiang", "design3_logcosh")}


def _jumping_sequence(precision, length=400, seed=5):
    """A robot and a reference turning continuously (|step| < pi), each
    heading handed over either wrapped to (-pi, pi] or shifted by 2 pi k with
    k changing at every call (jumps of up to 8 pi between calls)."""
    rng = np.random.default_rng(seed)
    u = np.cumsum(rng.uniform(-0.5, 0.5, (length, 2)), axis=0) + np.array([-2 * math.pi, 0.3])
    k = rng.integers(-2, 3, (length, 2)).astype(float)
    wrapped = rng.random((length, 1)) < 0.3
    kw = np.floor((u + math.pi) / TWO_PI)
    k = np.where(wrapped, kw, k)
    heads = u - TWO_PI * k
    pos = rng.uniform(-3, 3, (length, 4))
    rows = np.column_stack([pos[:, 0], pos[:, 1], heads[:, 0], pos[:, 2], pos[:, 3], heads[:, 1]])
    turns = (k[:, 1] - k[0, 1]) - (k[:, 0] - k[0, 0])
    if precision == "float":
        rows = rows.astype(np.float32).astype(float)
    return rows, turns, u


@pytest.mark.parametrize("precision", ["double", "float"])
def test_c_errors_and_tracker_against_mpmath_with_2pi_jumps(compiled, precision):
    lib = compiled["design3_logcosh"]
    f32 = precision == "float"
    rows, turns, u = _jumping_sequence(precision)
    assert np.abs(np.diff(rows[:, 2])).max() > 2 * math.pi      # the inputs do jump
    e1, e2, e3, st = lib.track(rows, f32=f32)
    worst = validate.check_errors("design3_logcosh", f"C {precision} tracker", rows, turns, (e1, e2, e3), st,
                                  precision)
    assert worst <= validate.TOL[precision]
    # e3 is the continuous heading difference: it moves as the true headings do
    true_e3 = (u[:, 1] - u[:, 0]) - (u[0, 1] - u[0, 0]) + (rows[0, 5] - rows[0, 2])
    assert np.abs(e3 - true_e3).max() < (1e-9 if precision == "double" else 2e-5)
    assert np.abs(np.diff(e3)).max() < 1.0 + 1e-6
    # without the tracker (headings as given) e3 jumps by multiples of 2 pi
    _, _, raw3, st2 = lib.errors(rows, f32=f32)
    assert (st2 == 0).all() and np.abs(np.diff(raw3)).max() > 2 * math.pi
    worst = validate.check_errors("design3_logcosh", f"C {precision} errors (7)", rows, None,
                                  lib.errors(rows, f32=f32)[:3], st2, precision)
    assert worst <= validate.TOL[precision]


def test_python_errors_and_tracker_against_mpmath_with_2pi_jumps(modules):
    mod = modules["design3_logcosh"]
    rows, turns, _ = _jumping_sequence("double", seed=9)
    tracker = mod.Tracker()
    got = np.array([tracker.track(tuple(r[:3]), tuple(r[3:])) for r in rows])
    validate.check_errors("design3_logcosh", "Python tracker", rows, turns, got[:, :3].T, got[:, 3], "double")
    # vectorised: three robots at once give the same as one at a time
    seqs = [_jumping_sequence("double", seed=s) for s in (1, 2, 3)]
    batch = mod.Tracker()
    out = [batch.track(tuple(np.array([s[0][k, j] for s in seqs]) for j in range(3)),
                       tuple(np.array([s[0][k, j] for s in seqs]) for j in range(3, 6))) for k in range(len(rows))]
    for i, (r, _, _) in enumerate(seqs):
        single = mod.Tracker()
        for k in range(len(rows)):
            want = single.track(tuple(r[k, :3]), tuple(r[k, 3:]))
            assert [float(out[k][j][i]) for j in range(3)] == list(want[:3])
    ex = reference.tracking_errors(rows, turns)
    assert np.abs(got[:, 2] - ex["hi"][:, 2]).max() <= 1e-12 * (np.abs(rows[:, [2, 5]]).sum(axis=1).max() + 50)


def test_tracker_keeps_its_state_on_bad_input(compiled, modules):
    lib, mod = compiled["design1_jiang"], modules["design1_jiang"]
    rows = np.array([[0, 0, 3.0, 1, 0, 3.0],
                     [0, 0, math.nan, 1, 0, 3.1],        # status 2, state kept
                     [0, 0, 1e13, 1, 0, 3.1],            # beyond UWMR_HEADING_MAX: status 4
                     [0, 0, -3.1, 1, 0, 3.1]])           # 3.0 -> -3.1 is +0.18 rad: one turn up
    e1, e2, e3, st = lib.track(rows)
    assert list(st) == [0, 2, 4, 0]
    assert e3[1] == e3[2] == 0.0 and e1[1] == 0.0
    assert e3[3] == pytest.approx(3.1 - (-3.1 + TWO_PI), abs=1e-15)
    tracker = mod.Tracker()
    py = [tracker.track(tuple(r[:3]), tuple(r[3:])) for r in rows]
    assert [p[3] for p in py] == [0, 2, 4, 0] and py[3][2] == e3[3]
    with pytest.raises(ValueError, match="shape"):
        tracker.track((np.zeros(2), 0.0, 0.0), (0.0, 0.0, 0.0))


def _closed_loop_python(mod, gains, steps=8000, h=0.01):
    """The paper's circle at 100 Hz driven by the Python `step` (reference
    heading wrapped, robot from (2, 2, -2 pi)); rows for the C batch step."""
    tracker = mod.Tracker()
    x, y, th = 2.0, 2.0, -TWO_PI
    rows, vw = [], []
    for k in range(steps + 1):
        t = k * h
        ref = (0.5 * math.sin(t), 0.5 * (1 - math.cos(t)), math.atan2(math.sin(t), math.cos(t)))
        v, w = mod.step(tracker, (x, y, th), ref, 0.5, 1.0, gains)
        rows.append([x, y, th, *ref, 0.5, 1.0, gains["k1"], gains["k2"], gains["lam"]])
        vw.append((v, w))
        if k == steps:
            break
        half = 0.5 * w * h
        d = v * h * (math.sin(half) / half if half != 0 else 1.0)
        x, y, th = x + d * math.cos(th + half), y + d * math.sin(th + half), th + w * h
    return np.array(rows), np.array(vw), (x, y, th)


@pytest.mark.parametrize("stem", ["design1_jiang", "design3_logcosh"])
def test_c_and_python_step_agree_along_a_trajectory(compiled, modules, stem):
    mod, lib = modules[stem], compiled[stem]
    g = load_design(ROOT / "designs" / f"{stem}.py").gains["circle"]
    gains = {k: float(g[k]) for k in ("k1", "k2", "lam")}
    rows, vw, final = _closed_loop_python(mod, gains)
    v, w, st = lib.step(rows)
    assert (st == 0).all()
    assert np.abs(v - vw[:, 0]).max() <= 1e-12 and np.abs(w - vw[:, 1]).max() <= 1e-12
    # the loop converged within Vmax, Wmax and bound (10); e3(0) = 2 pi was followed, not wrapped
    assert np.abs(vw[:, 0]).max() <= float(g["Vmax"]) and np.abs(vw[:, 1]).max() <= float(g["Wmax"])
    assert math.hypot(final[0] - 0.5 * math.sin(80.0), final[1] - 0.5 * (1 - math.cos(80.0))) < 0.01
    assert abs(80.0 - final[2]) < 0.01                         # the robot's heading unwrapped: 80 rad
    # the gain alias: lambda for lam
    t1, t2 = mod.Tracker(), mod.Tracker()
    a = mod.step(t1, tuple(rows[5, :3]), tuple(rows[5, 3:6]), 0.5, 1.0, gains)
    b = mod.step(t2, tuple(rows[5, :3]), tuple(rows[5, 3:6]), 0.5, 1.0,
                 {"k1": gains["k1"], "k2": gains["k2"], "lambda": gains["lam"]})
    assert a == b


def test_float_example_and_new_functions_build_strictly(tmp_path):
    """-std=c99 -Wall -Wextra -Werror -pedantic -Wdouble-promotion, double and
    -DUWMR_NO_DOUBLE: the library and the example loop; the float example
    converges too."""
    src = ROOT / "generated" / "design2_sqrt"
    for flags, name in (([], "d"), (["-DUWMR_NO_DOUBLE"], "f")):
        exe = tmp_path / name
        subprocess.run(["gcc", *STRICT, "-O2", *flags, str(src / "design2_sqrt.c"), str(src / "example_main.c"),
                        "-o", str(exe), "-lm"], check=True, capture_output=True, text=True)
        run = subprocess.run([str(exe)], capture_output=True, text=True)
        assert run.returncode == 0, run.stdout
        assert "converged within the limits: yes" in run.stdout


def _values(out: str) -> dict:
    vals = {}
    for line in out.splitlines():
        m = re.match(r"^(.+?)\s+=\s+(\S+)", line)
        if m:
            vals[m.group(1)] = float(m.group(2))
    return vals


@pytest.mark.skipif(shutil.which("cmake") is None, reason="cmake missing: `make test` installs it")
def test_cmake_package_builds_and_the_example_converges(tmp_path):
    """All designs through add_subdirectory in one parent project (distinct
    uwmr::<stem> targets), a consumer linking two of them, the examples built
    with the strict flags; every example converges on the circle within Vmax,
    Wmax and bound (10), and design 3's ends where the Python simulation ends."""
    parent = tmp_path / "parent"
    parent.mkdir()
    lines = ["cmake_minimum_required(VERSION 3.10)", "project(consumer C)"]
    for stem in STEMS:
        lines.append(f"set(UWMR_{stem.upper()}_EXAMPLE ON CACHE BOOL \"\")")
        lines.append(f"add_subdirectory({(ROOT / 'generated' / stem).as_posix()} {stem})")
    lines += ["add_executable(consumer consumer.c)",
              "target_link_libraries(consumer PRIVATE uwmr::design1_jiang uwmr::design3_logcosh)"]
    (parent / "CMakeLists.txt").write_text("\n".join(lines) + "\n")
    (parent / "consumer.c").write_text(
        '#include "design1_jiang.h"\n#include "design3_logcosh.h"\n'
        "int main(void)\n{\n    double v, w;\n    uwmr_design3_logcosh_gains g = {0.25, 0.7, 0.3};\n"
        "    uwmr_design1_jiang_gains g1 = {0.25, 0.7, 1.2};\n"
        "    return uwmr_design3_logcosh_control(0.1, 0.2, 0.3, 0.5, 1.0, &g, &v, &w)\n"
        "        | uwmr_design1_jiang_control(0.1, 0.2, 0.3, 0.5, 1.0, &g1, &v, &w);\n}\n")
    build_dir = tmp_path / "build"
    flags = " ".join(STRICT[1:]) + " -O2"
    cfg = subprocess.run(["cmake", "-S", str(parent), "-B", str(build_dir), f"-DCMAKE_C_FLAGS={flags}"],
                         capture_output=True, text=True)
    assert cfg.returncode == 0, cfg.stdout + cfg.stderr
    bld = subprocess.run(["cmake", "--build", str(build_dir), "-j", "2"], capture_output=True, text=True)
    assert bld.returncode == 0, bld.stdout + bld.stderr
    assert subprocess.run([str(build_dir / "consumer")]).returncode == 0
    finals = {}
    for stem in STEMS:
        run = subprocess.run([str(build_dir / stem / f"uwmr_{stem}_example")], capture_output=True, text=True)
        assert run.returncode == 0, (stem, run.stdout)
        v = _values(run.stdout)
        gains = load_design(ROOT / "designs" / f"{stem}.py").gains["circle"]
        assert v["Vmax"] == float(gains["Vmax"]) and v["Wmax"] == float(gains["Wmax"])
        assert v["max |v|"] <= v["Vmax"] and v["max |w|"] <= v["Wmax"]
        assert v["max |v|"] <= v["bound (10) v"] and v["max |w|"] <= v["bound (10) w"]
        assert v["max |w|"] > 1.5          # e3(0) = 2 pi: the robot turned back hard, within the limit
        assert math.hypot(v["final e1"], v["final e2"]) < 1e-3 and abs(v["final e3"]) < 1e-3
        finals[stem] = v
    from uwmr_symbolic.simulation.api import paper_scenario
    from uwmr_symbolic.simulation.controllers import load_controllers
    from uwmr_symbolic.simulation.loop import run_digital
    ctl = load_controllers(ROOT / "designs/design3_logcosh.py", generated_dir=ROOT / "generated/design3_logcosh")
    sc = paper_scenario("circle")
    tr = run_digital(ctl.c, sc.reference, sc.pose0, dict(k1=0.25, k2=0.7, lam=0.3))
    assert abs(tr.e[0][-1] - finals["design3_logcosh"]["final e1"]) < 1e-9
    assert abs(tr.e[1][-1] - finals["design3_logcosh"]["final e2"]) < 1e-9
    assert np.abs(tr.w).max() == pytest.approx(finals["design3_logcosh"]["max |w|"], abs=1e-8)


def test_validation_refuses_a_wrapped_e3(tmp_path):
    """The translation validation checks errors (7): a C error function that
    wraps e3 into (-pi, pi] (the classic atan2 mistake) is not written."""
    design_path = ROOT / "designs" / "design1_jiang.py"
    model, files = build(design_path)
    stem = "design1_jiang"
    text = files[f"{stem}.c"]
    line = "    d = (thr - th) + n * 6.283185307179586;"
    assert line in text
    files[f"{stem}.c"] = text.replace(line, "    d = remainder(thr - th, 6.283185307179586) + n * 6.283185307179586;")
    with pytest.raises(validate.ValidationFailed, match=r"C double errors \(7\).*e3"):
        validate.validate(load_design(design_path), model, files, None, casadi=False)


def test_design_files_accept_lambda_for_lam(tmp_path):
    text = (ROOT / "designs" / "design1_jiang.py").read_text()
    alias = tmp_path / "alias.py"
    alias.write_text(text.replace("lam=1.2", "**{'lambda': 1.2}"))
    assert float(load_design(alias).gains["circle"]["lam"]) == 1.2
    both = tmp_path / "both.py"
    both.write_text(text.replace("lam=1.2", "lam=1.2, **{'lambda': 1.2}"))
    from uwmr_symbolic.design import DesignError
    with pytest.raises(DesignError, match="alias"):
        load_design(both)
