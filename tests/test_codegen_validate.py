"""The validation gate: code that disagrees with the law is never written,
`uwmr-verify --codegen` exits 1 with one line naming the design, the target,
the input and both values."""
from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

from uwmr_symbolic import cli
from uwmr_symbolic.codegen import (CodegenInvalid, CodegenRefused, build, c_backend, casadi_function, generate,
                                    python_backend, validate_build)
from uwmr_symbolic.verify import verify_design

ROOT = Path(__file__).resolve().parent.parent
D1 = ROOT / "designs/design1_jiang.py"
D5 = ROOT / "designs/design5_rational.py"        # NOT VERIFIED (P3 refuted): needs --force
pytestmark = [pytest.mark.slow, pytest.mark.skipif(shutil.which("gcc") is None, reason="needs gcc")]


@pytest.fixture(scope="module")
def report():
    return verify_design(D1)


def _corrupt(monkeypatch, backend, old, new, count=1, stem=D1.stem):
    render = backend.render

    def bad(*args, **kwargs):
        files = render(*args, **kwargs)
        out = {}
        for name, text in files.items():
            assert old in text or name != stem + (".c" if backend is c_backend else ".py")
            out[name] = text.replace(old, new, count)
        return out
    monkeypatch.setattr(backend, "render", bad)


def test_correct_code_passes_and_reports_what_was_checked(report):
    model, files = build(D1, report=report)
    res = validate_build(D1, model, files, report)
    names = [t.name for t in res.targets]
    assert names[:3] == ["C double", "C float", "Python"] and "CasADi" in names
    assert all(t.rows > 1000 for t in res.targets[:3]) and all(t.worst <= 1e-12 for t in res.targets[:1])


def test_wrong_c_double_is_not_written(report, tmp_path, monkeypatch):
    # H = 1/(rho + 1) of design 1 off by one part in 1e9, in the double variant only
    _corrupt(monkeypatch, c_backend, "const double H = (1.0/(rho + 1.0));", "const double H = (1.000000001/(rho + 1.0));")
    out = tmp_path / "d1"
    with pytest.raises(CodegenInvalid) as exc:
        generate(D1, out, report=report)
    line = exc.value.reasons[0]
    assert line.startswith("design1_jiang: C double: error ") and "got v=" in line and "exact v=" in line
    assert "\n" not in line
    assert not out.exists() and list(tmp_path.iterdir()) == []


def test_c_that_does_not_compile_is_not_written(report, tmp_path, monkeypatch):
    _corrupt(monkeypatch, c_backend, "const float H = ", "const float H = M_PI_2 + ")
    with pytest.raises(CodegenInvalid, match=r"design1_jiang: C: the strict build fails: .*M_PI_2"):
        generate(D1, tmp_path / "d1", report=report)
    assert list(tmp_path.iterdir()) == []


def test_python_that_crashes_is_not_written(report, tmp_path, monkeypatch):
    _corrupt(monkeypatch, python_backend, "return (1.0/(rho + 1.0))", "return math.erf(rho)")
    with pytest.raises(CodegenInvalid, match=r"design1_jiang: Python: the generated module fails: NameError"):
        generate(D1, tmp_path / "d1", report=report)
    assert list(tmp_path.iterdir()) == []


def test_status_4_on_a_finite_input_is_refused(report, tmp_path, monkeypatch):
    # the far form made to overflow, as the t**k forms did for log(1 + rho)**2/4
    _corrupt(monkeypatch, c_backend, "const double D = ", "const double D = (tt < 1e-200 ? HUGE_VAL : 1.0) * ")
    with pytest.raises(CodegenInvalid, match="nonzero status on a finite input whose law is finite"):
        generate(D1, tmp_path / "d1", report=report)


def test_cli_exits_1_with_one_line_and_writes_nothing(tmp_path, monkeypatch, capsys):
    _corrupt(monkeypatch, c_backend, "const double H = (1.0/(rho + 1.0));", "const double H = (1.5/(rho + 1.0));")
    out = tmp_path / "gen"
    status = cli.main([str(D1), "--codegen", str(out), "--no-cache", "-q"])
    err = capsys.readouterr().err
    assert status == 1
    lines = [ln for ln in err.splitlines() if "validation" in ln]
    assert len(lines) == 1 and "design1_jiang: C double: error" in lines[0], err
    assert "Traceback" not in err and not out.exists()


def test_code_that_cannot_be_checked_is_not_written(report, tmp_path, monkeypatch):
    from uwmr_symbolic.codegen import harness

    def broken(*args, **kwargs):
        raise OSError("cannot load the shared library")
    monkeypatch.setattr(harness, "build_library", broken)
    with pytest.raises(CodegenInvalid, match="design1_jiang: the validation could not run: OSError: cannot load"):
        generate(D1, tmp_path / "d1", report=report)
    assert list(tmp_path.iterdir()) == []


