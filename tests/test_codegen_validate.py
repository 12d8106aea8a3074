"""The validation gate: code that disagrees with the law is never written,
`uwmr-verify --codegen` exits 1 with one line naming the design, the target,
the input and both values."""
from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from uwmr_symbolic import cli
from uwmr_symbolic.codegen import CodegenInvalid, build, c_backend, generate, python_backend, validate_build
from uwmr_symbolic.verify import verify_design

ROOT = Path(__file__).resolve().parent.parent
D1 = ROOT / "designs/design1_jiang.py"
pytestmark = [pytest.mark.slow, pytest.mark.skipif(shutil.which("gcc") is None, reason="needs gcc")]


@pytest.fixture(scope="module")
def report():
    return verify_design(D1)


def _corrupt(monkeypatch, backend, old, new, count=1):
    render = backend.render

    def bad(*args, **kwargs):
        files = render(*args, **kwargs)
        out = {}
        for name, text in files.items():
            assert old in text or name != D1.stem + (".c" if backend is c_backend else ".py")
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
