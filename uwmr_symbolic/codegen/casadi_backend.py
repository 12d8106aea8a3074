"""CasADi back-end: the law as a `casadi.Function` of SX expressions.

    control(e1, e2, e3, vr, wr, k1, k2, lam) -> (v, w)

For a radial design it uses the mid-region form g = e2 H(rho) of `law`
(with `if_else` for Piecewise branches and for sin(e3)/e3 at 0), which is
what an optimiser wants: smooth, cheap, exact in the range where a robot's
errors live; below TINY (rho < TINY^2) the leading term of F' at 0 is used,
as in C.  The overflow-safe far region of the C and Python code is not
reproduced: the function is validated (and documented) for
max(|e1|, |e2|) <= FAR (the model's double threshold, at most 1e4) and |e3|, |vr|, |wr|, gains <= 1e3; beyond,
rho or H(rho) may overflow.  A function CasADi lacks (gamma, ...) raises
NotImplementedError naming it."""
from __future__ import annotations

import functools
import math
import operator
from dataclasses import dataclass

import casadi as ca
import sympy as sp
from sympy.codegen.cfunctions import expm1, log1p

from .law import RHO, LawModel, rho_minus_b, split_boundary
from .. import e1 as E1, e2 as E2


@dataclass(frozen=True)
class CasadiConfig:
    """name      the casadi.Function's name;
    sinc_cut  |e3| below which sin(e3)/e3 is its series 1 - e3^2/6 + e3^4/120."""
    name: str = "control"
    sinc_cut: float = 2.0 ** -12


_UNARY = {sp.sin: ca.sin, sp.cos: ca.cos, sp.tan: ca.tan, sp.tanh: ca.tanh, sp.sinh: ca.sinh,
          sp.cosh: ca.cosh, sp.exp: ca.exp, sp.log: ca.log, sp.atan: ca.atan, sp.asin: ca.asin,
          sp.acos: ca.acos, sp.asinh: ca.asinh, sp.acosh: ca.acosh, sp.atanh: ca.atanh, sp.Abs: ca.fabs,
          sp.erf: ca.erf, sp.erfc: lambda x: 1 - ca.erf(x), log1p: ca.log1p, expm1: ca.expm1,
          sp.sign: ca.sign}


def to_casadi(expr: sp.Expr, env: dict):
    """A SymPy expression as a CasADi SX expression (symbols from env)."""
    if expr in env:
        return env[expr]
    if expr.is_Number or isinstance(expr, sp.NumberSymbol):
        return ca.SX(float(expr))
    if isinstance(expr, (sp.Min, sp.Max)):
        fn = ca.fmin if isinstance(expr, sp.Min) else ca.fmax
        out = to_casadi(expr.args[0], env)
        for a in expr.args[1:]:
            out = fn(out, to_casadi(a, env))
        return out
    if isinstance(expr, sp.Add):
        out = 0
        for a in expr.args:
            out = out + to_casadi(a, env)
        return out
    if isinstance(expr, sp.Mul):
        out = 1
        for a in expr.args:
            out = out * to_casadi(a, env)
        return out
    if isinstance(expr, sp.Pow):
        b, e = expr.args
        cb = to_casadi(b, env)
        if e == sp.Rational(1, 2):
            return ca.sqrt(cb)
        if e == -sp.Rational(1, 2):
            return 1 / ca.sqrt(cb)
        if e.is_Integer:
            return cb ** int(e) if e > 0 else 1 / cb ** int(-e)
        return ca.power(cb, to_casadi(e, env))
    if type(expr) in _UNARY:
        return _UNARY[type(expr)](to_casadi(expr.args[0], env))
    if isinstance(expr, sp.Piecewise):
        out = None
        for value, cond in reversed(expr.args):
            v = to_casadi(value, env)
            out = v if out is None or cond == sp.true else ca.if_else(to_casadi(cond, env), v, out)
        return out
    if isinstance(expr, sp.core.relational.Relational):
        a, b = to_casadi(expr.lhs, env), to_casadi(expr.rhs, env)
        return {sp.StrictLessThan: operator.lt, sp.LessThan: operator.le, sp.StrictGreaterThan: operator.gt,
                sp.GreaterThan: operator.ge, sp.Equality: operator.eq, sp.Unequality: operator.ne}[type(expr)](a, b)
    if isinstance(expr, (sp.And, sp.Or)):
        join = ca.logic_and if isinstance(expr, sp.And) else ca.logic_or
        return functools.reduce(join, [to_casadi(c, env) for c in expr.args])
    if isinstance(expr, sp.Not):
        return ca.logic_not(to_casadi(expr.args[0], env))
    raise NotImplementedError(f"no CasADi translation for {expr.func.__name__}")


def casadi_function(model: LawModel, config: CasadiConfig = CasadiConfig()) -> ca.Function:
    names = ["e1", "e2", "e3", "vr", "wr", "k1", "k2", "lam"]
    sym = {n: ca.SX.sym(n) for n in names}
    e1, e2, e3, vr, wr, k1, k2, lam = (sym[n] for n in names)
    env = {E1: e1, E2: e2}
    if model.radial:
        rho = e1 * e1 + e2 * e2
        env[RHO] = rho
        # branches in increasing rho: the first whose upper end the exact rho has not passed, its formula
        # read at the rounded rho brought into the branch's ends (as the C code: `c_backend._chain`)
        ends = [-math.inf, *(float(br.hi) for br in model.mid[:-1]), math.inf]
        H = None
        for i in reversed(range(len(model.mid))):
            br = model.mid[i]
            inside = rho if len(model.mid) == 1 else ca.fmin(ca.fmax(rho, ends[i]), ends[i + 1])
            value = to_casadi(br.expr, {**env, RHO: inside})
            if H is None:
                H = value
            else:
                bh, bl = split_boundary(br.hi)      # the exact rho's side (CasADi rewrites (p1 + p2) - p1: fmax)
                d = rho_minus_b(e1, e2, bh, float(bl), opaque=lambda s: ca.fmax(s, -1.7976931348623157e308))
                H = ca.if_else(d <= 0 if br.hi_closed else d < 0, value, H)
        g = e2 * H
        if model.tiny is not None:
            # F'(s) ~ a s^j near 0: H = a s^(j-1) where rho underflows (0/0 otherwise): a power of rho
            # for odd j, else of s = m sqrt((e1/m)^2 + (e2/m)^2), m = max(|e1|, |e2|), which does not underflow
            a, j = model.tiny
            if j % 2 == 1:
                power = rho ** ((j - 1) // 2)
            else:
                m = ca.fmax(ca.fabs(e1), ca.fabs(e2))
                unit = ca.if_else(m == 0, 1, m)
                power = (m * ca.sqrt((e1 / unit) ** 2 + (e2 / unit) ** 2)) ** (j - 1)
            g = ca.if_else(rho < model.thresholds["double"][0] ** 2, e2 * float(a) * power, g)
    else:
        g = to_casadi(model.general, env)
    z = e3 * e3
    safe = ca.if_else(e3 == 0, 1, e3)
    sinc = ca.if_else(ca.fabs(e3) < config.sinc_cut, 1 - z * (1.0 / 6 - z / 120), ca.sin(safe) / safe)
    v = vr * ca.cos(e3) + k1 * ca.tanh(e1)
    w = wr + lam * vr * g * sinc + k2 * ca.tanh(e3)
    return ca.Function(config.name, [sym[n] for n in names], [v, w], names, ["v", "w"])
