"""`uwmr-verify FILE --codegen DIR --simulate` verifies the design once more
(besides the batch worker), in a worker process killed past --timeout, and
hands that report to both the code generator and the simulation."""
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
    assert calls == [(str(design), 45.0, True)]
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["CMakeLists.txt", "example_main.c", "jiang.c", "jiang.h", "jiang.py"]
