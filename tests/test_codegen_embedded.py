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


@pytest.mark.skipif(not embedded.available(), reason="arm-none-eabi-gcc missing: `make embedded` installs it")
def test_cortex_m4f_example_links_against_newlib(tmp_path):
    """The example loop (float variant) links with --specs=nosys.specs; its
    flash, static RAM and stack are measured, and the generated functions'
    frames are all there."""
    src = ROOT / "generated" / "design3_logcosh"
    ex = embedded.example(src, tmp_path)
    for label in ("newlib", "newlib-nano"):
        flash, ram = ex[label]
        assert 4000 < flash < 200_000 and 0 < ram < 64_000
    assert ex["newlib-nano"][0] < ex["newlib"][0]
    frames = ex["frames"]
    assert {"main", "uwmr_design3_logcosh_step_f32", "uwmr_design3_logcosh_control_f32"} <= set(frames)
    assert ex["stack"] == sum(frames.values()) and 0 < ex["stack"] < 4096


def test_double_helpers_are_recognised():
    for name in ("__aeabi_dmul", "__aeabi_f2d", "__aeabi_d2f", "__muldf3", "__extendsfdf2", "__aeabi_i2d"):
        assert embedded.DOUBLE_HELPER.match(name), name
    for name in ("__aeabi_fmul", "sinf", "__aeabi_f2iz"):
        assert not embedded.DOUBLE_HELPER.match(name) and name not in embedded.DOUBLE_LIBM, name
