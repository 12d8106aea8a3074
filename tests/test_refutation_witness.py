"""Refuted verdicts in design certificates (issue 9): the kernel re-checks
the witness of a refutation, and the link (`design_certificate.
link_refutation`) checks that the kernel's claim is exactly the negation the
property needs about this f at that point.

Hand-made f, values by hand:
* f = e1^2 + e2^2 - 1: f(0, 0) = -1 != 0 (P2 fails); f(1/2, 0) = -3/4 <= 0
  (P3 fails); f(2, 0) = 3 > 0 (no refutation); df/de1 = 2 e1.
* g = 1 - e1^2 (not radial): df/de1(1, 0) = -2 < 0 (P5, P6 fail);
  g(3/5, 4/5) = 16/25 != g(1, 0) = 0 on the unit circle (P4 fails);
  g(1, 0) - g(1/2, 0) = -3/4 < 0 with 0 < 1/2 < 1 (P5, P6 fail).
* n = sqrt(e1^2 + e2^2): df/de2(0, h) = 1, df/de2(0, -h) = -1 for h > 0
  (P1, P7, P8 fail at the origin).
"""
import copy
import json

import pytest
import sympy as sp

from uwmr_symbolic import design_certificate as DC, e1, e2
from uwmr_symbolic.certify import refutation_theorems
from uwmr_symbolic.kernel import arb, core as K
from uwmr_symbolic.certify import to_certificate
from uwmr_symbolic.kernel.parse import parse
from uwmr_symbolic.verdict import refuted

F = e1 ** 2 + e2 ** 2 - 1
G = 1 - e1 ** 2
N = sp.sqrt(e1 ** 2 + e2 ** 2)


def cert(f, name, theorems, record):
    """A design certificate with one refuted property."""
    return {"format": DC.FORMAT, "version": DC.VERSION,
            "design": {"name": "t", "file": "t.py", "f": sp.srepr(f)},
            "properties": {name: {"status": "refuted", "reason": "", "kernel": to_certificate(theorems),
                                  "witness": record, "unchecked": []}}}


def proposed(name, f, witness):
    theorems, record, why = refutation_theorems(name, refuted("", witness), f)
    assert theorems is not None, why
    return cert(f, name, theorems, record)


def as_property(data, old, new):
    """The certificate with property old's entry filed under new."""
    out = copy.deepcopy(data)
    out["properties"][new] = out["properties"].pop(old)
    return out


def checked(data):
    (pc,) = DC.check(json.dumps(data))
    return pc


def test_value_witnesses_of_p2_and_p3():
    pc = checked(proposed("P2", F, {"e1": "0", "e2": "0", "f": "-1"}))
    assert pc.refutation_checked and pc.witness == "f(0, 0) != 0" and pc.assumptions == ["arb", "sympy-core"]
    data = proposed("P3", F, {"e1": "1/2", "e2": "0"})
    assert data["properties"]["P3"]["witness"] == {"kind": "value", "points": [["Rational(1, 2)", "Integer(0)"]]}
    assert checked(data).line() == ("P3: refuted; 1 kernel theorem(s) re-checked (rests on arb, sympy-core); "
                                    "kernel-checked: f(1/2, 0) <= 0")


def test_moved_point_or_flipped_sign_is_rejected():
    data = proposed("P3", F, {"e1": "1/2", "e2": "0"})
    moved = copy.deepcopy(data)
    moved["properties"]["P3"]["witness"]["points"][0][0] = "Rational(1, 3)"     # f(1/3, 0) = -8/9: another constant
    with pytest.raises(DC.CertificateError, match="P3: the kernel's conclusions are not the witness 'value'"):
        DC.check(moved)
    flipped = copy.deepcopy(data)
    flipped["properties"]["P3"]["kernel"]["theorems"][0]["claim"]["want"] = 1
    with pytest.raises(DC.CertificateError, match="P3: theorem 0"):
        DC.check(flipped)
    # a true kernel claim that is no refutation: f(2, 0) = 3 > 0
    two = (sp.Integer(2), sp.Integer(0))
    good = cert(F, "P3", [K.value_sign(value=F.subs({e1: 2, e2: 0}))],
                {"kind": "value", "points": [[sp.srepr(c) for c in two]]})
    with pytest.raises(DC.CertificateError, match=r"P3: the kernel's claim \(f\(2, 0\) <= 0\) does not refute P3"):
        DC.check(good)
    # P2 at a point other than the origin; P3 at the origin
    at_half = copy.deepcopy(data)
    at_half["properties"]["P2"] = at_half["properties"].pop("P3")
    with pytest.raises(DC.CertificateError, match="P2: the kernel's claim"):
        DC.check(at_half)
    origin = proposed("P2", F, {})
    origin["properties"]["P3"] = origin["properties"].pop("P2")
    with pytest.raises(DC.CertificateError, match="P3: the kernel's claim"):
        DC.check(origin)


def test_circle_witness_of_p4():
    data = proposed("P4", G, {"point_a": ["1", "0"], "point_b": ["3/5", "4/5"]})
    assert checked(data).witness == "f(3/5, 4/5) != f(1, 0) on the circle of radius 1"
    off = copy.deepcopy(data)
    off["properties"]["P4"]["witness"]["points"][1] = ["Rational(4, 5)", "Rational(3, 5)"]   # g = 9/25 there
    with pytest.raises(DC.CertificateError, match="P4: the kernel's conclusions are not the witness 'circle'"):
        DC.check(off)
    off["properties"]["P4"]["witness"]["points"][1] = ["Rational(3, 5)", "Rational(3, 5)"]   # same g, off the circle
    with pytest.raises(DC.CertificateError, match=r"P4: the kernel's claim \(f\(3/5, 3/5\) != f\(1, 0\) on the "
                                                  r"circle of radius 1\) does not refute P4"):
        DC.check(off)
    # both points moved consistently, kernel claim remade: the link still wants one circle
    p, q = (sp.Integer(1), sp.Integer(0)), (sp.Rational(1, 2), sp.Integer(0))
    val = G.subs({e1: q[0], e2: q[1]}) - G.subs({e1: p[0], e2: p[1]})
    bad = cert(G, "P4", [K.value_sign(value=val)], {"kind": "circle", "points": [[sp.srepr(c) for c in x] for x in (p, q)]})
    with pytest.raises(DC.CertificateError, match="does not refute P4"):
        DC.check(bad)


