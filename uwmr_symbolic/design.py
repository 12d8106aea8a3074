"""Design loading: read a design file, check it is usable, return a `Design`.

A design file is Python that defines ``f`` (a SymPy expression in real ``e1``,
``e2``), and optionally ``params``, ``gains``, ``name`` and ``description``.
Everything that makes a file unusable raises `DesignError` with one line that
says what is wrong and how to fix it; the CLI turns it into exit status 2."""
from __future__ import annotations

import ast
import contextlib
import decimal
import fractions
import math
import numbers
import os
import re
import runpy
import sys
import tokenize
import time
from dataclasses import dataclass, field
from pathlib import Path

import mpmath
import sympy as sp
from sympy.core.function import AppliedUndef

from . import e1 as E1, e2 as E2
from .design_certificate import at_point
from .timeouts import TimeLimit, attempt

GAIN_KEYS = ("k1", "k2", "lam", "Vmax", "Wmax", "Vr_max", "Wr_max")
#: |Wr|max = 0 is a straight-line reference: (3) bounds |Wr(t)| by it and
#: bound (10) holds with it as written.  Every other entry must be positive
#: (lam, k1, k2 > 0 in (9); lim Vr(t) != 0 needs |Vr|max > 0).
NONNEGATIVE_KEYS = ("Wr_max",)


REWRITE_SECONDS = 5.0     # SymPy's rewrite of Abs, Max, Min, ... as a Piecewise


class DesignError(Exception):
    """The design file cannot be used; the message is one line."""


@dataclass
class Design:
    path: Path
    f: sp.Expr                       # parameters substituted, canonical e1, e2
    f_source: sp.Expr                # as written, before substitution
    params: dict = field(default_factory=dict)   # name -> exact SymPy number
    gains: dict = field(default_factory=dict)    # scenario -> {key: Rational}
    name: str = ""
    description: str = ""
    f_line: int = 1                  # line of the file that defines f

    @property
    def stem(self) -> str:
        return self.path.stem


def exact_float(x: sp.Float) -> sp.Rational:
    """The exact rational a float stands for.  A double (a Python float, or a
    SymPy Float of 53 bits or less that a double holds exactly) is read as its
    shortest round-trip decimal, Python's ``repr`` (0.1 -> 1/10, 1/3.0 ->
    3333333333333333/10**16): the decimal a person reads, never a shorter
    one.  A SymPy Float of 53 bits or less that no double holds (beyond the
    double range, or finer than a subnormal: Float('1e-400'), Float('3e-324'))
    is read the same way at 53 bits and any exponent, the shortest decimal
    that rounds back to it (`float()` had read 1e-400 as 0).  A SymPy Float
    of more than 53 bits is read as its exact binary value."""
    if isinstance(x, float):
        return sp.Rational(repr(x))
    if x._prec > 53:
        return sp.Rational(x)
    double = float(x)
    if math.isfinite(double) and sp.Rational(double) == sp.Rational(x):
        return sp.Rational(repr(double))
    for digits in range(1, 18):          # 17 significant digits always round back at 53 bits
        text = mpmath.libmp.to_str(x._mpf_, digits, strip_zeros=False)
        if mpmath.libmp.from_str(text, 53, mpmath.libmp.round_nearest) == x._mpf_:
            return sp.Rational(text)
    return sp.Rational(x)


def exact_number(value, what: str) -> sp.Expr:
    """A number from a design file (params, gains) as an exact SymPy number:
    floats of a double's precision or less (Python, numpy, mpmath, SymPy) as
    `exact_float` reads them, a numpy float finer than a double (longdouble)
    that no double holds as its exact binary value, integers (numpy's too),
    Fractions and Decimals exactly; at most 4,200 digits (what Python prints)."""
    value = _exact_number(value, what)
    if any(max(abs(r.p), r.q).bit_length() > 14_000 for r in value.atoms(sp.Rational)):
        raise DesignError(f"{what} holds a number of more than 4,200 digits, which cannot be printed into a "
                          f"certificate or code; use a smaller one")
    return value


