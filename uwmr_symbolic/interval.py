"""Rigorous extended-real interval evaluation of SymPy expressions.

Every finite computation is done with python-flint's ``arb`` (ball arithmetic
with mathematically rigorous error bounds).  Interval endpoints are *exact*
``arb`` values (dyadic rationals, radius 0) or the two sentinels ``-inf`` /
``+inf``.  Whenever an endpoint is computed, the exact operation is performed
in ball arithmetic (the ball contains the true value) and the lower bound of
the ball is taken for a lower endpoint, the upper bound for an upper endpoint.
Hence every returned interval contains every true value (outward rounding).
If arb cannot produce a finite bound (overflow, NaN) the endpoint is widened to
``-inf`` / ``+inf``, which is always sound.

Two modes
---------
``mode="range"``
    The result encloses the closure (in the extended reals) of the set
    ``{expr(x) : x in the box, every sub-expression defined at x}``.
    Infinite endpoints are allowed in inputs and outputs.  A Piecewise whose
    conditions cannot be decided on the box yields the hull of the candidate
    branches.  Each candidate branch is evaluated on the box narrowed by the
    bounds "symbol op constant" implied by its own condition and by the
    negations of the earlier conditions (a closed superset of the points where
    the branch is active; other conditions imply no narrowing), so the hull
    is sound; a branch whose narrowed box is empty is skipped.
``mode="continuous"``
    As above, and additionally the evaluation *proves* that the expression is
    defined and continuous on the whole (closed, bounded) box: the expression
    is a composition of operations each of which is continuous on an interval
    containing all of its argument's values.  Anything that could break this
    raises :class:`Undefined`: an infinite endpoint anywhere (input or
    intermediate), division by an interval containing 0, ``sign`` /
    ``Heaviside`` / ``floor`` / ``ceiling`` on an interval containing a jump
    point, or a Piecewise whose active branch is not the same on the whole box.

Extended (limit) arithmetic
---------------------------
Used to reason about ``s -> oo`` through ``s = 1/t``, ``t in [0, delta]``.

* ``a / b`` with ``b = [0, h]`` (``h > 0``) and ``a`` sign-definite
  (``a.lo > 0`` or ``a.hi < 0``) gives e.g. ``[a.lo/h, +inf]``; symmetric for
  ``b = [l, 0]``.  If ``a`` contains 0, or 0 is interior to ``b``, or
  ``b = [0, 0]``: :class:`Undefined` (a genuine pole / indeterminate form).
  In continuous mode any denominator containing 0 is :class:`Undefined`.
* Products use the set convention ``0 * (+-inf) = 0`` for endpoint products:
  the intervals are sets of *reals*, so this computes the exact hull of
  ``{x*y}``.  Sums never meet ``inf - inf`` for lower/upper endpoint sums; any
  non-finite arb result is widened to the infinite sentinel.
* Monotone functions take their limits at infinite endpoints
  (``exp(-inf) = 0``, ``tanh(+inf) = 1``, ``atan(+inf) = pi/2`` (enclosed),
  ``x**(-p)`` at ``+inf`` is 0, ...); ``sin``/``cos`` of an infinite interval
  or one at least ``2*pi`` long is ``[-1, 1]``.

Why limit values are covered: every enclosure is a closed interval containing
all values of the sub-expression at points where it is defined; a finite limit
of such values lies in the closure, hence in the interval.  An operation
applied to an enclosure only needs to contain the operation's values on the
*real* members of its input enclosure, which the rules above guarantee.

``Undefined`` is raised (both modes) whenever some operation is not defined on
part of its input enclosure (``sqrt``/non-integer power of a possibly negative
number, ``log`` of a not strictly positive interval, domain errors of
``acosh``/``atanh``/``asin``/``acos``, ``tan`` across a pole, ``nan``/``zoo``/
``I``, unevaluated ``Derivative``/``Integral``/..., unsupported nodes).
Raising is always sound: it never claims anything.

Implementation: :class:`IntervalFunction` compiles the SymPy tree once into
nested closures working on tuples ``(lo, hi)``; constant sub-trees are folded
at compile time, and sub-expressions occurring several times are cached per
call.  ``prec`` (bits) is set on ``flint.ctx`` for the duration of a call and
restored afterwards (not thread-safe, like flint's global context).
"""
from __future__ import annotations

import math
import operator
from dataclasses import dataclass
from fractions import Fraction

import sympy as sp
from flint import arb, ctx, fmpq

__all__ = ["Undefined", "Interval", "evaluate", "IntervalFunction"]


class Undefined(Exception):
    """The expression is not defined (or, in 'continuous' mode, not provably
    continuous) on the box; ``str(e)`` says which sub-expression and why
    (printed only when asked for: the search raises thousands of these)."""

    def __init__(self, why, expr=None):
        super().__init__(why)
        self.expr = expr

    def __str__(self):
        return self.args[0] if self.expr is None else f"{self.args[0]}: {_short(self.expr)}"


# ---------------------------------------------------------------------------
# endpoint helpers (internal intervals are plain tuples (lo, hi) of exact arbs)
# ---------------------------------------------------------------------------

NINF = arb.neg_inf()
PINF = arb.pos_inf()
ZERO = arb(0)
ONE = arb(1)
MONE = arb(-1)
_UNIT = (ONE, ONE)
_PM1 = (MONE, ONE)


def _lo(r):
    """Exact lower bound of ball ``r`` (``-inf`` if arb has no finite one)."""
    x = r.lower()
    return x if x.is_finite() else NINF


def _hi(r):
    """Exact upper bound of ball ``r`` (``+inf`` if arb has no finite one)."""
    x = r.upper()
    return x if x.is_finite() else PINF


def _neg(x):
    if x is NINF:
        return PINF
    if x is PINF:
        return NINF
    return -x  # exact


def _negi(a):
    return (_neg(a[1]), _neg(a[0]))


