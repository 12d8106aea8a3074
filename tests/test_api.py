"""The Python API: verify (in memory, in a worker process or in the calling
thread, from any thread), verify_file, generate, simulate, and what a Report
and a SimulationResult show.  The tests that start a worker process, compile
or simulate are marked slow (not in make test-fast)."""
import json
import threading
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
import sympy as sp  # noqa: E402

import uwmr_symbolic  # noqa: E402
from _cli import SEARCH_ONLY  # noqa: E402
from uwmr_symbolic import DesignError, e1, e2, generate, simulate, verify, verify_file  # noqa: E402

ROOT = Path(__file__).resolve().parent.parent
ALPHA, BETA = sp.symbols("alpha beta", positive=True)
F3 = sp.log(sp.cosh(sp.sqrt(BETA * e1**2 + BETA * e2**2 + 1) - 1)) / ALPHA      # design 3, (31)
JIANG = sp.log(1 + e1**2 + e2**2) / 2                                              # design 1, (26)
CIRCLE = dict(k1=0.25, k2=0.7, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0)       # Table 1


def _verdicts(report):
    return {p: str(v.status) for p, v in report.properties.items()}


def test_the_module_stays_importable_and_is_callable():
    import uwmr_symbolic.verify as module
    from uwmr_symbolic.verify import verify_design
    assert module is uwmr_symbolic.verify is verify
    assert module.verify_design is verify_design
    assert callable(verify) and "gains" in str(__import__("inspect").signature(verify))


@pytest.mark.slow
def test_verify_design_3_in_memory_matches_the_file():
    report = verify(F3, {ALPHA: 1.0, BETA: 4.0}, {"circle": dict(CIRCLE, lam=0.3)}, name="Design 3", worker=False)
    assert _verdicts(report) == {p: "proved" for p in uwmr_symbolic.verify.PROPERTIES}
    assert report.kf.exact == 2                       # sqrt(beta)/alpha, Table 1
    assert report.exit_status == 0
    g = report.gains["circle"]
    # bound (10): |W| <= 1 + 0.3 * 0.5 * 2 + 0.7 = 2 = Wmax exactly
    assert g.W_bound == 2 and g.W_margin == 0 and g.V_bound == sp.Rational(3, 4)
    assert report.path == Path("<in-memory>/design_3.py")
    from_file = verify_file(ROOT / "designs" / "design3_logcosh.py", worker=False)
    assert _verdicts(from_file) == _verdicts(report) and from_file.kf.exact == report.kf.exact


@pytest.mark.slow
def test_verify_in_a_worker_process_gives_the_same_report():
    here = verify(JIANG, gains={"circle": dict(CIRCLE, lam=1.2)}, name="Jiang", worker=False)
    there = verify(JIANG, gains={"circle": dict(CIRCLE, lam=1.2)}, name="Jiang")
    assert there.kf.exact == here.kf.exact == sp.Rational(1, 2)
    assert _verdicts(there) == _verdicts(here) == {p: "proved" for p in here.properties}
    assert there.exit_status == here.exit_status == 0


def test_kernel_only_is_the_default_and_its_opposite_reaches_the_worker():
    """sqrt(rho + 10^-40) - 10^-20 (tests/_cli.py) has P1 proved by the
    search only (no kernel bound of F' near 0).  By default (kernel_only=True) P1
    is unknown and the report inconclusive, P2 stays proved;
    kernel_only=False, in a worker process as here, counts the search's
    proof.  The kernel summary is the same either way."""
    f = sp.sympify(SEARCH_ONLY, locals={"rho": e1**2 + e2**2})
    searched = verify(f, name="search_only", kernel_only=False)
    strict = verify(f, name="search_only", worker=False)
    assert searched.properties["P1"].status == "proved" and strict.properties["P1"].status == "unknown"
    assert strict.properties["P1"].reason.startswith(
        "not re-checked by the kernel (the search says proved, which counts only with --trust-search: ")
    assert strict.properties["P2"].status == "proved" and strict.exit_status == 3
    assert strict.kernel == searched.kernel and "P1" in strict.kernel["search"]


