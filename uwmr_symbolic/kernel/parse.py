"""Read an `srepr` string back into a SymPy expression.  The text is data,
never code: a small tokenizer and recursive descent accept only calls of
allow-listed SymPy constructors whose arguments are such calls, integers,
quoted names and the keywords real/positive/nonnegative=True, with a minus
sign before a number or an expression; nothing is `eval`ed."""
from __future__ import annotations

import re
from functools import lru_cache

import sympy as sp

# Piecewise and its conditions are read (an identity between two identical
# Piecewise expressions, or one with the same Piecewise on both sides, is
# exact), but the Arb evaluator and `defined_for_positive` refuse them, so no
# sign, limit or continuity rule accepts a claim that needs their values.
_NAMES = ("Symbol Integer Rational Add Mul Pow exp log sin cos tanh atan asinh sinh cosh erf Abs sign "
          "pi E EulerGamma Catalan GoldenRatio oo Tuple Piecewise Equality Unequality StrictGreaterThan "
          "StrictLessThan GreaterThan LessThan And Or Not true false").split()
_SCOPE = {n: getattr(sp, n) for n in _NAMES} | {"ExprCondPair": sp.functions.elementary.piecewise.ExprCondPair}
# a design's f (design certificates) may use more; still constructors only
_DESIGN_NAMES = "Max Min erfc erfi gamma acosh atanh asin acos tan sqrt".split()
_DESIGN_SCOPE = {**_SCOPE, **{n: getattr(sp, n) for n in _DESIGN_NAMES}}
_ASSUMPTIONS = {"real", "positive", "nonnegative"}
# a name, an integer (with its sign), a quoted name without quotes or
# backslashes inside, a punctuation mark, blanks; anything else is one bad
# character (every character starts a match: no backtracking over the text)
_TOKEN = re.compile(r"([A-Za-z_]\w*)|(-?[0-9]+)|'([^'\\]*)'|([(),=-])|(\s+)|(.)", re.ASCII | re.DOTALL)


class ParseError(ValueError):
    pass


def _tokens(text):
    for m in _TOKEN.finditer(text):
        name, number, quoted, mark, blank, bad = m.groups()
        if blank is not None:
            continue
        if bad is not None:
            raise ParseError(f"character not allowed: {bad!r}")
        if number is not None:
            try:
                yield "int", int(number)
            except ValueError as exc:           # more digits than Python converts
                raise ParseError(f"integer not allowed: {exc}") from None
        else:
            yield ("name", name) if name is not None else ("str", quoted) if quoted is not None else (mark, mark)


def parse(text: str, design: bool = False) -> sp.Expr:
    """The expression of an srepr; `design=True` also allows what a design's
    f may contain (Piecewise and its conditions, Max, Min, more functions)."""
    scope = _DESIGN_SCOPE if design else _SCOPE
    if not isinstance(text, str) or len(text) > 200_000:
        raise ParseError("expected an srepr string")
    tokens = list(_tokens(text)) + [("end", None)]
    at = 0

    def expect(kind):
        nonlocal at
        if tokens[at][0] != kind:
            found = "the end" if tokens[at][0] == "end" else repr(tokens[at][1])
            raise ParseError(f"expected {kind!r}, found {found}")
        at += 1
        return tokens[at - 1][1]

    def value():                                # an argument: a literal or an expression
        kind, v = tokens[at]
        if kind in ("int", "str"):
            expect(kind)
            return v
        if kind == "-":                         # srepr(-oo) is "-oo"
            expect(kind)
            operand = expression()
            if not isinstance(operand, sp.Expr):
                raise ParseError("a minus sign before what is not an expression")
            return -operand
        return expression()

    def expression():                           # NAME, or NAME(arguments)
        nonlocal at
        name = expect("name")
        if name not in scope:
            raise ParseError(f"name not allowed: {name}")
        if tokens[at][0] != "(":
            return scope[name]
        at += 1
        args, keywords = [], {}
        while tokens[at][0] != ")":
            if tokens[at][0] == "name" and tokens[at + 1][0] == "=":
                key = tokens[at][1]
                if key not in _ASSUMPTIONS or tokens[at + 2] != ("name", "True"):
                    raise ParseError(f"keyword not allowed: {key}")
                keywords[key] = True
                at += 3
            elif keywords:
                raise ParseError("a positional argument after a keyword")
            else:
                args.append(value())
            if tokens[at][0] != ")":
                expect(",")
        at += 1
        try:
            return scope[name](*args, **keywords)
        except (TypeError, ValueError, AttributeError) as exc:
            raise ParseError(f"{name}: {exc}") from None
    try:
        out = value()
    except RecursionError:
        raise ParseError("nested too deeply") from None
    expect("end")
    return out


parse = lru_cache(maxsize=4096)(parse)      # not a decorator: mutmut skips decorated functions
