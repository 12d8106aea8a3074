"""Translation validation: the generated artifacts against the exact law,
before anything is written.

`validate(design, model, files)` compiles the rendered C (strict flags,
`harness.build_library`), imports the rendered Python module and builds the
CasADi function, evaluates each on a deterministic sample of inputs and
compares with the exact law (`reference`, Arb ball arithmetic).  The sample
(`sample_inputs`) holds, per precision,

* every input over an extreme grid: 0, +-the smallest subnormal, +-the
  smallest normal, +-1e-300 (float: 1e-40), 1e-150, 1e-8, 1, 3, 1e4, 1e8,
  1e154, 1e300 and +-the largest finite number (float: the float-range
  analogues), e1 x e2 in full, the others one at a time and in small
  products with vr = 0, lam = 0 and e3 = 0 among them;
* both sides (x (1 +- 2^-10)) of every region switch of the generated code
  (TINY, FAR, Piecewise boundaries in rho and t), and points near a
  boundary in rho where rho and its rounding fall on different sides;
* random rows, log-uniform over every magnitude of the type and over
  1e-4..1e4.

Rows with a NaN or infinite input or a negative gain must give the safe
stop (status 2 or 3, v = w = 0: `check_safe_stop`).  A row fails (`check`)
when, for finite inputs and gains >= 0: the status is
not 0 although the exact v and w are finite; the status is 0 although one of
them is beyond the type's range (status 4 is required there); an output is
not finite; the safe stop does not give v = w = 0; the error exceeds 1e-12
(double) / 1e-5 (float) of the scale of `reference.errors`; or, for a
verified design, bound (10) is violated by more than 4 ulps.  The first
failing row raises `ValidationFailed` with one line naming the design, the
target, the input and both values.  The CasADi function is checked on the
range it documents (|e1|, |e2| <= FAR, the other inputs moderate):
`check_casadi`, also run alone by `validate_casadi` for
`codegen.casadi_function`.

The tests use the same functions (`check`, `sample_inputs`) on larger samples."""
from __future__ import annotations

import importlib.util
import math
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from . import reference
from .accuracy import lam_vr_kf
from .law import LawModel, rho_minus_b, split_boundary

OK, ERR_NULL, ERR_NONFINITE, ERR_GAIN, ERR_RANGE = 0, 1, 2, 3, 4
TOL = {"double": 1e-12, "float": 1e-5}
NAMES = ("e1", "e2", "e3", "vr", "wr", "k1", "k2", "lam")


class ValidationFailed(Exception):
    """A generated artifact disagrees with the law; `line` says where."""

    def __init__(self, line: str):
        self.line = line
        super().__init__(line)


def _limits(precision):
    if precision == "float":
        f = np.finfo(np.float32)
        return float(f.smallest_subnormal), float(f.tiny), float(f.max), float(f.eps)
    f = np.finfo(np.float64)
    return float(f.smallest_subnormal), float(f.tiny), float(f.max), float(f.eps)


def extreme_values(precision: str) -> list[float]:
    """Non-negative magnitudes of the extreme grid for one precision."""
    sub, tiny, big, _ = _limits(precision)
    if precision == "float":
        mags = [sub, tiny, 1e-40, 1e-20, 1e-6, 1.0, 3.0, 1e4, 1e8, 1.8e19, 1e30, big]
    else:
        mags = [sub, tiny, 1e-300, 1e-150, 1e-8, 1.0, 3.0, 1e4, 1e8, 1.3e154, 1e300, big]
    return [0.0, *mags]


def _cast(x, precision):
    x = np.asarray(x, dtype=float)
    if precision == "float":
        with np.errstate(over="ignore"):
            x = x.astype(np.float32).astype(np.float64)
        x[~np.isfinite(x)] = 0.0
    return x