def test_verify_from_another_thread_respects_its_timeout():
    out = {}

    def run():
        start = time.monotonic()
        # parameters no other test uses: nothing of this f is memoised in the process (serial `make test`)
        out["report"] = verify(F3, {ALPHA: 3, BETA: 7}, timeout=0.3, worker=False)
        out["seconds"] = time.monotonic() - start

    thread = threading.Thread(target=run)
    thread.start()
    thread.join(120)
    assert not thread.is_alive(), "verify() in a thread did not return"
    report = out["report"]
    assert report.timed_out
    reasons = [v.reason for v in report.properties.values() if not v.proved]
    # each property either ran out of time, or (a fast host) the search finished but the kernel's re-check did not
    assert reasons and all("did not finish within" in r or r.startswith("not re-checked by the kernel")
                                     for r in reasons), reasons
    assert sum("did not finish within" in r for r in reasons) >= 4, reasons
    assert not any(v.refuted for v in report.properties.values())
    # the property loop stops at 0.3 s; kf and the replay get at least 1 s and 5 s of their own
    assert out["seconds"] < 15, out["seconds"]
    # and with time enough, a thread gets the verdicts of the main thread
    def full():
        out["full"] = verify(JIANG, worker=False)
    thread = threading.Thread(target=full)
    thread.start()
    thread.join(300)
    assert _verdicts(out["full"]) == {p: "proved" for p in out["full"].properties}


@pytest.mark.slow
def test_two_threads_verify_in_worker_processes_at_once():
    out = {}

    def run(key, f):
        out[key] = verify(f)

    threads = [threading.Thread(target=run, args=("jiang", JIANG)),
               threading.Thread(target=run, args=("sqrt", sp.sqrt(1 + e1**2 + e2**2) - 1))]
    for t in threads:
        t.start()
    for t in threads:
        t.join(300)
    assert out["jiang"].kf.exact == sp.Rational(1, 2) and out["sqrt"].kf.exact == 1      # Table 1
    assert out["jiang"].exit_status == out["sqrt"].exit_status == 0


class Label(str):
    """Defined in this test module, which a worker process cannot import."""


@pytest.mark.slow
def test_what_the_worker_cannot_read_is_verified_here():
    with pytest.warns(RuntimeWarning, match="could not read the design"):
        report = verify(JIANG, name=Label("jiang"))
    assert report.kf.exact == sp.Rational(1, 2) and report.exit_status == 0


@pytest.mark.slow
def test_a_dying_design_file_is_reported_unusable(tmp_path):
    design = tmp_path / "exits.py"
    design.write_text("import os\nos._exit(7)\n")
    report = verify_file(design, timeout=20)
    assert report.exit_status == 2 and "died" in report.error


@pytest.mark.slow
def test_worker_is_killed_when_the_design_blocks_inside_c():
    start = time.monotonic()
    report = verify_file(ROOT / "tests" / "adversarial" / "blocks_in_c.py", timeout=1)
    elapsed = time.monotonic() - start
    assert report.timed_out and report.exit_status == 3
    assert all("worker process was stopped" in v.reason for v in report.properties.values())
    assert elapsed < 40, elapsed


def test_bad_input_raises_in_memory_and_is_reported_from_a_file():
    x, y = sp.symbols("x y", real=True)
    with pytest.raises(DesignError, match="name them e1 and e2"):
        verify(sp.log(1 + x**2 + y**2), worker=False)
    with pytest.raises(DesignError, match="not a SymPy expression"):
        verify("log(1 + e1**2)")
    report = verify_file(ROOT / "tests" / "bad_inputs" / "numpy_log.py", worker=False)
    assert report.exit_status == 2 and "use sympy.log" in report.error
    assert "use sympy.log" in report._repr_html_()


