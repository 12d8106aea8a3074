"""The float variant of every generated controller compiles for a Cortex-M4F
without any double-precision symbol (`make embedded` installs the toolchain;
`make test` runs it, so CI does)."""
from __future__ import annotations

from pathlib import Path

import pytest

from uwmr_symbolic.codegen import embedded

ROOT = Path(__file__).resolve().parent.parent
DIRS = sorted(p for p in (ROOT / "generated").iterdir() if p.is_dir())


@pytest.mark.skipif(not embedded.available(), reason="arm-none-eabi-gcc missing: `make embedded` installs it")
@pytest.mark.parametrize("src", DIRS, ids=[d.name for d in DIRS])
def test_cortex_m4f_float_variant_has_no_double(src, tmp_path):
    text, bad = embedded.check(src, tmp_path)
    assert bad == []
    assert 0 < text < 16384


def test_double_helpers_are_recognised():
    for name in ("__aeabi_dmul", "__aeabi_f2d", "__aeabi_d2f", "__muldf3", "__extendsfdf2", "__aeabi_i2d"):
        assert embedded.DOUBLE_HELPER.match(name), name
    for name in ("__aeabi_fmul", "sinf", "__aeabi_f2iz"):
        assert not embedded.DOUBLE_HELPER.match(name) and name not in embedded.DOUBLE_LIBM, name