def test_slope_and_step_witnesses_of_p5_and_p6():
    for name in ("P5", "P6"):
        data = proposed(name, G, {"e1": "1", "e2": "0"})
        pc = checked(data)
        assert pc.refutation_checked and pc.witness == "df/de1(1, 0) has sign -1" and "sympy-diff" in pc.assumptions
    # df/de1 = 2 e1 > 0 at (1, 0) for F: no refutation
    bad = cert(F, "P5", [K.value_sign(value=sp.Integer(2))], {"kind": "slope", "points": [["Integer(1)", "Integer(0)"]]})
    with pytest.raises(DC.CertificateError, match="does not refute P5"):
        DC.check(bad)
    # on the other side of the axis df/de1 < 0 is what P5 needs: (-1, 0) for F
    bad = cert(F, "P5", [K.value_sign(value=sp.Integer(-2))], {"kind": "slope", "points": [["Integer(-1)", "Integer(0)"]]})
    with pytest.raises(DC.CertificateError, match="does not refute P5"):
        DC.check(bad)
    # a Piecewise f: no slope witness (a branch taken at one point only has an unrelated derivative)
    pw = sp.Piecewise((2 - 5 * (e1 - 1), sp.Eq(e1, 1)), (1 + e1, True))       # f = 1 + e1, continuous
    bad = cert(pw, "P5", [K.value_sign(value=sp.Integer(-5))], {"kind": "slope", "points": [["Integer(1)", "Integer(0)"]]})
    with pytest.raises(DC.CertificateError, match="a slope witness needs an f without Piecewise"):
        DC.check(bad)
    # step: g(1, 0) - g(1/2, 0) = -3/4 with 0 < 1/2 < 1
    step = lambda p, q, g=G: cert(g, "P6", [K.value_sign(value=g.subs({e1: q[0], e2: q[1]}) - g.subs({e1: p[0], e2: p[1]}))],  # noqa: E731
                                  {"kind": "step", "points": [[sp.srepr(sp.sympify(c)) for c in x] for x in (p, q)]})
    assert checked(step((sp.Rational(1, 2), 0), (1, 0))).witness == "f(1, 0) - f(1/2, 0) has sign -1"
    with pytest.raises(DC.CertificateError, match="does not refute P6"):
        DC.check(step((-1, 0), (1, 0)))          # across e1 = 0: g(1) - g(-1) = 0 says nothing
    with pytest.raises(DC.CertificateError, match="does not refute P6"):
        DC.check(step((-1, 0), (sp.Rational(-1, 2), 0), F))   # F decreases for e1 < 0: what P6 needs there
    assert checked(step((-1, 0), (sp.Rational(-1, 2), 0))).witness == "f(-1/2, 0) - f(-1, 0) has sign 1"
    with pytest.raises(DC.CertificateError, match="does not refute P6"):
        DC.check(step((sp.Rational(1, 2), 0), (1, 1)))     # not on one horizontal line


def test_origin_jump_witness():
    for name in ("P1", "P7", "P8"):
        pc = checked(proposed(name, N, {"e1": "0", "e2": "0"}))
        assert pc.refutation_checked and pc.theorems == 3
        assert pc.witness == "df/de2 -> 1 and -1 along the e2 axis on either side of the origin"
    data = proposed("P5", N, {"e1": "0", "e2": "0"})
    assert data["properties"]["P5"]["witness"] == {"kind": "origin_jump", "var": "e1"}
    assert checked(data).refutation_checked
    wrong = copy.deepcopy(data)
    wrong["properties"]["P8"] = wrong["properties"].pop("P5")       # a jump of df/de1 says nothing about P8
    with pytest.raises(DC.CertificateError, match="P8: an origin jump of df/de1 does not refute P8"):
        DC.check(wrong)
    # the same for f written with a Piecewise: refused (no derivative witness for Piecewise f)
    pw = sp.Piecewise((N, e1 > -1), (N + 1, True))        # = N near the origin
    bad = copy.deepcopy(data)
    bad["design"]["f"] = sp.srepr(pw)
    with pytest.raises(DC.CertificateError, match="P5: a origin_jump witness needs an f without Piecewise"):
        DC.check(bad)
    # f = e1^2 + e2^2 - 1 has no jump: no witness is found, the refutation would rest on the search
    theorems, record, why = refutation_theorems("P8", refuted("", {"e1": "0", "e2": "-> 0+"}), F)
    assert theorems is None and record is None and "origin_jump" in why


def test_unknown_kind_and_unlinked_property_are_rejected():
    data = proposed("P3", F, {"e1": "1/2", "e2": "0"})
    data["properties"]["P3"]["witness"]["kind"] = "guess"
    with pytest.raises(DC.CertificateError, match="P3: no known witness kind"):
        DC.check(data)
    data = proposed("P3", F, {"e1": "1/2", "e2": "0"})
    data["properties"]["P5"] = data["properties"].pop("P3")
    with pytest.raises(DC.CertificateError, match="P5: a witness of kind 'value' does not refute P5"):
        DC.check(data)
    data = proposed("P3", F, {"e1": "1/2", "e2": "0"})
    # a refutation without its witness (or written before witnesses were checked) rests on the search, visibly
    data["properties"]["P3"]["kernel"], data["properties"]["P3"]["unchecked"] = None, []
    pc = checked(data)
    assert not pc.refutation_checked and pc.line() == f"P3: refuted; still rests on the search for: {DC.WITNESS_SEARCH}"
    # a refutation's theorems under a verdict "unknown": rejected
    data = proposed("P3", F, {"e1": "1/2", "e2": "0"})
    data["properties"]["P3"]["status"] = "unknown"
    with pytest.raises(DC.CertificateError, match="P3: kernel theorems for a verdict 'unknown'"):
        DC.check(data)


B = 1 - 1 / (1 + e1 ** 2 + e2 ** 2)        # f -> 1 as |e| -> oo: B <= 2 on every ray
Q = (e1 ** 2 + e2 ** 2) ** 2                # df/de2(0, h) = 4 h^3 -> oo; df/de1(h, 0)/h = 4 h^2 -> oo


def test_bounded_ray_witness_of_p3():
    data = proposed("P3", B, {"direction": "every", "limit": "1"})
    assert data["properties"]["P3"]["witness"] == {"kind": "bounded", "direction": ["Integer(1)", "Integer(0)"]}
    assert checked(data).witness == "f(h, 0) <= 2 for all h > 0"
    data = proposed("P3", B, {"direction": [-1, 2], "limit": "1"})
    assert checked(data).witness == "f(-h, 2*h) <= 2 for all h > 0"
    zero = copy.deepcopy(data)
    zero["properties"]["P3"]["witness"]["direction"] = ["Integer(0)", "Integer(0)"]
    with pytest.raises(DC.CertificateError, match="P3: the kernel's conclusions are not the witness 'bounded'"):
        DC.check(zero)
    other = copy.deepcopy(data)
    other["properties"]["P3"]["witness"]["direction"] = ["Integer(1)", "Integer(0)"]     # another ray
    with pytest.raises(DC.CertificateError, match="P3: the kernel's conclusions are not the witness 'bounded'"):
        DC.check(other)
    # Q is unbounded on the ray: no witness is found
    theorems, _, why = refutation_theorems("P3", refuted("", {"direction": "every", "limit": "1"}), Q)
    assert theorems is None and "bounded" in why