def _exact_number(value, what: str) -> sp.Expr:
    if isinstance(value, bool):
        raise DesignError(f"{what} is a boolean, not a number")
    if isinstance(value, numbers.Integral) and not isinstance(value, sp.Basic):     # (numpy integers too)
        return sp.Integer(int(value))
    if isinstance(value, fractions.Fraction):
        return sp.Rational(value)
    if isinstance(value, (float, decimal.Decimal, mpmath.mpf)) or \
            isinstance(value, numbers.Real) and not isinstance(value, sp.Basic):    # numpy floats
        if not (value == value and abs(value) != float("inf")):
            raise DesignError(f"{what} is {value}, not a finite number")
        if isinstance(value, float):
            return exact_float(float(value))        # (repr of numpy's float64 is 'np.float64(...)')
        if isinstance(value, decimal.Decimal):
            return sp.Rational(fractions.Fraction(value))
        if isinstance(value, mpmath.mpf):           # its own precision: 53 bits or more
            return exact_float(sp.Float(value, precision=max(53, int(value.man).bit_length())))
        exact = fractions.Fraction(*value.as_integer_ratio())
        double = float(value)
        return exact_float(double) if math.isfinite(double) and fractions.Fraction(double) == exact \
            else sp.Rational(exact)
    if isinstance(value, str):
        try:
            value = sp.sympify(value, rational=True)
        except (sp.SympifyError, SyntaxError, TypeError) as exc:
            raise DesignError(f"{what} = {value!r} is not a number") from exc
    if isinstance(value, sp.Float):
        if not value.is_finite:
            raise DesignError(f"{what} is {value}, not a finite number")
        return exact_float(value)
    if isinstance(value, sp.Basic) and getattr(value, "is_number", False) and not value.has(sp.I):
        value = value.xreplace({x: exact_float(x) for x in value.atoms(sp.Float)})
        if value.is_real is False or value.has(sp.nan, sp.zoo, sp.oo, -sp.oo):
            raise DesignError(f"{what} = {value} is not a finite real number")
        return value
    raise DesignError(f"{what} = {value!r} is not a number")


def _f_line(source: str) -> int:
    """Line of the last module-level assignment to ``f`` (for annotations)."""
    line = 1
    for node in ast.parse(source).body:
        targets = []
        if isinstance(node, ast.Assign):
            targets = node.targets
        elif isinstance(node, (ast.AnnAssign, ast.AugAssign)):
            targets = [node.target]
        for t in targets:
            if isinstance(t, ast.Name) and t.id == "f":
                line = node.lineno
    return line


def _run_file(path: Path) -> tuple[dict, str]:
    if path.exists() and not path.is_file() and not path.is_dir():
        raise DesignError("not a regular file (a FIFO or a device): give the design's .py file")
    if path.suffix == ".json":      # (it was run as Python: "name 'true' is not defined")
        raise DesignError("a JSON file, not a design: re-check a certificate with `uwmr-verify "
                          "--check-certificate FILE`")
    try:
        with tokenize.open(path) as fh:     # as Python reads a source: a BOM, a coding line (red team 28)
            source = fh.read()
    except FileNotFoundError:
        raise DesignError("no such file") from None
    except (OSError, UnicodeDecodeError, SyntaxError) as exc:     # (SyntaxError: an unknown coding)
        raise DesignError(f"cannot read the file ({exc.__class__.__name__}: {_text(exc)}); save it as "
                          f"UTF-8") from None
    try:
        compile(source, str(path), "exec")
    except SyntaxError as exc:
        raise DesignError(f"syntax error at line {exc.lineno}: {exc.msg}") from None
    try:
        # a print() in a design file must not corrupt JSON on stdout
        with contextlib.redirect_stdout(sys.stderr), _standard_fds_kept(), _importable(path.parent):
            namespace = runpy.run_path(str(path), run_name="__uwmr_design__")
    except SystemExit as exc:
        raise DesignError(f"the file called exit({exc.code}) while loading") from None
    except KeyboardInterrupt:
        raise DesignError("the file raised KeyboardInterrupt while loading") from None
    except TimeLimit:
        raise
    except BaseException as exc:  # any failure of the user's code is unusable input
        if not isinstance(exc, Exception):      # GeneratorExit, its own BaseException class (red team 28)
            raise DesignError(f"raised {exc.__class__.__name__} while loading: {_text(exc)}".rstrip(": ")) from None
        tb = exc.__traceback__
        line = None
        while tb is not None:
            if tb.tb_frame.f_code.co_filename == str(path):
                line = tb.tb_lineno
            tb = tb.tb_next
        where = f" at line {line}" if line else ""
        text = source.splitlines()[line - 1] if line and line <= len(source.splitlines()) else ""
        hint = mistake_hint(exc, text)
        if hint:
            raise DesignError(f"at line {line}: {hint}" if line else hint) from None
        raise DesignError(f"raised {exc.__class__.__name__}{where}: {_text(exc)}".rstrip(": ")) from None
    return namespace, source