def test_report_dict_html_and_profile_plot():
    report = verify(F3, {ALPHA: 1.0, BETA: 4.0}, {"circle": dict(CIRCLE, lam=0.3)}, name="Design 3", worker=False)
    d = report.to_dict()
    json.dumps(d)
    assert d["kf"]["exact"] == "2" and d["properties"]["P6"]["verdict"] == "proved"
    html = report._repr_html_()
    for words in (r"\(f(e_1, e_2) = ", r"\alpha = 1, \beta = 4", "<td>P8</td>", "kf = 2 (approached at infinity",
                  "bound (10)", "all properties proved, gains within the limits"):
        assert words in html, words
    assert html.count(">proved</b>") == 8
    fig = report.plot_profile(s_max=20)
    f_axis, df_axis, ratio_axis = fig.axes
    s, dF = df_axis.lines[0].get_data()
    assert np.nanmax(dF) <= 2 and np.nanmax(dF) > 1.99           # F' approaches kf = 2 from below
    assert [tuple(line.get_ydata()) for line in df_axis.lines[1:]] == [(2.0, 2.0)]
    k6 = d["properties"]["P6"]["k_float"]
    assert ratio_axis.lines[1].get_ydata()[0] == k6 and np.nanmax(ratio_axis.lines[0].get_ydata()) <= k6


def test_no_gains_report_says_so():
    report = verify(JIANG, worker=False)
    assert "no gain scenarios given, so bound (10) was not checked" in report._repr_html_()
    assert "gains within the limits" not in str(report)


@pytest.mark.slow
def test_generate_targets(tmp_path):
    import casadi
    report = verify(JIANG, name="Jiang", worker=False)
    only_py = generate(report, tmp_path / "py", targets=("python",))
    assert [p.name for p in only_py] == ["jiang.py"]
    every = generate(report, tmp_path / "all")
    assert sorted(p.name for p in every) == ["CMakeLists.txt", "example_main.c", "jiang.c", "jiang.casadi",
                                             "jiang.h", "jiang.py"]
    fn = casadi.Function.load(str(tmp_path / "all" / "jiang.casadi"))
    ns = {}
    exec((tmp_path / "all" / "jiang.py").read_text(), ns)
    args = (0.3, -0.2, 0.1, 0.5, 1.0, 0.25, 0.7, 1.2)
    v, w = fn(*args)
    assert np.allclose([float(v), float(w)], ns["control"](*args), rtol=1e-12)
    with pytest.raises(ValueError, match="unknown target"):
        generate(report, tmp_path / "x", targets=("rust",))
    from uwmr_symbolic.codegen import CodegenRefused
    unverified = verify(e1**2 + e2**2 * (1 + e1**2), worker=False)
    with pytest.raises(CodegenRefused):
        generate(unverified, tmp_path / "no")
    assert not (tmp_path / "no").exists()


@pytest.mark.slow
def test_simulate_circle_with_the_baseline():
    report = verify(JIANG, gains={"circle": dict(CIRCLE, lam=1.2)}, name="Jiang", worker=False)
    sim = simulate(report, "circle", baseline=True)
    assert sim.ok and set(sim.runs) == {"continuous", "digital", "baseline"}
    for kind in ("continuous", "digital"):
        m = sim.runs[kind]
        assert m["max_abs_v"] <= 0.75 and m["max_abs_w"] <= 2.0 and m["converged"]
        tr = sim.trajectories[kind]
        assert tr.t[-1] == pytest.approx(80.0) and len(tr.x) == len(tr.t)
    # the unsaturated controller (38) exceeds Vmax on the circle, as in the paper
    assert sim.runs["baseline"]["max_abs_v"] > 0.75 and not sim.runs["baseline"]["v_ok"]
    t, U = sim.lyapunov("continuous")
    assert U[-1] < 1e-6 * U[0] and sim.runs["continuous"]["lyapunov_ok"]
    d = sim.to_dict()
    assert json.loads(json.dumps(d))["runs"]["digital"]["converged"] is True
    assert "unsaturated (38)" in sim._repr_html_() and "&gt; Vmax" in sim._repr_html_()
    fig = sim.plot_inputs()
    v_axis = fig.axes[0]
    assert sorted({line.get_ydata()[0] for line in v_axis.lines if len(line.get_ydata()) == 2}) == [-0.75, 0.75]
    assert len(sim.plot_path().axes) >= 3 and len(sim.plot_errors().axes) == 3
    assert len(sim.plot_lyapunov().axes[0].lines) == 1
    with pytest.raises(ValueError, match="no gain scenario 'lemniscate'"):
        simulate(report, "lemniscate")