def test_unbounded_witness_of_p1_and_p6():
    pc = checked(proposed("P1", Q, {"s": "oo", "limit": "oo"}))
    assert pc.refutation_checked and pc.witness == "df/de2(0, h) -> oo as h -> oo" and "sympy-diff" in pc.assumptions
    data = proposed("P6", Q, {"s": "oo", "limit": "oo"})
    assert checked(data).witness == "df/de1(h, 0)/h -> oo as h -> oo"
    swapped = copy.deepcopy(data)
    swapped["properties"]["P1"] = swapped["properties"].pop("P6")
    with pytest.raises(DC.CertificateError, match=r"P1: a divergence \('e1', 1, 'oo'\) does not refute P1"):
        DC.check(swapped)
    swapped["properties"]["P1"]["witness"]["var"] = "e2"      # df/de1(h, 0)/h is not df/de2(0, h)
    with pytest.raises(DC.CertificateError, match="P1: the kernel's conclusions are not the witness 'unbounded'"):
        DC.check(swapped)
    # B' is bounded: no witness
    theorems, _, why = refutation_theorems("P1", refuted("", {"s": "oo", "limit": "oo"}), B)
    assert theorems is None and "unbounded" in why


@pytest.mark.slow
def test_no_witness_links_for_a_property_that_holds():
    """For every property that holds (tests/expectations.py, derived by hand)
    of every design file, made-up witnesses of every kind -- points of a
    grid, pairs on circles, rays, the origin, divergence -- never give kernel
    theorems that link as a refutation."""
    import sys
    from pathlib import Path
    root = Path(__file__).resolve().parents[1]
    sys.path.insert(0, str(root / "tests"))
    from expectations import EXPECTATIONS
    from uwmr_symbolic.design import load_design
    grid = ["1/3", "-1/2", "1", "-5/2"]
    witnesses = [{"e1": "0", "e2": "0"}, {"e1": "0", "e2": "-> 0+"}, {"s": "oo", "limit": "oo"},
                 {"direction": [-1, 2], "limit": "1"},
                 {"point_a": ["1", "0"], "point_b": ["3/5", "4/5"]}, {"point_a": ["0", "5/2"], "point_b": ["-3/2", "2"]},
                 *[{"e1": x, "e2": y} for x in grid for y in ("0", "1/3")]]
    tried = 0
    for rel, exp in EXPECTATIONS.items():
        path = root / rel
        if not path.exists() or rel.startswith("tests/adversarial"):
            continue
        f = load_design(path).f
        for name, verdict in exp["verdicts"].items():
            if verdict != "proved":
                continue
            for w in witnesses:
                theorems, record, _ = refutation_theorems(name, refuted("", w), f)
                assert theorems is None, (rel, name, record)
                tried += 1
    assert tried > 500


R34 = (e1 ** 2 + e2 ** 2) ** sp.Rational(3, 4)     # F = s^(3/2): F'(s)/s = 3/(2 sqrt(s)), F'' = 3/(4 sqrt(s))


def test_unbounded_near_the_origin_refutes_p6_and_p7():
    data = proposed("P6", R34, {"e1": "h -> 0+", "e2": "0", "limit": "oo"})
    assert data["properties"]["P6"]["witness"] == {"kind": "unbounded", "var": "e1", "order": 1, "at": "0"}
    assert checked(data).witness == "df/de1(h, 0)/h -> oo as h -> 0+"
    data = proposed("P7", R34, {"e1": "0", "e2": "h -> 0+", "limit": "oo"})
    assert checked(data).witness == "d2f/de2^2(0, h) -> oo as h -> 0+"
    at_oo = copy.deepcopy(data)
    at_oo["properties"]["P7"]["witness"]["at"] = "oo"       # unbounded at infinity says nothing about P7
    with pytest.raises(DC.CertificateError, match=r"P7: a divergence \('e2', 2, 'oo'\) does not refute P7"):
        DC.check(at_oo)
    as_p1 = copy.deepcopy(data)
    as_p1["properties"]["P1"] = as_p1["properties"].pop("P7")
    with pytest.raises(DC.CertificateError, match="P1: a divergence"):
        DC.check(as_p1)
    as_p1["properties"]["P1"]["witness"]["order"] = 1        # df/de2(0, h) = 3 sqrt(h)/2 -> 0: another expression
    with pytest.raises(DC.CertificateError, match="P1: the kernel's conclusions are not the witness 'unbounded'"):
        DC.check(as_p1)
    # P1 fails too, but at infinity: df/de2(0, h) = 3 sqrt(h)/2 has no finite bound kf
    data = proposed("P1", R34, {"e1": "0", "e2": "h -> 0+", "limit": "oo"})
    assert checked(data).witness == "df/de2(0, h) -> oo as h -> oo"


def test_a_refuted_p4_does_not_stand_for_the_radial_reduction():
    """Only a *proved* P4 (the identity f = F(|e|)) discharges the reduction
    that other properties rest on; a kernel-checked refutation of P4 must not."""
    from uwmr_symbolic.certify import REDUCTION
    data = proposed("P4", G, {"point_a": ["1", "0"], "point_b": ["3/5", "4/5"]})
    data["properties"]["P5"] = {"status": "proved", "reason": "", "kernel": None, "unchecked": [REDUCTION]}
    checks = {c.name: c for c in DC.check(json.dumps(data))}
    assert checks["P4"].refutation_checked and not checks["P4"].kernel_checked
    assert checks["P5"].unchecked == [REDUCTION]


RHO = e1 ** 2 + e2 ** 2
JUMP = sp.Piecewise((RHO, RHO <= 1), (RHO + 1, True))          # f(t, 0) -> 1 from the left of t = 1, -> 2 from the right
POINT = sp.Piecewise((5, sp.Eq(e1, 1)), (1 + e1, True))         # the value 5 at t = 1 only; limits 2 both sides
SMOOTH = sp.Piecewise((RHO, RHO <= 1), (2 * RHO - 1, True))      # continuous at t = 1 (a kink)