def _text(exc: BaseException) -> str:
    """The exception's text on one line (its __str__ may itself raise)."""
    try:
        return " ".join(str(exc).split())
    except Exception:  # noqa: BLE001 - the user's own __str__
        return "(its message cannot be printed)"


@contextlib.contextmanager
def _standard_fds_kept():
    """While a design file runs, file descriptor 1 goes to stderr and 0 reads
    /dev/null: what its os.write(1, ...), os.system("echo") or stdin.read()
    does cannot reach the report on stdout or the code generator's worker,
    whose messages use 0 and 1 (red team 28)."""
    for stream in (sys.stdout, sys.stderr, sys.__stdout__):
        with contextlib.suppress(AttributeError, OSError, ValueError):
            stream.flush()
    saved = []
    try:
        for fd, target in ((0, os.open(os.devnull, os.O_RDONLY)), (1, 2)):
            saved.append((fd, os.dup(fd)))
            os.dup2(target, fd)
            if target != 2:
                os.close(target)
    except OSError:             # (a descriptor closed from the start: nothing to keep apart)
        pass
    try:
        yield
    finally:
        with contextlib.suppress(AttributeError, OSError, ValueError):
            sys.__stdout__.flush()
        for fd, copy in reversed(saved):
            os.dup2(copy, fd)
            os.close(copy)


@contextlib.contextmanager
def _importable(directory: Path):
    """The design's own directory is importable while it loads (a helper
    module or package beside it), and the modules imported from there (and
    below) are forgotten afterwards (an edited helper is read again next
    time)."""
    directory = directory.resolve()
    before = set(sys.modules)
    sys.path.insert(0, str(directory))
    try:
        yield
    finally:
        with contextlib.suppress(ValueError):
            sys.path.remove(str(directory))
        for name in set(sys.modules) - before:
            file = getattr(sys.modules.get(name), "__file__", None)
            if file and Path(file).resolve().is_relative_to(directory):     # beside it or in a package there
                del sys.modules[name]


_FUNCTION_CALL = re.compile(r"\b(np|numpy|math)\.(\w+)\s*\(")


def mistake_hint(exc: Exception, line_text: str = "") -> str | None:
    """One line naming the fix for the usual mistakes of a design file (numpy
    or math functions applied to SymPy expressions, ``^`` for a power), or
    None."""
    message = _text(exc)
    calls = _FUNCTION_CALL.findall(line_text)
    if isinstance(exc, TypeError) and "unsupported operand type(s) for ^" in message:
        return "`^` is exclusive-or in Python; write powers with ** (e1**2, not e1^2)"
    ufunc = re.search(r"no callable (\w+) method", message)
    if isinstance(exc, (TypeError, AttributeError)) and (ufunc or "loop of ufunc" in message):
        name = ufunc.group(1) if ufunc else next((n for m, n in calls if m != "math"), "log")
        return (f"numpy's {name} cannot take a SymPy expression; use sympy.{name} "
                f"(import sympy as sp; sp.{name}(...))")
    if isinstance(exc, TypeError) and ("convert expression to float" in message
                                       or "must be real number, not" in message):
        name = next((n for m, n in calls if m == "math"), None)
        if name or "math." in line_text:
            name = name or "sqrt"
            return (f"math.{name} cannot take a SymPy expression; use sympy.{name} "
                    f"(import sympy as sp; sp.{name}(...))")
        return f"a float was asked of a SymPy expression ({message}); use sympy functions (sympy.sqrt, sympy.log) on e1, e2"
    return None


