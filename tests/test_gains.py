"""Bound (10) in exact arithmetic (`gains.check_gains`), with kf exact or
only enclosed: a violation is claimed only when kf's lower bound proves it."""
import sympy as sp

from uwmr_symbolic.gains import check_gains

Q = sp.Rational
CIRCLE = {"c": dict(k1=Q(1, 4), k2=Q(7, 10), lam=Q(6, 5), Vmax=Q(3, 4), Wmax=Q(2), Vr_max=Q(1, 2), Wr_max=Q(1))}
# W bound = 1 + (6/5)(1/2) kf + 7/10 = 17/10 + (3/5) kf: exactly Wmax at kf = 1/2


def test_exact_kf_on_the_limit_passes_and_above_fails():
    assert check_gains(CIRCLE, Q(1, 2))["c"].W_ok is True
    assert check_gains(CIRCLE, Q(1, 2) + Q(1, 10 ** 9))["c"].W_ok is False


def test_enclosed_kf_straddling_the_limit_is_undecided():
    # kf in [1/2, 1/2 + 1e-9]: the true kf may be 1/2 (passes) or above (fails)
    g = check_gains(CIRCLE, Q(1, 2) + Q(1, 10 ** 9), kf_lower=Q(1, 2))["c"]
    assert g.W_ok is None and g.V_ok is True


def test_enclosed_kf_below_or_above_the_limit_decides():
    assert check_gains(CIRCLE, Q(49, 100), kf_lower=Q(48, 100))["c"].W_ok is True
    assert check_gains(CIRCLE, Q(52, 100), kf_lower=Q(51, 100))["c"].W_ok is False


def test_gains_beyond_the_doubles_are_printed_not_lost(tmp_path):
    """Since SymPy Floats no double holds are read as written (1e-400 is not
    0), a gain may be beyond the doubles: the text and HTML reports printed
    the margins through float (None: a TypeError, a traceback).  By hand, with
    kf = 1 (log(1 + rho), at |e| = 1): |V| <= Vr_max + k1 = 1/2 + 10^-400,
    margin Vmax - that = 10^400 - 1/2 - 10^-400; |W| <= Wr_max + lam Vr_max kf +
    k2 = 1 + 5·10^401 + 7/10, margin 2 - that."""
    from uwmr_symbolic.display import report_html
    from uwmr_symbolic.report import render_text, to_dict
    from uwmr_symbolic.verify import verify_design
    path = tmp_path / "huge.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nf = sp.log(1 + e1**2 + e2**2)\n"
                    "gains = {'circle': dict(k1=sp.Float('1e-400'), k2=0.7, lam=sp.Float('1e402'), "
                    "Vmax=sp.Float('1e400'), Wmax=2.0, Vr_max=0.5, Wr_max=1.0)}\n")
    d = to_dict(verify_design(path))
    g = d["gains"]["circle"]
    assert g["V_ok"] is True and g["W_ok"] is False
    assert sp.sympify(g["V_margin"]) == sp.Integer(10) ** 400 - sp.Rational(1, 2) - sp.Rational(1, 10 ** 400)
    assert g["text"] == {"V_bound": "0.5", "V_margin": "+1.000e+400", "W_bound": "5.0000000e+401",
                         "W_margin": "-5.000e+401", "lam_max": "0.6"}
    row = next(line for line in render_text(d).splitlines() if line.startswith("  circle"))
    assert row.split() == ["circle", "0.5", "+1.000e+400", "PASS", "5.0000000e+401", "-5.000e+401", "FAIL", "0.6"]
    assert "+1.000e+400" in report_html(verify_design(path))


def test_a_margin_sympy_cannot_sign_leaves_the_scenario_undecided(tmp_path):
    """Red team 15a: Vmax = atan(1/2) + atan(1/3) (= pi/4 exactly) and Vr_max =
    k1 = pi/8 give a |V| margin that is 0 in disguise; bool(margin >= 0) was an
    internal error.  Now the |V| part is undecided ("????", exit status 3,
    not a failure), and its margin prints as "?", not SymPy's noise."""
    from uwmr_symbolic.report import render_text, to_dict
    from uwmr_symbolic.verify import verify_design
    path = tmp_path / "disguised.py"
    path.write_text("import sympy as sp\ne1, e2 = sp.symbols('e1 e2', real=True)\nf = sp.log(1 + e1**2 + e2**2)\n"
                    "z = sp.atan(sp.Rational(1, 2)) + sp.atan(sp.Rational(1, 3))\n"
                    "gains = {'circle': dict(k1=sp.pi/8, k2=0.7, lam=0.3, Vmax=z, Wmax=2.0, Vr_max=sp.pi/8, Wr_max=1.0)}\n")
    report = verify_design(path)
    g = report.gains["circle"]
    assert g.V_ok is None and g.W_ok is True and report.exit_status == 3
    row = next(line for line in render_text(report).splitlines() if line.startswith("  circle"))
    assert row.split()[1:4] == ["0.78539816", "?", "????"]
    assert to_dict(report)["gains"]["circle"]["text"]["V_margin"] == "?"
    assert to_dict(report)["gains"]["circle"]["V_margin_float"] is None      # (not SymPy's noise, 2e-165)