def _short(e, n=160):
    s = str(e)
    return s if len(s) <= n else s[: n - 3] + "..."


def _undef(e, why):
    return Undefined(why, e)


def _sub(a, b):
    return (_lo(a[0] - b[1]), _hi(a[1] - b[0]))


def _infprod(x, y):
    # at least one of x, y is infinite; 0 * inf = 0 (set semantics)
    if x == ZERO or y == ZERO:
        return ZERO
    return PINF if (x > ZERO) == (y > ZERO) else NINF


def _mlo(x, y):
    if x is NINF or x is PINF or y is NINF or y is PINF:
        return _infprod(x, y)
    return _lo(x * y)


def _mhi(x, y):
    if x is NINF or x is PINF or y is NINF or y is PINF:
        return _infprod(x, y)
    return _hi(x * y)


def _mul(a, b):
    al, ah = a
    bl, bh = b
    if al >= ZERO:
        if bl >= ZERO:
            return (_mlo(al, bl), _mhi(ah, bh))
        if bh <= ZERO:
            return (_mlo(ah, bl), _mhi(al, bh))
        return (_mlo(ah, bl), _mhi(ah, bh))
    if ah <= ZERO:
        if bl >= ZERO:
            return (_mlo(al, bh), _mhi(ah, bl))
        if bh <= ZERO:
            return (_mlo(ah, bh), _mhi(al, bl))
        return (_mlo(al, bh), _mhi(al, bl))
    if bl >= ZERO:
        return (_mlo(al, bh), _mhi(ah, bh))
    if bh <= ZERO:
        return (_mlo(ah, bl), _mhi(al, bl))
    return (min(_mlo(al, bh), _mlo(ah, bl)), max(_mhi(al, bl), _mhi(ah, bh)))


def _scale(c, a):
    """Exact finite nonzero constant ``c`` times interval ``a``."""
    if c > ZERO:
        return (_lo(c * a[0]), _hi(c * a[1]))
    return (_lo(c * a[1]), _hi(c * a[0]))


def _divpos(a, b):
    """a / b for b.lo >= 0 < b.hi; if b.lo == 0 then a is sign-definite."""
    al, ah = a
    bl, bh = b
    if al >= ZERO:
        lo = _lo(al / bh)  # al finite; al / +inf = 0 in arb
    elif al is NINF or bl == ZERO:
        lo = NINF
    else:
        lo = _lo(al / bl)
    if ah <= ZERO:
        hi = _hi(ah / bh)  # ah finite
    elif ah is PINF or bl == ZERO:
        hi = PINF
    else:
        hi = _hi(ah / bl)
    return (lo, hi)


def _div(a, b, cont, e):
    bl, bh = b
    if bl > ZERO:
        return _divpos(a, b)
    if bh < ZERO:
        return _negi(_divpos(a, _negi(b)))
    if cont:
        raise _undef(e, "denominator may vanish (not continuous)")
    if not (a[0] > ZERO or a[1] < ZERO):
        raise _undef(e, "division: denominator may vanish and numerator is not sign-definite")
    if bl == ZERO and bh > ZERO:
        return _divpos(a, b)
    if bh == ZERO and bl < ZERO:
        return _negi(_divpos(a, _negi(b)))
    raise _undef(e, "division by an interval with 0 in its interior (pole)")


def _plo(x, n):
    if x is NINF or x is PINF:
        return PINF if (x is PINF or n % 2 == 0) else NINF
    return _lo(x * x if n == 2 else x ** n)


def _phi(x, n):
    if x is NINF or x is PINF:
        return PINF if (x is PINF or n % 2 == 0) else NINF
    return _hi(x * x if n == 2 else x ** n)


def _ipow(a, n):
    """a**n for an integer n >= 1 (tight)."""
    al, ah = a
    if n % 2 == 1 or al >= ZERO:
        return (_plo(al, n), _phi(ah, n))
    if ah <= ZERO:
        return (_plo(ah, n), _phi(al, n))
    m = _neg(al)
    if ah > m:
        m = ah
    return (ZERO, _phi(m, n))


def _hull(a, b):
    return (min(a[0], b[0]), max(a[1], b[1]))


def _mono(a, f, lim_lo, lim_hi):
    """Increasing f; lim_lo / lim_hi: endpoint values at -inf / +inf."""
    lo = lim_lo() if a[0] is NINF else _lo(f(a[0]))
    hi = lim_hi() if a[1] is PINF else _hi(f(a[1]))
    return (lo, hi)


def _const_ninf():
    return NINF


def _const_pinf():
    return PINF


def _const_zero():
    return ZERO


def _const_one():
    return ONE


def _const_mone():
    return MONE


def _exp_i(a):
    r = _mono(a, arb.exp, _const_zero, _const_pinf)
    if r[0] < ZERO:
        r = (ZERO, r[1])
    return r


def _log_i(a, e):
    if not a[0] > ZERO:
        raise _undef(e, "log of an interval that is not strictly positive")
    return _mono(a, arb.log, _const_ninf, _const_pinf)


def _int_range(tlo, thi):
    """Integers n with tlo <= n <= thi (tlo, thi exact finite arbs)."""
    a = int(tlo.ceil().unique_fmpz())
    b = int(thi.floor().unique_fmpz())
    return range(a, b + 1)


def _trig(a, f, shift):
    """sin (shift = 1/2) or cos (shift = 0): max 1 at x = (shift + 2k) pi,
    min -1 at x = (shift + 2k + 1) pi."""
    al, ah = a
    if al is NINF or ah is PINF:
        return _PM1
    if al == ah:
        r = f(al)
        return (max(_lo(r), MONE), min(_hi(r), ONE))
    pi = arb.pi()
    if not (ah - al < 2 * pi):
        return _PM1
    ra, rb = f(al), f(ah)
    lo = min(_lo(ra), _lo(rb))
    hi = max(_hi(ra), _hi(rb))
    tlo = _lo(al / pi - shift)
    thi = _hi(ah / pi - shift)
    if tlo is NINF or thi is PINF:
        return _PM1
    for n in _int_range(tlo, thi):
        if n % 2 == 0:
            hi = ONE
        else:
            lo = MONE
    return (max(lo, MONE), min(hi, ONE))