# --force lifts the refusal of an unverified design, never the validation gate


@pytest.fixture(scope="module")
def report5():
    return verify_design(D5)


def test_forced_unverified_design_is_validated_and_written(report5, tmp_path):
    model, files = build(D5, force=True, report=report5)
    assert not model.verified
    res = validate_build(D5, model, files, report5)       # kf = None: no bound (10), the rest in full
    assert [t.name for t in res.targets][:3] == ["C double", "C float", "Python"]
    written = generate(D5, tmp_path / "d5", force=True, report=report5)
    assert len(written) == 5 and all("NOT VERIFIED: P3 refuted" in p.read_text()[:400] for p in written)


def test_forced_unverified_design_whose_c_disagrees_is_not_written(report5, tmp_path, monkeypatch, capsys):
    # H = 2/(rho + 1)^2 of design 5 off by one part in 1e9, in the double variant only
    _corrupt(monkeypatch, c_backend, "const double H = 2.0/", "const double H = 2.000000002/", stem=D5.stem)
    out = tmp_path / "d5"
    with pytest.raises(CodegenInvalid) as exc:
        generate(D5, out, force=True, report=report5)
    line = exc.value.reasons[0]
    assert line.startswith("design5_rational: C double: error ") and "got v=" in line and "exact v=" in line
    assert "\n" not in line
    assert not out.exists() and list(tmp_path.iterdir()) == []
    assert "warning" not in capsys.readouterr().err          # refused, not a warning


def test_forced_unverified_design_whose_python_disagrees_is_not_written(report5, tmp_path, monkeypatch):
    _corrupt(monkeypatch, python_backend, "return 2.0/((rho*rho)", "return 2.5/((rho*rho)", stem=D5.stem)
    with pytest.raises(CodegenInvalid, match=r"refused: design5_rational: Python: error .* above 1e-12"):
        generate(D5, tmp_path / "d5", force=True, report=report5)
    assert list(tmp_path.iterdir()) == []


def test_forced_unverified_design_against_a_different_reference_is_not_written(report5, tmp_path, monkeypatch):
    # the code is the one `make generate` writes; the law it is checked against says w is 1e-6 larger
    from uwmr_symbolic.codegen import reference
    table = reference.table

    def scaled(law, x, cache=None):
        ref = table(law, x, cache)
        w = ref["w_hi"]
        with np.errstate(over="ignore"):
            return dict(ref, w_hi=np.where(np.abs(w) < 1e300, w * (1 + 1e-6), w))
    monkeypatch.setattr(reference, "table", scaled)
    with pytest.raises(CodegenInvalid, match="design5_rational: C double: error"):
        generate(D5, tmp_path / "d5", force=True, report=report5)
    assert list(tmp_path.iterdir()) == []


def test_cli_force_exits_1_with_one_line_and_writes_nothing(tmp_path, monkeypatch, capsys):
    _corrupt(monkeypatch, c_backend, "const double H = 2.0/", "const double H = 3.0/", stem=D5.stem)
    out = tmp_path / "gen"
    status = cli.main([str(D5), "--codegen", str(out), "--force", "--no-cache", "-q"])
    err = capsys.readouterr().err
    assert status == 1
    lines = [ln for ln in err.splitlines() if "validation" in ln]
    assert len(lines) == 1 and "design5_rational: C double: error" in lines[0], err
    assert "Traceback" not in err and "warning" not in err and not out.exists()


def test_module_entry_point_force_exits_1_and_writes_nothing(tmp_path, monkeypatch, capsys):
    # `make generate` is `python -m uwmr_symbolic.codegen --force designs/*.py`
    from uwmr_symbolic.codegen.__main__ import main
    _corrupt(monkeypatch, c_backend, "const double H = 2.0/", "const double H = 3.0/", stem=D5.stem)
    status = main(["--force", "--out", str(tmp_path), str(D5)])
    err = capsys.readouterr().err
    assert status == 1 and list(tmp_path.iterdir()) == []
    assert "design5_rational: C double: error" in err and len(err.strip().splitlines()) == 1, err


def test_cli_simulate_of_refused_code_is_one_line_not_a_traceback(tmp_path, monkeypatch, capsys):
    # --simulate runs the generated code: refused code is reported, the verdict still printed
    from uwmr_symbolic.simulation import controllers
    monkeypatch.setattr(controllers, "_CACHE", {})
    _corrupt(monkeypatch, c_backend, "const double H = 2.0/", "const double H = 3.0/", stem=D5.stem)
    status = cli.main([str(D5), "--simulate", "--no-cache", "-q"])
    out, err = capsys.readouterr()
    assert status == 1 and "Traceback" not in err
    lines = [ln for ln in err.splitlines() if "not simulated" in ln]
    assert len(lines) == 1 and "design5_rational: C double: error" in lines[0], err
    assert "P3" in out