def test_jump_of_a_piecewise_f_along_the_axis():
    data = proposed("P1", JUMP, {"e1": "1", "e2": "0"})
    w = data["properties"]["P1"]["witness"]
    assert (w["kind"], w["branches"], w["compare"]) == ("jump", [0, 1], "sides")
    pc = checked(data)
    assert pc.refutation_checked and pc.theorems == 5
    assert pc.witness == "f(t, 0) jumps at t = 1: left limit 1, right limit 2, value 1"
    # Eq: the branch taken at t = 1 only; the value 5 differs from the limit 2 on the left
    data = proposed("P1", POINT, {"e1": "1", "e2": "0"})
    assert data["properties"]["P1"]["witness"]["compare"] == "left" and checked(data).refutation_checked
    # (for P5 a step comes first: f(5/4, 0) - f(1, 0) = 9/4 - 5 < 0)
    assert proposed("P5", POINT, {"e1": "1", "e2": "0"})["properties"]["P5"]["witness"]["kind"] == "step"
    # a continuous f with a kink: f(t, 0) = t^2, then 2 t^2 - 1; no jump of f, but df/de1 -> 2 from
    # the left and 4 from the right, so df/de1 cannot exist near (1, 0): P1, P5, P6 fail
    for name in ("P1", "P5", "P6"):
        data = proposed(name, SMOOTH, {"e1": "1", "e2": "0"})
        w = data["properties"][name]["witness"]
        assert (w["kind"], w["var"], w["order"], w["compare"]) == ("jump", "e1", 1, "sides")
        assert checked(data).witness.startswith("df/de1(t, 0) jumps at t = 1: left limit 2, right limit 4")
    for other in ("P7", "P8", "P3"):        # a kink says nothing about these
        bad = copy.deepcopy(data)
        bad["properties"][other] = bad["properties"].pop("P6")
        with pytest.raises(DC.CertificateError, match=f"{other}: a"):
            DC.check(bad)


HALF = sp.Piecewise((sp.log(1 + RHO), e1 > 0), (2 * sp.log(1 + RHO), True))   # switches across the line e1 = 0


def test_jump_across_a_line_off_the_axes():
    """HALF on the line e2 = 1: f(t, 1) = 2 log(2 + t^2) for t <= 0, log(2 + t^2) for t > 0, so the
    limits at t = 0 are 2 log 2 (left, also the value) and log 2 (right): df/de1 does not exist at
    (0, 1), and P1, P5, P6 fail.  On the axis itself f(t, 0) is continuous at 0 (both sides -> 0)."""
    for name in ("P1", "P5", "P6"):
        data = proposed(name, HALF, {"e1": "0", "e2": "1", "jump": "e1"})
        w = data["properties"][name]["witness"]
        assert (w["kind"], w["points"], w["compare"]) == ("jump", [["Integer(0)", "Integer(1)"]], "sides")
        assert checked(data).witness == "f(t, 1) jumps at t = 0: left limit 2*log(2), right limit log(2), value 2*log(2)"
    with pytest.raises(DC.CertificateError, match="P7: a jump of the order-0 derivative in e1 does not refute P7"):
        DC.check(as_property(data, "P6", "P7"))
    for point in (["Integer(0)", "Integer(0)"], ["Integer(0)", "Integer(2)"],
                  ["Integer(0)", "Pow(Integer(2), Rational(1, 2))"]):       # the axis, another line, not rational
        bad = copy.deepcopy(data)
        bad["properties"]["P6"]["witness"]["points"] = [point]
        with pytest.raises(DC.CertificateError, match="P6: the kernel's conclusions are not the witness 'jump'"):
            DC.check(bad)
    # switching across e2 = 0: f(1, t) jumps at t = 0, so df/de2 does not exist at (1, 0): P1, P7
    flip = HALF.xreplace({e1 > 0: e2 > 0})
    data = proposed("P7", flip, {"e1": "1", "e2": "0", "jump": "e2"})
    assert checked(data).witness == "f(1, t) jumps at t = 0: left limit 2*log(2), right limit log(2), value 2*log(2)"
    theorems, record, why = refutation_theorems("P5", refuted("", {"e1": "1", "e2": "0", "jump": "e2"}), flip)
    assert theorems is None                 # no jump of f in e1 there: P5 holds for flip


def test_tampered_jump_witness_is_rejected():
    data = proposed("P6", JUMP, {"e1": "1", "e2": "0"})
    for key, value in (("branches", [1, 1]), ("branches", [0, 0]), ("compare", "left"), ("width", "Rational(1, 2)"),
                       ("points", [["Integer(1)", "Integer(1)"]]), ("points", [["Rational(1, 2)", "Integer(0)"]])):
        bad = copy.deepcopy(data)
        bad["properties"]["P6"]["witness"][key] = value
        with pytest.raises(DC.CertificateError, match="P6: (the kernel's conclusions are not the witness 'jump'|jump:)"):
            DC.check(bad)
    # malformed records are refused as such, never a traceback (found by an adversarial campaign)
    for key, value, msg in (("points", [["Integer(1)", "1"]], "P6: the kernel's conclusions are not the witness"),
                            ("branches", [0, 9], "P6: the kernel's conclusions are not the witness"),
                            ("points", [["Integer(1)", "Integer(0)", "Integer(0)"]], "malformed design certificate"),
                            ("points", [], "malformed design certificate")):
        bad = copy.deepcopy(data)
        bad["properties"]["P6"]["witness"][key] = value
        with pytest.raises(DC.CertificateError, match=msg):
            DC.check(bad)
    dropped = copy.deepcopy(data)        # without the theorem that the left branch applies
    kernel = dropped["properties"]["P6"]["kernel"]
    kernel["conclusions"] = kernel["conclusions"][1:]
    with pytest.raises(DC.CertificateError, match="P6: the kernel's conclusions are not the witness 'jump'"):
        DC.check(dropped)
    other = copy.deepcopy(data)          # the same certificate about the continuous SMOOTH
    other["design"]["f"] = sp.srepr(SMOOTH)
    with pytest.raises(DC.CertificateError, match="P6: the kernel's conclusions are not the witness 'jump'"):
        DC.check(other)
    with pytest.raises(DC.CertificateError, match="P3: a witness of kind 'jump' does not refute P3"):
        DC.check(as_property(data, "P6", "P3"))