_HALF = arb(0.5)


def _sin_i(a):
    return _trig(a, arb.sin, _HALF)


def _cos_i(a):
    return _trig(a, arb.cos, ZERO)


def _tan_i(a, e):
    al, ah = a
    if al is NINF or ah is PINF:
        raise _undef(e, "tan of an unbounded interval (poles)")
    pi = arb.pi()
    tlo = _lo(al / pi - _HALF)
    thi = _hi(ah / pi - _HALF)
    if tlo is NINF or thi is PINF or len(_int_range(tlo, thi)) > 0:
        raise _undef(e, "tan: interval may contain a pole")
    return (_lo(al.tan()), _hi(ah.tan()))


def _cosh_i(a):
    al, ah = a
    if al >= ZERO:
        return (_lo(al.cosh()), PINF if ah is PINF else _hi(ah.cosh()))
    if ah <= ZERO:
        return (_lo(ah.cosh()), PINF if al is NINF else _hi(al.cosh()))
    if al is NINF or ah is PINF:
        return (ONE, PINF)
    return (ONE, max(_hi(al.cosh()), _hi(ah.cosh())))


def _abs_i(a):
    al, ah = a
    if al >= ZERO:
        return a
    if ah <= ZERO:
        return _negi(a)
    m = _neg(al)
    return (ZERO, ah if ah > m else m)


def _root_ep(x, q, lower):
    if x is PINF:
        return PINF
    if x == ZERO:
        return ZERO
    r = x.sqrt() if q == 2 else x.root(q)
    return _lo(r) if lower else _hi(r)


# ---------------------------------------------------------------------------
# The Interval class (public)
# ---------------------------------------------------------------------------


def _dyadic_arb(num, den):
    """Exact arb for num/den if den is a power of two, else None."""
    if den & (den - 1) == 0:
        return arb((num, -(den.bit_length() - 1)))
    return None


def _enclose_rational(num, den):
    x = _dyadic_arb(num, den)
    if x is not None:
        return (x, x)
    r = arb(fmpq(num, den))
    return (_lo(r), _hi(r))


def _enclose_value(x, prec):
    """Tight enclosure (lo, hi) of a user supplied value (exact arbs / sentinels)."""
    if isinstance(x, Interval):
        return (x.lo, x.hi)
    if isinstance(x, bool):
        raise TypeError("bool is not a number")
    if isinstance(x, int):
        return _enclose_rational(x, 1)
    if isinstance(x, Fraction):
        return _enclose_rational(x.numerator, x.denominator)
    if isinstance(x, float):
        if math.isnan(x):
            raise ValueError("nan is not a valid endpoint")
        if math.isinf(x):
            return (PINF, PINF) if x > 0 else (NINF, NINF)
        f = Fraction(x)
        return _enclose_rational(f.numerator, f.denominator)
    if isinstance(x, arb):
        if x.is_nan():
            raise ValueError("nan is not a valid endpoint")
        if not x.is_finite():
            if x.is_exact():
                return (PINF, PINF) if x > ZERO else (NINF, NINF)
            return (NINF, PINF)
        return (x.lower(), x.upper())
    if isinstance(x, fmpq):
        return _enclose_rational(int(x.p), int(x.q))
    e = sp.sympify(x)
    if e is sp.oo:
        return (PINF, PINF)
    if e is sp.S.NegativeInfinity:
        return (NINF, NINF)
    if e.is_Rational:
        return _enclose_rational(int(e.p), int(e.q))
    if e.is_Float:
        if not e.is_finite:
            raise ValueError(f"invalid endpoint {e}")
        r = sp.Rational(e)
        return _enclose_rational(int(r.p), int(r.q))
    if e.free_symbols:
        raise ValueError(f"endpoint {e} is not a number")
    r = IntervalFunction(e, [], "range", prec)()
    return (r.lo, r.hi)


def _to_fraction(x):
    m, ex = x.man_exp()
    m, ex = int(m), int(ex)
    if ex >= 0:
        return Fraction(m << ex)
    return Fraction(m, 1 << -ex)