def _assumed(s: sp.Symbol) -> dict:
    """The assumptions a symbol was declared with (as written, e.g. positive=True)."""
    return dict(getattr(s, "_assumptions_orig", None) or s.assumptions0)


def _check_assumptions(f_source: sp.Expr, params: dict) -> None:
    """SymPy uses a symbol's assumptions while the file builds f (sqrt(e1**2)
    becomes e1 for a positive e1, |c| - c becomes 0 for a positive c), so
    they must hold: e1, e2 range over all reals, and a parameter's value must
    satisfy what its symbol was declared."""
    for s in sorted(f_source.free_symbols, key=lambda x: x.name):
        facts = _assumed(s)
        if s.name in ("e1", "e2"):
            strong = sorted(k for k, v in facts.items() if E1.assumptions0.get(k) != v)
            if strong:
                raise DesignError(f"{s.name} is declared {strong[0]}={facts[strong[0]]}, but f is studied for every real "
                                  f"{s.name}, and SymPy may already have used that to simplify f; declare "
                                  f"e1, e2 = sympy.symbols('e1 e2', real=True)")
        elif s.name in params:
            value = params[s.name]
            wrong = sorted(k for k, v in facts.items() if getattr(value, f"is_{k}", None) != v)
            if wrong:
                raise DesignError(f"params[{s.name!r}] = {value} does not satisfy {wrong[0]}={facts[wrong[0]]}, which "
                                  f"the symbol {s.name} was declared with and SymPy may already have used to simplify f; "
                                  f"give a value that does, or declare {s.name} with fewer assumptions")


def _canonical_symbols(expr: sp.Expr, evaluate: bool = True) -> sp.Expr:
    """Replace any symbol named e1/e2 (whatever its assumptions) by ours."""
    return _put_in(expr, {s: {"e1": E1, "e2": E2}[s.name] for s in expr.free_symbols if s.name in ("e1", "e2")},
                   evaluate)


def _put_in(f: sp.Expr, values: dict, evaluate: bool) -> sp.Expr:
    """f with the symbols' values put in, all at once; `evaluate=False` keeps
    every product and sum as written (0 (...) and e1/e1 stay: the loader's
    check of f's values then sees them)."""
    with sp.evaluate(evaluate):
        return f.xreplace(values)


#: a Derivative of these is not carried out (SymPy differentiates branch by
#: branch, so d/de1 sign(e1) came out 0 where it does not exist; red team 27)
_SWITCHING = (sp.Piecewise, sp.Abs, sp.sign, sp.Heaviside, sp.Max, sp.Min, sp.floor, sp.ceiling, sp.frac,
              sp.Mod, sp.DiracDelta)


def _held_carried_out(f: sp.Expr, evaluate: bool = True) -> sp.Expr:
    """f with its unevaluated derivatives carried out and its substitutions
    made, all variables at once (SymPy's Subs.doit substitutes them one after
    another: Subs(g, (e1, e2), (e2, e1)) would become g(e1, e1)); a
    derivative of what may switch (`_SWITCHING`) is refused."""
    if not f.has(sp.Derivative, sp.Subs):
        return f
    switching = next((d.expr for d in f.atoms(sp.Derivative) if d.expr.has(*_SWITCHING)), None)
    if switching is not None:
        raise DesignError(f"f holds the derivative of {switching}, which switches (Piecewise, Abs, sign, Max, Min, "
                          f"...) and may have none where it does; write that derivative by hand, with its value "
                          f"where it switches")
    f = f.replace(lambda e: isinstance(e, sp.Derivative), lambda e: e.doit())
    with sp.evaluate(evaluate):         # (replace builds each term around a Subs again)
        return f.replace(lambda e: isinstance(e, sp.Subs), lambda e: e.expr.xreplace(dict(zip(e.variables, e.point))))


