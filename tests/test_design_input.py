"""Design files the loader must accept: no gains (and the report says bound (10)
was not checked), a straight-line reference (|Wr|max = 0), a helper module
beside the design file."""
import sys
from pathlib import Path

import pytest
import sympy as sp

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _cli import run_cli  # noqa: E402

from uwmr_symbolic.design import DesignError, load_design  # noqa: E402
from uwmr_symbolic.gains import check_gains  # noqa: E402

JIANG = "import sympy as sp\nfrom uwmr_symbolic import e1, e2\nf = sp.log(1 + e1**2 + e2**2)/2\n"


@pytest.mark.slow        # runs the command line
def test_no_gains_says_bound_10_was_not_checked(tmp_path):
    design = tmp_path / "jiang.py"
    design.write_text(JIANG)
    run = run_cli([design, "--no-cache"], timeout=300)
    assert run.returncode == 0, run.describe()
    assert "gains within the limits" not in run.stdout
    assert "no gain scenarios given, so bound (10) was not checked" in run.stdout.splitlines()[-1]


def test_straight_line_reference_wr_max_zero_is_accepted(tmp_path):
    design = tmp_path / "line.py"
    design.write_text(JIANG + "gains = {'line': dict(k1=0.25, k2=0.7, lam=1.2, Vmax=0.75, Wmax=2.0, "
                              "Vr_max=0.5, Wr_max=0)}\n")
    d = load_design(design)
    assert d.gains["line"]["Wr_max"] == 0
    g = check_gains(d.gains, sp.Rational(1, 2))["line"]
    # bound (10): |W| <= 0 + 1.2 * 0.5 * 1/2 + 0.7 = 1
    assert g.W_bound == 1 and g.W_ok and g.V_ok
    # Vr_max = 0 stays refused: lim Vr(t) != 0 is assumed in (2)-(3)
    design.write_text(JIANG + "gains = {'line': dict(k1=0.25, k2=0.7, lam=1.2, Vmax=0.75, Wmax=2.0, "
                              "Vr_max=0, Wr_max=0)}\n")
    try:
        load_design(design)
    except DesignError as exc:
        assert "Vr_max" in str(exc) and "positive" in str(exc)
    else:
        raise AssertionError("Vr_max = 0 accepted")
    design.write_text(JIANG + "gains = {'line': dict(k1=0.25, k2=0.7, lam=1.2, Vmax=0.75, Wmax=2.0, "
                              "Vr_max=0.5, Wr_max=-1)}\n")
    try:
        load_design(design)
    except DesignError as exc:
        assert "must not be negative" in str(exc)
    else:
        raise AssertionError("Wr_max = -1 accepted")


def test_design_imports_a_helper_module_beside_it(tmp_path):
    (tmp_path / "uwmr_test_helper_shapes.py").write_text(
        "import sympy as sp\ndef jiang(a, b):\n    return sp.log(1 + a**2 + b**2) / 2\n")
    design = tmp_path / "uses_helper.py"
    design.write_text("from uwmr_symbolic import e1, e2\nfrom uwmr_test_helper_shapes import jiang\n"
                      "f = jiang(e1, e2)\n")
    d = load_design(design)
    e1, e2 = sp.symbols("e1 e2", real=True)
    assert d.f == sp.log(1 + e1**2 + e2**2) / 2
    # the helper is read afresh next time (edited between two runs in a notebook)
    assert "uwmr_test_helper_shapes" not in sys.modules
    assert str(tmp_path) not in sys.path
    (tmp_path / "uwmr_test_helper_shapes.py").write_text(
        "import sympy as sp\ndef jiang(a, b):\n    return sp.sqrt(1 + a**2 + b**2) - 1\n")
    assert load_design(design).f == sp.sqrt(1 + e1**2 + e2**2) - 1


def test_design_imports_a_helper_package_beside_it(tmp_path):
    """The same with a package (helpers/shapes.py): its modules are forgotten
    too, so an edit is seen by the next load in the same session."""
    (tmp_path / "uwmr_test_helpers").mkdir()
    (tmp_path / "uwmr_test_helpers" / "__init__.py").write_text("")
    shapes = tmp_path / "uwmr_test_helpers" / "shapes.py"
    shapes.write_text("import sympy as sp\ndef g(a, b):\n    return sp.log(1 + a**2 + b**2) / 2\n")
    design = tmp_path / "uses_package.py"
    design.write_text("from uwmr_symbolic import e1, e2\nfrom uwmr_test_helpers.shapes import g\nf = g(e1, e2)\n")
    e1, e2 = sp.symbols("e1 e2", real=True)
    assert load_design(design).f == sp.log(1 + e1**2 + e2**2) / 2
    assert not any(m.startswith("uwmr_test_helpers") for m in sys.modules)
    shapes.write_text("import sympy as sp\ndef g(a, b):\n    return sp.sqrt(1 + a**2 + b**2) - 1\n")
    assert load_design(design).f == sp.sqrt(1 + e1**2 + e2**2) - 1


