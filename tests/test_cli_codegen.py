"""`uwmr-verify --codegen [DIR] [--force]` and `--check-generated`."""
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow        # more than a few seconds: not in make test-fast

ROOT = Path(__file__).resolve().parent.parent


def cli(*args, cwd=ROOT):
    return subprocess.run([sys.executable, "-m", "uwmr_symbolic.cli", *map(str, args)], cwd=cwd,
                          capture_output=True, text=True, timeout=600)


def test_verified_design_is_generated_as_committed(tmp_path):
    out = tmp_path / "d1"
    run = cli(ROOT / "designs/design1_jiang.py", "--codegen", out, "--no-cache")
    assert run.returncode == 0, run.stderr
    names = sorted(p.name for p in out.iterdir())
    assert names == ["CMakeLists.txt", "design1_jiang.c", "design1_jiang.h", "design1_jiang.py", "example_main.c"]
    for name in names:
        assert (out / name).read_text() == (ROOT / "generated/design1_jiang" / name).read_text()


def test_refuted_design_needs_force_and_then_carries_the_banner(tmp_path):
    out = tmp_path / "d5"
    run = cli(ROOT / "designs/design5_rational.py", "--codegen", out)
    assert run.returncode == 1
    assert "not verified" in run.stderr and "P3 refuted" in run.stderr
    assert not out.exists()
    run = cli(ROOT / "designs/design5_rational.py", "--codegen", out, "--force")
    assert run.returncode == 1                      # the verdict is still a refutation
    for name in ("design5_rational.c", "design5_rational.h", "design5_rational.py", "example_main.c", "CMakeLists.txt"):
        head = (out / name).read_text()[:400]
        assert "NOT VERIFIED: P3 refuted" in head, name


