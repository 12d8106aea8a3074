"""The wheel works off the source tree.

Builds the wheel with `python -m build` from a copy of the package's sources,
installs it into a fresh virtual environment in a temporary folder (not the
repository), and runs `uwmr-verify` there on a design copied into another
temporary folder: verification, `--codegen` (the jinja2 templates must be in
the wheel), `--simulate` (the generated C is compiled and run), the kernel's
certificate schema, `python -m uwmr_symbolic`, `--cache-dir` and the
`[tool.uwmr-symbolic]` settings of a pyproject.toml beside the design.

The third-party dependencies are not downloaded again: a .pth file in the new
environment points at the test environment's site-packages, after the new
environment's own.  uwmr_symbolic itself must come from the new environment,
which the test checks.  UWMR_WHEEL_TEST_DEPS=pypi installs the dependencies
from the package index instead (slower, needs the network).
"""
import json
import os
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parent.parent

DESIGN = '''\
"""Design 1 of the paper with its circle gains only (Table 1)."""
import sympy as sp

e1, e2 = sp.symbols("e1 e2", real=True)
name = "wheel check"
f = sp.log(1 + e1**2 + e2**2) / 2
gains = {"circle": dict(k1=0.25, k2=0.7, lam=1.2, Vmax=0.75, Wmax=2.0, Vr_max=0.5, Wr_max=1.0)}
'''


def _run(argv, cwd, env, timeout=900):
    proc = subprocess.run([str(a) for a in argv], cwd=cwd, env=env, capture_output=True, text=True,
                          timeout=timeout, stdin=subprocess.DEVNULL)
    return proc


def _explain(proc) -> str:
    return f"exit {proc.returncode}\nstdout:\n{proc.stdout[-4000:]}\nstderr:\n{proc.stderr[-4000:]}"


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    """(python, uwmr-verify, environment) of a fresh venv holding only the wheel."""
    base = tmp_path_factory.mktemp("wheel")
    src = base / "src"
    src.mkdir()
    for name in ("pyproject.toml", "README.md", "LICENSE"):
        shutil.copy2(ROOT / name, src / name)
    shutil.copytree(ROOT / "uwmr_symbolic", src / "uwmr_symbolic",
                    ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    dist = base / "dist"
    build = _run([sys.executable, "-m", "build", "--wheel", "--outdir", dist, src], cwd=base,
                 env=os.environ.copy())
    assert build.returncode == 0, _explain(build)
    wheels = list(dist.glob("uwmr_symbolic-*.whl"))
    assert len(wheels) == 1, wheels

    venv = base / "venv"
    made = _run([sys.executable, "-m", "venv", venv], cwd=base, env=os.environ.copy())
    assert made.returncode == 0, _explain(made)
    python, verify = venv / "bin" / "python", venv / "bin" / "uwmr-verify"
    if os.environ.get("UWMR_WHEEL_TEST_DEPS") == "pypi":
        pip = [python, "-m", "pip", "install", "--quiet", wheels[0]]
    else:
        site = _run([python, "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
                    cwd=base, env=os.environ.copy())
        (Path(site.stdout.strip()) / "_uwmr_test_deps.pth").write_text(
            sysconfig.get_paths()["purelib"] + "\n" + sysconfig.get_paths()["platlib"] + "\n")
        pip = [python, "-m", "pip", "install", "--quiet", "--no-deps", "--no-index", wheels[0]]
    inst = _run(pip, cwd=base, env=os.environ.copy())
    assert inst.returncode == 0, _explain(inst)

    env = {k: v for k, v in os.environ.items()
           if k not in ("UWMR_CACHE_DIR", "PYTHONPATH", "VIRTUAL_ENV", "XDG_CACHE_HOME")}
    env["HOME"] = str(base / "home")        # nothing of the user's cache is read or written
    env["PATH"] = f"{venv / 'bin'}{os.pathsep}{env.get('PATH', '')}"
    return python, verify, env, base


def test_the_package_comes_from_the_wheel(installed):
    python, _, env, base = installed
    probe = _run([python, "-c", "import uwmr_symbolic, uwmr_symbolic.kernel.certificate as c; "
                  "print(uwmr_symbolic.__file__); print(c.SCHEMA.is_file())"], cwd=base, env=env)
    assert probe.returncode == 0, _explain(probe)
    where, schema = probe.stdout.split()
    assert Path(where).is_relative_to(base / "venv"), where
    assert not Path(where).is_relative_to(ROOT), where
    assert schema == "True"
    package = Path(where).parent
    assert (package / "py.typed").is_file()
    assert sorted(p.name for p in (package / "codegen" / "templates").iterdir()) == sorted(
        p.name for p in (ROOT / "uwmr_symbolic" / "codegen" / "templates").glob("*.j2"))


def test_verify_codegen_and_simulate_outside_the_repository(installed):
    _, verify, env, base = installed
    work = base / "work"
    work.mkdir()
    (work / "jiang.py").write_text(DESIGN)
    (work / "pyproject.toml").write_text('[tool.uwmr-symbolic]\ntimeout = 300\ncache-dir = "proofs"\n')
    run = _run([verify, "jiang.py", "--codegen", "out", "--simulate"], cwd=work, env=env)
    assert run.returncode == 0, _explain(run)
    for line in ("P1  proved", "P4  proved", "P8  proved", "kf = 1/2 = 0.5", "(attained)",
                 "=> all properties proved, gains within the limits", "simulation circle: ok"):
        assert line in run.stdout, _explain(run)
    assert ("wrote out/CMakeLists.txt, out/example_main.c, out/jiang.c, out/jiang.h, out/jiang.py"
            in run.stderr), _explain(run)
    c_source = (work / "out" / "jiang.c").read_text()
    assert "uwmr_jiang_control_f32" in c_source and "NOT VERIFIED" not in c_source
    python_module = (work / "out" / "jiang.py").read_text()
    assert "def control(" in python_module
    # the cache folder from [tool.uwmr-symbolic], relative to that pyproject.toml
    entries = list((work / "proofs").rglob("*.json"))
    assert len(entries) == 1, entries
    assert not (base / "home" / ".cache" / "uwmr-symbolic").exists()


def test_python_m_and_cache_dir_flag(installed):
    python, _, env, base = installed
    work = base / "work-m"
    work.mkdir()
    (work / "jiang.py").write_text(DESIGN)
    first = _run([python, "-m", "uwmr_symbolic", "jiang.py", "--format", "json", "--cache-dir", "c2"],
                 cwd=work, env=env)
    assert first.returncode == 0, _explain(first)
    report = json.loads(first.stdout)
    assert report["cached"] is False
    assert {p: v["verdict"] for p, v in report["properties"].items()} == {
        f"P{i}": "proved" for i in range(1, 9)}
    again = _run([python, "-m", "uwmr_symbolic", "jiang.py", "--format", "json", "--cache-dir", "c2"],
                 cwd=work, env=env)
    assert again.returncode == 0, _explain(again)
    assert json.loads(again.stdout)["cached"] is True
    assert len(list((work / "c2").rglob("*.json"))) == 1