def test_a_constant_written_as_a_python_number_is_read(tmp_path):
    """f = 0 (a plain int) is the design f = 0: f(0, 0) = 0 (P2), f > 0 fails
    everywhere (P3), df/de1 = 0 so P5 fails; 0.5 keeps its binary value."""
    path = tmp_path / "zero.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nf = 0\n")
    assert load_design(path).f == 0
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nf = 0.5\n")
    assert load_design(path).f == sp.Rational(1, 2)
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nf = True\n")
    with pytest.raises(DesignError, match="is a bool"):
        load_design(path)


def test_functions_the_checker_does_not_read_are_rewritten_when_that_is_an_identity(tmp_path):
    """sech, coth, cot and the golden ratio become quotients of cosh, sinh,
    cos, sin and a radical (the same function on the same domain), and an
    unevaluated Subs of a Derivative is carried out, so that the kernel can
    re-check the design; Apery's constant zeta(3) has no such form, and the
    certificate check then says which name it cannot read."""
    from uwmr_symbolic import design_certificate as DC
    from uwmr_symbolic.verify import verify_design
    e1, e2 = sp.symbols("e1 e2", real=True)
    rho = e1 ** 2 + e2 ** 2
    cases = {"sp.sech(rho) + sp.coth(1 + rho) + sp.cot(1 + rho)":
             1 / sp.cosh(rho) + sp.cosh(1 + rho) / sp.sinh(1 + rho) + sp.cos(1 + rho) / sp.sin(1 + rho),
             "sp.GoldenRatio * sp.log(1 + rho)": (1 + sp.sqrt(5)) / 2 * sp.log(1 + rho),
             "sp.Subs(sp.Derivative(sp.log(1 + t * rho), t), t, 1)": rho / (1 + rho)}
    for text, want in cases.items():
        path = tmp_path / "d.py"
        path.write_text(f"import sympy as sp\nfrom uwmr_symbolic import e1, e2\nt = sp.Symbol('t')\n"
                        f"rho = e1**2 + e2**2\nf = {text}\n")
        f = load_design(path).f
        assert sp.simplify(f - want) == 0 and not f.has(sp.sech, sp.coth, sp.cot, sp.Subs, sp.GoldenRatio), f
    path = tmp_path / "apery.py"
    path.write_text("import sympy as sp\nfrom uwmr_symbolic import e1, e2\nf = sp.zeta(3) * sp.log(1 + e1**2 + e2**2)\n")
    with pytest.raises(DC.CertificateError, match="cannot read the design's f .name not allowed: zeta."):
        DC.check(DC.build(verify_design(path)))


def test_a_membership_without_relations_is_left_as_written(tmp_path):
    """Contains(e1, [0, 1]) becomes 0 <= e1 <= 1; a set with no relations
    (the even integers, an ImageSet) stays a Contains, with no internal error."""
    e1 = sp.Symbol("e1", real=True)
    for where, want in (("sp.Interval(0, 1)", sp.And(e1 >= 0, e1 <= 1)),
                        ("sp.ImageSet(sp.Lambda(n, 2 * n), sp.Integers)", None)):
        path = tmp_path / "d.py"
        path.write_text("import sympy as sp\nfrom uwmr_symbolic import e1, e2\nn = sp.Symbol('n')\n"
                        f"f = sp.Piecewise((e1**2 + e2**2, sp.Contains(e1, {where})), (2*e1**2 + e2**2, True))\n")
        cond = load_design(path).f.args[0][1]
        assert cond == want if want is not None else isinstance(cond, sp.Contains), cond