@dataclass(frozen=True)
class Interval:
    """Closed extended-real interval [lo, hi].

    ``lo`` is an exact finite ``flint.arb`` (radius 0) or ``-inf``; ``hi`` is
    an exact finite ``arb`` or ``+inf``.  Infinite endpoints are always the
    module sentinels ``NINF`` / ``PINF``.
    """

    lo: arb
    hi: arb

    def __post_init__(self):
        lo, hi = self.lo, self.hi
        if not isinstance(lo, arb) or not isinstance(hi, arb):
            raise TypeError("Interval endpoints must be flint.arb; use Interval.of / Interval.point")
        if lo.is_nan() or hi.is_nan():
            raise ValueError("nan endpoint")
        lo = lo.lower() if lo.is_finite() else NINF
        hi = hi.upper() if hi.is_finite() else PINF
        if self.lo.is_exact() and not self.lo.is_finite() and self.lo > ZERO:
            raise ValueError("lower endpoint +inf")
        if self.hi.is_exact() and not self.hi.is_finite() and self.hi < ZERO:
            raise ValueError("upper endpoint -inf")
        if not lo <= hi:
            raise ValueError("empty interval: lo > hi")
        object.__setattr__(self, "lo", lo)
        object.__setattr__(self, "hi", hi)

    # fast internal constructor (no validation)
    @staticmethod
    def _make(lo, hi):
        obj = object.__new__(Interval)
        object.__setattr__(obj, "lo", lo)
        object.__setattr__(obj, "hi", hi)
        return obj

    @staticmethod
    def point(x, prec=128) -> "Interval":
        """The point x (exact if dyadic, else a tight enclosure at ``prec`` bits).

        x: int, Fraction, float, sympy Rational/Integer/Float, flint arb/fmpq,
        or an exact real SymPy number expression such as ``sqrt(3)/2`` or ``pi``.
        """
        old = ctx.prec
        ctx.prec = prec
        try:
            lo, hi = _enclose_value(x, prec)
        finally:
            ctx.prec = old
        if lo is NINF or hi is PINF:
            raise ValueError("Interval.point needs a finite value")
        return Interval._make(lo, hi)

    @staticmethod
    def of(lo, hi, prec=128) -> "Interval":
        """[lo, hi]; endpoints as in :meth:`point`, or ``sympy.oo``, ``-sympy.oo``,
        ``float('inf')`` etc.  Inexact endpoints are rounded outward."""
        old = ctx.prec
        ctx.prec = prec
        try:
            l = _enclose_value(lo, prec)[0]
            h = _enclose_value(hi, prec)[1]
        finally:
            ctx.prec = old
        if l is PINF:
            raise ValueError("lower endpoint +inf")
        if h is NINF:
            raise ValueError("upper endpoint -inf")
        if not l <= h:
            raise ValueError(f"empty interval: {lo} > {hi}")
        return Interval._make(l, h)

    # -- conversions -------------------------------------------------------
    def lower_float(self) -> float:
        """A float <= lo."""
        lo = self.lo
        if lo is NINF:
            return -math.inf
        f = float(lo)
        while math.isnan(f) or arb(f) > lo:
            f = math.nextafter(-math.inf if math.isnan(f) else f, -math.inf)
        return f

    def upper_float(self) -> float:
        """A float >= hi."""
        hi = self.hi
        if hi is PINF:
            return math.inf
        f = float(hi)
        while math.isnan(f) or arb(f) < hi:
            f = math.nextafter(math.inf if math.isnan(f) else f, math.inf)
        return f

    def lower_fraction(self):
        """Exact lo as a Fraction (None for -inf)."""
        return None if self.lo is NINF else _to_fraction(self.lo)

    def upper_fraction(self):
        """Exact hi as a Fraction (None for +inf)."""
        return None if self.hi is PINF else _to_fraction(self.hi)

    # -- predicates ----------------------------------------------------------
    def is_positive(self) -> bool:
        return self.lo > ZERO

    def is_negative(self) -> bool:
        return self.hi < ZERO

    def is_nonnegative(self) -> bool:
        return self.lo >= ZERO

    def is_nonpositive(self) -> bool:
        return self.hi <= ZERO

    def contains_zero(self) -> bool:
        return self.lo <= ZERO <= self.hi

    def is_finite(self) -> bool:
        return self.lo is not NINF and self.hi is not PINF

    def is_point(self) -> bool:
        return self.lo == self.hi

    def width(self) -> float:
        """A float >= hi - lo (inf if unbounded)."""
        if not self.is_finite():
            return math.inf
        return Interval._make(ZERO, _hi(self.hi - self.lo)).upper_float()

    def mid(self) -> Fraction:
        """An exact finite point of the interval, usable for bisection."""
        lo, hi = self.lower_fraction(), self.upper_fraction()
        if lo is not None and hi is not None:
            return (lo + hi) / 2
        if lo is not None:
            return max(2 * lo, lo + 1)
        if hi is not None:
            return min(2 * hi, hi - 1)
        return Fraction(0)

    def contains(self, x) -> bool:
        """True if x (a number or Interval) provably lies in this interval."""
        if isinstance(x, (int, Fraction)) or (isinstance(x, sp.Basic) and x.is_Rational):
            q = Fraction(int(x.p), int(x.q)) if isinstance(x, sp.Basic) else Fraction(x)
            lo, hi = self.lower_fraction(), self.upper_fraction()
            return (lo is None or lo <= q) and (hi is None or q <= hi)
        if isinstance(x, Interval):
            lo, hi = x.lo, x.hi
        else:
            old = ctx.prec
            ctx.prec = 512
            try:
                lo, hi = _enclose_value(x, 512)
            finally:
                ctx.prec = old
        return self.lo <= lo and hi <= self.hi

    def hull(self, other: "Interval") -> "Interval":
        return Interval._make(min(self.lo, other.lo), max(self.hi, other.hi))

    def __repr__(self):
        return f"Interval({self.lower_float()!r}, {self.upper_float()!r})"


# ---------------------------------------------------------------------------
# compiler: SymPy tree -> nested closures  f(args) -> (lo, hi)
# ---------------------------------------------------------------------------

NUMBER_SYMBOLS = {
    sp.pi: lambda: arb.pi(),
    sp.E: lambda: arb.const_e(),
    sp.EulerGamma: lambda: arb.const_euler(),
    sp.Catalan: lambda: arb.const_catalan(),
    sp.GoldenRatio: lambda: (1 + arb(5).sqrt()) / 2,
}

_UNSUPPORTED_HINT = {
    "Derivative": "unevaluated Derivative",
    "Integral": "unevaluated Integral",
    "Subs": "unevaluated Subs",
    "Limit": "unevaluated Limit",
    "DiracDelta": "DiracDelta is not a function",
    "ImaginaryUnit": "complex unit I",
    "NaN": "nan",
    "ComplexInfinity": "zoo (complex infinity)",
    "Infinity": "infinite constant oo",
    "NegativeInfinity": "infinite constant -oo",
}


def _cached(f):
    """Per-call result cache keyed on the identity of the argument tuple.  The
    cache keeps a reference to that tuple, so no other live tuple can have the
    same identity; (args, result) is stored in one atomic assignment."""
    slot = [((), None)]

    def c(a):
        k = slot[0]
        if k[0] is a:
            return k[1]
        r = f(a)
        slot[0] = (a, r)
        return r

    return c


