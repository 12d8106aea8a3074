"""Read an `srepr` string back into a SymPy expression without `eval` of
arbitrary text: only calls of allow-listed SymPy constructors, with literal
arguments, are accepted (a certificate is data, never code)."""
from __future__ import annotations

import ast
from functools import lru_cache

import sympy as sp

# Piecewise and its conditions are read (an identity between two identical
# Piecewise expressions, or one with the same Piecewise on both sides, is
# exact), but the Arb evaluator and `defined_for_positive` refuse them, so no
# sign, limit or continuity rule accepts a claim that needs their values.
_NAMES = ("Symbol Integer Rational Add Mul Pow exp log sin cos tanh atan asinh "
          "sinh cosh erf Abs pi E oo Tuple Piecewise Equality Unequality StrictGreaterThan "
          "StrictLessThan GreaterThan LessThan And Or Not true false").split()
_SCOPE = {n: getattr(sp, n) for n in _NAMES} | {"ExprCondPair": sp.functions.elementary.piecewise.ExprCondPair}
# a design's f (design certificates) may use more; still constructors only
_DESIGN_NAMES = "Max Min sign erfc erfi gamma acosh atanh asin acos tan sqrt".split()
_DESIGN_SCOPE = {**_SCOPE, **{n: getattr(sp, n) for n in _DESIGN_NAMES}}
_ASSUMPTIONS = {"real", "positive", "nonnegative"}


class ParseError(ValueError):
    pass


def _check(node, scope=_SCOPE):
    if isinstance(node, ast.Expression):
        return _check(node.body, scope)
    if isinstance(node, ast.Name):
        if node.id not in scope:
            raise ParseError(f"name not allowed: {node.id}")
        return
    if isinstance(node, ast.Constant):
        if not isinstance(node.value, (int, str)) or isinstance(node.value, bool):
            raise ParseError(f"literal not allowed: {node.value!r}")
        return
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        return _check(node.operand, scope)
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
        _check(node.func, scope)
        for a in node.args:
            _check(a, scope)
        for k in node.keywords:
            if k.arg not in _ASSUMPTIONS or not (isinstance(k.value, ast.Constant) and k.value.value is True):
                raise ParseError(f"keyword not allowed: {k.arg}")
        return
    raise ParseError(f"syntax not allowed: {ast.dump(node)[:60]}")


def parse(text: str, design: bool = False) -> sp.Expr:
    """The expression of an srepr; `design=True` also allows what a design's
    f may contain (Piecewise and its conditions, Max, Min, more functions)."""
    scope = _DESIGN_SCOPE if design else _SCOPE
    if not isinstance(text, str) or len(text) > 200_000:
        raise ParseError("expected an srepr string")
    try:
        tree = ast.parse(text, mode="eval")
    except SyntaxError as exc:
        raise ParseError(f"not an srepr: {exc}") from None
    _check(tree, scope)
    return eval(compile(tree, "<srepr>", "eval"), {"__builtins__": {}}, dict(scope))  # noqa: S307


parse = lru_cache(maxsize=4096)(parse)      # not a decorator: see core.rule
