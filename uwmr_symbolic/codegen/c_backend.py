"""C99 back-end: `<stem>.h` and `<stem>.c` with a double and a float variant
(law (9), errors (7), the heading tracker and `_step`), the example loop
`example_main.c` and a `CMakeLists.txt` (static library `uwmr::<stem>`).

The law's structure (regions, branches, guarded product) comes from
`law.LawModel`; this module only prints it.  Both variants share one
template and differ by the `CConfig` below."""
from __future__ import annotations

import dataclasses
import hashlib
import math
import re
from dataclasses import dataclass

import sympy as sp

from .law import LT, RHO, SIN_MIN, SINC_SHIFT, ST, THRESHOLDS, LawModel, mid_h_bounds, split_boundary
from .printers import CPrinter, Unsupported, cse_lines
from .. import e1 as E1, e2 as E2
from ..univariate import T


@dataclass(frozen=True)
class CConfig:
    """One precision of the C back-end.

    precision  "double" or "float": the C type and the libm family
               (sin/sinf ...), literal suffix and limits (DBL_*/FLT_*).
    suffix     appended to public names: "" for double, "_f32" for float.
    tiny, far  region switches on m = max(|e1|, |e2|) (see `law`).
    sinc_cut   |e3| below which sin(e3)/e3 = 1 - e3^2/6 + e3^4/120
               (truncation error below e3^6/5040, far under one ulp)."""
    precision: str
    suffix: str
    tiny: float
    far: float
    sinc_cut: float
    fast: "FastRange"

    @property
    def ctype(self) -> str:
        return "float" if self.precision == "float" else "double"

    @property
    def fn(self) -> str:
        return "f" if self.precision == "float" else ""

    @property
    def limit(self) -> str:
        return "FLT" if self.precision == "float" else "DBL"

    def printer(self, names=None) -> CPrinter:
        return CPrinter(self.precision, names)

    def lit(self, value) -> str:
        return self.printer().literal(value)


@dataclass(frozen=True)
class FastRange:
    """The one range test of the fast path (see `fast_lines`).

    e3_max  |e3| above which the careful path is taken: below it |sin(e3)|
            stays above smin (doubles: |x - k pi| > 2^-61 for every double,
            Kahan/McDonald; floats in [2^-6, 2^10]: min |sin| = 2^-26.8, by
            enumeration), so sinc >= smin / e3_max.
    q_lo    lower bound of |lam vr H|: q_lo * smin / e3_max is still normal,
            so no partial product underflows before the last factor e2.
    q_hi    upper bound of |lam vr H|: q_hi * FAR is far below the type's max.
    big     bound of |vr| + |wr| + k1 + k2: with |lam vr g sinc| <= q_hi FAR
            neither v nor w can overflow.  (With proved bounds of H, lam
            joins the sum and big is lowered to sqrt(upper bound of |lam vr|).)
    lv_lo_max  the a-priori form of the q test (bounds on lam vr from proved
            bounds of H) is used only when its lower bound on |lam vr| is at
            most this; otherwise q is tested after H is computed."""
    e3_max: float
    q_lo: float
    q_hi: float
    big: float
    lv_lo_max: float


DOUBLE = CConfig("double", "", *THRESHOLDS["double"], sinc_cut=2.0 ** -12,
                 fast=FastRange(e3_max=2.0 ** 20, q_lo=2.0 ** -930, q_hi=2.0 ** 980, big=2.0 ** 1020,
                               lv_lo_max=2.0 ** -100))
FLOAT = CConfig("float", "_f32", *THRESHOLDS["float"], sinc_cut=2.0 ** -6,
                fast=FastRange(e3_max=2.0 ** 10, q_lo=2.0 ** -86, q_hi=2.0 ** 86, big=2.0 ** 125,
                              lv_lo_max=2.0 ** -24))


def c_identifier(stem: str) -> str:
    """The C name of a design's functions and (upper-cased) macros: the stem
    itself when it is a lower-case C identifier; otherwise the stem made
    one, plus 8 hex digits of its SHA-256, so that `my-design`, `my design`
    and `My_design` do not clash when linked into one program."""
    ident = re.sub(r"[^0-9A-Za-z_]", "_", stem)
    ident = ident if not ident[:1].isdigit() else "d_" + ident
    return ident if ident == stem.lower() == stem else f"{ident}_{hashlib.sha256(stem.encode()).hexdigest()[:8]}"