def _narrow(a, cons):
    """Box ``a`` intersected with the bounds ``cons`` (None if empty)."""
    b = list(a)
    for idx, kind, fk in cons:
        kl, kh = fk(None)  # a folded constant (may raise Undefined: conservative)
        lo, hi = b[idx]
        if kind != "le" and kl > lo:
            lo = kl
        if kind != "ge" and kh < hi:
            hi = kh
        if lo > hi:
            return None
        b[idx] = (lo, hi)
    return tuple(b)


def _raiser(msg):
    def f(a):
        raise Undefined(msg)

    return f


class _Compiler:
    def __init__(self, index, cont, expr):
        self.index = index
        self.cont = cont
        self.memo = {}
        self.cmemo = {}
        # sub-expressions occurring more than once get a per-call result cache
        counts = {}
        for node in sp.preorder_traversal(expr):
            counts[node] = counts.get(node, 0) + 1
        self.shared = {k for k, v in counts.items()
                       if v > 1 and isinstance(k, sp.Expr) and not k.is_Symbol}

    # -- expressions -----------------------------------------------------
    def compile(self, e):
        f = self.memo.get(e)
        if f is None:
            f = self._compile(e)
            self.memo[e] = f
        return f

    def _compile(self, e):
        if not isinstance(e, sp.Expr):
            return _raiser(f"not a real expression ({type(e).__name__}): {_short(e)}")
        if not e.free_symbols:
            # constant folding (evaluated once, at this precision and mode)
            try:
                val = self._node(e)(None)
                if self.cont and (val[0] is NINF or val[1] is PINF):
                    raise _undef(e, "infinite constant (not continuous)")
            except Undefined as ex:
                return _raiser(str(ex))
            return lambda a: val
        f = self._node(e)
        if self.cont and not e.is_Symbol:
            def g(a, f=f, e=e):
                r = f(a)
                if r[0] is NINF or r[1] is PINF:
                    raise _undef(e, "unbounded intermediate (not continuous)")
                return r

            f = g
        if e in self.shared:
            f = _cached(f)
        return f

    def _node(self, e):
        if e.is_Symbol:
            return operator.itemgetter(self.index[e])
        if e.is_Number:
            if e.is_Rational:
                v = _enclose_rational(int(e.p), int(e.q))
                return lambda a: v
            if e.is_Float and e.is_finite:
                r = sp.Rational(e)
                v = _enclose_rational(int(r.p), int(r.q))
                return lambda a: v
        if e.is_NumberSymbol and e in NUMBER_SYMBOLS:
            r = NUMBER_SYMBOLS[e]()
            v = (_lo(r), _hi(r))
            return lambda a: v
        if e.is_Add:
            return self._add(e)
        if e.is_Mul:
            return self._mul(e)
        if e.is_Pow:
            return self._pow(e)
        if isinstance(e, sp.Piecewise):
            return self._piecewise(e)
        h = _FUNCS.get(e.func)
        if h is not None:
            return h(self, e, *[self.compile(x) for x in e.args])
        name = type(e).__name__
        hint = _UNSUPPORTED_HINT.get(name, f"unsupported SymPy node {name}")
        return _raiser(f"{hint}: {_short(e)}")

    def _add(self, e):
        fs = [self.compile(x) for x in e.args]
        if len(fs) == 2:
            f1, f2 = fs

            def add2(a):
                x = f1(a)
                y = f2(a)
                return (_lo(x[0] + y[0]), _hi(x[1] + y[1]))

            return add2
        f0, rest = fs[0], fs[1:]

        def addn(a):
            x = f0(a)
            lo, hi = x
            for g in rest:
                y = g(a)
                lo = lo + y[0]  # ball accumulation; rounded once at the end
                hi = hi + y[1]
            return (_lo(lo), _hi(hi))

        return addn

    def _mul(self, e):
        coeff = sp.S.One
        num, den = [], []
        for x in e.args:
            if x.is_Number:
                coeff = coeff * x
            elif x.is_Pow and x.exp.is_Number and x.exp.is_negative and x.exp.is_finite:
                den.append(self.compile(sp.Pow(x.base, -x.exp)))
            else:
                num.append(self.compile(x))
        cont = self.cont
        cf = None  # coefficient handler
        if coeff != 1:
            if coeff == -1:
                cf = _negi
            else:
                try:
                    cv = self.compile(coeff)(None)
                except Undefined as ex:
                    return _raiser(str(ex))
                if cv[0] == cv[1]:
                    c = cv[0]
                    if c == ZERO:
                        cf = lambda x: (ZERO, ZERO)
                    else:
                        cf = lambda x: _scale(c, x)
                else:
                    cf = lambda x: _mul(cv, x)

        def numer(a):
            if not num:
                return _UNIT
            r = num[0](a)
            for g in num[1:]:
                r = _mul(r, g(a))
            return r

        if len(num) == 2 and cf is None:
            n1, n2 = num

            def numer(a):
                return _mul(n1(a), n2(a))

        if den:
            d0, drest = den[0], den[1:]

            def mul_div(a):
                n = numer(a)
                if cf is not None:
                    n = cf(n)
                d = d0(a)
                for g in drest:
                    d = _mul(d, g(a))
                return _div(n, d, cont, e)

            return mul_div
        if cf is None:
            return numer
        if len(num) == 1:
            n1 = num[0]
            return lambda a: cf(n1(a))
        return lambda a: cf(numer(a))

    def _pow(self, e):
        base, ex = e.base, e.exp
        cont = self.cont
        fb = self.compile(base)
        if ex.is_Float and ex.is_finite:
            ex = sp.Rational(ex)
        if ex.is_Integer:
            n = int(ex)
            if n == 0:
                return lambda a: (fb(a), _UNIT)[1]
            if n == 1:
                return fb
            if n > 0:
                return lambda a: _ipow(fb(a), n)
            m = -n
            if m == 1:
                return lambda a: _div(_UNIT, fb(a), cont, e)
            return lambda a: _div(_UNIT, _ipow(fb(a), m), cont, e)
        if ex.is_Rational and int(ex.q) <= 1024:
            p, q = int(ex.p), int(ex.q)

            def rpow(a):
                b = fb(a)
                if not b[0] >= ZERO:
                    raise _undef(e, "non-integer power of a possibly negative base")
                r = (_root_ep(b[0], q, True), _root_ep(b[1], q, False))
                if p == 1:
                    return r
                if p > 0:
                    return _ipow(r, p)
                if p == -1:
                    return _div(_UNIT, r, cont, e)
                return _div(_UNIT, _ipow(r, -p), cont, e)

            return rpow
        fx = self.compile(ex)
        if not ex.free_symbols:
            # constant real exponent
            def cpow(a):
                c = fx(a)
                b = fb(a)
                return _powc(b, c, cont, e)

            return cpow

        def gpow(a):
            b = fb(a)
            if not b[0] > ZERO:
                raise _undef(e, "power with symbolic exponent needs a strictly positive base")
            return _exp_i(_mul(fx(a), _log_i(b, e)))

        return gpow

    def _piecewise(self, e):
        pairs = [(self.compile(pc.expr), self.compile_cond(pc.cond)) for pc in e.args]
        if self.cont:
            def pw_cont(a):
                for fe, fc in pairs:
                    v = fc(a)
                    if v is False:
                        continue
                    if v is True:
                        return fe(a)
                    raise _undef(e, "Piecewise branch not decided on the whole box (not provably continuous)")
                raise _undef(e, "Piecewise: no condition holds")

            return pw_cont

        # Branch i is only active where cond_i holds and cond_0..cond_{i-1} fail;
        # simple bounds "symbol op constant" from these are used to narrow the
        # box on which an undecided branch is evaluated (a closed superset of
        # the points where it is active, so the hull stays sound).
        narrows = []
        previous = []
        for pc in e.args:
            cons = self._simple_bounds(pc.cond, True) + previous
            narrows.append(cons)
            previous = previous + self._simple_bounds(pc.cond, False)

        def pw_range(a):
            lo = hi = None
            for (fe, fc), cons in zip(pairs, narrows):
                v = fc(a)
                if v is False:
                    continue
                if cons:
                    b = _narrow(a, cons)
                    if b is None:  # branch provably inactive on the box
                        continue
                    r = fe(b)
                else:
                    r = fe(a)
                if lo is None:
                    lo, hi = r
                else:
                    if r[0] < lo:
                        lo = r[0]
                    if r[1] > hi:
                        hi = r[1]
                if v is True:
                    return (lo, hi)
            raise _undef(e, "Piecewise: no condition provably holds (may be undefined) on part of the box")

        return pw_range

    def _simple_bounds(self, c, positive):
        """Bounds (index, kind, constant_fn) implied by ``c`` (if positive) or by
        ``not c``; kind 'ge': sym >= const, 'le': sym <= const, 'eq': both.
        Only conditions of the form Symbol op constant (and And / Or of them)
        are used; anything else implies nothing (returns [])."""
        if isinstance(c, sp.core.relational.Relational):
            op = c.rel_op
            if c.lhs.is_Symbol and c.lhs in self.index and not c.rhs.free_symbols:
                sym, k = c.lhs, c.rhs
            elif c.rhs.is_Symbol and c.rhs in self.index and not c.lhs.free_symbols:
                sym, k = c.rhs, c.lhs
                op = {">": "<", ">=": "<=", "<": ">", "<=": ">=", "==": "==", "!=": "!="}[op]
            else:
                return []
            if not isinstance(k, sp.Expr):
                return []
            kind = {">": "ge", ">=": "ge", "<": "le", "<=": "le", "==": "eq"}.get(op)
            if not positive:
                kind = {"ge": "le", "le": "ge"}.get(kind)  # not(s > c) => s <= c, etc.
                if op == "!=":
                    kind = "eq"
            if kind is None:
                return []
            return [(self.index[sym], kind, self.compile(k))]
        if positive and isinstance(c, sp.And) or (not positive) and isinstance(c, sp.Or):
            out = []
            for x in c.args:
                out += self._simple_bounds(x, positive)
            return out
        if isinstance(c, sp.Not):
            return self._simple_bounds(c.args[0], not positive)
        return []

    # -- conditions ------------------------------------------------------
    def compile_cond(self, c):
        f = self.cmemo.get(c)
        if f is None:
            f = self._cond(c)
            self.cmemo[c] = f
        return f

    def _cond(self, c):
        if c is sp.true:
            return lambda a: True
        if c is sp.false:
            return lambda a: False
        if isinstance(c, sp.core.relational.Relational):
            op = c.rel_op
            fl, fr = self.compile(c.lhs), self.compile(c.rhs)

            def d(a):
                return _sub(fl(a), fr(a))

            if op == ">":
                def rel(a):
                    lo, hi = d(a)
                    return True if lo > ZERO else (False if hi <= ZERO else None)
            elif op == ">=":
                def rel(a):
                    lo, hi = d(a)
                    return True if lo >= ZERO else (False if hi < ZERO else None)
            elif op == "<":
                def rel(a):
                    lo, hi = d(a)
                    return True if hi < ZERO else (False if lo >= ZERO else None)
            elif op == "<=":
                def rel(a):
                    lo, hi = d(a)
                    return True if hi <= ZERO else (False if lo > ZERO else None)
            elif op == "==":
                def rel(a):
                    lo, hi = d(a)
                    if lo == ZERO and hi == ZERO:
                        return True
                    return False if (lo > ZERO or hi < ZERO) else None
            elif op == "!=":
                def rel(a):
                    lo, hi = d(a)
                    if lo == ZERO and hi == ZERO:
                        return False
                    return True if (lo > ZERO or hi < ZERO) else None
            else:
                return _raiser(f"unsupported relation {op}: {_short(c)}")
            return rel
        if isinstance(c, sp.And):
            fs = [self.compile_cond(x) for x in c.args]

            def and_(a):
                res = True
                for g in fs:
                    v = g(a)
                    if v is False:
                        return False
                    if v is None:
                        res = None
                return res

            return and_
        if isinstance(c, sp.Or):
            fs = [self.compile_cond(x) for x in c.args]

            def or_(a):
                res = False
                for g in fs:
                    v = g(a)
                    if v is True:
                        return True
                    if v is None:
                        res = None
                return res

            return or_
        if isinstance(c, sp.Not):
            g = self.compile_cond(c.args[0])

            def not_(a):
                v = g(a)
                return None if v is None else (not v)

            return not_
        return _raiser(f"unsupported condition {type(c).__name__}: {_short(c)}")