def test_a_gradient_unbounded_at_the_origin_refutes_p1_p6_p7_p8():
    """f = rho^(1/4) + (5/3) tanh(tanh(rho)) (a fuzzer design): df/de2(0, h) =
    h^(-1/2)/2 + (10 h/3) sech^2(h^2) sech^2(tanh(h^2)) -> oo as h -> 0+.  At
    "0" the kernel sees E(1/h) = sqrt(h)/2 + (10/(3h)) (1 - tanh(h^-2)^2)(...)
    and proves it diverges by comparison with sqrt(h)/2 (the other term is
    >= 0).  df/de2 is then unbounded near the origin: no kf (P1), no limit 0
    as e2 -> 0 (P8), not continuous as it would be with d2f/de2^2 existing (P7);
    df/de1(h, 0)/h -> oo refutes P6.  P5 by df/de1(h, 0) -> oo itself, not
    divided by h: were df/de1 to exist near the origin, g(t) = f(t, 0) would
    have g'(0) = lim g'(xi_t) = oo by the mean value theorem."""
    f = (e1 ** 2 + e2 ** 2) ** sp.Rational(1, 4) + sp.Rational(5, 3) * sp.tanh(sp.tanh(e1 ** 2 + e2 ** 2))
    origin = {"e1": "0", "e2": "0", "F'(0+)": "oo"}
    for name, witness, var in (("P1", origin, "e2"), ("P6", origin, "e1"), ("P7", origin, "e2"),
                               ("P8", {"e1": "0", "e2": "-> 0+", "limit": "oo"}, "e2")):
        data = proposed(name, f, witness)
        assert data["properties"][name]["witness"] == {"kind": "unbounded", "var": var, "order": 1, "at": "0"}
        assert checked(data).refutation_checked
    data5 = proposed("P5", f, origin)
    assert data5["properties"]["P5"]["witness"] == {"kind": "unbounded", "var": "e1", "order": 1, "at": "0",
                                                    "divided": False}
    assert checked(data5).witness == "df/de1(h, 0) -> oo as h -> 0+"
    for other, how in (("P7", "0"), ("P5", "oo")):       # df/de1 -> oo says nothing of P7, nor at infinity
        bad = copy.deepcopy(data5)
        bad["properties"][other] = bad["properties"].pop("P5")
        bad["properties"][other]["witness"]["at"] = how
        with pytest.raises(DC.CertificateError, match=f"{other}: a"):
            DC.check(bad)
    # the divergence of df/de2 does not refute P5 nor P3, and at infinity not P8
    for other, how in (("P5", "0"), ("P3", "0"), ("P8", "oo")):
        bad = copy.deepcopy(data)
        bad["properties"][other] = bad["properties"].pop("P8")
        bad["properties"][other]["witness"]["at"] = how
        with pytest.raises(DC.CertificateError, match=f"{other}: a (divergence|witness of kind 'unbounded')"):
            DC.check(bad)


def test_a_witness_shared_by_properties_is_proposed_once_and_complete():
    """f = 1/2 at the origin, 2 log(1 + 4 rho)/7 elsewhere: f(t, 0) jumps at
    t = 0 (1/2 against the limit 0), which refutes P1, P5 and P6 with one
    `jump` record.  The proposer completes that record (branches, side,
    width) and keeps the theorems for the next property: each certificate
    still carries the whole record and re-checks."""
    rho = e1 ** 2 + e2 ** 2
    f = sp.Piecewise((sp.Rational(1, 2), sp.Eq(rho, 0)), (2 * sp.log(4 * rho + 1) / 7, True))
    witness = {"e1": "0", "e2": "0", "f": "1/2", "limit": "0"}
    records = []
    for name in ("P1", "P5", "P6"):
        data = proposed(name, f, witness)
        assert checked(data).refutation_checked
        records.append(data["properties"][name]["witness"])
    assert records[0]["kind"] == "jump" and "branches" in records[0] and records[0] == records[1] == records[2]


def test_bounded_ray_witness_of_a_piecewise_f():
    """f = 2 on the circle rho = 3, rho/(1 + rho) < 1 elsewhere: f -> 1, so P3
    fails; f(h, 0) <= 2 for all h > 0 is shown piece by piece between the
    roots of the condition (h^2 = 3: (0, sqrt 3), the point, (sqrt 3, oo)).
    The limit 1 itself is no bound (f = 2 at h = sqrt 3), and the proposer
    does not find it one."""
    from uwmr_symbolic.certify import sup_upper_theorem
    rho = e1 ** 2 + e2 ** 2
    f = sp.Piecewise((2, sp.Eq(rho, 3)), (rho / (1 + rho), True))
    data = proposed("P3", f, {"direction": "every", "limit": "1"})
    assert checked(data).witness == "f(h, 0) <= 2 for all h > 0"
    assert sup_upper_theorem(DC.along_ray(f, (1, 0)), 1, DC.H) is None
    assert sup_upper_theorem(DC.along_ray(f, (1, 0)), sp.Rational(199, 100), DC.H) is None


def test_bounded_ray_witness_through_a_transcendental_condition():
    """f = Max(rho/(1 + rho), atan(rho)), which the loader writes as a
    Piecewise on atan(rho) >= rho/(1 + rho).  By hand, d/dx (atan x - x/(1 + x))
    = 1/(1 + x^2) - 1/(1 + x)^2 >= 0 and the difference is 0 at x = 0, so the
    condition holds for every rho >= 0, f = atan(rho) < pi/2 < 2, and P3 fails
    (f -> pi/2; the bound proposed is 1 + pi/2).  The condition has no polynomial root to cut at: the kernel
    signs it on all of (0, oo).  For g = Max(rho/(1 + rho), 3 rho e^-rho) the
    condition changes sign (3x e^-x vs x/(1 + x): 3x > x near 0, below 1 for
    large x), and g(1, 0) = 3/e > 21/20: no proof of g <= 21/20."""
    from uwmr_symbolic.certify import sup_upper_theorem
    rho = e1 ** 2 + e2 ** 2
    f = sp.piecewise_fold(sp.Max(rho / (1 + rho), sp.atan(rho)).rewrite(sp.Piecewise))
    assert isinstance(f, sp.Piecewise)
    data = proposed("P3", f, {"direction": "every", "limit": "pi/2"})
    assert checked(data).witness == "f(h, 0) <= 1 + pi/2 for all h > 0"
    g = sp.piecewise_fold(sp.Max(rho / (1 + rho), 3 * rho * sp.exp(-rho)).rewrite(sp.Piecewise))
    assert sup_upper_theorem(DC.along_ray(g, (1, 0)), sp.Rational(21, 20), DC.H) is None


