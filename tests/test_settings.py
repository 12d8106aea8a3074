"""[tool.uwmr-symbolic] in pyproject.toml: found by walking up from the current
folder, overridden by command-line flags, and refused in one line (exit 2)
when a key is unknown or a value is wrong."""
import argparse
import json

import os

import pytest

from uwmr_symbolic import cli, settings

JIANG = ("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\n"
         "f = sp.log(1 + e1**2 + e2**2)/2\n")


def _args(**given):
    base = dict(timeout=None, jobs=None, cache_dir=None, files=[])
    return argparse.Namespace(**{**base, **given})


def test_nearest_pyproject_with_the_table_wins(tmp_path, monkeypatch):
    monkeypatch.delenv("UWMR_CACHE_DIR", raising=False)
    (tmp_path / "pyproject.toml").write_text(
        '[tool.uwmr-symbolic]\ntimeout = 7\njobs = 3\ndesigns = ["designs/*.py"]\ncache-dir = "c"\n')
    inner = tmp_path / "pkg" / "sub"
    inner.mkdir(parents=True)
    # a pyproject.toml without the table is passed over, as ruff does
    (tmp_path / "pkg" / "pyproject.toml").write_text('[project]\nname = "x"\n')
    monkeypatch.chdir(inner)
    got = settings.load()
    assert got.source == tmp_path / "pyproject.toml"
    assert (got.timeout, got.jobs) == (7.0, 3)
    assert got.designs == [str(tmp_path / "designs" / "*.py")]      # relative to the file, not the cwd
    assert got.cache_dir == str(tmp_path / "c")
    args = _args()
    settings.apply(args, 60.0)
    assert (args.timeout, args.jobs, args.cache_dir) == (7.0, 3, str(tmp_path / "c"))
    assert args.files == [str(tmp_path / "designs" / "*.py")]


def test_flags_and_environment_override_the_file(tmp_path, monkeypatch):
    (tmp_path / "pyproject.toml").write_text('[tool.uwmr-symbolic]\ntimeout = 7\njobs = 3\ncache-dir = "c"\n')
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("UWMR_CACHE_DIR", str(tmp_path / "env"))
    args = _args(timeout=2.5, jobs=1, files=["mine.py"])
    settings.apply(args, 60.0)
    assert (args.timeout, args.jobs, args.files) == (2.5, 1, ["mine.py"])
    assert args.cache_dir == str(tmp_path / "env")
    args = _args(cache_dir="flag")
    settings.apply(args, 60.0)
    assert args.cache_dir == os.path.abspath("flag")        # (a design file may chdir: red team 28)


def test_no_file_means_defaults(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.delenv("UWMR_CACHE_DIR", raising=False)
    if settings.find_pyproject() is not None:
        pytest.skip("a pyproject.toml with [tool.uwmr-symbolic] above the temporary folder")
    args = _args()
    assert settings.apply(args, 60.0).source is None
    from uwmr_symbolic.cache import default_dir
    assert (args.timeout, args.jobs, args.cache_dir, args.files) == (60.0, None, str(default_dir()), [])


@pytest.mark.parametrize("body, message", [
    ("timout = 5", "[tool.uwmr-symbolic] unknown setting 'timout' (known: cache-dir, designs, jobs, timeout)"),
    ("timeout = -1", "[tool.uwmr-symbolic] timeout must be a number of seconds above 0 and at most 1e+06, not -1"),
    ('timeout = "60"', "[tool.uwmr-symbolic] timeout must be a number of seconds above 0 and at most 1e+06, "
                       "not '60'"),
    ("timeout = inf", "[tool.uwmr-symbolic] timeout must be a number of seconds above 0 and at most 1e+06, not inf"),
    ("jobs = 0", "[tool.uwmr-symbolic] jobs must be an integer of at least 1, not 0"),
    ("jobs = 1.5", "[tool.uwmr-symbolic] jobs must be an integer of at least 1, not 1.5"),
    ("designs = [1]", "[tool.uwmr-symbolic] designs must be a list of glob patterns, not [1]"),
    ("cache-dir = 3", "[tool.uwmr-symbolic] cache-dir must be a folder name, not 3"),
    ("timeout = ", "not valid TOML"),
])
def test_bad_settings_exit_2_with_one_line(tmp_path, monkeypatch, capsys, body, message):
    (tmp_path / "pyproject.toml").write_text(f"[tool.uwmr-symbolic]\n{body}\n")
    monkeypatch.chdir(tmp_path)
    assert cli.main(["whatever.py"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith(f"uwmr-verify: {tmp_path / 'pyproject.toml'}: "), err
    assert message in err


def test_designs_and_cache_dir_from_the_file_drive_the_command(tmp_path, monkeypatch, capsys):
    monkeypatch.delenv("UWMR_CACHE_DIR", raising=False)
    (tmp_path / "controllers").mkdir()
    (tmp_path / "controllers" / "jiang.py").write_text(JIANG)
    (tmp_path / "pyproject.toml").write_text(
        '[tool.uwmr-symbolic]\ndesigns = ["controllers/*.py"]\ncache-dir = "proofs"\njobs = 1\n')
    sub = tmp_path / "notes"
    sub.mkdir()
    monkeypatch.chdir(sub)
    assert cli.main(["--format", "json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["design"] == str(tmp_path / "controllers" / "jiang.py")
    assert report["cached"] is False
    assert len(list((tmp_path / "proofs").rglob("*.json"))) == 1
    # --cache-dir beats the file's cache-dir
    assert cli.main(["--format", "json", "--cache-dir", str(tmp_path / "other")]) == 0
    assert json.loads(capsys.readouterr().out)["cached"] is False
    assert len(list((tmp_path / "other").rglob("*.json"))) == 1