def _indent(lines, n):
    pad = " " * n
    return [pad + ln if ln else ln for ln in lines]


def _split_constant(value, cfg) -> tuple[str, str]:
    """(hi, lo) literals with hi + lo = value to twice the type's precision (`law.split_boundary`)."""
    hi, lo = split_boundary(value, cfg.precision)
    return cfg.lit(sp.Rational(hi)), cfg.lit(lo)


def _chain(branches, var, cfg, body):
    """if/else chain over branches (sorted by increasing var); `body(branch)`
    gives the lines of one branch.  A branch in rho is chosen by `rho_cmp`,
    the sign of e1^2 + e2^2 - b without the rounding of rho."""
    if len(branches) == 1:
        return ["{", *_indent(body(branches[0]), 4), "}"]
    ends = [_split_constant(b.hi, cfg) for b in branches[:-1]] if var == "rho" else []
    out = []
    for i, br in enumerate(branches):
        clamp = []
        if var == "rho":    # the branch is the exact rho's, but its formula reads the rounded rho, which may lie
            # an ulp or two beyond the branch's ends (then a root of b - rho below b would not be real): brought back
            value = "rho" if i == len(branches) - 1 else f"rho > {ends[i][0]} ? {ends[i][0]} : rho"
            if i:
                value = f"rho < {ends[i - 1][0]} ? {ends[i - 1][0]} : " + (f"({value})" if value != "rho" else value)
            clamp = [f"rho = {value};"]
        if i < len(branches) - 1:
            op = "<=" if br.hi_closed else "<"
            if var == "rho":
                test = f"rho_cmp{cfg.suffix}(e1, e2, {ends[i][0]}, {ends[i][1]}) {op} 0"
            else:
                test = f"{var} {op} {cfg.lit(br.hi)}"
            head = ("if" if i == 0 else "} else if") + f" ({test}) {{"
        else:
            head = "} else {"
        out.append(head)
        out.extend(_indent(clamp + body(br), 4))
    out.append("}")
    return out


def _product(cfg, factors, name):
    """Multiply the factors in order, times 2^shift (shift != 0 only for a
    sin(e3)/e3 below the normal range, passed scaled: see the template's
    `careful`); if a partial product leaves the normal range (or a factor is
    0), or shift != 0, call the exponent-splitting `prod_slow`."""
    n = len(factors)
    t = cfg.ctype
    lines = [f"const {t} p1 = {factors[0]} * {factors[1]};"]
    for i in range(2, n):
        lines.append(f"const {t} p{i} = p{i - 1} * {factors[i]};")
    checks = " & ".join(["(shift == 0)"] + [f"(fabs{cfg.fn}(p{i}) >= {cfg.limit}_MIN)" for i in range(1, n)])
    lines += [f"if ({checks} & (fabs{cfg.fn}(p{n - 1}) <= {cfg.limit}_MAX)) {{",
              f"    return p{n - 1};",
              "} else {",
              f"    const {t} {name}[{n}] = {{{', '.join(factors)}}};",
              f"    return prod_slow{cfg.suffix}({name}, {n}, shift);",
              "}"]
    return lines


def kf_cap(model: LawModel, cfg: CConfig) -> str | None:
    """The header's macro of KF when it is a certified upper bound of kf for a
    verified design: the generated code clamps lam vr g sinc to lam |vr| KF
    (bound (10)); None otherwise (no clamp)."""
    if model.bound_kf is None:
        return None
    return f"UWMR_{c_identifier(model.stem).upper()}_KF" + ("_F32" if cfg.precision == "float" else "")


