"""Soundness fuzzing: random designs from `fuzz/grammar.py`, verified in a
worker process, every verdict checked by `fuzz/oracle.py` against the truth
known by construction and against robust 50/100-digit numeric evidence.

The fixed-seed profile below runs in every `pytest` run (about a minute).
`make fuzz` runs the long profile (UWMR_FUZZ_EXAMPLES designs, fresh seed)
and prints the table.  Contradictions explained by a reported issue
(`oracle.KNOWN`, each with a strict-xfail reproducer in
`test_fuzz_findings.py`) are listed but do not fail this test: remove the
class from `KNOWN` when the issue is fixed."""
import os
from fractions import Fraction

import mpmath
import pytest
import sympy as sp
from hypothesis import HealthCheck, given, settings

from fuzz import grammar, oracle
from fuzz.grammar import RHO, Case, designs
from fuzz.run import run_profile
from uwmr_symbolic import e1, e2

pytestmark = pytest.mark.slow        # more than a few seconds: not in make test-fast

FIXED_EXAMPLES = int(os.environ.get("UWMR_FUZZ_FIXED_EXAMPLES", "16"))
FIXED_SEED = 20261123


def test_fixed_seed_profile_has_no_unexplained_false_proof_or_wrong_refutation(tmp_path, capsys):
    stats = run_profile(FIXED_EXAMPLES, seed=FIXED_SEED, timeout=10.0, keep=tmp_path)
    with capsys.disabled():
        print("\n" + stats.table())
    assert stats.tried == FIXED_EXAMPLES
    assert len(stats.by_family) >= 4, stats.by_family          # the grammar really varies
    bad = stats.unexplained()
    assert not bad, "\n".join(f"{p}: {c.line()}" for p, _, c in bad)
    # the verifier must still prove most of what is true (no soundness by silence)
    assert stats.true_proved >= 0.4 * stats.true_known, stats.table()


@pytest.mark.fuzz
@pytest.mark.skipif("UWMR_FUZZ_EXAMPLES" not in os.environ, reason="long profile: set UWMR_FUZZ_EXAMPLES (make fuzz)")
def test_long_profile(tmp_path, capsys):
    seed = int(os.environ["UWMR_FUZZ_SEED"]) if "UWMR_FUZZ_SEED" in os.environ else None
    n = int(os.environ["UWMR_FUZZ_EXAMPLES"])
    stats = run_profile(n, seed=seed if seed is not None else FIXED_SEED + n, timeout=10.0, keep=tmp_path)
    with capsys.disabled():
        print("\n" + stats.table())
    bad = stats.unexplained()
    assert not bad, "\n".join(f"{p}: {c.line()}" for p, _, c in bad)


# ---------------------------------------------------------------- the oracle itself
def _result(statuses, kf=None):
    props = {p: {"status": statuses.get(p, "unknown"), "reason": "test", "witness": None} for p in grammar.PROPS}
    return {"properties": props, "kf": kf}


def _kf(lower, upper, exact=None):
    return {"lower": str(lower), "upper": str(upper), "exact": exact, "unbounded": False, "reason": "test"}


def test_oracle_flags_a_proof_of_positivity_with_a_touching_zero():
    case = Case("dip", sp.log(1 + RHO * (sp.sqrt(RHO) - 6) ** 2), {"P3": None}, zeros=[(6, 0)])
    found = oracle.check(case, _result({"P3": "proved", "P2": "proved"}))
    assert [(c.prop, c.kind) for c in found] == [("P3", "false proof")]
    assert "f(6, 0) = 0 exactly" in found[0].evidence


def test_oracle_finds_a_dip_negative_only_on_a_tiny_interval():
    f = sp.log(1 + sp.log(1 + RHO) * ((RHO - 2) ** 2 - sp.Rational(1, 10 ** 10)))
    case = Case("dip", f, {}, radii=[sp.sqrt(2)])
    found = oracle.check(case, _result({"P3": "proved"}))
    assert [(c.prop, c.kind) for c in found] == [("P3", "false proof")]
    assert "-" in found[0].evidence.split("=")[1]