@pytest.mark.slow
def test_simulate_a_straight_line_with_wr_max_zero():
    from uwmr_symbolic.simulation import from_path
    line = from_path("line", lambda t: (0.5 * t, 0.0 * t), lambda t: (0.5 + 0 * t, 0 * t),
                     lambda t: (0 * t, 0 * t), 0.0, 40.0, "straight line at 0.5 m/s")
    gains = dict(CIRCLE, lam=1.2, Wr_max=0)        # a straight line: |Wr|max = 0 in (3)
    report = verify(JIANG, gains={"line": gains}, name="Jiang", worker=False)
    assert report.gains["line"].W_bound == sp.Rational(3, 10) + sp.Rational(7, 10)    # 0 + 1.2*0.5*0.5 + 0.7
    sim = simulate(report, line, kinds=("digital",), backends=("python",))
    m = sim.runs["digital"]
    assert sim.ok and m["converged"] and m["max_abs_v"] <= 0.75 and m["max_abs_w"] <= 2.0
    assert sim.scenario.pose0 == pytest.approx((-0.5, -0.5, 0.0))      # 0.5 m beside the start
    tr = sim.trajectories["digital"]
    assert abs(tr.y[-1]) < 0.01 and tr.x[-1] == pytest.approx(20.0, abs=0.01)


@pytest.mark.slow
def test_the_reused_worker_reads_relative_paths_from_the_current_folder(tmp_path, monkeypatch):
    for folder, f in (("a", "sp.log(1 + e1**2 + e2**2) / 2"), ("b", "sp.sqrt(1 + e1**2 + e2**2) - 1")):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / "d.py").write_text(f"import sympy as sp\nfrom uwmr_symbolic import e1, e2\nf = {f}\n")
    monkeypatch.chdir(tmp_path / "a")
    assert verify_file("d.py").kf.exact == sp.Rational(1, 2)
    monkeypatch.chdir(tmp_path / "b")
    assert verify_file("d.py").kf.exact == 1


def test_huge_exact_numbers_are_reported_as_powers_that_sympy_reads_back():
    """10^300 log(1 + rho) printed f, kf and P6's k as 301-digit integers."""
    d = verify(10**300 * sp.log(1 + e1**2 + e2**2), worker=False).to_dict()
    assert d["f"] == "(10**300)*log(e1**2 + e2**2 + 1)" and d["kf"]["exact"] == "10**300"
    assert d["properties"]["P6"]["reason"].startswith("k = 2*10**300 (sup F'(s)/s = 2*10**300 = 2e+300), h = ")
    assert sp.sympify(d["kf"]["exact"]) == 10**300 and d["exit_status"] == 0


@pytest.mark.parametrize("value, text", [(10**21, "10**21"), (-3 * 10**40, "-3*10**40"), (2**100, "2**100"),
                                         (10**21 + 1, str(10**21 + 1)), (10**20, str(10**20)),
                                         (sp.Rational(7, 10**30), "7/(10**30)"), (sp.Rational(1, 3), "1/3")])
def test_exact_text_of_numbers(value, text):
    from uwmr_symbolic.kf import exact_text
    assert exact_text(value) == text and sp.sympify(text) == value


def test_exact_text_reads_back_as_the_same_expression():
    from hypothesis import given, settings, strategies as st
    from uwmr_symbolic.kf import exact_text
    x = sp.Symbol("x")
    huge = st.builds(lambda m, k, neg: (-1) ** neg * m * sp.Integer(10) ** k, st.integers(1, 999), st.integers(0, 400),
                     st.booleans()) | st.builds(lambda k: sp.Integer(2) ** k, st.integers(60, 1100))
    number = huge | st.builds(lambda p, q: sp.Rational(p, q), huge, huge)
    shape = st.sampled_from([lambda c: c, lambda c: c * x, lambda c: x - c, lambda c: x**c, lambda c: sp.exp(-c * x),
                             lambda c: sp.log(1 + c * x**2) / c, lambda c: (x + c) ** sp.Rational(3, 2), lambda c: c**x])

    @settings(max_examples=300, deadline=None, derandomize=True)
    @given(number, shape)
    def round_trip(c, make):
        e = make(c)
        assert sp.sympify(exact_text(e), locals={"x": x}) == e
    round_trip()