def switch_points(model: LawModel, precision: str) -> list[float]:
    """Values of m = max(|e1|, |e2|) at which the generated code changes
    form: TINY, FAR and the Piecewise boundaries (rho = m^2 on the axis,
    t = 1/m), each with its neighbours x (1 +- 2^-10)."""
    tiny, far = model.thresholds[precision]
    pts = [tiny, far, 2 * tiny]
    for br in model.mid:
        if br.hi_float not in (0.0, math.inf):
            pts.append(math.sqrt(br.hi_float))
    for br in model.far:
        if 0 < br.hi_float < math.inf:
            pts.append(1 / br.hi_float)
    out = []
    for p in pts:
        out += [p * (1 - 2.0 ** -10), p, p * (1 + 2.0 ** -10)]
    return out


def rounding_crossings(model: LawModel, precision: str, per_boundary: int = 8, tries: int = 40_000):
    """Points (e1, e2) of the type near each Piecewise boundary b in rho
    where rho = e1^2 + e2^2 and its rounding e1*e1 + e2*e2 lie strictly on
    different sides of b: the generated C picks the exact rho's branch
    (`rho_cmp`), whose formula then reads the rounded rho (a boundary with
    an odd last bit lets the rounding cross it).  Found among random points
    of the circle, a few ulps either way, with rho - b signed as `rho_cmp`
    signs it (`law.rho_minus_b`, b as a pair of the type)."""
    t = np.float32 if precision == "float" else np.float64
    split = t(4097.0 if precision == "float" else 134217729.0)
    rng = np.random.default_rng(1)
    out = []
    with np.errstate(all="ignore"):
        for br in model.mid[:-1]:
            bh, bl = split_boundary(br.hi, precision)
            bh, bl = t(bh), t(float(bl))
            e1 = t(math.sqrt(float(br.hi))) * rng.uniform(0.05, 0.999, tries).astype(t)
            e2 = np.sqrt(bh - e1 * e1)
            found = []
            for _ in range(3):          # e2 and its next two neighbours up
                r = rho_minus_b(e1, e2, bh, bl, split)
                rounded = (e1 * e1 + e2 * e2) - bh
                hit = ((r < 0) & (rounded > 0)) | ((r > 0) & (rounded < 0))
                found += [(float(x), float(y)) for x, y in zip(e1[hit], e2[hit])]
                e2 = np.nextafter(e2, t(np.inf))
            out += found[:per_boundary]
    return out