def test_oracle_reads_a_float_as_the_verifier_documents():
    # (0.1 + 0.2)/0.3 = 1.0000000000000002 (repr): f(0, 0) = -2e-16 < 0
    f = sp.sqrt(1 + RHO) - sp.Float((0.1 + 0.2) / 0.3)
    case = Case("float-offset", f, {"P2": False, "P3": False})
    found = oracle.check(case, _result({"P2": "proved", "P3": "proved"}))
    assert {(c.prop, c.kind) for c in found} == {("P2", "false proof"), ("P3", "false proof")}
    assert "f(0, 0) = -2.0000000000000000000E-16" in found[0].evidence, found[0].evidence


def test_oracle_takes_p2_from_f_as_read_where_sympy_folded_a_float():
    """c (sqrt(1 + e2^2) - 1) + sqrt(1 + e1^2) - 1 with c = 0.30000000000000004
    is 0 at the origin by construction, but SymPy folds -1 - c to the double
    -1.3: as read, f(0, 0) = 4e-17 (seed 4181609, design 79).  Refuting P2
    is then right, proving it is not."""
    c = sp.Float(0.1 + 0.2)
    f = sp.sqrt(1 + e1 ** 2) - 1 + c * (sp.sqrt(1 + e2 ** 2) - 1)
    assert sp.Float(-1.3) in f.atoms(sp.Float)
    case = Case("separable", f, {"P2": True})
    assert oracle.check(case, _result({"P2": "refuted"})) == []
    found = oracle.check(case, _result({"P2": "proved"}))
    assert [(c.prop, c.kind) for c in found] == [("P2", "false proof")]
    exact = Case("separable", sp.sqrt(1 + e1 ** 2) - 1 + sp.Rational(3, 10) * (sp.sqrt(1 + e2 ** 2) - 1), {"P2": True})
    assert [(c.prop, c.kind) for c in oracle.check(exact, _result({"P2": "refuted"}))] == [("P2", "wrong refutation")]


def test_oracle_reads_a_float_beyond_the_doubles_as_the_decimal_written():
    """Float('1e-400') went through float() (0) in the verifier until red team
    14a; the oracle must not share that reading: log(1 + rho) + Float('1e-400')
    has f(0, 0) = 10^-400, so a proved P2 is a false proof."""
    c = grammar.fl_text("1e-400")
    assert grammar.as_read(c) == sp.Rational(1, 10 ** 400) and grammar.as_read(-c) == -sp.Rational(1, 10 ** 400)
    case = Case("extreme", sp.log(1 + RHO) + c, {"P2": False})
    found = oracle.check(case, _result({"P2": "proved"}))
    assert [(c.prop, c.kind) for c in found] == [("P2", "false proof")]
    assert oracle.check(case, _result({"P2": "refuted"})) == []


def test_oracle_flags_a_kf_enclosure_below_the_true_value_and_a_made_up_exact_value():
    c = 0.30000000000000004
    f = sp.Float(c) * sp.log(1 + RHO)           # kf = c exactly (at |e| = 1)
    case = Case("radial", f, {}, kf=grammar.kfc(c))
    found = oracle.check(case, _result({}, _kf(Fraction(3, 10), Fraction(3, 10), "3/10")))
    assert [c.kind for c in found] == ["wrong kf", "wrong kf"]
    # and without any known kf: the sampled maximum at 50 digits exceeds the upper bound
    case = Case("radial", f, {})
    found = oracle.check(case, _result({}, _kf(Fraction(3, 10), Fraction(3, 10))))
    assert [c.kind for c in found] == ["wrong kf"] and "(50 and 100 digits)" in found[0].evidence


