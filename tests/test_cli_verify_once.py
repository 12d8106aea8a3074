"""`uwmr-verify FILE --codegen DIR --simulate` verifies the design once: the
batch's process (killed past --timeout) sends its report back with its
result, and the code generator and the simulation both use it; the result
printed is that verification's, never a cache entry's (red team 28: a
cached "proved" was printed above a code generator that had verified again
within a shorter --timeout and refused)."""
import pytest

import uwmr_symbolic.api as api
from uwmr_symbolic import cli

pytestmark = pytest.mark.slow        # simulates both paths: not in make test-fast


def test_codegen_and_simulate_share_one_verification(tmp_path, monkeypatch):
    design = tmp_path / "jiang.py"
    design.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\n"
                      "f = sp.log(1 + e1**2 + e2**2)/2\n")
    calls = []
    real = api.verify_file

    def counting(path, *, timeout, worker, kernel_only=True):
        calls.append((str(path), timeout, worker))
        return real(path, timeout=timeout, worker=worker, kernel_only=kernel_only)

    monkeypatch.setattr(api, "verify_file", counting)
    status = cli.main([str(design), "--codegen", str(tmp_path / "out"), "--simulate", "--no-cache",
                       "--timeout", "45", "--jobs", "1"])
    assert status == 0
    assert calls == []          # no verification besides the batch's
    # a result in the cache is not what --codegen prints: it verifies, with this command's --timeout
    cache = tmp_path / "cache"
    assert cli.main([str(design), "--cache-dir", str(cache), "--timeout", "45"]) == 0
    assert cli.main([str(design), "--cache-dir", str(cache), "--codegen", str(tmp_path / "again"),
                     "--timeout", "45"]) == 0 and calls == []
    assert (tmp_path / "again" / "jiang.c").is_file()
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["CMakeLists.txt", "example_main.c", "jiang.c", "jiang.h", "jiang.py"]
