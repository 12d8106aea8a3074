"""Reference trajectories for the kinematic model (2).

A `Reference` evaluates ``(xr, yr, thr, vr, wr)`` at an array of times.  The
heading thr is *continuous* (unwrapped): the controller works on e3 = thr - th
without wrapping, so a heading that jumps by 2 pi (atan2 taken at face value)
would make the robot spin a full turn at every jump.  Every constructor
therefore checks the heading on a dense grid and refuses a reference whose
heading jumps (`WrappedHeadingError`).

Constructors:

* `circle`      -- the paper's circle: (2) integrated from xr = yr = thr = 0
                   with Vr = 0.5 m/s, Wr = 1 rad/s (diameter 1 m, centre (0, 0.5)).
* `lemniscate`  -- (39)-(43): xr = 0.9 sin(2 pi t/20), yr = 0.9 sin(4 pi t/20),
                   thr = atan2(yr', xr') made continuous, thr(0) = atan2(2, 1).
* `from_path`   -- any smooth planar curve given by x(t), y(t) and their first
                   two derivatives (a Python function of t).
* `from_waypoints` -- sampled waypoints (t_i, x_i, y_i) through a C2 cubic spline.
* `from_function`  -- a user function t -> (xr, yr, thr, vr, wr), checked.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

TWO_PI = 2.0 * math.pi


class WrappedHeadingError(ValueError):
    """The reference heading is not continuous (it jumps, e.g. by 2 pi)."""


class ReferenceError(ValueError):
    """The reference is not a trajectory of (2) (inconsistent or singular)."""


#: how far a reference may be from (2) per step of `Reference.check`, relative
#: to the step times max |wr| (heading) or max |vr| (position): the trapezoidal
#: rule on a smooth reference errs by O(step^2) of that (1e-7 at 1 ms), while a
#: vr 4 % off the path's speed (0.52 for 0.5) is 4e-2
TOLERANCE_2 = 1e-3


def _shaped(values, t: np.ndarray) -> tuple:
    """The values (xr, yr, thr, vr, wr) at the times t as float arrays of t's
    shape; a constant may be given as a plain number.  ReferenceError saying
    what pose(t) must return otherwise."""
    try:
        values = list(values)               # (a tuple, or an array of five rows)
    except TypeError:
        values = None
    if values is None or len(values) != 5:
        raise ReferenceError("pose(t) must return five values (xr, yr, thr, vr, wr), each a number or an array "
                             "shaped like t")
    out = []
    for name, a in zip(("xr", "yr", "thr", "vr", "wr"), values):
        a = np.asarray(a)
        if np.iscomplexobj(a):
            raise ReferenceError(f"pose(t) returned complex values for {name}: they must be real numbers")
        try:
            out.append(a.astype(float) * np.ones_like(t))
        except (TypeError, ValueError):
            raise ReferenceError(f"pose(t) returned {name} of shape {a.shape} for t of shape {t.shape}: each "
                                 f"value must be a number or an array shaped like t") from None
    return tuple(out)


@dataclass
class Reference:
    """A reference pose trajectory of (2) on [t0, t1].

    `fn(t)` takes a 1-d float array and returns five arrays (xr, yr, thr, vr, wr)."""
    name: str
    fn: Callable[[np.ndarray], tuple]
    t0: float
    t1: float
    description: str = ""
    meta: dict = field(default_factory=dict)

    def __call__(self, t):
        t = np.atleast_1d(np.asarray(t, dtype=float))
        return _shaped(self.fn(t), t)

    def at(self, t: float) -> tuple:
        """The five values at one time, as Python floats."""
        return tuple(float(a[0]) for a in self(np.array([t])))

    def check(self, dt: float = 1e-3, max_heading_step: float = math.pi / 4) -> None:
        """Refuse a heading that is not continuous, a non-finite value, or
        a reference that does not satisfy (2).  Raises WrappedHeadingError /
        ReferenceError."""
        n = max(2, int(math.ceil((self.t1 - self.t0) / dt)) + 1)
        t = np.linspace(self.t0, self.t1, n)
        xr, yr, thr, vr, wr = self(t)
        for name, a in zip(("xr", "yr", "thr", "vr", "wr"), (xr, yr, thr, vr, wr)):
            if not np.all(np.isfinite(a)):
                raise ReferenceError(f"reference {self.name!r}: {name} is not finite at "
                                     f"t = {t[~np.isfinite(a)][0]:.6g}")
        jumps = np.abs(np.diff(thr))
        bound = np.maximum(max_heading_step, 4.0 * np.abs(wr[:-1]) * (t[1] - t[0]))
        bad = np.nonzero(jumps > np.minimum(bound, math.pi))[0]
        if bad.size:
            i = int(bad[0])
            raise WrappedHeadingError(
                f"reference {self.name!r}: the heading jumps from {thr[i]:.6g} to {thr[i + 1]:.6g} rad "
                f"between t = {t[i]:.6g} and {t[i + 1]:.6g} s; give a continuous (unwrapped) heading "
                f"(e3 is not wrapped, the robot would turn a full circle)")
        # (2): thr' = wr (trapezoidal rule), xr' = vr cos thr, yr' = vr sin thr
        h = t[1] - t[0]
        dth = np.diff(thr) - 0.5 * h * (wr[1:] + wr[:-1])
        scale = max(1.0, float(np.max(np.abs(wr)))) * h
        if np.max(np.abs(dth)) > TOLERANCE_2 * scale + 1e-9:
            i = int(np.argmax(np.abs(dth)))
            raise ReferenceError(f"reference {self.name!r}: thr' != wr near t = {t[i]:.6g} s "
                                 f"(the heading does not integrate the angular velocity)")
        dx = np.diff(xr) - 0.5 * h * (vr[1:] * np.cos(thr[1:]) + vr[:-1] * np.cos(thr[:-1]))
        dy = np.diff(yr) - 0.5 * h * (vr[1:] * np.sin(thr[1:]) + vr[:-1] * np.sin(thr[:-1]))
        vscale = max(1.0, float(np.max(np.abs(vr)))) * h
        if max(np.max(np.abs(dx)), np.max(np.abs(dy))) > TOLERANCE_2 * vscale + 1e-9:
            raise ReferenceError(f"reference {self.name!r}: (xr', yr') != vr (cos thr, sin thr)")

    def maxima(self, dt: float = 1e-3) -> tuple[float, float]:
        """(max |vr|, max |wr|) on a dense grid (floating point; see paper.py
        for the exact values of the paper's references)."""
        t = np.arange(self.t0, self.t1 + dt / 2, dt)
        _, _, _, vr, wr = self(t)
        return float(np.max(np.abs(vr))), float(np.max(np.abs(wr)))


def circle(radius: float = 0.5, speed: float = 0.5, center=(0.0, 0.5), theta0: float = 0.0,
           duration: float = 80.0) -> Reference:
    """Counter-clockwise circle at constant speed, heading thr = theta0 + (speed/radius) t.

    Default: the paper's circle (diameter 1.0 m, Vr = 0.5 m/s, Wr = 1.0 rad/s),
    i.e. (2) integrated from xr(0) = yr(0) = 0, thr(0) = 0: centre (0, 0.5)."""
    w = speed / radius
    cx, cy = center

    def fn(t):
        th = theta0 + w * t
        return (cx + radius * np.sin(th), cy - radius * np.cos(th), th,
                np.full_like(t, speed), np.full_like(t, w))
    # the start must lie on the circle: centre - radius * (-sin th0, cos th0) ...
    ref = Reference("circle", fn, 0.0, duration,
                    f"circle, radius {radius} m, centre ({cx}, {cy}), Vr = {speed} m/s, Wr = {w} rad/s",
                    dict(radius=radius, center=(cx, cy), speed=speed))
    ref.check()
    return ref


class _Unwrapper:
    """Continuous branch of atan2(dy, dx): anchored on a dense grid, where
    consecutive headings differ by less than pi, then exact at any t."""

    def __init__(self, deriv: Callable, t0: float, t1: float, dt: float):
        n = max(2, int(math.ceil((t1 - t0) / dt)) + 1)
        self.t = np.linspace(t0, t1, n)
        dx, dy = deriv(self.t)
        wrapped = np.arctan2(dy, dx)
        self.anchor = np.unwrap(wrapped)
        self.deriv = deriv

    def __call__(self, t):
        dx, dy = self.deriv(t)
        wrapped = np.arctan2(dy, dx)
        anchor = np.interp(t, self.t, self.anchor)
        return wrapped + TWO_PI * np.round((anchor - wrapped) / TWO_PI)


def from_path(name: str, pos: Callable, d1: Callable, d2: Callable, t0: float, t1: float,
              description: str = "", anchor_dt: float = 1e-3, meta=None) -> Reference:
    """A reference tracing the planar curve pos(t) = (x, y) forwards, with
    d1(t) = (x', y') and d2(t) = (x'', y'').  vr = |(x', y')| > 0 is required
    (a stop makes the heading undefined); thr is the continuous branch of
    atan2(y', x') with thr(t0) in (-pi, pi]; wr = (x' y'' - x'' y')/vr^2."""
    unwrap = _Unwrapper(d1, t0, t1, anchor_dt)

    def fn(t):
        x, y = pos(t)
        dx, dy = d1(t)
        ddx, ddy = d2(t)
        v2 = dx * dx + dy * dy
        return x, y, unwrap(t), np.sqrt(v2), (dx * ddy - ddx * dy) / v2

    ref = Reference(name, fn, t0, t1, description, dict(meta or {}))
    _, _, _, vr, _ = ref(unwrap.t)
    if np.min(vr) <= 1e-9:
        raise ReferenceError(f"reference {name!r}: the speed vanishes at t = "
                             f"{unwrap.t[int(np.argmin(vr))]:.6g} s, the heading is undefined there")
    ref.check()
    return ref


def lemniscate(amplitude: float = 0.9, period: float = 20.0, duration: float = 200.0) -> Reference:
    """(39)-(43): xr = a sin(2 pi t/T), yr = a sin(4 pi t/T), continuous heading."""
    a, om = amplitude, TWO_PI / period

    def pos(t):
        return a * np.sin(om * t), a * np.sin(2 * om * t)

    def d1(t):
        return a * om * np.cos(om * t), 2 * a * om * np.cos(2 * om * t)

    def d2(t):
        return -a * om * om * np.sin(om * t), -4 * a * om * om * np.sin(2 * om * t)

    return from_path("lemniscate", pos, d1, d2, 0.0, duration,
                     f"lemniscate (39)-(43), amplitude {amplitude} m, period {period} s",
                     meta=dict(amplitude=amplitude, period=period))


def from_waypoints(t, x, y, name: str = "waypoints") -> Reference:
    """Sampled waypoints (t_i, x_i, y_i), interpolated by a C2 cubic spline
    (not-a-knot); the robot must move forwards all the time (|spline'| > 0)."""
    from scipy.interpolate import CubicSpline
    t = np.asarray(t, dtype=float)
    if t.ndim != 1 or len(t) < 4 or np.any(np.diff(t) <= 0):
        raise ReferenceError("waypoints: need at least 4 samples with strictly increasing times")
    try:
        sx, sy = CubicSpline(t, np.asarray(x, dtype=float)), CubicSpline(t, np.asarray(y, dtype=float))
    except ValueError as exc:       # scipy names its own arguments (`dydx`), not the columns
        raise ReferenceError(f"waypoints: no cubic spline through them in double precision ({exc}); "
                             f"give times and positions of moderate size") from None
    return from_path(name, lambda s: (sx(s), sy(s)), lambda s: (sx(s, 1), sy(s, 1)),
                     lambda s: (sx(s, 2), sy(s, 2)), float(t[0]), float(t[-1]),
                     f"cubic spline through {len(t)} waypoints")


def from_function(fn: Callable, t0: float, t1: float, name: str = "user") -> Reference:
    """A user function t -> (xr, yr, thr, vr, wr) (vectorised over numpy
    arrays).  Checked: a heading that jumps (wrapped) or values inconsistent
    with (2) are refused."""
    if not t0 < t1 or not math.isfinite(t1 - t0):
        raise ReferenceError(f"reference {name!r}: the time span [{t0:g}, {t1:g}] s is empty or not finite; "
                             f"give a positive, finite duration")

    def shaped(t):          # the loops call fn itself: a constant output may be a plain number there too
        try:
            values = fn(t)
        except Exception as exc:  # noqa: BLE001 - the user's function: its failure is the reference's
            raise ReferenceError(f"pose(t) raised {type(exc).__name__}: {exc}") from None
        return _shaped(values, np.asarray(t, dtype=float))
    ref = Reference(name, shaped, float(t0), float(t1), "user function of t")
    ref.check()
    return ref