def test_unbounded_slope_of_the_last_branch_of_a_piecewise_f():
    """f = rho/2 for rho <= 1, rho - 1/2 beyond (continuous at rho = 1): on the
    e2 axis beyond t = 1 f(0, t) = t^2 - 1/2, whose derivative 2t -> oo, so kf
    is infinite (P1).
    The record names the branch (1) and where it starts (R = 1): the kernel
    shows the condition h^2 + 2h + 1 > 1, i.e. (1 + h)^2 - 1 > 0, on h > 0.
    Another branch or R = 0 (where rho <= 1 still holds) is refused."""
    rho = e1 ** 2 + e2 ** 2
    f = sp.Piecewise((rho / 2, rho <= 1), (rho - sp.Rational(1, 2), True))
    data = proposed("P1", f, {"s": "oo", "limit": "oo"})
    w = data["properties"]["P1"]["witness"]
    assert (w["kind"], w["var"], w["branch"], parse(w["from"])) == ("unbounded", "e2", 1, 1)
    assert checked(data).witness == "df/de2(0, h) -> oo as h -> oo"
    for key, value in (("branch", 0), ("from", "Integer(0)"), ("at", "0")):
        bad = copy.deepcopy(data)
        bad["properties"]["P1"]["witness"][key] = value
        with pytest.raises(DC.CertificateError):
            DC.check(bad)


def test_jump_where_a_condition_is_an_or_or_an_and_of_relations():
    """f = rho if (rho < 1/2 or rho < 1), else rho + 1: f(t, 0) -> 1 from the
    left of t = 1 and is 2 from the right (the Or holds on (3/4, 1) by its
    second relation and fails beyond 1 by both): P1 is refuted by the jump.
    With And in place of Or the first branch stops at 1/sqrt(2): f(t, 0) =
    t^2 + 1 on both sides of 1, no jump, no witness."""
    rho = e1 ** 2 + e2 ** 2
    f = sp.Piecewise((rho, (rho < sp.Rational(1, 2)) | (rho < 1)), (rho + 1, True))
    data = proposed("P1", f, {"e1": "1", "e2": "0"})
    assert checked(data).witness == "f(t, 0) jumps at t = 1: left limit 1, right limit 2, value 2"
    g = sp.Piecewise((rho, (rho < sp.Rational(1, 2)) & (rho < 1)), (rho + 1, True))
    theorems, _, why = refutation_theorems("P1", refuted("", {"e1": "1", "e2": "0"}), g)
    assert theorems is None


# Not radial, by hand: W = log(1 + e1^2 + e1 e2 + e2^2) (a positive definite quadratic form inside).
# df/de1 = (2 e1 + e2)/(1 + Q), df/de2 = (e1 + 2 e2)/(1 + Q).
# df/de1(0, 1) = 1/2 != 0, where P6's k e1 h is 0; df/de2(1, h) -> 1/2 as h -> 0+ (P8 wants 0).
W = sp.log(1 + e1 ** 2 + e1 * e2 + e2 ** 2)


def test_slope_on_the_e2_axis_refutes_p6_only():
    data = proposed("P6", W, {"e1": "0", "e2": "1"})
    assert data["properties"]["P6"]["witness"] == {"kind": "slope", "points": [["Integer(0)", "Integer(1)"]]}
    assert checked(data).witness == "df/de1(0, 1) has sign 1"
    # P5 asks nothing on e1 = 0 (df/de1 tanh(0) = 0 whatever df/de1 is): the same claim refutes nothing
    with pytest.raises(DC.CertificateError, match=r"P5: the kernel's claim \(df/de1\(0, 1\) has sign 1\) does not"):
        DC.check(as_property(data, "P6", "P5"))
    # a zero slope on e1 = 0 is what P6 needs: F's df/de1(0, 1) = 0
    zero = cert(F, "P6", [K.value_sign(value=sp.Integer(0))], {"kind": "slope", "points": [["Integer(0)", "Integer(1)"]]})
    with pytest.raises(DC.CertificateError, match="does not refute P6"):
        DC.check(zero)


def test_e2_limit_witness_of_p8():
    data = proposed("P8", W, {"e1": "1", "e2": "0", "approach": "e2", "limit": "1/2"})
    assert data["properties"]["P8"]["witness"] == {"kind": "e2_limit", "points": [["Integer(1)", "Integer(0)"]]}
    pc = checked(data)
    assert pc.refutation_checked and pc.theorems == 2 and pc.witness == "df/de2(1, h) -> 1/2 != 0 as h -> 0+"
    # another e1: the kernel's limit is about df/de2(1, h), not df/de2(2, h)
    moved = copy.deepcopy(data)
    moved["properties"]["P8"]["witness"]["points"][0][0] = "Integer(2)"
    with pytest.raises(DC.CertificateError, match="P8: the kernel's conclusions are not the witness 'e2_limit'"):
        DC.check(moved)
    # only P8: the same limit says nothing about P1
    with pytest.raises(DC.CertificateError, match="P1: a witness of kind 'e2_limit' does not refute P1"):
        DC.check(as_property(data, "P8", "P1"))
    # F's df/de2(1, h) = 2 h -> 0: the kernel's limit is 0, and a zero limit refutes nothing
    lim = K.continuous_at_end(expr=2 * DC.H, var=DC.H, c=0, width=sp.Rational(1, 2))
    bad = cert(F, "P8", [lim, K.value_sign(value=sp.Integer(0))], {"kind": "e2_limit", "points": [["Integer(1)", "Integer(0)"]]})
    with pytest.raises(DC.CertificateError, match="the kernel's conclusions are not the witness 'e2_limit'"):
        DC.check(bad)
    # the witness is not looked for without the search's e2 approach
    theorems, record, why = refutation_theorems("P8", refuted("", {"e1": "1", "e2": "0"}), W)
    assert theorems is None


# Max and Min as the loader reads them (Piecewise); the arguments cross where log(1 + x) = x/2, x = 2.5128624...
MAXC, MINC = (sp.piecewise_fold(m(sp.log(1 + RHO), RHO / 2).rewrite(sp.Piecewise)) for m in (sp.Max, sp.Min))
R2 = sp.sqrt(2)
# 3 e1/2 - sqrt(2)/2 + log(1 + e2^2) written as two branches that differ by |e1 - sqrt(2)| terms: smooth,
# so df/de1 = 3/2 everywhere, although the branches' e1-derivatives, with sign(e1 - sqrt(2))/2 cancelled,
# differ by 1
CANCEL = sp.Piecewise((2 * e1 - R2 - sp.Abs(e1 - R2) / 2 + sp.log(1 + e2 ** 2), e1 >= R2),
                      (e1 - sp.Abs(e1 - R2) / 2 + sp.log(1 + e2 ** 2), True))