def _powc(b, c, cont, e):
    """b**c for a constant real exponent enclosed by c (not an integer)."""
    if c[0] > ZERO:
        if not b[0] >= ZERO:
            raise _undef(e, "non-integer power of a possibly negative base")
        cb = c[0] if c[0] == c[1] else c[0].union(c[1])
        bl, bh = b
        lo = ZERO if bl == ZERO else _lo((cb * bl.log()).exp())
        if bh is PINF:
            hi = PINF
        elif bh == ZERO:
            hi = ZERO
        else:
            hi = _hi((cb * bh.log()).exp())
        return (lo, hi)
    if c[1] < ZERO:
        return _div(_UNIT, _powc(b, _negi(c), cont, e), cont, e)
    if not b[0] > ZERO:
        raise _undef(e, "power with exponent of unknown sign needs a strictly positive base")
    return _exp_i(_mul(c, _log_i(b, e)))


# -- elementary function handlers: h(compiler, expr, *arg_fns) -> closure ------


def _h1(fn):
    """Handler for a one-argument function given as an interval map fn(x, e, cont)."""

    def h(comp, e, f, *rest):
        if rest:
            return _raiser(f"{type(e).__name__} with {1 + len(rest)} arguments unsupported: {_short(e)}")
        cont = comp.cont
        return lambda a: fn(f(a), e, cont)

    return h


