"""Small SymPy printers for the back-ends.

Every constant subexpression (pi/2, log(2), 2/sqrt(pi), 1/3 ...) is printed
as one correctly rounded literal of the target type -- never a `M_*` macro,
which C99 does not define, and never an expression evaluated at run time;
float literals carry the `F` suffix.  Integer powers become products and
half-integer powers products with one square root, so the float variant
never calls `pow` or promotes to double.  Every power is printed as one
parenthesised unit or one call, so it binds like an atom wherever it is
used (a power of a sum inside a product or a quotient keeps its meaning).

A function that a target cannot evaluate raises `Unsupported` (the
generator refuses the design with that message; nothing is written)."""
from __future__ import annotations

import numpy as np
import sympy as sp
from sympy.codegen.ast import float32, real
from sympy.printing.c import C99CodePrinter
from sympy.printing.numpy import NumPyPrinter

MAX_PRODUCT_POWER = 8


class Unsupported(ValueError):
    """An expression a back-end cannot print faithfully."""


def _value(expr) -> float:
    """The double nearest to the real constant expr (evaluated to 40 digits)."""
    val = sp.N(expr, 40)
    if not val.is_real or not val.is_finite:
        raise Unsupported(f"the constant {sp.sstr(expr)} is not a finite real number")
    return float(val)


def double_literal(value) -> str:
    x = _value(value)
    if not np.isfinite(x):                      # (a literal inf.0 would not even compile)
        raise Unsupported(f"the constant {sp.N(value, 6)} is beyond the double range (about 1.8e308)")
    text = repr(x)
    if "e" not in text and "." not in text:
        text += ".0"
    return text


def float_literal(value) -> str:
    with np.errstate(over="ignore"):            # beyond the float range: inf, refused below
        x = np.float32(_value(value))
    if not np.isfinite(x):
        raise Unsupported(f"the constant {_value(value):.6g} is beyond the float range (about 3.4e38)")
    text = str(x)      # shortest round-trip form
    if "e" not in text and "." not in text:
        text += ".0"
    return text + "F"


def _is_constant(expr) -> bool:
    return isinstance(expr, sp.Expr) and not expr.free_symbols and expr.is_number \
        and not isinstance(expr, sp.Piecewise)


