"""`uwmr-verify FILE --codegen DIR --simulate` verifies the design once in
the command's own process (besides the batch worker), with --timeout, and
hands that report to both the code generator and the simulation."""
import pytest

import uwmr_symbolic.verify as verify_module
from uwmr_symbolic import cli

pytestmark = pytest.mark.slow        # simulates both paths: not in make test-fast


def test_codegen_and_simulate_share_one_verification(tmp_path, monkeypatch):
    design = tmp_path / "jiang.py"
    design.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\n"
                      "f = sp.log(1 + e1**2 + e2**2)/2\n")
    calls = []
    real = verify_module.verify_design

    def counting(path, timeout=verify_module.DEFAULT_TIMEOUT, kernel_only=True):
        calls.append((str(path), timeout))
        return real(path, timeout=timeout, kernel_only=kernel_only)

    monkeypatch.setattr(verify_module, "verify_design", counting)
    status = cli.main([str(design), "--codegen", str(tmp_path / "out"), "--simulate", "--no-cache",
                       "--timeout", "45", "--jobs", "1"])
    assert status == 0
    assert calls == [(str(design), 45.0)]
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["CMakeLists.txt", "example_main.c", "jiang.c", "jiang.h", "jiang.py"]