def _pi_half_lo():
    return _lo(arb.pi() / 2)


def _pi_half_hi():
    return _hi(arb.pi() / 2)


def _mpi_half_lo():
    return _lo(-arb.pi() / 2)


def _two():
    return arb(2)


def _f_exp(x, e, cont):
    return _exp_i(x)


def _f_log(x, e, cont):
    return _log_i(x, e)


def _f_sin(x, e, cont):
    return _sin_i(x)


def _f_cos(x, e, cont):
    return _cos_i(x)


def _f_tan(x, e, cont):
    return _tan_i(x, e)


def _f_sinh(x, e, cont):
    return _mono(x, arb.sinh, _const_ninf, _const_pinf)


def _f_cosh(x, e, cont):
    return _cosh_i(x)


def _clamp1(r):
    lo, hi = r
    if lo < MONE:
        lo = MONE
    if hi > ONE:
        hi = ONE
    return (lo, hi)


def _f_tanh(x, e, cont):
    return _clamp1(_mono(x, arb.tanh, _const_mone, _const_one))


def _f_asinh(x, e, cont):
    return _mono(x, arb.asinh, _const_ninf, _const_pinf)


def _f_acosh(x, e, cont):
    if not x[0] >= ONE:
        raise _undef(e, "acosh of an interval not contained in [1, oo)")
    return _mono(x, arb.acosh, _const_ninf, _const_pinf)


def _f_atanh(x, e, cont):
    if not (x[0] > MONE and x[1] < ONE):
        raise _undef(e, "atanh of an interval not contained in (-1, 1)")
    return _mono(x, arb.atanh, _const_ninf, _const_pinf)


def _f_atan(x, e, cont):
    return _mono(x, arb.atan, _mpi_half_lo, _pi_half_hi)


def _f_asin(x, e, cont):
    if not (x[0] >= MONE and x[1] <= ONE):
        raise _undef(e, "asin of an interval not contained in [-1, 1]")
    return _mono(x, arb.asin, _const_ninf, _const_pinf)


def _f_acos(x, e, cont):
    if not (x[0] >= MONE and x[1] <= ONE):
        raise _undef(e, "acos of an interval not contained in [-1, 1]")
    return (_lo(x[1].acos()), _hi(x[0].acos()))


def _f_erf(x, e, cont):
    return _clamp1(_mono(x, arb.erf, _const_mone, _const_one))


def _f_erfc(x, e, cont):
    lo = ZERO if x[1] is PINF else _lo(x[1].erfc())
    hi = arb(2) if x[0] is NINF else _hi(x[0].erfc())
    if lo < ZERO:
        lo = ZERO
    return (lo, hi)


def _f_abs(x, e, cont):
    return _abs_i(x)


def _f_sign(x, e, cont):
    lo, hi = x
    if lo > ZERO:
        return _UNIT
    if hi < ZERO:
        return (MONE, MONE)
    if lo == ZERO and hi == ZERO:
        return (ZERO, ZERO)
    if cont:
        raise _undef(e, "sign of an interval containing 0 (jump)")
    if lo == ZERO:
        return (ZERO, ONE)
    if hi == ZERO:
        return (MONE, ZERO)
    return _PM1


def _floorlike(fl):
    def f(x, e, cont):
        lo, hi = x
        a = lo if lo is NINF else (lo.floor() if fl else lo.ceil())
        b = hi if hi is PINF else (hi.floor() if fl else hi.ceil())
        if cont and not (a == b):
            raise _undef(e, f"{'floor' if fl else 'ceiling'} of an interval containing a jump point")
        return (_lo(a) if a is not NINF else NINF, _hi(b) if b is not PINF else PINF)

    return f