def gterm_lines(model: LawModel, cfg: CConfig, names) -> list[str]:
    """Body of the static function returning lam*vr*g*sinc."""
    pr = cfg.printer(names)
    decl = lambda n, c: f"const {cfg.ctype} {n} = {c};"   # noqa: E731
    t = cfg.ctype
    if not model.radial:
        lines, g = cse_lines(model.general, pr, decl)
        unused = [f"(void){n};" for x, n in ((E1, "e1"), (E2, "e2")) if x not in model.general.free_symbols]
        return [*unused, *lines, f"const {t} g = {g};", *_product(cfg, ["lam", "vr", "sinc", "g"], "x")]

    out = [f"const {t} a1 = fabs{cfg.fn}(e1), a2 = fabs{cfg.fn}(e2);",
           f"const {t} m = a1 > a2 ? a1 : a2;"]
    lower = f"m >= {cfg.lit(cfg.tiny)}" if model.tiny is not None else "m > 0"
    out.append(f"if ({lower} && m <= {cfg.lit(cfg.far)}) {{")
    uses_rho = len(model.mid) > 1 or any(br.expr.has(RHO) for br in model.mid)
    mid = [f"{'const ' * (len(model.mid) == 1)}{t} rho = e1 * e1 + e2 * e2;"] if uses_rho else []

    def mid_body(br):
        lines, h = cse_lines(br.expr, pr, decl)
        return [*lines, f"const {t} H = {h};", *_product(cfg, ["lam", "vr", "sinc", "e2", "H"], "x")]

    mid += _chain(model.mid, "rho", cfg, mid_body)
    out += _indent(mid, 4) + ["}",
                              f"if (m == {cfg.lit(0)}) {{",
                              f"    return {cfg.lit(0)};   /* g(0, 0) = F'(0+) * 0 */",
                              "}",
                              "{"]
    rest = [f"const {t} q = (a1 > a2 ? a2 : a1) / m;",
            f"const {t} r = sqrt{cfg.fn}({cfg.lit(1)} + q * q);   /* s = m r, no overflow */",
            f"const {t} ir = {cfg.lit(1)} / r;"]
    if model.tiny is not None:
        a, j = model.tiny
        rest += [f"if (m < {cfg.lit(cfg.tiny)}) {{",
                 f"    /* F'(s) = {sp.sstr(a)} s^{j} (1 + O(s^2)) with s^{j} = m^{j} r^{j} */",
                 f"    const {t} c = (e2 / m) * ir;   /* e2 / s: no underflow while m < TINY */",
                 *_indent(_product(cfg, ["lam", "vr", "sinc", "c", cfg.lit(a)] + ["m"] * j + ["r"] * j, "x"), 4),
                 "}"]
    rest.append("{")
    far = [f"const {t} im = {cfg.lit(1)} / m;   /* e2/s = e2 im ir, as separate factors */"]
    if len(model.far) > 1 or any(br.expr.has(T, ST) for br in model.far):
        far.append(f"const {t} tt = im * ir;   /* t = 1/s */")
    if any(br.expr.has(ST) for br in model.far):
        far.append(f"const {t} st = fmin{cfg.fn}({cfg.lit(1)} / tt, {cfg.limit}_MAX);   /* s = 1/t, kept finite */")
    if any(br.expr.has(LT) for br in model.far):
        far.append(f"const {t} lt = -(log{cfg.fn}(m) + {cfg.lit(sp.Rational(1, 2))} * log1p{cfg.fn}(q * q));"
                   "   /* log t = -log s, s = m r */")

    def far_body(br):
        lines, d = cse_lines(br.expr, pr, decl)
        comment = f"/* F'(1/t) = t^{br.k} D(t) */" if br.k else "/* F'(1/t) = D(t) */"
        return [comment, *lines, f"const {t} D = {d};",
                *_product(cfg, ["lam", "vr", "sinc", "e2", "im", "ir", "D"]
                          + (["im", "ir"] * br.k if br.k > 0 else ["m", "r"] * -br.k), "x")]

    far += _chain(model.far, "tt", cfg, far_body)
    rest += _indent(far, 4) + ["}"]
    out += _indent(rest, 4) + ["}"]
    return out


