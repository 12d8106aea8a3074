"""Fast packaging checks (the slow, real one is test_wheel.py): every file the
package reads at run time is declared as package data, and the metadata a
user sees is there."""
import fnmatch
import subprocess
import sys
from pathlib import Path

try:
    import tomllib
except ImportError:             # Python 3.10: tomli is a dependency there
    import tomli as tomllib

from uwmr_symbolic import __version__

ROOT = Path(__file__).resolve().parent.parent
PACKAGE = ROOT / "uwmr_symbolic"


def _pyproject() -> dict:
    with open(ROOT / "pyproject.toml", "rb") as fh:
        return tomllib.load(fh)


def test_every_data_file_of_the_package_is_declared_as_package_data():
    declared = _pyproject()["tool"]["setuptools"]["package-data"]
    missing = []
    for path in sorted(PACKAGE.rglob("*")):
        if not path.is_file() or path.suffix in (".py", ".pyc") or "__pycache__" in path.parts:
            continue
        # the nearest enclosing package (a folder with __init__.py) owns the file
        owner = path.parent
        while not (owner / "__init__.py").is_file():
            owner = owner.parent
        package = ".".join(owner.relative_to(ROOT).parts)
        relative = path.relative_to(owner).as_posix()
        if not any(fnmatch.fnmatch(relative, pattern) for pattern in declared.get(package, [])):
            missing.append(f"{package}: {relative}")
    assert not missing, f"not in [tool.setuptools.package-data], so not in the wheel: {missing}"
    # the files the code generator and the kernel read are among them
    assert (PACKAGE / "codegen" / "templates" / "c_source.c.j2").is_file()
    assert (PACKAGE / "kernel" / "certificate.schema.json").is_file()
    assert (PACKAGE / "py.typed").is_file()


def test_licence_and_metadata():
    project = _pyproject()["project"]
    assert project["license"] == "BSD-3-Clause"
    assert project["license-files"] == ["LICENSE"]
    text = (ROOT / "LICENSE").read_text()
    assert text.startswith("BSD 3-Clause License") and "the uwmr-symbolic authors" in text
    assert "Typing :: Typed" in project["classifiers"]
    assert project["scripts"]["uwmr-verify"] == "uwmr_symbolic.cli:run"
    markers = _pyproject()["tool"]["pytest"]["ini_options"]["markers"]
    assert any(m.startswith("slow:") for m in markers)


def test_python_m_uwmr_symbolic_is_uwmr_verify():
    run = subprocess.run([sys.executable, "-m", "uwmr_symbolic", "--version"], capture_output=True,
                         text=True, cwd=ROOT, timeout=120)
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == f"uwmr-verify {__version__}"
    run = subprocess.run([sys.executable, "-m", "uwmr_symbolic"], capture_output=True, text=True,
                         cwd=ROOT, timeout=120)
    assert run.returncode == 2
    assert run.stderr == "uwmr-verify: no design file given (try: uwmr-verify designs/*.py)\n"