def test_symbol_assumptions_that_hold_are_accepted_and_the_others_refused(tmp_path):
    """e1, e2 with no assumptions or real=True (SymPy's simplifications for
    them hold for every real value) are read as the real e1, e2; anything
    more, or a parameter value against its symbol's declaration, is refused
    (tests/bad_inputs has the cases where SymPy had already used it)."""
    design = tmp_path / "d.py"
    head = "import sympy as sp\n"
    for decl in ("sp.symbols('e1 e2')", "sp.symbols('e1 e2', real=True)", "sp.symbols('e1 e2', finite=True)"):
        design.write_text(head + f"e1, e2 = {decl}\nf = sp.sqrt(e1**2) + e2**2\n")
        f = load_design(design).f       # |e1| + e2^2, whatever form: 3 at (-3, 0) (e1 + e2^2 would give -3)
        assert f.subs({sp.Symbol("e1", real=True): -3, sp.Symbol("e2", real=True): 0}) == 3, decl
    for decl, fact in (("sp.symbols('e1 e2', nonnegative=True)", "nonnegative=True"),
                       ("sp.symbols('e1 e2', integer=True)", "integer=True"),
                       ("(sp.Symbol('e1', real=True), sp.Symbol('e2', nonzero=True))", "nonzero=True")):
        design.write_text(head + f"e1, e2 = {decl}\nf = e1**2 + e2**2\n")
        with pytest.raises(DesignError, match=f"is declared {fact}, but f is studied for every real"):
            load_design(design)
    params = "e1, e2 = sp.symbols('e1 e2', real=True)\nc = sp.Symbol('c', {})\nf = c * (e1**2 + e2**2)\n" \
             "params = {{c: {}}}\n"
    for decl, value, read in (("positive=True", "sp.Rational(1, 3)", sp.Rational(1, 3)), ("integer=True", "2", 2),
                              ("real=True", "-1", -1)):
        design.write_text(head + params.format(decl, value))
        assert load_design(design).params["c"] == read, decl
    for decl, value, fact in (("positive=True", "0", "positive=True"), ("integer=True", "0.5", "integer=True"),
                              ("nonpositive=True", "sp.sqrt(2)", "nonpositive=True")):
        design.write_text(head + params.format(decl, value))
        with pytest.raises(DesignError, match=rf"params\['c'\] = .* does not satisfy {fact}"):
            load_design(design)


def test_a_sympy_float_no_double_holds_is_read_as_written():
    """A SymPy Float of 53 bits that no double holds was read through
    float(): 1e-400 as 0 (log(1 + rho) + Float('1e-400') had P2 "proved"),
    3e-324 as 5e-324.  It is now read as the shortest decimal that rounds
    back to it at 53 bits; what a double holds keeps Python's repr."""
    from uwmr_symbolic.design import exact_float
    cases = {sp.Float("1e-400"): sp.Rational(1, 10 ** 400), sp.Float("-2.5e-500"): sp.Rational(-25, 10 ** 501),
             sp.Float("3e-324"): sp.Rational(3, 10 ** 324), sp.Float("1e400"): sp.Integer(10) ** 400,
             sp.Float("1.2345678901234e-320"): sp.Rational(12345678901234, 10 ** 333),
             sp.Float(5e-324): sp.Rational(5, 10 ** 324), sp.Float(0.1): sp.Rational(1, 10),
             sp.Float(1 / 3.0): sp.Rational(3333333333333333, 10 ** 16)}
    for x, value in cases.items():
        assert exact_float(x) == value, x
    tiny = sp.N(sp.exp(-1000))          # a 53-bit Float of 5.08e-435
    assert exact_float(tiny) == sp.Rational(5075958897549457, 10 ** 450)
    assert sp.Float(exact_float(tiny), precision=53) == tiny