def test_oracle_accepts_a_kf_enclosure_that_is_exactly_the_supremum():
    for f, sup in [(sp.log(1 + RHO) / 3, "1/3"), (sp.asinh(RHO), "Pow(Integer(2), Rational(1, 2))"),
                   (sp.Rational(333333333333333, 10 ** 15) * sp.asinh(4 * RHO),
                    "Mul(Rational(333333333333333, 500000000000000), Pow(Integer(2), Rational(1, 2)))")]:
        kf = {"lower": sup, "upper": sup, "exact": None, "unbounded": False, "reason": "test"}
        assert oracle.check(Case("radial", f, {}), _result({}, kf)) == [], f


def test_oracle_flags_refutations_of_true_properties_and_accepts_honest_verdicts():
    case = Case("radial", sp.log(1 + RHO) / 2, grammar.radial_truth((Fraction(0), Fraction(1))), kf=sp.Rational(1, 2))
    honest = _result({p: "proved" for p in grammar.PROPS}, _kf(Fraction(1, 2), Fraction(1, 2), "1/2"))
    assert oracle.check(case, honest) == []
    found = oracle.check(case, _result({"P5": "refuted", "P6": "unknown"}))
    assert [(c.prop, c.kind) for c in found] == [("P5", "wrong refutation")]


def test_oracle_rechecks_the_witness_of_a_refutation():
    case = Case("mixed", sp.sqrt(1 + RHO) - sp.Rational(9, 10) * sp.log(1 + RHO) - 1, {})
    def refuted(prop, x, reason):
        r = _result({})
        r["properties"][prop] = {"status": "refuted", "reason": reason, "witness": {"e1": x, "e2": "0"}}
        return oracle.check(case, r)
    # F(2) = sqrt(5) - 0.9 log 5 - 1 = -0.212... < 0 and F'(1) = 1/sqrt(2) - 0.9 < 0: right refutations
    assert refuted("P3", "2", "f is not positive: fails at s = 2") == []
    assert refuted("P5", "1", "F'(s) > 0 fails at |e| = 1: fails at s = 1") == []
    # F(10) = sqrt(101) - 0.9 log 101 - 1 = 4.89 > 0 and F'(10) > 0: the witnesses are no counterexamples
    assert [c.kind for c in refuted("P3", "10", "f is not positive: fails at s = 10")] == ["bad witness"]
    assert [c.kind for c in refuted("P5", "10", "F'(s) > 0 fails at |e| = 10: fails at s = 10")] == ["bad witness"]


def test_oracle_numeric_searches_catch_non_smooth_points_without_truth():
    # |e| and a jump on the circle |e| = 1: no truth given, numbers alone must refute the proofs
    cases = [Case("power", sp.sqrt(RHO), {}),
             Case("circle", sp.Piecewise((RHO, RHO < 1), (RHO + 1, True)), {}, radii=[sp.Integer(1)]),
             Case("origin", sp.Piecewise((0, sp.Eq(RHO, 0)), (1 + RHO, True)), {})]
    for case in cases:
        found = oracle.check(case, _result({"P1": "proved", "P7": "proved", "P5": "proved"}))
        assert {c.prop for c in found} == {"P1", "P5", "P7"}, (case.f, [c.line() for c in found])
    found = oracle.check(Case("ell", sp.log(1 + e1 ** 2 + 2 * e2 ** 2), {}), _result({"P4": "proved"}))
    assert [c.prop for c in found] == ["P4"]
    found = oracle.check(Case("rot", RHO + e1 * e2, {}), _result({"P8": "proved", "P5": "proved"}))
    assert {c.prop for c in found} == {"P5", "P8"}


# ---------------------------------------------------------------- the grammar's truth
@settings(max_examples=25, deadline=None, derandomize=True, database=None,
          suppress_health_check=list(HealthCheck))
