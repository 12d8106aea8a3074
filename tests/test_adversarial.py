"""Designs built to trap a careless verifier: branch-wise radial pieces that
are not radial together, a norm that is not radial, a radial f that SymPy
writes with flipped Piecewise conditions.  A wrong "proved" here would be the
worst kind of bug, so each test pins the verdicts that are decidable."""
import json
from pathlib import Path

import pytest

from _cli import run_cli

HERE = Path(__file__).parent / "adversarial"


def verdicts(name):
    run = run_cli([HERE / name, "--format", "json"], timeout=300)
    assert "Traceback" not in run.stderr, run.describe()
    report = json.loads(run.stdout)
    return {p: v["verdict"] for p, v in report["properties"].items()}, report, run.returncode


@pytest.mark.parametrize("name", ["l1_norm.py", "half_plane_switch.py"])
def test_non_radial_is_refuted_and_nothing_else_is_claimed(name):
    v, report, code = verdicts(name)
    assert v["P4"] == "refuted"
    assert report["properties"]["P4"]["witness"] is not None
    assert v["P2"] == "proved"
    # none of the other properties may be claimed proved on the strength of
    # the branch-wise derivative identity
    for p in ("P1", "P5", "P6", "P7", "P8"):
        assert v[p] in ("refuted", "unknown"), (p, v[p])
    assert code == 1


PROPS = [f"P{i}" for i in range(1, 9)]


def test_flipped_piecewise_conditions_still_radial():
    v, report, code = verdicts("max_disguise.py")
    assert v["P4"] == "proved"
    assert v["P1"] == "refuted"            # kf infinite: F'(s) = s
    assert report["kf"]["upper"] is None
    assert all(v[p] == "proved" for p in ("P2", "P3", "P5", "P6", "P7", "P8"))
    assert code == 1
    # the kernel reads the Max's condition r/2 >= sqrt(r) - 1/2 as the profile's
    # s <= s^2/2 + 1/2: the reduction and every proof through it are checked;
    # P1 by the branch r/2 taken beyond |e| = 1, whose df/de2(0, h) = h -> oo
    assert report["kernel"] == {"checked": PROPS, "search": []}


@pytest.mark.slow        # waits for the kill: about 13 s
def test_a_check_stuck_in_c_code_is_killed_and_reported_unknown():
    run = run_cli([HERE / "blocks_in_c.py", "--timeout", "2", "--format", "json"], timeout=120)
    assert run.elapsed < 60, run.describe()
    assert run.returncode == 3, run.describe()
    report = json.loads(run.stdout)
    assert all(v["verdict"] == "unknown" for v in report["properties"].values())
    assert "stopped after" in report["properties"]["P1"]["reason"]


def test_a_jump_of_the_mixed_second_derivative_refutes_p7():
    v, report, code = verdicts("mixed_slope_switch.py")
    assert {p: v[p] for p in ("P1", "P2", "P4", "P5", "P6", "P7")} == {
        "P1": "refuted", "P2": "proved", "P4": "refuted", "P5": "refuted", "P6": "refuted", "P7": "refuted"}
    assert {"P1", "P2", "P4", "P5", "P6", "P7"} <= set(report["kernel"]["checked"])
    assert "(1, 1)" in report["properties"]["P7"]["reason"]
    assert code == 1