def sample_inputs(model: LawModel, precision: str, nominal, n_random: int = 600, seed: int = 0) -> np.ndarray:
    """Rows of 8 inputs (see the module doc), as doubles holding values of
    the precision's type."""
    rng = np.random.default_rng(seed)
    mags = extreme_values(precision)
    signed = sorted({*mags, *[-m for m in mags]})
    k1, k2, lam = nominal
    base = np.array([0.3, -0.7, 0.2, 0.5, 1.0, k1, k2, lam])
    rows = []
    # e1 x e2 over the full grid (e1 >= 0: the law is even in e1), nominal rest
    for a in mags:
        for b in signed:
            rows.append([a, b, *base[2:]])
    # each of e3, vr, wr, gains over the grid, with a few (e1, e2)
    pairs = [(0.0, 0.0), (0.3, -0.7), (1e-6, 2e-6), (mags[-3], -mags[-3]), (mags[1], mags[-1])]
    for e1, e2 in pairs:
        for i in range(2, 8):
            for val in (mags if i >= 5 else signed):
                r = [e1, e2, *base[2:]]
                r[i] = val
                rows.append(r)
    # small products with the degenerate cases vr = 0, lam = 0, e3 = 0
    some = [0.0, mags[1], 1.0, mags[-2], mags[-1]]
    for e2 in (-mags[-1], -1.0, mags[2], 1e-3):
        for e3 in (0.0, -some[1], 1.0, some[-1]):
            for vr in (0.0, -some[-2], some[1], 1.0):
                for lam in (0.0, some[1], 1.0, some[-1]):
                    rows.append([0.5, e2, e3, vr, -1.0, k1, k2, lam])
    # both sides of every switch of the generated code
    for m in switch_points(model, precision):
        for q in (0.0, 0.5, 1.0):
            rows.append([m * q, m, *base[2:]])
            rows.append([m, -m * q, *base[2:]])
    # where the rounding of rho crosses a boundary that rho does not
    for e1, e2 in rounding_crossings(model, precision):
        rows.append([e1, e2, *base[2:]])
        rows.append([e2, -e1, *base[2:]])
    # random: every magnitude, and moderate
    lo = math.log10(_limits(precision)[0]) + 0.3
    hi = math.log10(_limits(precision)[2]) - 0.1
    for a, b, n in ((lo, hi, n_random // 2), (-4.0, 4.0, n_random - n_random // 2)):
        x = 10.0 ** rng.uniform(a, b, (n, 8)) * rng.choice([-1.0, 1.0], (n, 8))
        x[rng.random((n, 8)) < 0.05] = 0.0
        x[:, 5:] = np.abs(x[:, 5:])
        rows.extend(x.tolist())
    return _cast(np.array(rows, dtype=float), precision)


def bad_rows(nominal):
    """(rows, expected status): each input NaN, +inf or -inf in turn (status
    2), each gain negative in turn (status 3); the safe stop gives v = w = 0."""
    base = [0.3, -0.7, 0.2, 0.5, 1.0, *nominal]
    rows, want = [], []
    for i in range(8):
        for bad in (math.nan, math.inf, -math.inf):
            r = list(base)
            r[i] = bad
            rows.append(r)
            want.append(ERR_NONFINITE)
    for i in (5, 6, 7):
        r = list(base)
        r[i] = -1e-30
        rows.append(r)
        want.append(ERR_GAIN)
    return np.array(rows), np.array(want)


def check_safe_stop(stem, target, x, want, v, w, st):
    bad = (np.asarray(st) != want) | (np.asarray(v) != 0) | (np.asarray(w) != 0)
    if np.any(bad):
        i = int(np.flatnonzero(bad)[0])
        raise ValidationFailed(f"{stem}: {target}: no safe stop at {_fmt(x[i])}: got v={v[i]}, w={w[i]}, "
                               f"status {int(st[i])}; expected v = w = 0, status {int(want[i])}")


POSE_NAMES = ("x", "y", "th", "xr", "yr", "thr")


def pose_rows(precision: str, n_random: int = 600, seed: int = 0) -> np.ndarray:
    """Rows (x, y, th, xr, yr, thr) for errors (7): x against xr over the
    signed extreme grid, y and yr over it one at a time, the heading th over the signed grid
    (huge headings included) with a few positions, and random rows over
    every magnitude and over 1e-4..1e4 (headings within 1e4 rad there)."""
    rng = np.random.default_rng(seed)
    mags = extreme_values(precision)
    signed = sorted({*mags, *[-m for m in mags]})
    base = [0.3, -0.7, 0.4, 1.1, 0.2, -2.5]
    rows = []
    for a in signed:
        for b in signed:
            rows.append([a, base[1], base[2], b, base[4], base[5]])
        rows.append([base[0], a, -base[2], base[3], base[4], base[5]])
        rows.append([base[0], base[1], -base[2], base[3], a, base[5]])
    for t in signed:
        for pos in ([0.3, -0.7, 1.1, 0.2], [mags[-1], 0.0, -mags[-1], mags[-2]], [mags[1], 0.0, 0.0, mags[2]]):
            rows.append([pos[0], pos[1], t, pos[2], pos[3], -t])
            rows.append([pos[0], pos[1], t, pos[2], pos[3], base[5]])
    lo = math.log10(_limits(precision)[0]) + 0.3
    hi = math.log10(_limits(precision)[2]) - 0.1
    for a, b, n in ((lo, hi, n_random // 2), (-4.0, 4.0, n_random - n_random // 2)):
        x = 10.0 ** rng.uniform(a, b, (n, 6)) * rng.choice([-1.0, 1.0], (n, 6))
        x[rng.random((n, 6)) < 0.05] = 0.0
        rows.extend(x.tolist())
    return _cast(np.array(rows, dtype=float), precision)


def bad_pose_rows():
    """Rows with NaN, +inf or -inf in each pose input in turn (status 2)."""
    rows = []
    for i in range(6):
        for bad in (math.nan, math.inf, -math.inf):
            r = [0.3, -0.7, 0.4, 1.1, 0.2, -2.5]
            r[i] = bad
            rows.append(r)
    return np.array(rows)


def heading_sequences(precision: str, n_seq: int = 6, length: int = 150, seed: int = 0):
    """(rows (S, K, 6), turns (S, K), status (S, K)): S pose sequences as a
    robot and its reference would send them.  The true headings move by
    less than pi per call (steps of up to 3 rad); each arrives wrapped to
    (-pi, pi] or shifted by a random multiple of 2 pi (jumps of up to 6
    turns between calls), around 0 or around 1e3 rad (double: also 1e6).
    `turns` is the exact number of turns by which the tracker must correct
    thr - th (the shifts relative to the first call); a few rows are NaN or
    beyond UWMR_HEADING_MAX (status 2 / 4; the tracker must keep its state)."""
    rng = np.random.default_rng(seed)
    centres = [0.0, 1e3] + ([1e6] if precision == "double" else [])
    rows = np.zeros((n_seq, length, 6))
    turns = np.zeros((n_seq, length))
    status = np.zeros((n_seq, length), dtype=int)
    hmax = 1e12 if precision == "double" else 1e5
    for s in range(n_seq):
        steps = rng.uniform(-0.3, 0.3, (length, 2))
        big = rng.random((length, 2)) < 0.1
        steps[big] = rng.uniform(-3.0, 3.0, (int(big.sum()),))
        u = np.cumsum(steps, axis=0) + centres[s % len(centres)]
        shift = rng.integers(-3, 4, (length, 2)).astype(float)
        wrapped = rng.random(length) < 0.5
        heads = u - 2 * math.pi * shift
        # "wrapped": the heading reduced to (-pi, pi], the shift it took
        w_shift = np.floor((u + math.pi) / (2 * math.pi))
        heads[wrapped] = (u - 2 * math.pi * w_shift)[wrapped]
        shift[wrapped] = w_shift[wrapped]
        pos = rng.uniform(-5.0, 5.0, (length, 4))
        rows[s] = np.column_stack([pos[:, 0], pos[:, 1], heads[:, 0], pos[:, 2], pos[:, 3], heads[:, 1]])
        # the exact correction: the shifts relative to the first accepted call
        turns[s] = (shift[:, 1] - shift[0, 1]) - (shift[:, 0] - shift[0, 0])
    rows = _cast(rows.reshape(-1, 6), precision).reshape(rows.shape)
    for s in range(n_seq):
        for k in rng.choice(np.arange(1, length), 3, replace=False):
            col = rng.choice([0, 2, 3, 5])
            rows[s, k, col] = math.nan if col in (0, 3) or rng.random() < 0.5 else hmax * 4.0
            status[s, k] = ERR_NONFINITE if math.isnan(rows[s, k, col]) else ERR_RANGE
    return rows, turns, status


def check_errors(stem, target, x, turns, got, st, precision, want=None, exact=None):
    """Errors (7) against `reference.tracking_errors` (mpmath, 200 bits;
    `exact` may pass its result in): for finite rows status 0 with every
    error <= TOL of its scale (floored at the smallest normal number), or
    status 4 exactly where an exact error is beyond the type's largest finite
    number (either status within 1e-9 of it); rows with `want` != 0 must give
    that status and zeros.  Raises ValidationFailed at the first bad row;
    returns the largest error."""
    x = np.asarray(x, dtype=float)
    st = np.asarray(st)
    got = np.column_stack([np.asarray(g, dtype=float) for g in got])
    want = np.zeros(len(x), dtype=int) if want is None else np.asarray(want)
    sub, tiny, big, eps = _limits(precision)
    tol = TOL[precision]
    if exact is None:
        exact = reference.tracking_errors(x, turns, big)
    good = want == OK
    over = good & exact["over"].any(axis=1)
    edge = good & exact["edge"].any(axis=1)
    zeros = np.all(got == 0, axis=1)
    with np.errstate(all="ignore"):
        err = np.abs((got - exact["hi"]) - exact["lo"]) / np.maximum(exact["scale"], tiny)
    ok = good & (st == OK)
    err = np.where(ok[:, None], err, 0.0)
    worst = err.max(axis=1) if len(x) else np.zeros(0)

    def fail(mask, why):
        if not np.any(mask):
            return
        i = int(np.flatnonzero(mask)[0])
        vals = ", ".join(f"e{j + 1}={got[i, j]:.17g}" for j in range(3))
        ex = ", ".join(f"e{j + 1}={exact['hi'][i, j]:.17g}" for j in range(3)) if want[i] == OK else \
            f"status {int(want[i])}"
        where = ", ".join(f"{n}={float(v):.17g}" for n, v in zip(POSE_NAMES, x[i]))
        if turns is not None:
            where += f", turns={float(np.asarray(turns)[i]):g}"
        raise ValidationFailed(f"{stem}: {target}: {why} at ({where}): got {vals}, status {int(st[i])}; exact {ex}")
    fail(~good & ((st != want) | ~zeros), "no safe stop")
    fail(over & ~edge & (st != ERR_RANGE), "an error beyond the type's range not reported as status 4")
    fail((st == ERR_RANGE) & ~zeros, "no safe stop (zeros) with status 4")
    fail(good & (st != OK) & ~((st == ERR_RANGE) & (over | edge)), "nonzero status on finite poses whose errors are finite")
    fail(ok & ~np.all(np.isfinite(got), axis=1), "non-finite error with status 0")
    fail(ok & ~(worst <= tol), f"an error off by {worst.max() if len(x) else 0:.3g} of the scale (above {tol:g})")
    return float(worst.max()) if len(x) else 0.0


def _check_error_functions(stem, lib, mod, precision_rows, seqs, float_variant=True):
    """Errors (7) and the tracker of the C variants and the Python module
    (see check_errors); returns the targets checked."""
    out, cache = [], {}
    xb = bad_pose_rows()
    wb = np.full(len(xb), ERR_NONFINITE)
    targets = [("double", False, "C double errors (7)"), ("float", True, "C float errors (7)"),
               ("double", None, "Python errors (7)")]
    for precision, f32, target in targets if float_variant else targets[::2]:
        x = precision_rows[precision]
        rows, turns, want = seqs[precision]
        big = _limits(precision)[2]
        key = (precision, "rows")
        if key not in cache:
            cache[key] = reference.tracking_errors(x, None, big)
            cache[(precision, "seq")] = reference.tracking_errors(rows.reshape(-1, 6), turns.ravel(), big)
        if f32 is None:
            e1, e2, e3, st = mod.errors_status(*xb.T)
            check_errors(stem, target, xb, None, (e1, e2, e3), st, precision, wb)
            e1, e2, e3, st = mod.errors_status(*x.T)
        else:
            e1, e2, e3, st = lib.errors(xb, f32=f32)
            check_errors(stem, target, xb, None, (e1, e2, e3), st, precision, wb)
            e1, e2, e3, st = lib.errors(x, f32=f32)
        worst = check_errors(stem, target, x, None, (e1, e2, e3), st, precision, exact=cache[key])
        # the tracker along every sequence: C one sequence at a time, Python all at once
        if f32 is None:
            tracker = mod.Tracker()
            res = [tracker.track(tuple(rows[:, k, :3].T), tuple(rows[:, k, 3:].T)) for k in range(rows.shape[1])]
            got = [np.stack([r[j] for r in res], axis=1).ravel() for j in range(4)]
        else:
            parts = [lib.track(seq, f32=f32) for seq in rows]
            got = [np.concatenate([p[j] for p in parts]) for j in range(4)]
        name = target.replace("errors (7)", "tracker")
        worst = max(worst, check_errors(stem, name, rows.reshape(-1, 6), turns.ravel(), got[:3], got[3], precision,
                                        want.ravel(), exact=cache[(precision, "seq")]))
        out.append(Target(target + " and tracker", precision, len(x) + rows.size // 6, worst))
    return out


@dataclass
class Target:
    name: str                       # "C double", "C float", "Python", "Python fast path", "CasADi"
    precision: str
    rows: int = 0
    worst: float = 0.0


@dataclass
class Result:
    stem: str
    targets: list = field(default_factory=list)
    seconds: float = 0.0

    def summary(self) -> str:
        return ", ".join(f"{t.name} {t.rows} rows (max err {t.worst:.2g})" for t in self.targets)


def _fmt(x) -> str:
    return "(" + ", ".join(f"{n}={float(v):.17g}" for n, v in zip(NAMES, x)) + ")"


def check(stem, target, x, ref, v, w, st, precision, kf=None):
    """Largest relative error; raises ValidationFailed at the first bad row
    (see the module doc).  kf: the certified kf bound for bound (10) (None:
    the design is not verified, no bound check)."""
    x = np.asarray(x, dtype=float)
    v = np.asarray(v, dtype=float)
    w = np.asarray(w, dtype=float)
    st = np.asarray(st)
    ev, ew, over = reference.errors(ref, v, w, precision)
    sub, _, big, eps = _limits(precision)
    finite_in = np.all(np.isfinite(x), axis=1) & np.all(x[:, 5:] >= 0, axis=1)

    def fail(mask, why):
        if np.any(mask):
            i = int(np.flatnonzero(mask)[0])
            exact = f"exact v={ref['v_hi'][i]:.17g}, w={ref['w_hi'][i]:.17g}"
            raise ValidationFailed(f"{stem}: {target}: {why} at {_fmt(x[i])}: got v={v[i]:.17g}, "
                                   f"w={w[i]:.17g}, status {int(st[i])}; {exact}")
    fail(finite_in & (st != OK) & ~over, "nonzero status on a finite input whose law is finite")
    fail(finite_in & over & (st != ERR_RANGE), "result beyond the type's range not reported as status 4")
    fail((st != OK) & ((v != 0) | (w != 0)), "no safe stop (v = w = 0) with a nonzero status")
    fail((st == OK) & ~(np.isfinite(v) & np.isfinite(w)), "non-finite output with status 0")
    err = np.where(st == OK, np.maximum(ev, ew), 0.0)
    tol = TOL[precision]
    fail(err > tol, f"error {err.max():.3g} above {tol:g} of the scale")
    if kf is not None:
        a = np.abs(x)
        with np.errstate(over="ignore", invalid="ignore"):
            bv = (a[:, 3] + a[:, 5]) * (1 + 4 * eps) + 8 * sub
            bw = (a[:, 4] + lam_vr_kf(a, kf) + a[:, 6]) * (1 + 4 * eps) + 8 * sub
        ok = st == OK
        fail(ok & ~(np.abs(v) <= bv), "|v| above bound (10)")
        fail(ok & ~(np.abs(w) <= bw), "|w| above bound (10)")
    return float(err.max()) if len(err) else 0.0


def check_certified(stem, target, model: LawModel, precision, x, ref, v, w, st, kf) -> None:
    """The outputs against the certified accuracy of the header
    (`accuracy.first_violation`): a violation means the error analysis is
    wrong, and the code is not written."""
    from .accuracy import first_violation
    acc = model.accuracy.get(precision)
    if acc is None or kf is None:
        return
    i = first_violation(acc, x, ref, v, w, st, kf)
    if i is not None:
        raise ValidationFailed(f"{stem}: {target}: outside the certified accuracy (v within {acc.v:.2g}, w within "
                               f"{acc.w:.2g} of the bound (10) terms) at {_fmt(x[i])}: got v={v[i]:.17g}, "
                               f"w={w[i]:.17g}; exact v={ref['v_hi'][i]:.17g}, w={ref['w_hi'][i]:.17g}")


def load_module(path: Path, name: str):
    spec = importlib.util.spec_from_file_location(name, path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _casadi_rows(x, far):
    """Rows within the CasADi function's documented range."""
    a = np.abs(x)
    keep = (np.maximum(a[:, 0], a[:, 1]) <= far) & np.all(a[:, 2:] <= 1e3, axis=1) \
        & np.all(np.isfinite(x), axis=1)
    return x[keep]


def _law(design, stem):
    try:
        return reference.Law.of(design)
    except NotImplementedError as exc:
        raise ValidationFailed(f"{stem}: the exact law cannot be evaluated, so the code cannot be "
                               f"validated ({exc})") from None


def _nominal(design):
    """(k1, k2, lam) of the design's first gain scenario (a default without one)."""
    sc = next(iter(design.gains.values()), None) if design.gains else None
    return tuple(float(sc[k]) for k in ("k1", "k2", "lam")) if sc else (0.25, 0.7, 0.3)


def check_casadi(stem, fn, law, model: LawModel, xd, kf, cache=None) -> Target:
    """The CasADi function `fn` on the rows of the double sample `xd` within
    its documented range (`_casadi_rows`: max(|e1|, |e2|) <= FAR, the other
    inputs <= 1e3) where the exact v and w are doubles (it has no status for
    "beyond the range": 10^307 log(1 + rho)), against the exact law (`check`,
    status 0 everywhere);
    raises ValidationFailed or returns what was checked."""
    xc = _casadi_rows(xd, model.thresholds["double"][1])
    rc = _table(law, xc, {} if cache is None else cache, stem)
    finite = np.isfinite(rc["v_hi"]) & np.isfinite(rc["w_hi"])     # (no status to say "beyond the doubles")
    xc, rc = xc[finite], {k: val[finite] for k, val in rc.items()}
    out = fn.map(len(xc))(*[xc[:, i][None, :] for i in range(8)])
    v, w = np.asarray(out[0]).ravel(), np.asarray(out[1]).ravel()
    worst = check(stem, "CasADi", xc, rc, v, w, np.zeros(len(xc), dtype=int), "double", kf)
    return Target("CasADi", "double", len(xc), worst)


def validate_casadi(design, model: LawModel, fn, kf: float | None, n_random: int = 2000,
                    seed: int = 0) -> Result:
    """Check a CasADi function of one design alone (`codegen.casadi_function`)
    on the same double sample as `validate` (`check_casadi`); raises
    ValidationFailed (one line) or returns what was checked."""
    t0 = time.perf_counter()
    stem = model.stem
    law = _law(design, stem)
    xd = sample_inputs(model, "double", _nominal(design), n_random, seed)
    res = Result(stem, [check_casadi(stem, fn, law, model, xd, kf)])
    res.seconds = time.perf_counter() - t0
    return res


def validate(design, model: LawModel, files: dict, kf: float | None, n_random: int = 2000,
             seed: int = 0, casadi=True) -> Result:
    """Check every artifact of one design (see the module doc); raises
    ValidationFailed (one line) or returns what was checked."""
    from .harness import build_library
    t0 = time.perf_counter()
    stem = model.stem
    law = _law(design, stem)
    nominal = _nominal(design)
    xd = sample_inputs(model, "double", nominal, n_random, seed)
    cache = {}
    rd = _table(law, xd, cache, stem)
    variants = [("C double", "double", xd, rd)]
    if not model.no_float:          # (a constant beyond the float range: the double variant alone)
        xf = sample_inputs(model, "float", nominal, n_random, seed + 1)
        variants.append(("C float", "float", xf, _table(law, xf, cache, stem)))
    res = Result(stem)
    with tempfile.TemporaryDirectory(prefix="uwmr-validate-") as tmp:
        tmp = Path(tmp)
        for name, text in files.items():
            (tmp / name).write_text(text, encoding="utf-8")
        try:
            lib = build_library(tmp, stem, tmp)
        except RuntimeError as exc:
            first = next((ln for ln in str(exc).splitlines() if "error:" in ln), str(exc).splitlines()[-1])
            raise ValidationFailed(f"{stem}: C: the strict build fails: {first.strip()}") from None
        xb, want = bad_rows(nominal)
        for target, precision, x, ref in variants:
            v, w, st = lib.run(xb, f32=precision == "float")
            check_safe_stop(stem, target, xb, want, v, w, st)
            v, w, st = lib.run(x, f32=precision == "float")
            worst = check(stem, target, x, ref, v, w, st, precision, kf)
            check_certified(stem, target, model, precision, x, ref, v, w, st, kf)
            res.targets.append(Target(target, precision, len(x), worst))
        modname = f"_uwmr_validate_{stem}_{id(files)}"
        try:
            mod = load_module(tmp / f"{stem}.py", modname)
            v, w, st = mod.control_status(*xb.T)
            check_safe_stop(stem, "Python", xb, want, v, w, st)
            v, w, st = mod.control_status(*xd.T)      # (st, checked here, is also what control() stands on)
            check(stem, "Python", xd, rd, v, w, st, "double", kf)
            v2, w2 = mod.control(*xd.T)
            worst = check(stem, "Python", xd, rd, v2, w2, st, "double", kf)
            check_certified(stem, "Python", model, "double", xd, rd, v2, w2, st, kf)
            res.targets.append(Target("Python", "double", len(xd), worst))
            # the fast path on moderate rows, as one array and row by row
            mod_rows = np.flatnonzero(np.all((np.abs(xd) >= 1e-4) & (np.abs(xd) <= 1e4), axis=1))
            v, w = mod.control(*xd[mod_rows].T)
            sub = {k: val[mod_rows] for k, val in rd.items()}
            worst = check(stem, "Python (fast path)", xd[mod_rows], sub, v, w, st[mod_rows], "double", kf)
            some = mod_rows[:60]
            pv, pw = np.array([mod.control(*r) for r in xd[some]]).reshape(-1, 2).T
            sub = {k: val[some] for k, val in rd.items()}
            worst = max(worst, check(stem, "Python (row by row)", xd[some], sub, pv, pw, st[some], "double", kf))
            res.targets.append(Target("Python fast path", "double", len(mod_rows) + len(some), worst))
            res.targets += _check_error_functions(
                stem, lib, mod, {p: pose_rows(p, n_random // 4, seed + i) for i, p in enumerate(("double", "float"))},
                {p: heading_sequences(p, seed=seed + i) for i, p in enumerate(("double", "float"))},
                float_variant=not model.no_float)
        except ValidationFailed:
            raise
        except Exception as exc:  # noqa: BLE001 - any crash of the module is a failure
            raise ValidationFailed(f"{stem}: Python: the generated module fails: "
                                   f"{type(exc).__name__}: {exc}".splitlines()[0]) from None
        finally:
            sys.modules.pop(modname, None)
    if casadi:
        from .casadi_backend import casadi_function
        try:
            fn = casadi_function(model)
        except NotImplementedError as exc:
            fn = None      # no CasADi function exists for this design (casadi_function raises the same)
            res.targets.append(Target(f"CasADi: not available ({exc})", "double"))
    if casadi and fn is not None:
        res.targets.append(check_casadi(stem, fn, law, model, xd, kf, cache))
    res.seconds = time.perf_counter() - t0
    return res


def _table(law, x, cache, stem):
    """reference.table with a cache shared between the samples; a row the
    reference cannot decide (a Piecewise condition at its boundary beyond
    16384 bits) stops the validation: unchecked code is not written."""
    try:
        return reference.table(law, x, cache)
    except (ArithmeticError, ValueError) as exc:
        raise ValidationFailed(f"{stem}: the exact law could not be evaluated on the "
                               f"validation sample ({exc})") from None