# casadi_function: refused unless verified (or force=True), validated like generate's CasADi target


def _wrong_casadi(monkeypatch, factor):
    """The CasADi back-end made to return w * factor."""
    import casadi as ca
    from uwmr_symbolic.codegen import casadi_backend
    orig = casadi_backend.casadi_function

    def wrong(model, *args, **kwargs):
        fn = orig(model, *args, **kwargs)
        xs = fn.sx_in()
        v, w = fn.call(xs)
        return ca.Function(fn.name(), xs, [v, w * factor], fn.name_in(), fn.name_out())
    monkeypatch.setattr(casadi_backend, "casadi_function", wrong)


def test_casadi_function_is_validated_on_the_same_rows_as_generate(report):
    from uwmr_symbolic.codegen import casadi_backend
    from uwmr_symbolic.codegen.validate import validate_casadi
    fn = casadi_function(D1, report)
    assert fn.name_in() == ["e1", "e2", "e3", "vr", "wr", "k1", "k2", "lam"] and fn.name_out() == ["v", "w"]
    model, files = build(D1, report=report)
    full = {t.name: t for t in validate_build(D1, model, files, report).targets}["CasADi"]
    kf = float(model.kf_upper)
    alone = validate_casadi(report.design, model, casadi_backend.casadi_function(model), kf).targets
    assert [t.name for t in alone] == ["CasADi"] and alone[0].rows == full.rows > 500
    assert alone[0].worst == full.worst <= 1e-12


def test_casadi_function_refuses_an_unverified_design_unless_forced(report5):
    with pytest.raises(CodegenRefused) as exc:
        casadi_function(D5, report5)
    assert not isinstance(exc.value, CodegenInvalid) and exc.value.reasons[0].startswith("P3 refuted")
    fn = casadi_function(D5, report5, force=True)
    v, w = fn(0.0, 1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0)      # w = lam vr df/de2 = 2 e2/(rho + 1)^2
    assert float(v) == 1.0 and float(w) == pytest.approx(0.5, rel=1e-15)


@pytest.mark.parametrize("which", ["verified", "forced"])
def test_casadi_function_that_disagrees_with_the_law_is_refused(which, report, report5, monkeypatch):
    _wrong_casadi(monkeypatch, 1 + 1e-9)
    path, rep, stem = (D1, report, "design1_jiang") if which == "verified" else (D5, report5, "design5_rational")
    with pytest.raises(CodegenInvalid) as exc:
        casadi_function(path, rep, force=which == "forced")
    line = exc.value.reasons[0]
    assert line.startswith(f"{stem}: CasADi: error ") and "got v=" in line and "exact v=" in line
    assert "\n" not in line


def test_generate_refuses_when_only_the_casadi_function_disagrees(report, tmp_path, monkeypatch):
    _wrong_casadi(monkeypatch, 1.5)
    with pytest.raises(CodegenInvalid, match="design1_jiang: CasADi: error"):
        generate(D1, tmp_path / "d1", report=report)
    assert list(tmp_path.iterdir()) == []


def test_the_bound_10_check_forms_lam_vr_kf_without_underflow():
    """lam |vr| KF with lam vr = 1e-359 (0 in double) and KF = 1e300 is
    1e-59: formed left to right it was 0, so a w of 1.4e-59 that is the
    exact law (the saturated term of 1e300 log cosh s) was called "above
    bound (10)" and the design refused.  A w twice the bound still fails."""
    from uwmr_symbolic.codegen.accuracy import lam_vr_kf
    from uwmr_symbolic.codegen.validate import ValidationFailed, check
    a = np.array([[0.0, 1e49, 0.0, 1e-254, 0.0, 0.0, 0.0, 1e-105]])
    assert lam_vr_kf(a, 1e300)[0] == pytest.approx(1e-59, rel=1e-15)
    ref = {k: np.zeros(1) for k in ("v_hi", "v_lo", "w_lo")} | {"w_hi": np.array([1e-59]),
                                                                  "scale_v": np.ones(1), "scale_w": np.ones(1)}
    check("d", "C double", a, ref, np.zeros(1), np.array([1e-59]), np.zeros(1, dtype=int), "double", 1e300)
    with pytest.raises(ValidationFailed, match=r"\|w\| above bound \(10\)"):
        check("d", "C double", a, ref | {"w_hi": np.array([2e-59])}, np.zeros(1), np.array([2e-59]),
              np.zeros(1, dtype=int), "double", 1e300)