def _power(printer, expr, sqrt, one):
    """The common power rules of both printers; None for a general power."""
    base, exp = expr.as_base_exp()
    arg = printer._print(base)
    b = arg if base.is_Symbol else f"({arg})"
    if not exp.is_Rational:
        return None
    p, q = int(exp.p), int(exp.q)
    if q == 1 and 0 < abs(p) <= MAX_PRODUCT_POWER:
        factors = [b] * abs(p)
    elif q == 2 and abs(p) <= 2 * MAX_PRODUCT_POWER + 1:
        factors = [b] * (abs(p) // 2) + [f"{sqrt}({arg})"]
    else:
        return None
    prod = "*".join(factors)
    if abs(p) == 1:                      # one call or one parenthesised base: already one unit
        return prod if p > 0 else f"({one}/{prod})"
    return f"({prod})" if p > 0 else f"({one}/({prod}))"


class CPrinter(C99CodePrinter):
    """C99 printer for one precision ("double" or "float")."""

    def __init__(self, precision: str = "double", names=None):
        settings = {"type_aliases": {real: float32}} if precision == "float" else {}
        super().__init__(settings)
        self.math_macros = {}          # never M_PI_2, M_LN2, M_2_SQRTPI ...
        self.precision = precision
        self.names = names or {}
        self.literal = float_literal if precision == "float" else double_literal
        self.sfx = "f" if precision == "float" else ""

    def _print(self, expr, **kwargs):
        if _is_constant(expr):
            return self.literal(expr)
        return super()._print(expr, **kwargs)

    def _print_Symbol(self, expr):
        return self.names.get(expr, expr.name)

    def _print_Integer(self, expr):
        return self.literal(expr)

    _print_Rational = _print_Integer
    _print_Float = _print_Integer
    _print_NumberSymbol = _print_Integer

    def _print_Pow(self, expr):
        out = _power(self, expr, f"sqrt{self.sfx}", self.literal(1))
        if out is not None:
            return out
        base, exp = expr.as_base_exp()
        return f"pow{self.sfx}({self._print(base)}, {self._print(exp)})"

    def _print_sign(self, expr):
        zero, one = self.literal(0), self.literal(1)
        a = self._print(expr.args[0])
        return f"(({a}) > {zero} ? {one} : (({a}) < {zero} ? -{one} : {zero}))"

    def _print_Function(self, expr):
        if expr.func.__name__ in self.known_functions:
            return super()._print_Function(expr)
        raise Unsupported(f"C: no C99 function for {expr.func.__name__}")

    def emptyPrinter(self, expr):
        raise Unsupported(f"C: cannot print {type(expr).__name__}")


_SCIPY = {"erf": "erf", "erfc": "erfc", "gamma": "gamma", "erfi": "erfi"}


class PyPrinter(NumPyPrinter):
    """NumPy printer with float literals (no `1/3` in the generated module);
    special functions from scipy.special (vectorised)."""

    def __init__(self, names=None):
        super().__init__({"fully_qualified_modules": True})
        self.names = names or {}

    def _print(self, expr, **kwargs):
        if expr is sp.nan:           # numpy.select's default (never selected: the last condition is True)
            return "numpy.nan"
        if _is_constant(expr):
            return double_literal(expr)
        return super()._print(expr, **kwargs)

    def _print_Symbol(self, expr):
        return self.names.get(expr, expr.name)

    def _print_Integer(self, expr):
        return double_literal(expr)

    _print_Rational = _print_Integer
    _print_Float = _print_Integer
    _print_NumberSymbol = _print_Integer

    def _print_Pow(self, expr, rational=False):
        out = _power(self, expr, "numpy.sqrt", "1.0")
        if out is not None:
            return out
        base, exp = expr.as_base_exp()
        return f"numpy.power({self._print(base)}, {self._print(exp)})"

    def _special(self, expr):
        return f"scipy.special.{_SCIPY[expr.func.__name__]}({self._print(expr.args[0])})"

    _print_erf = _special
    _print_erfc = _special
    _print_gamma = _special
    _print_erfi = _special

    def _print_loggamma(self, expr):
        return f"scipy.special.gammaln({self._print(expr.args[0])})"

    def _print_Abs(self, expr):
        return f"numpy.abs({self._print(expr.args[0])})"

    def _print_sign(self, expr):
        return f"numpy.sign({self._print(expr.args[0])})"

    def _minmax(self, expr, fn):
        out = self._print(expr.args[-1])
        for a in reversed(expr.args[:-1]):
            out = f"numpy.{fn}({self._print(a)}, {out})"
        return out

    def _print_Min(self, expr):
        return self._minmax(expr, "minimum")

    def _print_Max(self, expr):
        return self._minmax(expr, "maximum")

    def _print_Function(self, expr):
        known = self.known_functions.get(expr.func.__name__)
        if isinstance(known, str) and not known.startswith("math."):    # math.* does not vectorise
            return super()._print_Function(expr)
        raise Unsupported(f"Python: no vectorised function for {expr.func.__name__}")

    def emptyPrinter(self, expr):
        raise Unsupported(f"Python: cannot print {type(expr).__name__}")


def cse_lines(expr, printer, declare, prefix="x"):
    """(assignments, final expression) for expr after common-subexpression
    elimination; `declare(name, code)` formats one assignment.  The
    elimination is kept only when substituting its names back gives expr
    itself: SymPy's rewrites (factor_terms: 1e-104 rho^2 (... + 3.9e101),
    which underflows; (rho + 1)^(3/2) as rho x0 + x0) would print another
    expression than the one `accuracy` bounds."""
    symbols = sp.numbered_symbols(prefix)
    replacements, (reduced,) = sp.cse([expr], symbols=symbols, optimizations="basic")
    back = reduced
    for sym, sub in reversed(replacements):
        back = back.xreplace({sym: sub})
    if back != expr:
        replacements, reduced = [], expr
    lines = [declare(printer._print(sym), printer.doprint(sub)) for sym, sub in replacements]
    return lines, printer.doprint(reduced)