def _parse_params(raw, f: sp.Expr) -> dict:
    if raw is None:
        return {}
    if not isinstance(raw, dict):
        raise DesignError(f"params must be a dict, got {type(raw).__name__}")
    out = {}
    for key, value in raw.items():
        name = key.name if isinstance(key, sp.Symbol) else key
        if not isinstance(name, str):
            raise DesignError(f"params key {key!r} is neither a symbol nor a name")
        if name in ("e1", "e2"):
            raise DesignError(f"params gives a value to {name}, which is a variable of f")
        out[name] = exact_number(value, f"params[{name}]")
    return out


def _parse_gains(raw) -> dict:
    if raw is None:
        return {}
    if not isinstance(raw, dict):
        raise DesignError(f"gains must be a dict of scenarios, got {type(raw).__name__}")
    out = {}
    for scenario, entries in raw.items():
        if not str(scenario).isprintable():     # (a newline would start a line of its own in every report)
            raise DesignError(f"gain scenario {str(scenario)!r}: a scenario name is one line of printable text")
        if str(scenario) in out:                # 1 and "1": one name in every report (red team 28)
            raise DesignError(f"two gain scenarios are named {str(scenario)!r}; give each its own name")
        if not isinstance(entries, dict):
            raise DesignError(f"gain scenario {scenario!r} must be a dict with {', '.join(GAIN_KEYS)}")
        if "lambda" in entries:      # the paper's name, accepted for lam
            if "lam" in entries:
                raise DesignError(f"gain scenario {scenario!r} gives both 'lam' and its alias 'lambda'")
            entries = {("lam" if k == "lambda" else k): v for k, v in entries.items()}
        unknown_keys = sorted(set(entries) - set(GAIN_KEYS))
        if unknown_keys:
            raise DesignError(f"gain scenario {scenario!r} has unknown entry {unknown_keys[0]!r}; "
                              f"expected {', '.join(GAIN_KEYS)}")
        values = {}
        for key in GAIN_KEYS:
            if key not in entries:
                raise DesignError(f"gain scenario {scenario!r} has no {key!r}")
            v = exact_number(entries[key], f"gains[{scenario!r}][{key!r}]")
            if key in NONNEGATIVE_KEYS:
                if not (v >= 0) == True:  # noqa: E712  (SymPy relational)
                    raise DesignError(f"gains[{scenario!r}][{key!r}] = {entries[key]} must not be negative")
            elif not (v > 0) == True:  # noqa: E712  (SymPy relational)
                raise DesignError(f"gains[{scenario!r}][{key!r}] = {entries[key]} must be positive")
            values[key] = v
        out[str(scenario)] = values
    return out