def test_crossing_of_a_max_refutes_p1_p5_p6():
    """MAXC on the axis: d(t) = t^2/2 - log(1 + t^2), d' = t (t^2 - 1)/(1 + t^2) > 0 on [3/2, 8/5],
    d(3/2) = 9/8 - log(13/4) = -0.0537, d(8/5) = 32/25 - log(89/25) = 0.0102: one crossing c = 1.58520 in
    between, log(1 + t^2) before it, t^2/2 after.  The slopes there are 2t/(1 + t^2) in [0.898, 0.924] and
    t in [3/2, 8/5]: they differ, so f(t, 0) has a corner at c and df/de1 does not exist at (c, 0)."""
    for name in ("P1", "P5", "P6"):
        data = proposed(name, MAXC, {"e1": "1.585", "e2": "0", "crossing": ["3/2", "8/5"]})
        w = data["properties"][name]["witness"]
        assert (w["kind"], w["order"], w["points"]) == ("crossing", 1, [["Rational(3, 2)", "Integer(0)"],
                                                                          ["Rational(8, 5)", "Integer(0)"]])
        pc = checked(data)
        assert pc.refutation_checked and pc.theorems == 9
        assert pc.witness.startswith("df/de1 does not exist where") and "e1 axis, between 3/2 and 8/5" in pc.witness
    claims = [c["claim"] for c in data["properties"]["P6"]["kernel"]["theorems"]]
    signs = {(c["kind"], c["want"]) for c in claims if c["kind"] == "value_sign"}
    assert signs == {("value_sign", -1), ("value_sign", 1)}
    # the min of the same two crosses at the same point with the same corner
    assert checked(proposed("P1", MINC, {"e1": "1.585", "e2": "0", "crossing": ["3/2", "8/5"]})).refutation_checked
    # no crossing in [8/5, 2] (d > 0 at both ends), and at [1, 3/2] d(1) < 0 as well: nothing proposed
    for bracket in (["8/5", "2"], ["1", "3/2"]):
        theorems, _, why = refutation_theorems("P1", refuted("", {"e1": "2", "e2": "0", "crossing": bracket}), MAXC)
        assert theorems is None and "crossing" in why


def test_tampered_crossing_witness_is_rejected():
    data = proposed("P6", MAXC, {"e1": "1.585", "e2": "0", "crossing": ["3/2", "8/5"]})
    for key, value in (("order", 0), ("order", 2), ("order", True), ("order", None),
                       ("points", [["Rational(3, 2)", "Integer(0)"], ["Integer(2)", "Integer(0)"]]),
                       ("points", [["Rational(3, 2)", "Integer(1)"], ["Rational(8, 5)", "Integer(1)"]]),
                       ("points", [["Rational(8, 5)", "Integer(0)"], ["Rational(3, 2)", "Integer(0)"]])):
        bad = copy.deepcopy(data)
        bad["properties"]["P6"]["witness"][key] = value
        with pytest.raises(DC.CertificateError, match="P6: the kernel's conclusions are not the witness 'crossing'"):
            DC.check(bad)
    for drop in (0, 3, 8):          # d' signed, the gap, or that dB/de1 is defined: each is needed
        bad = copy.deepcopy(data)
        kernel = bad["properties"]["P6"]["kernel"]
        kernel["conclusions"] = [c for i, c in enumerate(kernel["conclusions"]) if i != drop]
        with pytest.raises(DC.CertificateError, match="P6: the kernel's conclusions are not the witness 'crossing'"):
            DC.check(bad)
    swapped = copy.deepcopy(data)        # "d is defined" and "A is defined" in each other's place
    kernel = swapped["properties"]["P6"]["kernel"]
    kernel["conclusions"][4:6] = kernel["conclusions"][5:3:-1]
    with pytest.raises(DC.CertificateError, match="P6: the kernel's conclusions are not the witness 'crossing'"):
        DC.check(swapped)
    # d' or the gap only weakly signed (>= 0 or <= 0) show no crossing and no corner
    from uwmr_symbolic.certify import _crossing_theorems
    record = {"kind": "crossing", "var": "e1", "order": 1,
              "points": [(sp.Rational(3, 2), sp.Integer(0)), (sp.Rational(8, 5), sp.Integer(0))]}
    theorems = _crossing_theorems(MAXC, record)
    for i in (0, 3):
        c = theorems[i].claim
        weak = list(theorems)
        weak[i] = K.sign_by_cover(expr=parse(c.expr), var=DC.H, cuts=[sp.Rational(3, 2), sp.Rational(8, 5)],
                                  want=c.want, strict=False)
        with pytest.raises(DC.CertificateError, match="P6: the kernel's conclusions are not the witness 'crossing'"):
            DC.check(cert(MAXC, "P6", weak, data["properties"]["P6"]["witness"]))
    assert checked(cert(MAXC, "P6", theorems, data["properties"]["P6"]["witness"])).refutation_checked
    other = copy.deepcopy(data)          # the same certificate about a design with one more branch
    other["design"]["f"] = sp.srepr(sp.Piecewise((RHO, RHO < 1), *MAXC.args))
    with pytest.raises(DC.CertificateError, match="crossing: f is not Piecewise"):
        DC.check(other)
    with pytest.raises(DC.CertificateError, match="P7: a crossing on the e1 axis does not refute P7"):
        DC.check(as_property(data, "P6", "P7"))
    with pytest.raises(DC.CertificateError, match="P3: a witness of kind 'crossing' does not refute P3"):
        DC.check(as_property(data, "P6", "P3"))
    # on the e2 axis the same corner refutes P1 and P7 (d2f/de2^2 needs df/de2 at (0, c)), not P5 or P6
    data = proposed("P7", MAXC, {"e1": "0", "e2": "1.585", "crossing": ["3/2", "8/5"]})
    w = data["properties"]["P7"]["witness"]
    assert (w["var"], w["points"]) == ("e2", [["Integer(0)", "Rational(3, 2)"], ["Integer(0)", "Rational(8, 5)"]])
    assert checked(data).witness.startswith("df/de2 does not exist where")
    assert checked(as_property(data, "P7", "P1")).refutation_checked
    with pytest.raises(DC.CertificateError, match="P5: a crossing on the e2 axis does not refute P5"):
        DC.check(as_property(data, "P7", "P5"))
    bad = copy.deepcopy(data)
    bad["properties"]["P7"]["witness"]["var"] = "e1"
    with pytest.raises(DC.CertificateError, match="P7: a crossing on the e1 axis does not refute P7"):
        DC.check(bad)
    bad["properties"]["P7"]["witness"]["var"] = "e3"
    with pytest.raises(DC.CertificateError, match="P7: a crossing on the e3 axis does not refute P7"):
        DC.check(bad)