def fast_lines(model: LawModel, cfg: CConfig, names) -> list[str] | None:
    """Body of the fast path, or None (no radial mid-region form).

    One range test on the inputs, before any libm call: |e1| + |e2| within the
    mid region [2 TINY, FAR] (so m = max(|e1|, |e2|) is in [TINY, FAR]),
    CUT <= |e3| <= e3_max, gains >= 0, lam vr a normal number and
    |vr| + |wr| + k1 + k2 <= big.  Every comparison is false for a NaN, and an
    infinite input fails one of them, so the test also rejects non-finite
    input.  q = lam vr H must lie in [q_lo, q_hi]: when H's range over the
    fast region is proved (`law.mid_h_bounds`, widened by 2 for rounding) this
    is a test of lam vr in the range test itself, so that everything is
    decided before the first libm call; otherwise q is tested once H is
    computed.  Then the plain law: sin(e3)/e3, lam vr g sinc = (q sinc) e2
    where only the last product may underflow (an absolute error below the
    smallest normal number times 2^-53) and nothing can overflow.
    These are the careful path's mid-region formulas without its guards, which
    this test makes unnecessary; anything else goes to the careful path.
    tanh is `tanh_fast` (template): -t/(t + 2), t = expm1(-2|x|), with the
    sign of x, which is glibc's own formula for |x| < 1 and accurate to 3 ulp
    everywhere, with one libm call instead of two."""
    if not model.radial or not model.mid:
        return None
    t, fn, f = cfg.ctype, cfg.fn, cfg.fast
    pr = cfg.printer(names)
    decl = lambda n, c: f"const {t} {n} = {c};"   # noqa: E731
    lit = cfg.lit
    tiny_normal = 2.0 ** (-126 if cfg.precision == "float" else -1022)
    lv_test = f"(fabs{fn}(lv) >= {cfg.limit}_MIN)"
    bounds = mid_h_bounds(model, cfg.tiny ** 2 / 2, 2 * cfg.far ** 2)
    a_priori, big, gains_sum = False, f.big, "k1 + k2"
    h_lo, h_hi = (bounds[0] / 2, bounds[1] * 2) if bounds is not None else (0.0, 0.0)
    ratios = (max(tiny_normal, f.q_lo / h_lo), f.q_hi / h_hi) if h_lo > 0 else (0.0, 0.0)
    if all(0 < r < 2.0 ** 1000 for r in ratios):    # (H's range far from 1: no a priori test of lam vr)
        lv_lo = 2.0 ** math.ceil(math.log2(ratios[0]))
        lv_hi = 2.0 ** math.floor(math.log2(ratios[1]))
        if lv_lo <= f.lv_lo_max:
            a_priori = True
            lv_test = f"(fabs{fn}(lv) >= {lit(lv_lo)})"
            # |lam vr| <= lv_hi follows from lam + |vr| <= sqrt(lv_hi): lam joins the sum test
            big = min(big, 2.0 ** math.floor(math.log2(lv_hi) / 2))
            gains_sum = "k1 + k2 + lam"
    out = [f"const {t} k1 = gains->k1, k2 = gains->k2, lam = gains->lam;",
           f"const {t} a1 = fabs{fn}(e1), a2 = fabs{fn}(e2), a3 = fabs{fn}(e3), s12 = a1 + a2;",
           f"const {t} kmin = k1 < k2 ? (k1 < lam ? k1 : lam) : (k2 < lam ? k2 : lam);",
           f"const {t} lv = lam * vr;",
           f"if ((s12 >= {lit(2 * cfg.tiny)}) & (s12 <= {lit(cfg.far)}) & (a3 >= {lit(cfg.sinc_cut)})"
           f" & (a3 <= {lit(f.e3_max)}) & (kmin >= {lit(0)})",
           f"    & {lv_test} & (fabs{fn}(vr) + fabs{fn}(wr) + {gains_sum} <= {lit(big)})) {{"]
    body = []
    if len(model.mid) > 1 or any(br.expr.has(RHO) for br in model.mid):
        body.append(f"{'const ' * (len(model.mid) == 1)}{t} rho = e1 * e1 + e2 * e2;")
    body.append(f"{t} H;")

    tanh_call = re.compile(rf"\btanh{fn}\(")

    def h_body(br):
        lines, h = cse_lines(br.expr, pr, decl)
        return [tanh_call.sub(f"tanh_fast{cfg.suffix}(", ln) for ln in [*lines, f"H = {h};"]]

    body += _chain(model.mid, "rho", cfg, h_body)
    cap = kf_cap(model, cfg)
    term = "(q * sinc) * e2" if cap is None else \
        f"clamp{cfg.suffix}((q * sinc) * e2, cap)"    # bound (10): see gterm in the template
    law = [f"const {t} sinc = sin{fn}(e3) / e3;",
           *([] if cap is None else [f"const {t} cap = fabs{fn}(lv) * {cap};"]),
           f"*v = vr * cos{fn}(e3) + k1 * tanh_fast{cfg.suffix}(e1);",
           f"*w = wr + {term} + k2 * tanh_fast{cfg.suffix}(e3);",
           "return UWMR_OK;"]
    if a_priori:
        h_text = f"{h_lo:.3g} <= |H| <= {h_hi:.3g}"
        body += ["{",
                 f"    const {t} q = lv * H;   /* {h_text} here: q_lo <= |q| <= q_hi */",
                 *_indent(law, 4),
                 "}"]
    else:
        body += ["{",
                 f"    const {t} q = lv * H;",
                 f"    if ((fabs{fn}(q) >= {lit(f.q_lo)}) & (fabs{fn}(q) <= {lit(f.q_hi)})) {{",
                 *_indent(law, 8),
                 "    }",
                 "}"]
    return out + _indent(body, 4) + ["}"]