def _check_real_valued(f: sp.Expr) -> None:
    """Refuse an f that is undefined or non-real at a sample point.

    This is a cheap screen for unusable input, not a proof of anything: each
    failure is a concrete point where f has no real value."""
    held = next((k.__name__ for k in (sp.Integral, sp.Sum, sp.Product, sp.Limit, sp.Derivative) if f.has(k)), None)
    if held:
        raise DesignError(f"f holds an unevaluated {held}; write f in closed form (its .doit(), or the formula "
                          f"by hand)")
    if f.has(sp.nan) or f.has(sp.zoo) or f.has(sp.oo) or f.has(-sp.oo):
        raise DesignError("f contains nan, zoo or infinity (a division by zero in the formula?)")
    if f.has(sp.I):
        raise DesignError("f contains the imaginary unit; f must be real-valued")
    pts = [(0, 0), (1, 0), (0, 1), (-1, 0), (0, -1), (sp.Rational(1, 2), sp.Rational(1, 3)),
           (3, -2), (-5, 7), (sp.Rational(1, 10), 0), (100, 100)]
    parts = _parts_with_a_domain(f)
    for a, b in pts + _zeros_of_denominators(f):
        point = {E1: sp.sympify(a), E2: sp.sympify(b)}
        if _huge_power_at(f, point):
            continue            # rho**(rho**2) at (100, 100): SymPy would compute its 6e9 bits exactly
        # at an irrational root only an exact nan or zoo counts: evalf of an exact 0 there can be noise
        # (|p|^(1/2) as (p^4)^(1/8) came out with an imaginary part of 1e-19; red team 19)
        rational = all(isinstance(c, int) or c.is_Rational for c in (a, b))
        try:
            try:                # all variables at once: one by one, e2^2/e2^2 turned 1 before e2 = 0
                v = f.xreplace(point)
            except TypeError:   # a later Piecewise condition with no value there: the conditions in order
                v = at_point(f, (a, b))
            if isinstance(v, sp.Piecewise) or v.free_symbols:
                continue
            v = v.evalf(30) if rational else v
        except (OverflowError, RecursionError):
            continue            # too large for SymPy to evaluate here: not a sign of bad input
        except (ZeroDivisionError, TypeError, ValueError):
            if not rational:
                continue
            raise DesignError(f"f cannot be evaluated at (e1, e2) = ({a}, {b})") from None
        if v.has(sp.nan, sp.zoo) or v.has(sp.oo) or v.has(-sp.oo):
            hint = " (define the value there with sympy.Piecewise)" if (a, b) == (0, 0) else ""
            raise DesignError(f"f is undefined at (e1, e2) = ({a}, {b}){hint}")
        re, im = v.as_real_imag() if rational else (v, 0)
        if im != 0 and abs(im) > 1e-25:
            raise DesignError(f"f is not real-valued at (e1, e2) = ({a}, {b}): f = {sp.N(v, 6)}")
        for part in parts if rational else ():
            try:
                w = part.xreplace(point).evalf(30)
                im = 0 if w.has(sp.nan, sp.zoo, sp.oo, -sp.oo) else w.as_real_imag()[1]
            except (OverflowError, RecursionError, ZeroDivisionError, TypeError, ValueError):
                continue
            if im != 0 and abs(im) > 1e-25:
                raise DesignError(f"f is not real-valued at (e1, e2) = ({a}, {b}): its part {part} has no real value "
                                  "there (f has one only in complex arithmetic); write f with real parts only")


def _huge_power_at(f: sp.Expr, point: dict) -> bool:
    """A power u**y of f with a variable exponent has more than a million
    bits at the point {e1: a, e2: b}, |y| log2(|u| + 2) > 10^6 (by 15-digit evalf)."""
    for p in f.atoms(sp.Pow):
        if p.exp.free_symbols:
            try:
                u, y = (complex(sp.N(t.xreplace(point), 15)) for t in (p.base, p.exp))
            except (TypeError, ValueError, OverflowError, ZeroDivisionError):
                return True         # too large for a float: certainly huge
            if abs(y) * math.log2(abs(u) + 2) > 1e6:
                return True
    return False


def _parts_with_a_domain(f: sp.Expr) -> list:
    """The logarithms, powers with an exponent that is not an integer and
    inverse functions of f (outside Piecewise, whose branches may be taken
    only where they are real): where one of them has no real value neither
    has f, though SymPy's complex values can cancel (log(2 e1 - 14) -
    log(e1 - 7) is log 2 at e1 = 0; red team 22)."""
    out, stack = [], [f]
    while stack:
        e = stack.pop()
        if isinstance(e, sp.Piecewise) or not isinstance(e, sp.Basic):
            continue
        if isinstance(e, _DOMAINED) or (e.is_Pow and not e.exp.is_integer):
            out.append(e)
        stack.extend(e.args)
    return out


_DOMAINED = (sp.log, sp.asin, sp.acos, sp.acosh, sp.atanh, sp.acoth, sp.asec, sp.acsc, sp.LambertW)


