"""Python back-end: `<stem>.py`, importing numpy only.

The module has a fast path (the plain mid-region form of `law`, in three
reused work arrays, after a range test made of a few reductions; any array
with an element outside the range goes to the careful path) and a careful
path that mirrors the C code element by element (regions, branches, guarded
product, status codes)."""
from __future__ import annotations

from dataclasses import dataclass

import sympy as sp

from .law import LT, RHO, SINC_SHIFT, ST, THRESHOLDS, LawModel, split_boundary
from .printers import PyPrinter, cse_lines, double_literal
from .. import e1 as E1, e2 as E2
from ..univariate import T


@dataclass(frozen=True)
class PythonConfig:
    """The Python back-end's choices.

    tiny, far  region switches on m = max(|e1|, |e2|) (as the C double variant).
    sinc_cut   |e3| below which sin(e3)/e3 is replaced by 1 - e3^2/6 + e3^4/120."""
    tiny: float = THRESHOLDS["double"][0]
    far: float = THRESHOLDS["double"][1]
    sinc_cut: float = 2.0 ** -12


def _function(name, arg, expr, printer):
    lines, value = cse_lines(expr, printer, lambda n, c: f"{n} = {c}")
    if expr.has(ST):     # s = 1/t kept finite, as in C
        lines.insert(0, "st = numpy.minimum(1.0 / tt, 1.7976931348623157e+308)")
    first = arg.split(",")[0]
    tail = f" + 0.0 * {first}" if not expr.free_symbols else ""   # keep the array shape
    return [f"def {name}({arg}):", *[f"    {ln}" for ln in lines], f"    return {value}{tail}"]


def _masks(branches, var):
    """[(condition code for branch i given earlier ones are excluded)]; in
    rho the exact rho's branch (`_rho_cmp`, as the C code's `rho_cmp`)."""
    out = []
    for i, br in enumerate(branches):
        if i == len(branches) - 1:
            out.append(None)
        elif var == "rho":
            bh, bl = split_boundary(br.hi)
            op = "<=" if br.hi_closed else "<"
            # rho - bh decides beyond 2^-50 bh (see `_rho_cmp`); all exact when that is not a normal double
            near = double_literal(bh * 2.0 ** -50) if bh >= 2.0 ** -960 else "numpy.inf"
            out.append(f"_rho_cmp(rho, e1, e2, {double_literal(bh)}, {double_literal(float(bl))}, {near}) {op} 0")
        else:
            out.append(f"{var} {'<=' if br.hi_closed else '<'} {double_literal(br.hi)}")
    return out


def render(env, model: LawModel, context: dict, config: PythonConfig | None = None) -> dict[str, str]:
    if config is None:
        config = PythonConfig(*model.thresholds["double"])
    pr = PyPrinter({RHO: "rho", T: "tt", LT: "lt", ST: "st", E1: "e1", E2: "e2"})
    functions = []
    ctx = dict(context, cfg=config, radial=model.radial,
               tiny_lit=double_literal(config.tiny), far_lit=double_literal(config.far),
               tiny2=double_literal(config.tiny ** 2), far2=double_literal(config.far ** 2),
               cut=double_literal(config.sinc_cut), sinc_shift=SINC_SHIFT["double"],
               sinc_up=double_literal(2.0 ** SINC_SHIFT["double"]))
    if not model.radial:
        functions += _function("_g_general", "e1, e2", model.general, pr)
        ctx.update(functions=functions, needs_scipy=any("scipy." in ln for ln in functions))
        return {f"{model.stem}.py": env.get_template("python_module.py.j2").render(ctx)}
    mid = []
    for i, (br, cond) in enumerate(zip(model.mid, _masks(model.mid, "rho"))):
        functions += _function(f"_H{i}", "rho", br.expr, pr) + [""]
        # the rounded rho brought into the branch's ends (see `c_backend._chain`)
        ends = [double_literal(split_boundary(b.hi)[0]) if b is not None else "None"
                for b in (model.mid[i - 1] if i else None, br if cond is not None else None)]
        mid.append(dict(fn=f"_H{i}", cond=cond, ends=ends))
    far = []
    uses_lt = any(br.expr.has(LT) for br in model.far)
    for i, (br, cond) in enumerate(zip(model.far, _masks(model.far, "tt"))):
        functions += _function(f"_D{i}", "tt, lt" if uses_lt else "tt", br.expr, pr) + [""]
        far.append(dict(fn=f"_D{i}", cond=cond, k=br.k))
    tiny = None
    if model.tiny is not None:
        tiny = dict(a=double_literal(model.tiny[0]), j=model.tiny[1], text=sp.sstr(model.tiny[0]))
    h_const = None
    if len(model.mid) == 1 and not model.mid[0].expr.free_symbols:
        h_const = double_literal(model.mid[0].expr)
    ctx.update(functions=functions, mid=mid, far=far, tiny_term=tiny, h_const=h_const,
               needs_scipy=any("scipy." in ln for ln in functions), uses_lt=uses_lt)
    return {f"{model.stem}.py": env.get_template("python_module.py.j2").render(ctx)}


def errors_source() -> str:
    """Errors (7) and the Tracker exactly as in every generated module, as
    a module of their own (numpy only): for the simulation of a controller
    that has no generated module (the baseline (38))."""
    from . import _env
    return "import numpy\n\n\n" + _env().get_template("python_tracking.py.j2").render()