def _h_heaviside(comp, e, f, *rest):
    cont = comp.cont
    if rest:
        fh = rest[0]
    else:
        fh = lambda a: (arb(0.5), arb(0.5))

    def hv(a):
        lo, hi = f(a)
        if lo > ZERO:
            return _UNIT
        if hi < ZERO:
            return (ZERO, ZERO)
        h0 = fh(a)
        if lo == ZERO and hi == ZERO:
            return h0
        if cont:
            raise _undef(e, "Heaviside of an interval containing 0 (jump)")
        r = h0
        if lo < ZERO:
            r = _hull(r, (ZERO, ZERO))
        if hi > ZERO:
            r = _hull(r, _UNIT)
        return r

    return hv


def _h_minmax(is_max):
    def h(comp, e, *fs):
        if is_max:
            def mx(a):
                r = fs[0](a)
                lo, hi = r
                for g in fs[1:]:
                    y = g(a)
                    if y[0] > lo:
                        lo = y[0]
                    if y[1] > hi:
                        hi = y[1]
                return (lo, hi)

            return mx

        def mn(a):
            r = fs[0](a)
            lo, hi = r
            for g in fs[1:]:
                y = g(a)
                if y[0] < lo:
                    lo = y[0]
                if y[1] < hi:
                    hi = y[1]
            return (lo, hi)

        return mn

    return h


def _h_log(comp, e, f, *rest):
    if rest:
        return _raiser(f"log with a base argument unsupported: {_short(e)}")
    return lambda a: _log_i(f(a), e)


_FUNCS = {
    sp.exp: _h1(_f_exp),
    sp.log: _h_log,
    sp.sin: _h1(_f_sin),
    sp.cos: _h1(_f_cos),
    sp.tan: _h1(_f_tan),
    sp.sinh: _h1(_f_sinh),
    sp.cosh: _h1(_f_cosh),
    sp.tanh: _h1(_f_tanh),
    sp.asinh: _h1(_f_asinh),
    sp.acosh: _h1(_f_acosh),
    sp.atanh: _h1(_f_atanh),
    sp.atan: _h1(_f_atan),
    sp.asin: _h1(_f_asin),
    sp.acos: _h1(_f_acos),
    sp.erf: _h1(_f_erf),
    sp.erfc: _h1(_f_erfc),
    sp.Abs: _h1(_f_abs),
    sp.sign: _h1(_f_sign),
    sp.floor: _h1(_floorlike(True)),
    sp.ceiling: _h1(_floorlike(False)),
    sp.Heaviside: _h_heaviside,
    sp.Max: _h_minmax(True),
    sp.Min: _h_minmax(False),
}


# ---------------------------------------------------------------------------
# public entry points
# ---------------------------------------------------------------------------

_MODES = ("range", "continuous")


class IntervalFunction:
    """Compile ``expr`` once (into nested closures); call with one Interval per
    symbol, in the order of ``symbols``."""

    __slots__ = ("expr", "symbols", "mode", "prec", "_fn", "_cont", "_n")

    def __init__(self, expr, symbols, mode="range", prec=128):
        if mode not in _MODES:
            raise ValueError(f"mode must be one of {_MODES}, not {mode!r}")
        expr = sp.sympify(expr)
        symbols = list(symbols)
        index = {}
        for i, s in enumerate(symbols):
            if s in index:
                raise ValueError(f"duplicate symbol {s}")
            index[s] = i
        missing = expr.free_symbols - set(index)
        if missing:
            raise ValueError(f"free symbols {sorted(map(str, missing))} have no box")
        self.expr = expr
        self.symbols = symbols
        self.mode = mode
        self.prec = int(prec)
        self._cont = mode == "continuous"
        self._n = len(symbols)
        old = ctx.prec
        ctx.prec = self.prec
        try:
            self._fn = _Compiler(index, self._cont, expr).compile(expr)
        finally:
            ctx.prec = old

    def __call__(self, *boxes):
        if len(boxes) != self._n:
            raise TypeError(f"expected {self._n} boxes, got {len(boxes)}")
        args = tuple([(b.lo, b.hi) for b in boxes])
        if self._cont:
            for b in boxes:
                if not (b.lo.is_finite() and b.hi.is_finite()):
                    raise Undefined("continuous mode needs a bounded box")
        old = ctx.prec
        ctx.prec = self.prec
        try:
            lo, hi = self._fn(args)
        finally:
            ctx.prec = old
        if self._cont and not (lo.is_finite() and hi.is_finite()):
            raise _undef(self.expr, "unbounded result (not continuous)")
        return Interval._make(lo, hi)


def mean_value_form(fn: IntervalFunction, slope: IntervalFunction, lo, hi, sign: int) -> Interval | None:
    """fn(m) + slope([lo, hi]) ([lo, hi] - m), m the midpoint of the finite
    [lo, hi]: an enclosure of the range of fn there when slope encloses fn'
    on the box (mean value theorem; compile slope in "continuous" mode, so
    that it fails where fn' is undefined).  Near a small extremum of fn it
    loses about the square of the box width, where `fn` loses the width.
    None, without evaluating slope, unless sign*fn(m) > 0 (sign = +-1): a
    caller after that sign on the box has no use for the form then."""
    box = Interval.of(lo, hi)
    m = box.mid()
    at = fn(Interval.point(m))
    if not (at.is_positive() if sign > 0 else at.is_negative()):
        return None
    d = slope(box)
    old = ctx.prec
    ctx.prec = max(fn.prec, slope.prec)
    try:
        c = arb(fmpq(m.numerator, m.denominator))
        p = _mul((d.lo, d.hi), (_lo(box.lo - c), _hi(box.hi - c)))
        return Interval._make(_lo(at.lo + p[0]), _hi(at.hi + p[1]))
    finally:
        ctx.prec = old


def evaluate(expr, env, mode="range", prec=128) -> Interval:
    """Enclosure of ``expr`` over the box ``env`` (dict Symbol -> Interval)."""
    syms = list(env.keys())
    boxes = [b if isinstance(b, Interval) else Interval.point(b, prec) for b in env.values()]
    return IntervalFunction(expr, syms, mode, prec)(*boxes)