def _zeros_of_denominators(f: sp.Expr, lines=(0, 1, -1)) -> list:
    """Points where a denominator of f that is a polynomial in e1, e2
    vanishes, on the lines e1 = c and e2 = c (c in `lines`): where f =
    e2/(e2 - 2) - 2/(e2 - 2) has no value, off the sample points.  Its real
    roots in radicals up to degree 4 (f = (e2^2 - 2)/((e2 - sqrt(2))(e2 +
    sqrt(2))) has none on e2 = +-sqrt(2), red team 18b), its rational roots
    over Q up to degree 8, within about 2 s (nested radicals in a quartic's
    coefficients can take SymPy seconds each)."""
    out, deadline = [], time.monotonic() + 2.0
    for p in f.atoms(sp.Pow):
        if not (p.exp.is_Rational and p.exp < 0 and p.base.free_symbols and p.base.is_polynomial(E1, E2)):
            continue
        for c in lines:
            for var, other in ((E1, E2), (E2, E1)):
                base = sp.Poly(p.base.subs(var, c), other)
                rational = base.domain.is_QQ or base.domain.is_ZZ
                if base.is_zero or base.degree() > (8 if rational else 4):
                    continue
                if time.monotonic() > deadline:
                    return out[:20]
                roots = sp.roots(base, filter="Q") if base.degree() > 4 else \
                    [r for r in attempt(lambda: sp.roots(base), 0.5, {}) if r.is_extended_real]
                out += [(c, r) if var == E1 else (r, c) for r in roots]
    return out[:20]


_RECIPROCALS = {sp.sech: lambda x: 1 / sp.cosh(x), sp.csch: lambda x: 1 / sp.sinh(x),
                sp.coth: lambda x: sp.cosh(x) / sp.sinh(x), sp.sec: lambda x: 1 / sp.cos(x),
                sp.csc: lambda x: 1 / sp.sin(x), sp.cot: lambda x: sp.cos(x) / sp.sin(x)}


def _plain_functions(f: sp.Expr) -> sp.Expr:
    """f with what the certificate checker does not read written with what
    it does, where that is an identity on the same domain: sech, csch, coth,
    sec, csc, cot as quotients of cosh, sinh, cos, sin; the golden ratio and
    the tribonacci constant as radicals.  Sums and integrals are left as
    written: carrying them out can bring in removable singularities or floor."""
    f = f.replace(lambda e: type(e) in _RECIPROCALS, lambda e: _RECIPROCALS[type(e)](e.args[0]))
    return f.xreplace({c: c.rewrite(sp.sqrt) for c in f.atoms(sp.GoldenRatio.func, sp.TribonacciConstant.func)})


def _plain_conditions(f: sp.Expr) -> sp.Expr:
    """f with each Piecewise condition written with relations, And, Or and
    Not only (the conditions the certificate checker reads): membership
    `Contains(x, set)` as the set's relations, Xor, ITE, Implies, Equivalent,
    Nand, Nor and a Not of an And or Or in negation normal form (logical
    equivalences: ~(Eq(e1, 0) & Eq(e2, 0)) is Ne(e1, 0) | Ne(e2, 0))."""
    def relations(b):                   # (an ImageSet has no relations: left as it is, unread by the checker)
        try:
            return b.args[1].as_relational(b.args[0])
        except (AttributeError, NotImplementedError, TypeError, ValueError):
            return b

    def plain(c):
        c = c.replace(lambda b: isinstance(b, sp.Contains), relations)
        return c.to_nnf() if c.has(*_COMPOUND) else c
    pieces = list(f.atoms(sp.Piecewise))
    if not any(c.has(sp.Contains, *_COMPOUND) for p in pieces for _, c in p.args):
        return f
    return f.replace(lambda e: isinstance(e, sp.Piecewise),
                     lambda e: sp.Piecewise(*[(x, plain(c)) for x, c in e.args]))


_COMPOUND = (sp.Xor, sp.ITE, sp.Implies, sp.Equivalent, sp.Nand, sp.Nor, sp.Not)


def load_design(path) -> Design:
    """Load and check a design file (the public contract of the README)."""
    path = Path(path)
    ns, source = _run_file(path)
    return design_from_namespace(ns, path, _f_line(source))


