"""Unusable design files: exit status 2, exactly one line on stderr naming the file,
no traceback.  A design that hangs at import must be given up on after --timeout."""
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _cli import ROOT, run_cli  # noqa: E402

BAD = "tests/bad_inputs"

#: file -> what is wrong with it
CASES = {
    "syntax_error.py": "not valid Python",
    "import_raises.py": "raises RuntimeError at import",
    "no_f.py": "defines no f",
    "f_string.py": "f is a str",
    "f_list.py": "f is a list",
    "free_symbol.py": "free symbol a without a value in params",
    "not_real.py": "sqrt(e1**2 - 1) is not real for |e1| < 1",
    "zoo_inside.py": "f contains zoo (e1/0)",
    "nan_inside.py": "f is nan",
    "gain_missing_wmax.py": "gain scenario without Wmax",
    "gain_negative_k1.py": "gain scenario with k1 = -0.1",
    "does_not_exist.py": "no such file",
    "symbols_x_y.py": "f written in x, y instead of e1, e2",
    "numpy_log.py": "np.log of a SymPy expression",
    "math_sqrt.py": "math.sqrt of a SymPy expression",
    "caret_power.py": "^ written for a power",
    "undefined_function.py": "f = g(rho) with g = sympy.Function('g')",
    "huge_constant.py": "a constant of 5,001 digits",
    "max_of_hidden_zero.py": "Max of a constant 0 in disguise (SymPy's Piecewise rewrite loops)",
    "e1_declared_positive.py": "e1, e2 declared positive (SymPy simplified f with it)",
    "param_against_assumption.py": "a parameter declared positive given -1",
    "undefined_on_a_line.py": "0/0 on the line e2 = 2 (a zero of a polynomial denominator)",
    "undefined_on_irrational_lines.py": "0/0 on the lines e2 = +-sqrt(2) (irrational zeros of a denominator)",
    "condition_compares_truth_values.py": "Eq(e1 > 0, e2 > 0) as a condition (a red team's crash)",
    "unevaluated_integral.py": "an unevaluated Integral in f",
    "complex_parts_cancel.py": "logarithms of negative numbers whose imaginary parts cancel",
    "complex_roots_cancel.py": "square roots of negative numbers whose product is real",
    "params_divide_zero_by_zero.py": "params that make f 0/0 everywhere, one substituted before the other",
    "zero_over_zero_at_origin_in_parts.py": "0/0 at the origin that one variable at a time hides",
    "params_cancel_e1_over_e1.py": "params that make f e1/e1, which evaluation would cancel",
    "unevaluated_zero_times_log_of_negative.py": "0 log(-1 - rho) built with evaluate=False",
    "substitution_makes_e1_over_e1.py": "a Subs whose values make x/y e1/e1",
    "derivative_of_sign.py": "a Derivative of sign(e1), which SymPy takes branch by branch",
}

#: file -> the words of the one line that name the fix
FIXES = {
    "symbols_x_y.py": ["f is written in x, y", "name them e1 and e2", "from uwmr_symbolic import e1, e2"],
    "numpy_log.py": ["at line 6", "numpy's log", "use sympy.log"],
    "math_sqrt.py": ["at line 7", "math.sqrt", "use sympy.sqrt"],
    "caret_power.py": ["at line 5", "write powers with **"],
    "undefined_function.py": ["the undefined function 'g'", "write f with SymPy's functions"],
    "huge_constant.py": ["more than 4,200 digits", "scale f"],
    "max_of_hidden_zero.py": ["could not write the Abs, Max", "write f as a Piecewise"],
    "e1_declared_positive.py": ["e1 is declared positive=True", "sympy.symbols('e1 e2', real=True)"],
    "param_against_assumption.py": ["params['c'] = -1 does not satisfy positive=True", "give a value that does"],
    "undefined_on_a_line.py": ["f is undefined at (e1, e2) = (0, 2)"],
    "undefined_on_irrational_lines.py": ["f is undefined at (e1, e2) = (0, -sqrt(2))"],
    "condition_compares_truth_values.py": ["compares truth values", "write it with And, Or and Not"],
    "unevaluated_integral.py": ["f holds an unevaluated Integral", "write f in closed form"],
    "complex_parts_cancel.py": ["f is not real-valued at (e1, e2) = (0, 0)", "its part log(2*e1 - 14)",
                                "write f with real parts only"],
    "complex_roots_cancel.py": ["f is not real-valued at (e1, e2) = (0, 0)", "has no real value there"],
    "params_divide_zero_by_zero.py": ["f contains nan, zoo or infinity", "a division by zero"],
    "zero_over_zero_at_origin_in_parts.py": ["f is undefined at (e1, e2) = (0, 0)", "sympy.Piecewise"],
    "params_cancel_e1_over_e1.py": ["f is undefined at (e1, e2) = (0, 0)"],
    "unevaluated_zero_times_log_of_negative.py": ["its part log(-e1**2 - e2**2 - 1) has no real value there"],
    "substitution_makes_e1_over_e1.py": ["f is undefined at (e1, e2) = (0, 0)"],
    "derivative_of_sign.py": ["f holds the derivative of sign(e1)", "write that derivative by hand"],
}
HANGS = "sleep_forever.py"


def test_every_bad_input_file_is_covered():
    on_disk = {p.name for p in (ROOT / BAD).glob("*.py")}
    assert on_disk == (set(CASES) - {"does_not_exist.py"}) | {HANGS}
    assert not (ROOT / BAD / "does_not_exist.py").exists()


@pytest.mark.parametrize("name", sorted(CASES), ids=lambda n: n.removesuffix(".py"))
def test_unusable_input(name):
    run = run_cli([f"{BAD}/{name}", "--format", "json"], timeout=300)
    info = f"case: {CASES[name]}\n{run.describe()}"
    assert not run.timed_out, info
    assert "Traceback" not in run.stdout and "Traceback" not in run.stderr, info
    assert run.returncode == 2, info
    lines = run.stderr.strip("\n").splitlines()
    assert len(lines) == 1, f"expected exactly one line on stderr, got {len(lines)}\n{info}"
    assert name in lines[0], f"stderr does not name the file\n{info}"


@pytest.mark.parametrize("name", sorted(FIXES), ids=lambda n: n.removesuffix(".py"))
def test_common_mistake_names_the_fix(name):
    run = run_cli([f"{BAD}/{name}", "--no-cache"], timeout=300)
    assert run.returncode == 2, run.describe()
    lines = run.stderr.strip("\n").splitlines()
    assert len(lines) == 1 and "Traceback" not in run.stderr, run.describe()
    assert lines[0].startswith(f"{BAD}/{name}: "), run.describe()
    for words in FIXES[name]:
        assert words in lines[0], f"{words!r} missing from: {lines[0]}"


def test_design_hanging_at_import_times_out():
    run = run_cli([f"{BAD}/{HANGS}", "--timeout", "3"], timeout=30)
    info = run.describe()
    assert not run.timed_out, f"still running after 30 s\n{info}"
    assert run.elapsed < 30, info
    assert "Traceback" not in run.stdout and "Traceback" not in run.stderr, info
    assert run.returncode == 3, info
    assert "did not finish within --timeout 3 s" in run.stdout, info
    assert "proof replay: not run" in run.stdout, info      # not "NOT ok" with nothing after it