def test_a_crossing_needs_each_branch_and_its_slope_defined():
    """CANCEL is smooth (df/de1 = 3/2), but the difference of its branches' e1-derivatives is 1 on
    [7/5, 3/2], where e1 >= sqrt(2) switches: without the claims that each part is defined there, a
    certificate would refute P1.  dA/de1 = 2 - sign(e1 - sqrt(2))/2 has no value of one sign near
    sqrt(2), so the kernel shows no bound of it, and nothing refutes P1."""
    d, dd, gap, defined = DC.crossing_parts(CANCEL, 1)
    assert (dd, gap) == (-1, 1) and len(defined) == 5
    q1, q2 = sp.Rational(7, 5), sp.Rational(3, 2)
    theorems = [K.sign_by_cover(expr=dd, var=DC.H, cuts=[q1, q2], want=-1),
                *[K.value_sign(value=d.xreplace({DC.H: q})) for q in (q1, q2)],
                K.sign_by_cover(expr=gap, var=DC.H, cuts=[q1, q2], want=1)]
    record = {"kind": "crossing", "order": 1, "points": [[K._s(q1), "Integer(0)"], [K._s(q2), "Integer(0)"]]}
    with pytest.raises(DC.CertificateError, match="P1: the kernel's conclusions are not the witness 'crossing'"):
        DC.check(cert(CANCEL, "P1", theorems, record))
    with pytest.raises(K.KernelError):
        K.sign_by_cover(expr=3 - defined[3], var=DC.H, cuts=[q1, q2], want=1, strict=False)
    theorems, _, why = refutation_theorems("P1", refuted("", {"e1": "1.41", "e2": "0", "crossing": ["7/5", "3/2"]}),
                                           CANCEL)
    assert theorems is None


def test_a_condition_at_a_witness_point_is_read_from_the_kernel_s_sign():
    """Red team 23: with x = 10^-40 rho and T4 = x - x^2/2 + x^3/3 - x^4/4, g = log(1 + x) - T4 has g(0) = 0
    and g' = x^4/(1 + x) > 0, so log(1 + x) < T4 never holds and f is log(1 + rho) everywhere: f(-3, -3) =
    log 19 > 0.  SymPy's comparison (2 digits) takes the condition for true at (-3, -3) (log(1 + 18 10^-40)
    evaluates as log 1), so f there had been read as 0**18 - 1 = -1 and a true P3 refuted, kernel-checked."""
    x = RHO / 10 ** 40
    t4 = x - x ** 2 / 2 + x ** 3 / 3 - x ** 4 / 4
    f = sp.Piecewise((sp.Pow(0, RHO) - 1, sp.log(1 + x) < t4), (sp.log(1 + RHO), True))
    at = {e1: -3, e2: -3}
    assert arb._SYMPY_N2(sp.log(1 + x).xreplace(at), t4.xreplace(at)) < 0      # SymPy's own misreading (`kernel.arb`)
    assert sp.Lt(sp.log(1 + x), t4).xreplace(at) == sp.false                    # as the kernel reads it
    assert DC.at_point(f, (-3, -3)) == sp.log(19)
    theorems, _, why = refutation_theorems("P3", refuted("", {"e1": "-3", "e2": "-3"}), f)
    assert theorems is None
    # a certificate that claims the value -1 there is refused: the link reads f(-3, -3) as log 19
    forged = cert(f, "P3", [K.value_sign(value=sp.Integer(-1))], {"kind": "value", "points": [["-3", "-3"]]})
    with pytest.raises(DC.CertificateError, match="P3: the kernel's conclusions are not the witness 'value'"):
        DC.check(forged)
    # Eq reads an exact 0; a sign beyond the kernel's 32,768 bits (log(2 + exp(-30000)) - log 2 > 0) is
    # neither true nor false, and f has no value there
    g = sp.Piecewise((1, sp.Eq(e1, 0)), (2, True))
    assert DC.at_point(g, (0, 5)) == 1 and DC.at_point(g, (sp.Rational(1, 10 ** 30), 0)) == 2
    tiny = sp.log(2 + sp.exp(-30000)) - sp.log(2)
    assert DC.at_point(sp.Piecewise((1, e1 < tiny), (2, True)), (0, 0)) is sp.nan


def test_abs_sign_max_min_at_a_witness_point_are_read_from_the_kernel_s_sign():
    """g = log(1 + x) - T4(x) > 0 for x = 10^-40 rho > 0 (remainder x^5/5), so |g| - g = 0 and f = log(1 + rho)
    + 10^200 (|g| - g) is log(1 + rho).  SymPy's Abs of the constant g(18) asks SymPy's sign of it (2 digits:
    negative), so f(-3, -3) had been read as log 19 - 2 10^200 g(18) < 0 and a certificate refuting the true
    P3 there was accepted.  |u|, sign, Max and Min are read as Piecewise, their conditions by the kernel."""
    x = RHO / 10 ** 40
    g = sp.log(1 + x) - (x - x ** 2 / 2 + x ** 3 / 3 - x ** 4 / 4)
    f = sp.log(1 + RHO) + 10 ** 200 * (sp.Abs(g) - g)
    g18 = g.xreplace({e1: -3, e2: -3})
    assert arb._SYMPY_SIGN(g18, False) is True and sp.Abs(g18) == g18          # SymPy's own misreading; the kernel's
    assert DC.at_point(f, (-3, -3)) == sp.log(19)
    assert refutation_theorems("P3", refuted("", {"e1": "-3", "e2": "-3"}), f)[0] is None
    forged = cert(f, "P3", [K.value_sign(value=sp.log(19) - 2 * 10 ** 200 * g.xreplace({e1: -3, e2: -3}))],
                  {"kind": "value", "points": [["-3", "-3"]]})
    with pytest.raises(DC.CertificateError, match="P3: the kernel's conclusions are not the witness 'value'"):
        DC.check(forged)
    # the same reading everywhere else: |u| < 1 (an ITE once rewritten), sign, Max, Min of three
    assert [DC.at_point(sp.Piecewise((1, sp.Abs(e1) < 1), (2, True)), p) for p in ((sp.Rational(1, 2), 5), (-3, 5))] == [1, 2]
    assert (DC.at_point(sp.Abs(e1) + sp.sign(e2), (-2, 0)), DC.at_point(sp.Min(e1, e2, 1), (3, 2))) == (2, 1)


def test_a_claim_s_constant_is_positive_by_the_kernel_s_sign():
    """d = log(1 + 10^-40) - T4(10^-40) = 2 10^-201 (1 + ...) > 0 (the Taylor remainder x^5/5), which SymPy's
    assumptions, evaluating to 2 digits, call negative.  P6's k > 0 (the links of f analytic on the plane,
    separable and Piecewise f) is read with the kernel's sign."""
    k = sp.Rational(1, 10 ** 40)
    d = sp.log(1 + k) - (k - k ** 2 / 2 + k ** 3 / 3 - k ** 4 / 4)
    assert arb._SYMPY_SIGN(d, False) is True and d.is_positive is True          # SymPy's own misreading; the kernel's
    assert DC._positive(sp.srepr(d)) and not DC._positive(sp.srepr(-d)) and not DC._positive("Symbol('x')")