def design_from_namespace(ns: dict, path: Path, f_line: int = 1) -> Design:
    """Check the names a design defines (``f``, and optionally ``params``,
    ``gains``, ``name``, ``description``, as in a design file's namespace) and
    return the `Design`; `path` names it in messages and generated files."""
    path = Path(path)
    if "f" not in ns:
        raise DesignError("defines no `f`; add e.g. `f = sympy.log(1 + e1**2 + e2**2) / 2`")
    f_source = ns["f"]
    if isinstance(f_source, (int, float)) and not isinstance(f_source, bool):
        f_source = sp.sympify(f_source)          # a constant written plainly (a float keeps its 53 bits)
    if isinstance(f_source, bool) or not isinstance(f_source, sp.Expr):
        raise DesignError(f"`f` is a {type(f_source).__name__}, not a SymPy expression in e1, e2")
    f = _canonical_symbols(f_source)
    raw = _held_carried_out(_canonical_symbols(f_source, evaluate=False), evaluate=False)   # f as written: see below
    f = _held_carried_out(f)
    undefined = sorted(str(g.func) for g in f.atoms(AppliedUndef))
    if undefined:
        raise DesignError(f"f uses the undefined function {undefined[0]!r}; write f with SymPy's functions "
                          f"(sympy.log, sympy.sqrt, ...) of e1 and e2")
    # floats in f (0.5, or 1/3 evaluated by Python) are read by `exact_float`,
    # like params and gains
    floats = f.atoms(sp.Float) | raw.atoms(sp.Float)
    if any(not x.is_finite for x in floats):
        raise DesignError("f contains a non-finite float (nan or inf)")
    exact = {x: exact_float(x) for x in floats}
    f = f.xreplace(exact)
    params = _parse_params(ns.get("params"), f)
    _check_assumptions(f_source, params)
    values = {s: sp.sympify(params[s.name]) for s in f.free_symbols | raw.free_symbols if s.name in params}
    f = _put_in(f, values, evaluate=True)
    raw = _put_in(raw, {**exact, **values}, evaluate=False)
    extra = sorted(s.name for s in f.free_symbols if s not in (E1, E2))
    if extra and not f.has(E1, E2):
        raise DesignError(f"f is written in {', '.join(extra)}, not in the error coordinates: name them e1 and e2 "
                          f"(`from uwmr_symbolic import e1, e2`, or sympy.symbols('e1 e2', real=True))")
    if extra:
        raise DesignError(f"free symbol {extra[0]!r} of f has no value; add it to `params`")
    unused = sorted(set(params) - {s.name for s in _canonical_symbols(f_source).free_symbols})
    if unused:
        raise DesignError(f"params[{unused[0]!r}] names no symbol of f")
    if f.has(sp.Abs, sp.Max, sp.Min, sp.Heaviside, sp.sign):
        start = time.monotonic()
        f = attempt(lambda: sp.piecewise_fold(f.rewrite(sp.Piecewise)), REWRITE_SECONDS)
        if f is None:       # SymPy can loop on an argument whose sign it cannot decide (a constant 0 in disguise)
            raise DesignError(f"SymPy could not write the Abs, Max, Min, Heaviside or sign of f as a Piecewise "
                              f"(stopped after {time.monotonic() - start:.1f} s); simplify their constant arguments, "
                              f"or write f as a Piecewise")
    f = _plain_conditions(_plain_functions(f))
    compared = next((r for r in f.atoms(sp.core.relational.Relational)
                     if not all(isinstance(a, sp.Expr) for a in r.args)), None)
    if compared is not None:
        raise DesignError(f"a condition of f compares truth values, {compared}; write it with And, Or and Not "
                          f"(Eq(e1 > 0, e2 > 0) is (e1 > 0) & (e2 > 0) | (e1 <= 0) & (e2 <= 0))")
    _check_real_valued(f)
    if raw != f:                # where SymPy's evaluation of f as written, or with params, dropped a 0/0 or 0 log(-1)
        _check_real_valued(raw)
    if any(max(abs(r.p), r.q).bit_length() > 14_000 for r in f.atoms(sp.Rational)):   # Python prints <= 4,300 digits
        raise DesignError("f holds a number of more than 4,200 digits, which cannot be printed into a certificate "
                          "or code; scale f (or its parameters) to smaller constants")
    gains = _parse_gains(ns.get("gains"))
    name = ns.get("name") if isinstance(ns.get("name"), str) else path.stem
    if not name.isprintable():
        raise DesignError(f"name = {name!r}: a design's name is one line of printable text")
    description = ns.get("description") if isinstance(ns.get("description"), str) else ""
    return Design(path=path, f=f, f_source=f_source, params=params, gains=gains,
                  name=name, description=description, f_line=f_line)