NAMES = {RHO: "rho", T: "tt", LT: "lt", ST: "st", E1: "e1", E2: "e2"}


def _variant(model: LawModel, base: CConfig) -> dict:
    """The template values of one precision (raises Unsupported)."""
    cfg = dataclasses.replace(base, tiny=model.thresholds[base.precision][0], far=model.thresholds[base.precision][1])
    return dict(cfg=cfg, body=gterm_lines(model, cfg, NAMES), fast=fast_lines(model, cfg, NAMES),
                cap=kf_cap(model, cfg),
                rho_cmp=model.radial and len(model.mid) > 1,
                tiny=cfg.lit(cfg.tiny), far=cfg.lit(cfg.far), cut=cfg.lit(cfg.sinc_cut),
                sinc_shift=SINC_SHIFT[base.precision], sinc_up=cfg.lit(2 ** SINC_SHIFT[base.precision]),
                sin_min=SIN_MIN[base.precision],
                zero=cfg.lit(0), one=cfg.lit(1), two=cfg.lit(2), half=cfg.lit(sp.Rational(1, 2)),
                huge="HUGE_VALF" if cfg.precision == "float" else "HUGE_VAL", c6=cfg.lit(sp.Rational(1, 6)),
                c120=cfg.lit(sp.Rational(1, 120)), pi=cfg.lit(sp.pi), two_pi=cfg.lit(2 * sp.pi),
                heading_max="UWMR_HEADING_MAX" + cfg.suffix.upper(),
                turns_max="UWMR_TURNS_MAX" + cfg.suffix.upper())


def float_missing(model: LawModel, kf_float_finite: bool) -> str | None:
    """Why the float variant cannot be written (a constant of the law, or KF,
    beyond the float range; no accurate float form near 0, `law.near_branch`),
    or None: the double variant and the Python module are then written
    without it."""
    if not kf_float_finite:
        return "KF is beyond the float range (about 3.4e38)"
    try:
        _variant(model, FLOAT)
    except Unsupported as exc:
        return str(exc)
    return model.float_blocked


def render(env, model: LawModel, context: dict) -> dict[str, str]:
    """{file name: text} for the C back-end (without the float variant when `model.no_float`)."""
    ident = c_identifier(model.stem)
    variants = [_variant(model, base) for base in ((DOUBLE,) if model.no_float else (DOUBLE, FLOAT))]
    ctx = dict(context, ident=ident, IDENT=ident.upper(), variants=variants, stem=model.stem,
               no_float=model.no_float,
               c_types=[("double", "")] + ([] if model.no_float else [("float", "_f32")]))
    return {f"{model.stem}.h": env.get_template("c_header.h.j2").render(ctx),
            f"{model.stem}.c": env.get_template("c_source.c.j2").render(ctx),
            "example_main.c": env.get_template("example_main.c.j2").render(ctx),
            "CMakeLists.txt": env.get_template("CMakeLists.txt.j2").render(ctx)}