def test_numbers_of_every_kind_in_params_and_gains_are_read_exactly():
    """Red team 15a: params and gains went through float() for mpmath, numpy
    longdouble and numpy integers (mpf('1e-400') as 0: log(1 + rho)/2 + c had
    P2 "proved"; int64(2^53 + 1) as 2^53), numpy's float64 was an internal
    error (its repr is 'np.float64(...)'), Decimal was refused, and 10^5000 a
    traceback."""
    import decimal
    import fractions

    import mpmath
    import numpy as np
    from uwmr_symbolic.design import exact_number
    mpmath.mp.prec = 53
    cases = [(mpmath.mpf("1e-400"), sp.Rational(1, 10 ** 400)), (np.int64(2 ** 53 + 1), sp.Integer(2 ** 53 + 1)),
             (np.uint64(2 ** 64 - 1), sp.Integer(2 ** 64 - 1)), (np.float64(0.25), sp.Rational(1, 4)),
             (np.float64(0.1), sp.Rational(1, 10)), (decimal.Decimal("0.1"), sp.Rational(1, 10)),
             (np.float32(0.5), sp.Rational(1, 2)), (fractions.Fraction(1, 3), sp.Rational(1, 3))]
    for value, read in cases:
        assert exact_number(value, "c") == read, value
    assert exact_number(np.longdouble(1) + np.longdouble(2) ** -60, "c") == 1 + sp.Rational(1, 2 ** 60)
    assert exact_number(np.longdouble("1e-400"), "c") > 0
    try:
        mpmath.mp.prec = 100
        assert exact_number(mpmath.mpf(1) + mpmath.mpf(2) ** -60, "c") == 1 + sp.Rational(1, 2 ** 60)
    finally:
        mpmath.mp.prec = 53
    for bad, why in ((10 ** 5000, "more than 4,200 digits"), (mpmath.mpf("inf"), "not a finite number"),
                     (decimal.Decimal("NaN"), "not a finite number"), (np.float64("nan"), "not a finite number")):
        with pytest.raises(DesignError, match=why):
            exact_number(bad, "c")


def test_a_root_of_a_denominator_in_a_branch_not_taken_is_no_refusal(tmp_path):
    """Red team 19: p = e2^3 + 2 e2 - 5 has one real root r (Cardano's radicals);
    f = (1 + e1^2) (p^4)^(1/8) times a Piecewise that is 1 for e2 < 2 and
    p/p beyond is real and defined everywhere (|p|^(1/2)), but SymPy's evalf
    of the exact 0 of p^4 at (0, r) is noise whose 8th root has an imaginary
    part of 1e-19, and the loader refused f as not real.  At an irrational
    root of a denominator only an exact nan or zoo now counts."""
    path = tmp_path / "root_in_other_branch.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\np = e2**3 + 2*e2 - 5\n"
                    "f = (1 + e1**2)*sp.expand(p**4)**sp.Rational(1, 8)*sp.Piecewise((1, e2 < 2), (sp.horner(p)/p, True))\n")
    design = load_design(path)
    assert design.f.has(sp.Piecewise)


def test_a_power_of_a_million_bits_is_not_evaluated_exactly_at_a_sample_point(tmp_path):
    """Red team 26: f = 2 log(1 + rho) + rho^(rho^2) - 1 ran past --timeout in
    the loader: at (100, 100), 20000^400000000 has 5.7e9 bits, which SymPy
    computes exactly.  Such a point is skipped; the others are still checked."""
    from uwmr_symbolic.design import _huge_power_at
    e1, e2 = sp.symbols("e1 e2", real=True)
    rho = e1 ** 2 + e2 ** 2
    tower = rho ** (rho ** 2)
    def at(a, b):
        return {e1: sp.Integer(a), e2: sp.Integer(b)}
    assert _huge_power_at(tower, at(100, 100)) and _huge_power_at(rho ** (rho ** (rho ** 2)), at(3, -2))
    assert not _huge_power_at(tower, at(3, -2)) and not _huge_power_at(rho ** 400, at(100, 100))   # (a constant exponent)
    path = tmp_path / "tower.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nrho = e1**2 + e2**2\n"
                    "f = 2*sp.log(1 + rho) + rho**(rho**2) - 1\n")
    assert load_design(path).f == 2 * sp.log(1 + rho) + tower - 1
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nrho = e1**2 + e2**2\n"
                    "f = sp.log(1 + rho) + rho**(rho**2)*sp.log(e1 - 7)\n")      # still refused at (0, 0)
    with pytest.raises(DesignError, match="not real-valued|undefined"):
        load_design(path)


def test_a_derivative_with_respect_to_a_parameter_is_carried_out_before_its_value_goes_in(tmp_path):
    """Red team 27: f = d/dc (c^2 log(1 + rho)) with params c = 1 stopped with
    an internal error (a derivative with respect to the number 1); it is
    2 c log(1 + rho) = 2 log(1 + rho)."""
    path = tmp_path / "by_param.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nc = sp.Symbol('c')\n"
                    "f = sp.Derivative(c**2*sp.log(1 + e1**2 + e2**2), c)\nparams = {c: 1}\n")
    e1, e2 = sp.symbols("e1 e2", real=True)
    assert load_design(path).f == 2 * sp.log(1 + e1 ** 2 + e2 ** 2)