def test_output_that_cannot_take_the_files_is_a_one_line_error(tmp_path):
    """--codegen naming a file, or a folder where a generated file's name is
    a folder: exit 2, one line, nothing written (`python -m
    uwmr_symbolic.codegen` alike)."""
    (tmp_path / "afile").write_text("mine")
    run = cli(ROOT / "designs/design1_jiang.py", "--codegen", tmp_path / "afile")
    assert run.returncode == 2 and "Traceback" not in run.stderr, run.stderr
    assert run.stderr.strip() == (f"{ROOT / 'designs/design1_jiang.py'}: no code generated: {tmp_path / 'afile'}: "
                                  "exists and is not a folder; name a folder for the generated code")
    (tmp_path / "half" / "design1_jiang.py").mkdir(parents=True)
    run = cli(ROOT / "designs/design1_jiang.py", "--codegen", tmp_path / "half")
    assert run.returncode == 2 and len(run.stderr.strip().splitlines()) == 1, run.stderr
    assert "design1_jiang.py: is a folder, where the generated file design1_jiang.py goes" in run.stderr
    assert [p.name for p in (tmp_path / "half").iterdir()] == ["design1_jiang.py"]
    module = subprocess.run([sys.executable, "-m", "uwmr_symbolic.codegen", "--out", tmp_path / "afile",
                             ROOT / "designs/design1_jiang.py", ROOT / "tests/bad_inputs/no_f.py"],
                            cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert module.returncode == 2 and "Traceback" not in module.stderr, module.stderr
    lines = module.stderr.strip().splitlines()
    assert len(lines) == 2 and "cannot write the generated code (Not a directory)" in lines[0], lines
    assert lines[1].endswith("no_f.py: defines no `f`; add e.g. `f = sympy.log(1 + e1**2 + e2**2) / 2`")
    assert (tmp_path / "afile").read_text() == "mine"


def test_force_without_codegen_is_a_usage_error():
    run = cli(ROOT / "designs/design1_jiang.py", "--force")
    assert run.returncode == 2 and "--codegen" in run.stderr


def test_check_generated_detects_a_stale_file(tmp_path):
    shutil.copy(ROOT / "designs/design1_jiang.py", tmp_path / "design1_jiang.py")
    shutil.copytree(ROOT / "generated/design1_jiang", tmp_path / "generated/design1_jiang")
    run = cli("--check-generated", "design1_jiang.py", cwd=tmp_path)
    assert run.returncode == 0, run.stdout + run.stderr
    c_file = tmp_path / "generated/design1_jiang/design1_jiang.c"
    c_file.write_text(c_file.read_text().replace("0.5", "0.25", 1))
    run = cli("--check-generated", "design1_jiang.py", cwd=tmp_path)
    assert run.returncode == 1
    assert "design1_jiang.c: stale" in run.stdout
    (tmp_path / "generated/design1_jiang/extra.txt").write_text("x")
    c_file.unlink()
    run = cli("--check-generated", "design1_jiang.py", cwd=tmp_path)
    assert "design1_jiang.c: missing" in run.stdout and "extra.txt: not produced" in run.stdout
    # named designs are checked alone: another design's folder is not an orphan then, but is without names
    shutil.copytree(ROOT / "generated/design2_sqrt", tmp_path / "generated/design2_sqrt")
    assert "design2_sqrt" not in cli("--check-generated", "design1_jiang.py", cwd=tmp_path).stdout
    (tmp_path / "designs").mkdir()
    shutil.move(tmp_path / "design1_jiang.py", tmp_path / "designs/design1_jiang.py")
    run = cli("--check-generated", cwd=tmp_path)
    assert f"{Path('generated/design2_sqrt')}: no design file design2_sqrt.py" in run.stdout, run.stdout


def test_design_that_prints_keeps_json_clean(tmp_path):
    src = (ROOT / "designs/design1_jiang.py").read_text() + "\nprint('hello from the design')\n"
    (tmp_path / "chatty.py").write_text(src)
    run = cli(tmp_path / "chatty.py", "--format", "json", "--no-cache")
    import json
    assert json.loads(run.stdout)["properties"]["P1"]["verdict"] == "proved"
    assert "hello from the design" in run.stderr


def test_simulate_json_has_the_checks_and_a_custom_reference(tmp_path):
    import json
    import numpy as np
    src = (ROOT / "designs/design1_jiang.py").read_text()
    src = src[:src.index("gains = {")] + (
        "gains = {'custom': dict(k1=0.25, k2=0.7, lam=1.2, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0)}\n")
    (tmp_path / "d.py").write_text(src)
    t = np.linspace(0, 30, 301)
    np.savetxt(tmp_path / "ref.csv", np.c_[t, 0.5 * np.sin(t / 2), 0.5 - 0.5 * np.cos(t / 2)], delimiter=",")
    run = cli(tmp_path / "d.py", "--simulate", "--reference", f"custom={tmp_path / 'ref.csv'}",
              "--format", "json", "--no-cache")
    assert run.returncode == 0, run.stderr[-2000:]
    sim = json.loads(run.stdout)["simulation"]["custom"]
    for kind in ("continuous", "digital"):
        m = sim[kind]
        for key in ("max_abs_v", "max_abs_w", "rms", "final_errors", "converged",
                    "max_lyapunov_increase", "c_python_max_diff"):
            assert key in m, (kind, key)
    assert sim["continuous"]["max_abs_v"] <= 0.75 and sim["continuous"]["max_abs_w"] <= 2.0
    # same law, same integrator: they agree to the integration tolerance (rtol 1e-10)
    assert sim["continuous"]["c_python_max_diff"] < 1e-6


def test_bad_reference_is_a_one_line_usage_error(tmp_path):
    (tmp_path / "ref.csv").write_text("0,1\n1,2\n")
    run = cli(ROOT / "designs/design1_jiang.py", "--simulate", "--reference", f"circle={tmp_path / 'ref.csv'}")
    assert run.returncode == 2
    assert len(run.stderr.strip().splitlines()) == 1 and "ref.csv" in run.stderr


def test_reference_files_get_one_line_that_names_the_column_or_the_limit(tmp_path):
    """Red team 16b: NaN in column x was reported as scipy's "`y` must contain
    only finite values", a header-only file as numpy's warning and "found 1"
    columns, a byte-order mark as a bad number, a Python reference that
    loops for ever hung whatever --timeout said, and a reference faster than
    the scenario's Vr_max was simulated, its V limit failure read as the
    controller's.  Each is now one line on stderr with exit status 2."""
    import numpy as np
    src = (ROOT / "designs/design1_jiang.py").read_text()
    (tmp_path / "d.py").write_text(src[:src.index("gains = {")] + (
        "gains = {'custom': dict(k1=0.25, k2=0.7, lam=1.2, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0)}\n"))
    t = np.linspace(0, 30, 301)
    x, y = 0.5 * np.sin(t / 2), 0.5 - 0.5 * np.cos(t / 2)         # a circle at 0.25 m/s
    lines = [f"{float(a)!r},{float(b)!r},{float(c)!r}" for a, b, c in zip(t, x, y)]
    rows = "\n".join(lines)
    files = {"nan_x.csv": "t,x,y\n" + "\n".join(lines[:5] + ["0.5,nan,0"] + lines[6:]),
             "header.csv": "t,x,y\n",
             "fast.csv": "\n".join(f"{float(a)!r},{float(4 * b)!r},{float(4 * c)!r}" for a, b, c in zip(t, x, y)),
             "hang.py": "while True:\n    pass\n"}          # fast.csv: the circle at 1 m/s > Vr_max = 0.5
    for name, text in files.items():
        (tmp_path / name).write_text(text)
    (tmp_path / "latin.csv").write_bytes(b"t,x,y\n0,0,\xff\n")
    expect = {"nan_x.csv": "column x is not a finite number in waypoint 6",
              "header.csv": "no waypoints: expected rows t,x,y",
              "fast.csv": "beyond Vr_max = 0.5 (bound (10) holds only for a reference within",
              "hang.py": "the reference did not load within --timeout (3 s)",
              "latin.csv": "not UTF-8 text (invalid start byte at byte 10); save it as UTF-8"}
    for name, message in expect.items():
        run = cli(tmp_path / "d.py", "--simulate", "--timeout", "3", "--no-cache", "--reference",
                  f"custom={tmp_path / name}")
        assert run.returncode == 2 and len(run.stderr.strip().splitlines()) == 1, (name, run.stderr)
        assert message in run.stderr and "Traceback" not in run.stderr, (name, run.stderr)
    # a byte-order mark before the header is no column name: read as the plain file
    (tmp_path / "bom.csv").write_bytes(b"\xef\xbb\xbft,x,y\n" + rows.encode())
    run = cli(tmp_path / "d.py", "--simulate", "--no-cache", "--reference", f"custom={tmp_path / 'bom.csv'}", "-q")
    assert run.returncode == 0, run.stderr


def test_codegen_refuses_an_unproved_design_without_verifying_it_again(tmp_path, capsys):
    """The batch's result says P3 is unknown: --codegen refused it only after
    a second verification in this process, which a red team saw run for
    25 minutes inside SymPy's C code (no time limit reaches there).  Now the
    refusal comes from the result itself; --force verifies in a worker
    process, killed past --timeout like the batch's."""
    from uwmr_symbolic.cli import write_code
    design = tmp_path / "d.py"
    results = [{"design": str(design), "f": "log(e1**2 + e2**2 + 1)", "properties": {
        "P1": {"verdict": "proved", "reason": "ok"}, "P3": {"verdict": "unknown", "reason": "undecided near s = 4"}}}]

    def reports(path):
        raise AssertionError("verified again")
    assert write_code([design], results, str(tmp_path / "out"), False, reports) == 1
    err = capsys.readouterr().err
    assert "d.py: no code generated, the design is not verified (1 reason(s): P3 unknown: undecided near s = 4" in err
    assert "use --force" in err and not (tmp_path / "out").exists()


def test_trust_search_does_not_extend_to_codegen_and_says_so(tmp_path):
    """A half-plane switch between log(1 + rho) and log((1 + rho)^2)/2, the
    same function: the search proves P1-P8, the kernel re-checks only P2
    (it has no rule for a Piecewise equal to one formula).  With
    --trust-search the report says all proved, and --codegen had refused it
    as "not verified ... counts only with --trust-search"; now it says why."""
    design = tmp_path / "switch.py"
    design.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nrho = e1**2 + e2**2\n"
                      "f = sp.Piecewise((sp.log(1 + rho), e1 > 0), (sp.log((1 + rho)**2)/2, True))\n")
    run = cli(design, "--no-cache", "--trust-search", "--codegen", tmp_path / "out")
    assert run.returncode == 1 and "all properties proved" in run.stdout
    assert run.stderr.strip().splitlines()[-1].startswith(
        f"{design}: no code generated: code is generated from the kernel's verdicts only, and P1, P3, P4, P5, P6, "
        "P7, P8 rest on the search alone (--trust-search does not extend to --codegen")
    assert not (tmp_path / "out").exists()