@given(designs())
def test_numeric_evidence_never_contradicts_a_truth_the_grammar_claims(case):
    """The grammar's 'True' must survive the oracle's own counterexample
    search (which, unlike the verifier, can only find, never prove)."""
    ev = oracle.Evidence(case)
    searches = {"P1": ev.p1, "P2": ev.p2, "P3": ev.p3, "P4": ev.p4, "P5": ev.p5, "P6": ev.p6,
                "P7": ev.p7, "P8": ev.p8}
    for p, truth in case.truth.items():
        if truth is True:
            assert searches[p]() is None, (p, case.family, case.note, case.f)
    if case.kf is not None and case.kf != sp.oo:
        best = ev.kf_lower()
        with mpmath.workdps(100):       # (kf = 10^-12 at 53 bits is below it)
            assert best is None or best[0] <= oracle._mp_of(case.kf) * (1 + 1e-30), (case.f, case.kf, best)


def test_an_iterated_log_is_unbounded_growth():
    """(sqrt(1 + rho) - 1) log(1 + log(1 + rho)): F(s) ~ s log(2 log s), so F'
    -> oo (about 2.0 at s = 1e12, 2.7 at 1e50) and kf is infinite.  The
    grammar read log log rho as a constant and called P1 true; the verifier's
    refutation (F' -> oo) was reported as wrong (seed 20261210)."""
    g = grammar.RHO_GROWTH
    loglog = grammar._log_growth(grammar._log_growth(g))
    assert loglog == (0, 0, 1)
    assert grammar.kf_finite(tuple(x / 2 for x in g))                      # sqrt(rho): F' -> 1
    assert not grammar.kf_finite(grammar.g_mul(tuple(x / 2 for x in g), loglog))
    assert grammar.kf_finite(loglog) and grammar.dG_bounded(g)
    assert not grammar.dG_bounded(grammar.g_mul(g, loglog))
    assert grammar.g_max(loglog, grammar._log_growth(g)) == (0, 1, 0)


def test_truth_values_are_python_bools_even_from_sympy_comparisons():
    a = sp.Rational(2)
    case = Case("dip", RHO, {"P5": a ** 2 / 8 + sp.Rational(1, 10 ** 12) > a ** 2 / 8, "P6": a < 1, "P7": None})
    assert case.truth == {"P5": True, "P6": False, "P7": None}
    assert case.truth["P6"] is False


def test_the_design_file_rebuilds_f_bit_for_bit():
    case = Case("x", sp.Float(0.1 + 0.2) * sp.log(1 + RHO) + sp.Piecewise((1, sp.Eq(RHO, 1)), (0, True)), {})
    ns = {}
    exec(grammar.design_source(case), ns)
    assert ns["f"] == case.f
    assert {float(a) for a in ns["f"].atoms(sp.Float)} == {0.30000000000000004}


def test_the_origin_value_is_read_before_sympy_folds_a_float():
    """5/3 (1 - exp(-rho)) + 5/3 log cosh(rho) + Float(pi) - pi: SymPy folds
    5/3 + Float(pi) into the double 4.80825932025646, so f(0, 0) as read is
    4.80825932025646 - 5/3 - pi = +9.5e-17 and P3 holds (F increases from
    it), although Float(pi) - pi < 0.  Substituting the origin into f first
    folds -5/3 into that double once more and gave the sign -1: the grammar
    called P3 false and the fuzzer reported the verifier's proof as false
    (seed 20261125)."""
    import math
    f = sp.Rational(5, 3) * (1 - sp.exp(-RHO)) + sp.Rational(5, 3) * sp.log(sp.cosh(RHO)) \
        + grammar.fl(math.pi) - sp.pi
    assert [repr(float(a)) for a in f.atoms(sp.Float)] == ["4.80825932025646"]
    assert grammar._exact_sign(grammar.fl(math.pi) - sp.pi) == -1
    assert grammar._exact_sign(f.subs({e1: 0, e2: 0})) == -1
    assert grammar._exact_sign(grammar._origin_as_read(f)) == 1
