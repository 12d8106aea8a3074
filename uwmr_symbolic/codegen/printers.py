"""Small SymPy printers for the back-ends.

Numbers are printed as correctly rounded literals of the target type (no
`M_PI`, which C99 does not define, and no `1.0/3.0` evaluated at run time);
integer powers become products and half-integer powers square roots, so the
float variant never calls `pow` or promotes to double."""
from __future__ import annotations

import numpy as np
import sympy as sp
from sympy.codegen.ast import float32, real
from sympy.printing.c import C99CodePrinter
from sympy.printing.numpy import NumPyPrinter

MAX_PRODUCT_POWER = 8


def double_literal(value) -> str:
    x = float(sp.N(value, 40))
    text = repr(x)
    if "e" not in text and "." not in text and "inf" not in text:
        text += ".0"
    return text


def float_literal(value) -> str:
    text = str(np.float32(float(sp.N(value, 40))))     # shortest round-trip form
    if "e" not in text and "." not in text and "inf" not in text:
        text += ".0"
    return text + "F"


class CPrinter(C99CodePrinter):
    """C99 printer for one precision ("double" or "float")."""

    def __init__(self, precision: str = "double", names=None):
        settings = {"type_aliases": {real: float32}} if precision == "float" else {}
        super().__init__(settings)
        self.precision = precision
        self.names = names or {}
        self.literal = float_literal if precision == "float" else double_literal
        self.sfx = "f" if precision == "float" else ""

    def _print_Symbol(self, expr):
        return self.names.get(expr, expr.name)

    def _print_Integer(self, expr):
        return self.literal(expr)

    _print_Rational = _print_Integer
    _print_Float = _print_Integer

    def _print_NumberSymbol(self, expr):
        return self.literal(expr)

    _print_Pi = _print_NumberSymbol
    _print_Exp1 = _print_NumberSymbol
    _print_EulerGamma = _print_NumberSymbol
    _print_GoldenRatio = _print_NumberSymbol
    _print_Catalan = _print_NumberSymbol

    def _print_Pow(self, expr):
        base, exp = expr.as_base_exp()
        one = self.literal(1)
        b = self.parenthesize(base, 1000)   # always safe to repeat
        if exp == sp.Rational(1, 2):
            return f"sqrt{self.sfx}({self._print(base)})"
        if exp == -sp.Rational(1, 2):
            return f"({one}/sqrt{self.sfx}({self._print(base)}))"
        if exp.is_Integer and 0 < abs(int(exp)) <= MAX_PRODUCT_POWER:
            prod = "*".join([b] * abs(int(exp)))
            return f"({prod})" if exp > 0 else f"({one}/({prod}))"
        if exp.is_Rational and exp.q == 2 and abs(exp.p) <= 2 * MAX_PRODUCT_POWER + 1:
            whole = sp.Pow(base, int(exp.p) // 2) if exp > 0 else sp.Pow(base, -((-int(exp.p)) // 2))
            return f"({self._print(whole)}*sqrt{self.sfx}({self._print(base)}))" if exp > 0 else \
                f"({one}/({self._print(sp.Pow(base, (-int(exp.p)) // 2))}*sqrt{self.sfx}({self._print(base)})))"
        return f"pow{self.sfx}({self._print(base)}, {self._print(exp)})"


class PyPrinter(NumPyPrinter):
    """NumPy printer with float literals (no `1/3` in the generated module)."""

    def __init__(self, names=None):
        super().__init__({"fully_qualified_modules": True})
        self.names = names or {}

    def _print_Symbol(self, expr):
        return self.names.get(expr, expr.name)

    def _print_Integer(self, expr):
        return double_literal(expr)

    _print_Rational = _print_Integer
    _print_Float = _print_Integer

    def _print_NumberSymbol(self, expr):
        return double_literal(expr)

    _print_Pi = _print_NumberSymbol
    _print_Exp1 = _print_NumberSymbol

    def _print_Pow(self, expr, rational=False):
        base, exp = expr.as_base_exp()
        if exp == sp.Rational(1, 2):
            return f"numpy.sqrt({self._print(base)})"
        if exp == -sp.Rational(1, 2):
            return f"(1.0/numpy.sqrt({self._print(base)}))"
        if exp.is_Integer and 0 < abs(int(exp)) <= MAX_PRODUCT_POWER:
            b = self.parenthesize(base, 1000)
            prod = "*".join([b] * abs(int(exp)))
            return f"({prod})" if exp > 0 else f"(1.0/({prod}))"
        return super()._print_Pow(expr, rational=rational)


def cse_lines(expr, printer, declare, prefix="x"):
    """(assignments, final expression) for expr after common-subexpression
    elimination; `declare(name, code)` formats one assignment."""
    symbols = sp.numbered_symbols(prefix)
    replacements, (reduced,) = sp.cse([expr], symbols=symbols, optimizations="basic")
    lines = [declare(printer._print(sym), printer.doprint(sub)) for sym, sub in replacements]
    return lines, printer.doprint(reduced)
