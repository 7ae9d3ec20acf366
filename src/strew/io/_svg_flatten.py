"""SVG geometry without per-segment objects: path data, basic shapes and transforms parsed
into arrays, and curves flattened in one batch of numpy per element, or for many elements
at once (:func:`flatten_many`) (issue 17 point 3).

svgelements made one Python object per path segment and sampled each curve on its own
(``npoint``), which cost 20-34 s per MB of path-heavy SVG. Here a path becomes a
:class:`Segments` table (one row per segment: its kind, its control points, and for arcs
the centre parametrisation) and :func:`flatten` samples every curve of an element at once.

The geometry is svgelements' own, to within float rounding (``tests/io/test_svg_fast.py``
compares both on random paths and transforms): its reading of smooth curves (``S`` / ``T``
reflect the previous segment's last control point whatever its kind), of arcs (negative
radii taken absolute, out-of-range radii scaled up, a zero radius or equal end points
giving a point at the end), and of ``Z`` (back to the last move). Curves are sampled at
the same parameters as before: ``n`` uniform steps in ``t`` with
``n = ceil(sqrt(bound / (8 tol)))``, where ``bound`` bounds ``|B''|`` (``h^2 max|B''| / 8``
is the chord error).

Anything outside the plain grammar (units in transforms, compact arc flags such as
``a1 1 0 01 5 5``, an inline ``z`` used as a coordinate, a rounded rect, odd counts of
numbers) is left to svgelements, whose result is converted to the same table, so that
odd files read exactly as they did.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = ["Segments", "parse_path", "parse_transform", "parse_numbers", "points_many", "from_svgelements", "flatten", "flatten_many", "path_d", "shape_segments", "too_large"]

LINE, QUAD, CUBIC, ARC = 0, 1, 2, 3
MAX_SEGMENT_POINTS = 20000

_FLOAT = r"[-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?"  # svgelements' PATTERN_FLOAT
_FLOAT_RE = re.compile(_FLOAT)
_COMMAND = re.compile(r"([MmZzLlHhVvCcSsQqTtAa])")
_SEPARATORS = re.compile(r"[ ,\t\n\r\x0c]*")
_TRANSFORM = re.compile(r"\s*(matrix|translate|scale|rotate|skewX|skewY)\s*\(([^()]*)\)\s*,?", re.IGNORECASE)
_ARGS = {"m": 2, "l": 2, "h": 1, "v": 1, "c": 6, "s": 4, "q": 4, "t": 2, "a": 7}


@dataclass
class Segments:
    """The segments of one element, in its own coordinates.

    Attributes
    ----------
    code : (n,) int8
        ``LINE``, ``QUAD``, ``CUBIC`` or ``ARC``.
    pts : (n, 4, 2) float
        start, first control, second control, end. A quadratic's control is in slot 1;
        an arc's centre is in slot 1.
    arc : (n, 5) float
        rx, ry, x-axis rotation (radians), start parameter, sweep (radians); zeros for
        other kinds. A point of the arc is ``centre + R(rot) (rx cos t, ry sin t)``.
    sub : (n,) int
        The subpath of each segment.
    closed : (k,) bool
        Whether subpath k ends with ``Z``.
    """

    code: np.ndarray
    pts: np.ndarray
    arc: np.ndarray
    sub: np.ndarray
    closed: np.ndarray

    @staticmethod
    def build(rows: list[tuple[int, tuple[float, ...], tuple[float, ...] | None, int]], closed: list[bool]) -> Segments:
        n = len(rows)
        code = np.fromiter((r[0] for r in rows), dtype=np.int8, count=n)
        pts = np.array([r[1] for r in rows], dtype=float).reshape(n, 4, 2)
        arc = np.zeros((n, 5))
        for i, r in enumerate(rows):
            if r[2] is not None:
                arc[i] = r[2]
        sub = np.fromiter((r[3] for r in rows), dtype=np.intp, count=n)
        return Segments(code, pts, arc, sub, np.array(closed, dtype=bool))


EMPTY = Segments(np.zeros(0, np.int8), np.zeros((0, 4, 2)), np.zeros((0, 5)), np.zeros(0, np.intp), np.zeros(0, bool))


# -- arcs --------------------------------------------------------------------------------
def _arc_centre(x0: float, y0: float, rx: float, ry: float, rot_deg: float, large: bool, sweep: bool, x1: float, y1: float) -> tuple[float, ...]:
    """Centre parametrisation of an SVG arc (SVG implementation notes F.6.5, as svgelements).

    Returns ``(cx, cy, rx, ry, rot, t0, dt)`` with radii scaled up when too small; a zero
    radius or equal end points give ``dt = 0`` (the arc is its end point).
    """
    rx, ry = abs(rx), abs(ry)
    if (x0 == x1 and y0 == y1) or rx == 0 or ry == 0:
        return (x0, y0, 0.0, 0.0, 0.0, 0.0, 0.0)
    cosr, sinr = math.cos(math.radians(rot_deg)), math.sin(math.radians(rot_deg))
    dx, dy = (x0 - x1) / 2, (y0 - y1) / 2
    xp = cosr * dx + sinr * dy
    yp = -sinr * dx + cosr * dy
    rx2, ry2 = rx * rx, ry * ry
    check = xp * xp / rx2 + yp * yp / ry2
    if check > 1:
        rx *= math.sqrt(check)
        ry *= math.sqrt(check)
        rx2, ry2 = rx * rx, ry * ry
        # The centre is then the chord's midpoint: c = 0 exactly. svgelements computes
        # sqrt(|rounding error|) here, about 1e-8 of the radius (the one place where the
        # two differ by more than 1e-9 relative).
        c = 0.0
    else:
        t1, t2 = rx2 * yp * yp, ry2 * xp * xp
        c = math.sqrt(abs((rx2 * ry2 - t1 - t2) / (t1 + t2)))
    if large == sweep:
        c = -c
    cxp, cyp = c * rx * yp / ry, -c * ry * xp / rx
    cx = cosr * cxp - sinr * cyp + (x0 + x1) / 2
    cy = sinr * cxp + cosr * cyp + (y0 + y1) / 2
    ux, uy = (xp - cxp) / rx, (yp - cyp) / ry
    vx, vy = (-xp - cxp) / rx, (-yp - cyp) / ry
    d = (ux * vx + uy * vy) / math.sqrt((ux * ux + uy * uy) * (vx * vx + vy * vy))
    delta = math.degrees(math.acos(min(1.0, max(-1.0, d))))
    if ux * vy - uy * vx < 0:
        delta = -delta
    delta %= 360
    if not sweep:
        delta -= 360
    return (cx, cy, rx, ry, math.radians(rot_deg), math.atan2(uy, ux), math.radians(delta))


# -- path data ---------------------------------------------------------------------------
class _Builder:
    """Collects segment rows as svgelements' Path would make them."""

    def __init__(self) -> None:
        self.rows: list[tuple[int, tuple[float, ...], tuple[float, ...] | None, int]] = []
        self.closed: list[bool] = []
        self.cx = self.cy = 0.0  # current point
        self.zx = self.zy = 0.0  # last move
        self.smooth: tuple[float, float] | None = None  # last curve's last control point
        self.open = False  # segments since the last move/close belong to subpath len(closed)-1

    def _sub(self) -> int:
        if not self.open:
            self.closed.append(False)
            self.open = True
        return len(self.closed) - 1

    def move(self, x: float, y: float) -> None:
        self.open = False
        self.cx, self.cy, self.zx, self.zy = x, y, x, y
        self.smooth = None

    def line(self, x: float, y: float) -> None:
        self.rows.append((LINE, (self.cx, self.cy, 0.0, 0.0, 0.0, 0.0, x, y), None, self._sub()))
        self.cx, self.cy, self.smooth = x, y, None

    def reflect(self) -> tuple[float, float]:
        if self.smooth is None:
            return self.cx, self.cy
        return 2 * self.cx - self.smooth[0], 2 * self.cy - self.smooth[1]

    def quad(self, x1: float, y1: float, x: float, y: float) -> None:
        self.rows.append((QUAD, (self.cx, self.cy, x1, y1, 0.0, 0.0, x, y), None, self._sub()))
        self.cx, self.cy, self.smooth = x, y, (x1, y1)

    def cubic(self, x1: float, y1: float, x2: float, y2: float, x: float, y: float) -> None:
        self.rows.append((CUBIC, (self.cx, self.cy, x1, y1, x2, y2, x, y), None, self._sub()))
        self.cx, self.cy, self.smooth = x, y, (x2, y2)

    def arc(self, rx: float, ry: float, rot: float, large: bool, sweep: bool, x: float, y: float) -> None:
        cx, cy, *params = _arc_centre(self.cx, self.cy, rx, ry, rot, large, sweep, x, y)
        self.rows.append((ARC, (self.cx, self.cy, cx, cy, 0.0, 0.0, x, y), tuple(params), self._sub()))
        self.cx, self.cy, self.smooth = x, y, None

    def close(self) -> None:
        if self.open:
            self.closed[-1] = True
        else:  # "M p Z": an empty subpath, closed (it draws nothing)
            self.closed.append(True)
        self.open = False
        self.cx, self.cy, self.smooth = self.zx, self.zy, None

    def done(self) -> Segments:
        return Segments.build(self.rows, self.closed) if self.rows else EMPTY


def parse_path(d: str) -> Segments | None:
    """Segments of SVG path data, or None where svgelements must read it (see the module doc).

    The data is split at its command letters (a number cannot hold one); each command's
    text must be numbers and separators only (issue 17.3: a scan token by token cost
    most of the reading of a path).
    """
    pieces = _COMMAND.split(d)
    if _SEPARATORS.fullmatch(pieces[0]) is None:
        return None  # numbers (or anything else) before the first command
    # Plain data (digits, ".", "e", signs, separators and commands, no "." without a
    # digit after it): each piece between separators that float() reads is one number of
    # the scan below (see points_many), so a command's numbers are its text split.
    plain = _PLAIN_PATH.fullmatch(d) is not None and _LONE_DOT.search(d) is None
    b = _Builder()
    started = False
    for i in range(1, len(pieces), 2):
        cmd, text = pieces[i], pieces[i + 1]
        vals = text.replace(",", " ").split() if plain else None
        if vals is not None:
            try:
                f = [float(v) for v in vals]
            except ValueError:
                vals = None
        if vals is None:
            if _SEPARATORS.fullmatch(_FLOAT_RE.sub("", text)) is None:
                return None
            vals = _FLOAT_RE.findall(text)
            f = [float(v) for v in vals]
        low = cmd.lower()
        rel = cmd != cmd.upper()
        if low == "z":
            if not started or vals:
                return None
            b.close()
            continue
        if not started and low != "m":
            return None
        started = True
        k = _ARGS[low]
        if not vals or len(vals) % k:
            return None  # svgelements has its own readings of these (inline z, empty commands)
        if low == "a":
            for j in range(0, len(vals), 7):
                if vals[j + 3] not in ("0", "1") or vals[j + 4] not in ("0", "1"):
                    return None
        for j in range(0, len(f), k):
            ox, oy = (b.cx, b.cy) if rel else (0.0, 0.0)
            if low == "m":
                if j == 0:
                    b.move(f[j] + ox, f[j + 1] + oy)
                else:
                    b.line(f[j] + ox, f[j + 1] + oy)
            elif low == "l":
                b.line(f[j] + ox, f[j + 1] + oy)
            elif low == "h":
                b.line(f[j] + ox, b.cy)
            elif low == "v":
                b.line(b.cx, f[j] + oy)
            elif low == "c":
                b.cubic(f[j] + ox, f[j + 1] + oy, f[j + 2] + ox, f[j + 3] + oy, f[j + 4] + ox, f[j + 5] + oy)
            elif low == "s":
                x1, y1 = b.reflect()
                b.cubic(x1, y1, f[j] + ox, f[j + 1] + oy, f[j + 2] + ox, f[j + 3] + oy)
            elif low == "q":
                b.quad(f[j] + ox, f[j + 1] + oy, f[j + 2] + ox, f[j + 3] + oy)
            elif low == "t":
                x1, y1 = b.reflect()
                b.quad(x1, y1, f[j] + ox, f[j + 1] + oy)
            else:
                b.arc(f[j], f[j + 1], f[j + 2], f[j + 3] == 1.0, f[j + 4] == 1.0, f[j + 5] + ox, f[j + 6] + oy)
    return b.done()


def parse_numbers(text: str) -> list[float] | None:
    """The numbers of a list separated by spaces or commas, or None when it holds anything else.

    The numbers are those a left-to-right scan for numbers and separators finds; the text
    left when they are removed must be separators only (a scan would stop at anything
    else at the same place, since a number cannot start with a separator).
    """
    if _SEPARATORS.fullmatch(_FLOAT_RE.sub("", text)) is None:
        return None
    return list(map(float, _FLOAT_RE.findall(text)))


def parse_points(text: str) -> list[float] | None:
    """The numbers of a ``points`` attribute, or None when it is not plain pairs."""
    out = parse_numbers(text)
    return out if out is not None and len(out) % 2 == 0 else None


def shape_segments(tag: str, num: dict[str, float], points: str | None) -> Segments | None:
    """Segments of a basic shape as svgelements decomposes it (SVG 2, 10.2-10.7).

    ``num`` holds the shape's lengths in user units; None where svgelements must do it
    (a rounded rect, unusual ``points``).
    """
    b = _Builder()
    if tag == "rect":
        if num.get("rx", 0.0) != 0.0 or num.get("ry", 0.0) != 0.0:
            return None
        x, y, w, h = num["x"], num["y"], num["width"], num["height"]
        b.move(x, y)
        b.line(x + w, y)
        b.line(x + w, y + h)
        b.line(x, y + h)
        b.close()
    elif tag in ("circle", "ellipse"):
        cx, cy = num["cx"], num["cy"]
        rx, ry = (num["r"], num["r"]) if tag == "circle" else (num["rx"], num["ry"])
        b.move(cx + rx, cy)
        sub = b._sub()
        step = math.tau / 4
        for q in range(4):
            t0 = q * step
            x0, y0 = cx + rx * math.cos(t0), cy + ry * math.sin(t0)
            x1, y1 = cx + rx * math.cos(t0 + step), cy + ry * math.sin(t0 + step)
            b.rows.append((ARC, (x0, y0, cx, cy, 0.0, 0.0, x1, y1), (rx, ry, 0.0, math.atan2(math.sin(t0), math.cos(t0)), step), sub))
        b.cx, b.cy = b.rows[-1][1][6], b.rows[-1][1][7]
        b.close()
    elif tag == "line":
        b.move(num["x1"], num["y1"])
        b.line(num["x2"], num["y2"])
    elif tag in ("polyline", "polygon"):
        vals = parse_points(points or "")
        if vals is None:
            return None
        if len(vals) < 4:  # no segment
            return EMPTY
        # what the builder makes, in a few array operations: one line per pair of points
        xy = np.array(vals).reshape(-1, 2)
        n = len(xy) - 1
        pts = np.zeros((n, 4, 2))
        pts[:, 0] = xy[:-1]
        pts[:, 3] = xy[1:]
        return Segments(np.zeros(n, np.int8), pts, np.zeros((n, 5)), np.zeros(n, np.intp), np.array([tag == "polygon"]))
        b.move(vals[0], vals[1])
        for j in range(2, len(vals), 2):
            b.line(vals[j], vals[j + 1])
        if tag == "polygon":
            b.close()
    else:
        return EMPTY
    return b.done()


_PLAIN_CHARS = re.compile(r"[0-9.eE+\-, \t\n\r\x0c]*")
_PLAIN_PATH = re.compile(r"[0-9.eE+\-, \t\n\r\x0cMmZzLlHhVvCcSsQqTtAa]*")
_LONE_DOT = re.compile(r"\.(?![0-9])")


def points_many(texts: list[str], polygon: list[bool]) -> list[Segments | None] | None:
    """:func:`shape_segments` of many ``<polygon>`` / ``<polyline>`` ``points`` texts at
    once (issue 17.3: per element, the regex and numpy calls cost more than their work).

    The texts are checked at once, split at separators and read by ``float``: the same
    numbers as :func:`parse_numbers`' scan, which costs more per text than the work. The
    tables' arrays are views of arrays shared by all of them (none is ever written to).

    Parameters
    ----------
    texts : list of str
        The ``points`` attributes (``""`` where there is none).
    polygon : list of bool
        Whether each is a polygon (closed) or a polyline.

    Returns
    -------
    list of Segments or None, or None
        Per text what :func:`shape_segments` returns (None: an odd count, left to
        svgelements); None when some text holds anything but numbers and separators
        (the caller reads them one by one).
    """
    k = len(texts)
    if k == 0:
        return []
    # Only digits, ".", "e", signs and separators, and no "." without a digit after it:
    # then each piece between separators that float() reads is exactly one number of
    # parse_numbers' scan (a piece holding two, such as "1-2" or ".5.5", or none, makes
    # float() fail, and the texts are left to the caller).
    joined = " ".join(texts)
    if _PLAIN_CHARS.fullmatch(joined) is None or _LONE_DOT.search(joined) is not None:
        return None
    # "nan" (which the texts cannot hold) between texts: its NaNs mark where each ends
    try:
        read = np.array(list(map(float, " nan ".join(texts).replace(",", " ").split())))
    except ValueError:
        return None
    ends = np.r_[np.flatnonzero(np.isnan(read)), len(read)]
    count = ends - np.r_[0, ends[:-1] + 1]
    vals = read[~np.isnan(read)]
    npt = count // 2
    nseg = np.where((count % 2 == 0) & (count >= 4), npt - 1, 0)
    xy = vals[: 2 * (len(vals) // 2)].reshape(-1, 2) if not (count % 2).any() else None
    out: list[Segments | None] = [None if c % 2 else EMPTY for c in count.tolist()]
    if not nseg.any():
        return out
    if xy is None:  # some odd counts: the pairs of the others only
        even = np.repeat(count % 2 == 0, count)
        xy = vals[even].reshape(-1, 2)
        npt = np.where(count % 2 == 0, npt, 0)
    first_pt = np.cumsum(npt) - npt
    seg_start = np.repeat(first_pt, nseg) + (np.arange(int(nseg.sum())) - np.repeat(np.cumsum(nseg) - nseg, nseg))
    total = len(seg_start)
    pts = np.zeros((total, 4, 2))
    pts[:, 0] = xy[seg_start]
    pts[:, 3] = xy[seg_start + 1]
    pts.setflags(write=False)
    # every table's codes (lines), arc parameters and subpath ids are zeros: shared,
    # read-only, by all tables of one length (one slice per table instead of four)
    top = int(nseg.max())
    code, arc, sub = np.zeros(top, np.int8), np.zeros((top, 5)), np.zeros(top, np.intp)
    for a in (code, arc, sub):
        a.setflags(write=False)
    zeros = {n: (code[:n], arc[:n], sub[:n]) for n in set(nseg.tolist())}
    shut = [_OPEN, _SHUT]
    lo = (np.cumsum(nseg) - nseg).tolist()
    for i, (a, n, closed) in enumerate(zip(lo, nseg.tolist(), polygon)):
        if n:
            c, r, u = zeros[n]
            out[i] = Segments(c, pts[a : a + n], r, u, shut[closed])
    return out


# the closed flags of one subpath that points_many's tables share (read-only)
_OPEN, _SHUT = np.array([False]), np.array([True])
_OPEN.setflags(write=False)
_SHUT.setflags(write=False)


def from_svgelements(segments: list[Any]) -> Segments:
    """The table of a list of svgelements segments (the fallback reader's output)."""
    import svgelements as se

    b = _Builder()
    for seg in segments:
        if isinstance(seg, se.Move):
            if seg.end is not None:
                b.move(float(seg.end.x), float(seg.end.y))
            continue
        if isinstance(seg, se.Close):
            b.close()
            if seg.end is not None:
                b.cx, b.cy = float(seg.end.x), float(seg.end.y)
            continue
        if seg.start is None or seg.end is None:
            continue
        if not b.open or (b.cx, b.cy) != (float(seg.start.x), float(seg.start.y)):
            if not b.open:
                b.move(float(seg.start.x), float(seg.start.y))
            b.cx, b.cy = float(seg.start.x), float(seg.start.y)
        ex, ey = float(seg.end.x), float(seg.end.y)
        if isinstance(seg, se.QuadraticBezier):
            b.quad(float(seg.control.x), float(seg.control.y), ex, ey)
        elif isinstance(seg, se.CubicBezier):
            b.cubic(float(seg.control1.x), float(seg.control1.y), float(seg.control2.x), float(seg.control2.y), ex, ey)
        elif isinstance(seg, se.Arc):
            sub = b._sub()
            if seg.sweep == 0 or seg.center is None:
                params = (0.0, 0.0, 0.0, 0.0, 0.0)
                centre = (float(seg.start.x), float(seg.start.y))
            else:
                params = (float(seg.rx), float(seg.ry), float(seg.get_rotation()), float(seg.get_start_t()), float(seg.sweep))
                centre = (float(seg.center.x), float(seg.center.y))
            b.rows.append((ARC, (b.cx, b.cy, *centre, 0.0, 0.0, ex, ey), params, sub))
            b.cx, b.cy, b.smooth = ex, ey, None
        else:
            b.line(ex, ey)
    return b.done()


# -- transforms --------------------------------------------------------------------------
def parse_transform(text: str) -> np.ndarray | None:
    """(2, 3) matrix of a ``transform`` attribute, or None where svgelements must read it."""
    pos = 0
    a, b, c, d, e, f = 1.0, 0.0, 0.0, 1.0, 0.0, 0.0  # x' = a x + c y + e, y' = b x + d y + f
    text = text.strip()
    while pos < len(text):
        match = _TRANSFORM.match(text, pos)
        if match is None:
            return None
        pos = match.end()
        name = match.group(1).lower()
        vals = parse_numbers(match.group(2))
        if vals is None:
            return None
        k = len(vals)
        if name == "matrix" and k == 6:
            sa, sb, sc, sd, se, sf = vals
        elif name == "translate" and k in (1, 2):
            sa, sb, sc, sd, se, sf = 1.0, 0.0, 0.0, 1.0, vals[0], vals[1] if k == 2 else 0.0
        elif name == "scale" and k in (1, 2):
            sa, sb, sc, sd, se, sf = vals[0], 0.0, 0.0, vals[1] if k == 2 else vals[0], 0.0, 0.0
        elif name == "rotate" and k in (1, 3):
            t = math.radians(vals[0])
            co, si = math.cos(t), math.sin(t)
            px, py = (vals[1], vals[2]) if k == 3 else (0.0, 0.0)
            sa, sb, sc, sd, se, sf = co, si, -si, co, px - co * px + si * py, py - si * px - co * py
        elif name == "skewx" and k == 1:
            sa, sb, sc, sd, se, sf = 1.0, 0.0, math.tan(math.radians(vals[0])), 1.0, 0.0, 0.0
        elif name == "skewy" and k == 1:
            sa, sb, sc, sd, se, sf = 1.0, math.tan(math.radians(vals[0])), 0.0, 1.0, 0.0, 0.0
        else:
            return None
        # apply the step first, then what came before it
        a, b, c, d, e, f = (a * sa + c * sb, b * sa + d * sb, a * sc + c * sd, b * sc + d * sd,
                            a * se + c * sf + e, b * se + d * sf + f)
    return np.array([[a, c, e], [b, d, f]])


def too_large(segs: Segments, limit: float) -> bool:
    """Whether a point that defines a segment (ends and control points) is beyond ``limit`` or not finite."""
    if len(segs.code) == 0:
        return False
    if float(np.abs(segs.pts).max()) <= limit:  # the common case, in one pass
        return False
    used = np.zeros((len(segs.code), 4), dtype=bool)
    used[:, 0] = used[:, 3] = True
    used[:, 1] = (segs.code == QUAD) | (segs.code == CUBIC)
    used[:, 2] = segs.code == CUBIC
    with np.errstate(invalid="ignore"):
        bad = ~(np.abs(segs.pts) <= limit).all(axis=2)
    return bool((bad & used).any())


# -- flattening --------------------------------------------------------------------------
def curve_bounds(segs: Segments) -> np.ndarray:
    """(n,) a bound on ``|B''(t)|`` per segment (0 for lines; NaN where a point is NaN)."""
    p = segs.pts
    out = np.zeros(len(segs.code))
    q = segs.code == QUAD
    if q.any():
        dd = p[q, 0] - 2 * p[q, 1] + p[q, 3]
        out[q] = 2 * np.sqrt((dd * dd).sum(axis=1))
    c = segs.code == CUBIC
    if c.any():
        d1 = p[c, 0] - 2 * p[c, 1] + p[c, 2]
        d2 = p[c, 1] - 2 * p[c, 2] + p[c, 3]
        out[c] = 6 * np.maximum(np.sqrt((d1 * d1).sum(axis=1)), np.sqrt((d2 * d2).sum(axis=1)))
    a = segs.code == ARC
    if a.any():
        out[a] = segs.arc[a, 4] ** 2 * np.maximum(segs.arc[a, 0], segs.arc[a, 1])
    return out


def flatten(segs: Segments, tol: float, small: int = 400) -> list[tuple[np.ndarray, bool, bool]]:
    """Subpaths as ``(points (m, 2), closed, curved)``, curves within ``tol`` of the chords.

    Consecutive equal points are merged; a subpath is closed when it ends with ``Z`` or
    when it has at least four points and its ends meet; paths with fewer than two points
    or with non-finite points are dropped (as the importer always did).

    Elements of at most ``small`` points are sampled in plain Python floats (the same
    arithmetic, in the same order): numpy's per-call cost outweighs its speed on a few
    dozen points, and most objects of a drawing are that small.
    """
    n = len(segs.code)
    if n == 0:
        return []
    code = segs.code
    if not code.any():  # lines only (polygons): the end points, no sampling
        if n <= small:
            return _flatten_small(segs, [1] * n, [False] * n)
        return _subpaths(segs, segs.pts[:, 3], np.ones(n, dtype=np.intp), np.zeros(n, dtype=bool))
    bound = curve_bounds(segs)
    is_curve = (code != LINE) & np.isfinite(bound)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        steps = np.ceil(np.sqrt(bound / (8 * tol)))
        cnt = np.where(is_curve, np.clip(steps, 1, MAX_SEGMENT_POINTS), 1).astype(np.intp)
    total = int(cnt.sum())
    if total <= small:
        return _flatten_small(segs, cnt.tolist(), is_curve.tolist())
    seg_of = np.repeat(np.arange(n), cnt)
    first = np.cumsum(cnt) - cnt
    j = np.arange(total) - first[seg_of] + 1  # 1 .. cnt
    t = j * (1.0 / cnt)[seg_of]
    last = j == cnt[seg_of]
    t[last] = 1.0
    out = np.empty((total, 2))
    p = segs.pts[seg_of]
    c = code[seg_of]
    sel = c == LINE
    out[sel] = p[sel, 3]
    sel = c == QUAD
    if sel.any():
        u = t[sel][:, None]
        v = 1 - u
        pp = p[sel]
        out[sel] = v * v * pp[:, 0] + 2 * (v * u) * pp[:, 1] + u * u * pp[:, 3]
    sel = c == CUBIC
    if sel.any():
        u = t[sel][:, None]
        v = 1 - u
        pp = p[sel]
        out[sel] = v * v * v * pp[:, 0] + 3 * (v * v * u * pp[:, 1] + u * u * v * pp[:, 2]) + u * u * u * pp[:, 3]
    sel = c == ARC
    if sel.any():
        ar = segs.arc[seg_of[sel]]
        pp = p[sel]
        tt = ar[:, 3] + ar[:, 4] * t[sel]
        cr, sr = np.cos(ar[:, 2]), np.sin(ar[:, 2])
        ct, st = np.cos(tt), np.sin(tt)
        out[sel, 0] = pp[:, 1, 0] + ar[:, 0] * ct * cr - ar[:, 1] * st * sr
        out[sel, 1] = pp[:, 1, 1] + ar[:, 0] * ct * sr + ar[:, 1] * st * cr
    # the end of every segment is its end point exactly (svgelements' "clean endings")
    out[last] = segs.pts[seg_of[last], 3]
    return _subpaths(segs, out, cnt, is_curve)


def _flatten_small(segs: Segments, cnt: list[int], is_curve: list[bool]) -> list[tuple[np.ndarray, bool, bool]]:
    """:func:`flatten` for a few points, one float at a time (same formulas as the arrays)."""
    code = segs.code.tolist()
    pts = segs.pts.tolist()
    arc = segs.arc.tolist() if ARC in code else None
    sub = segs.sub.tolist()
    closed_flags = segs.closed.tolist()
    result: list[tuple[np.ndarray, bool, bool]] = []
    n = len(code)
    i = 0
    while i < n:
        k = sub[i]
        (x, y), *_ = pts[i]
        xs, ys = [x], [y]
        curved = False
        while i < n and sub[i] == k:
            c, p, m = code[i], pts[i], cnt[i]
            curved = curved or is_curve[i]
            if c == CUBIC and m > 1:
                (x0, y0), (x1, y1), (x2, y2), _ = p
                step = 1.0 / m
                for j in range(1, m):
                    u = j * step
                    v = 1 - u
                    xs.append(v * v * v * x0 + 3 * (v * v * u * x1 + u * u * v * x2) + u * u * u * p[3][0])
                    ys.append(v * v * v * y0 + 3 * (v * v * u * y1 + u * u * v * y2) + u * u * u * p[3][1])
            elif c == QUAD and m > 1:
                (x0, y0), (x1, y1), _, (x2, y2) = p
                step = 1.0 / m
                for j in range(1, m):
                    u = j * step
                    v = 1 - u
                    xs.append(v * v * x0 + 2 * (v * u) * x1 + u * u * x2)
                    ys.append(v * v * y0 + 2 * (v * u) * y1 + u * u * y2)
            elif c == ARC and m > 1:
                rx, ry, rot, t0, dt = arc[i]  # type: ignore[index]
                cx, cy = p[1]
                cr, sr = math.cos(rot), math.sin(rot)
                step = 1.0 / m
                for j in range(1, m):
                    tt = t0 + dt * (j * step)
                    ct, st = math.cos(tt), math.sin(tt)
                    xs.append(cx + rx * ct * cr - ry * st * sr)
                    ys.append(cy + rx * ct * sr + ry * st * cr)
            xs.append(p[3][0])  # the end point exactly
            ys.append(p[3][1])
            i += 1
        # merge consecutive equal points
        kx, ky = [xs[0]], [ys[0]]
        for q in range(1, len(xs)):  # against the previous point, kept or not (as np.diff)
            if abs(xs[q] - xs[q - 1]) > 1e-12 or abs(ys[q] - ys[q - 1]) > 1e-12:
                kx.append(xs[q])
                ky.append(ys[q])
        ax, ay, bx, by = kx[0], ky[0], kx[-1], ky[-1]
        ends_meet = abs(ax - bx) <= 1e-9 + 1e-5 * abs(bx) and abs(ay - by) <= 1e-9 + 1e-5 * abs(by)
        closed = bool(closed_flags[k]) or (len(kx) >= 4 and ends_meet)
        if closed and len(kx) > 1 and ends_meet:
            kx.pop()
            ky.pop()
        if len(kx) >= 2:
            arr = np.empty((len(kx), 2))
            arr[:, 0] = kx
            arr[:, 1] = ky
            if np.isfinite(arr).all():
                result.append((arr, closed, curved))
    return result


def _subpaths(segs: Segments, out: np.ndarray, cnt: np.ndarray, is_curve: np.ndarray) -> list[tuple[np.ndarray, bool, bool]]:
    """Split the samples ``out`` (``cnt`` per segment) into subpaths, each led by its start point."""
    sub = segs.sub
    result: list[tuple[np.ndarray, bool, bool]] = []
    if sub[-1] == sub[0]:  # one subpath
        edges = [0, len(sub)]
        first = [0, len(out)]
    else:
        edges = np.flatnonzero(np.r_[True, sub[1:] != sub[:-1], True]).tolist()
        starts = np.r_[0, np.cumsum(cnt)]
        first = starts[edges].tolist()
    for i in range(len(edges) - 1):
        a, b = edges[i], edges[i + 1]
        k = int(sub[a])
        pts = np.concatenate([segs.pts[a, 0][None, :], out[first[i] : first[i + 1]]])
        keep = np.ones(len(pts), dtype=bool)
        keep[1:] = (np.abs(np.diff(pts, axis=0)) > 1e-12).any(axis=1)
        pts = pts[keep]
        (ax, ay), (bx, by) = pts[0], pts[-1]
        ends_meet = abs(ax - bx) <= 1e-9 + 1e-5 * abs(bx) and abs(ay - by) <= 1e-9 + 1e-5 * abs(by)
        closed = bool(segs.closed[k]) or (len(pts) >= 4 and ends_meet)
        if closed and len(pts) > 1 and ends_meet:
            pts = pts[:-1]
        if len(pts) >= 2 and np.isfinite(pts).all():
            result.append((pts, closed, bool(is_curve[a:b].any())))
    return result


# -- exact path data ---------------------------------------------------------------------
def _fmt(v: float) -> str:
    v = float(v)
    if abs(v) < 1e-10:  # rounding noise from transforms (e.g. -8.9e-16)
        v = 0.0
    s = format(v, ".12g")
    return "0" if s in ("-0", "0") else s


def path_d(segs: Segments, m: np.ndarray, rot: float, s: float) -> str:
    """Path data of ``segs`` mapped by the similarity ``m`` (rotation ``rot``, scale ``s``)."""
    lin, off = m[:, :2], m[:, 2]

    def pt(x: float, y: float) -> str:
        q = lin @ np.array([x, y]) + off
        return f"{_fmt(q[0])},{_fmt(q[1])}"

    out: list[str] = []
    prev_sub = -1
    prev_end: tuple[float, float] | None = None
    for i in range(len(segs.code)):
        k = int(segs.sub[i])
        p = segs.pts[i]
        if k != prev_sub:
            if prev_sub >= 0 and segs.closed[prev_sub]:
                out.append("Z")
            out.append("M" + pt(p[0, 0], p[0, 1]))
            prev_sub = k
        elif prev_end is not None and (p[0, 0], p[0, 1]) != prev_end:
            out.append("M" + pt(p[0, 0], p[0, 1]))
        c = int(segs.code[i])
        if c == LINE:
            out.append("L" + pt(p[3, 0], p[3, 1]))
        elif c == QUAD:
            out.append(f"Q{pt(p[1, 0], p[1, 1])} {pt(p[3, 0], p[3, 1])}")
        elif c == CUBIC:
            out.append(f"C{pt(p[1, 0], p[1, 1])} {pt(p[2, 0], p[2, 1])} {pt(p[3, 0], p[3, 1])}")
        else:
            rx, ry, phi, _, sweep = segs.arc[i]
            if sweep == 0:
                out.append("L" + pt(p[3, 0], p[3, 1]))
            else:
                large = int(abs(sweep) > math.pi)
                axis = math.degrees(math.atan2(math.sin(phi), math.cos(phi)) + rot)
                out.append(f"A{_fmt(s * rx)},{_fmt(s * ry)} {_fmt(axis)} {large},{int(sweep > 0)} {pt(p[3, 0], p[3, 1])}")
        prev_end = (p[3, 0], p[3, 1])
    if prev_sub >= 0 and segs.closed[prev_sub]:
        out.append("Z")
    return " ".join(out)


# -- many elements at once ---------------------------------------------------------------
def flatten_many(tables: list[Segments], tols: np.ndarray, *, plus_zero: bool = False) -> list[list[tuple[np.ndarray, bool, bool]]]:
    """:func:`flatten` of many elements in one batch of numpy (issue 17.3).

    Parameters
    ----------
    tables : list of Segments
        One table per element.
    tols : (k,) float
        The tolerance of each element.
    plus_zero : bool
        Add 0.0 to every point (what the identity map gives: -0.0 becomes 0.0), in one
        operation for all, for callers that draw the elements in their own frame.

    Returns
    -------
    list of lists of ``(points (m, 2), closed, curved)``
        What :func:`flatten` returns for each element: the same points, bit for bit (the
        same formulas in the same order, elementwise), the same merging of equal points
        and the same closing rule.
    """
    k = len(tables)
    out: list[list[tuple[np.ndarray, bool, bool]]] = [[] for _ in range(k)]
    nseg = np.fromiter((len(t.code) for t in tables), dtype=np.intp, count=k)
    if k == 0 or not nseg.any():
        return out
    nsub = np.fromiter((len(t.closed) for t in tables), dtype=np.intp, count=k)
    code = np.concatenate([t.code for t in tables])
    pts = np.concatenate([t.pts for t in tables])
    arc = np.concatenate([t.arc for t in tables])
    closed_flag = np.concatenate([t.closed for t in tables])
    elem = np.repeat(np.arange(k), nseg)
    # subpath ids, unique over all elements
    sub = np.concatenate([t.sub for t in tables]) + np.repeat(np.cumsum(nsub) - nsub, nseg)
    n = len(code)
    segs = Segments(code, pts, arc, sub, closed_flag)
    bound = curve_bounds(segs)
    is_curve = (code != LINE) & np.isfinite(bound)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        steps = np.ceil(np.sqrt(bound / (8 * np.asarray(tols, dtype=float)[elem])))
        cnt = np.where(is_curve, np.clip(steps, 1, MAX_SEGMENT_POINTS), 1).astype(np.intp)
    # every subpath: its start point, then cnt samples per segment
    first_of_sub = np.r_[True, sub[1:] != sub[:-1]]
    lead = first_of_sub.astype(np.intp)  # one leading point before the segment's samples
    per_seg = cnt + lead
    total = int(per_seg.sum())
    seg_of = np.repeat(np.arange(n), per_seg)
    first = np.cumsum(per_seg) - per_seg
    j = np.arange(total) - first[seg_of] + 1 - lead[seg_of]  # 0 for a leading point, else 1 .. cnt
    samples = np.empty((total, 2))
    is_lead = j == 0
    samples[is_lead] = pts[seg_of[is_lead], 0]
    body = ~is_lead
    sb = seg_of[body]
    jb = j[body]
    t = jb * (1.0 / cnt)[sb]
    last = jb == cnt[sb]
    t[last] = 1.0
    res = np.empty((len(sb), 2))
    p = pts[sb]
    c = code[sb]
    sel = c == LINE
    res[sel] = p[sel, 3]
    sel = c == QUAD
    if sel.any():
        u = t[sel][:, None]
        v = 1 - u
        pp = p[sel]
        res[sel] = v * v * pp[:, 0] + 2 * (v * u) * pp[:, 1] + u * u * pp[:, 3]
    sel = c == CUBIC
    if sel.any():
        u = t[sel][:, None]
        v = 1 - u
        pp = p[sel]
        res[sel] = v * v * v * pp[:, 0] + 3 * (v * v * u * pp[:, 1] + u * u * v * pp[:, 2]) + u * u * u * pp[:, 3]
    sel = c == ARC
    if sel.any():
        ar = arc[sb[sel]]
        pp = p[sel]
        tt = ar[:, 3] + ar[:, 4] * t[sel]
        cr, sr = np.cos(ar[:, 2]), np.sin(ar[:, 2])
        ct, st = np.cos(tt), np.sin(tt)
        res[sel, 0] = pp[:, 1, 0] + ar[:, 0] * ct * cr - ar[:, 1] * st * sr
        res[sel, 1] = pp[:, 1, 1] + ar[:, 0] * ct * sr + ar[:, 1] * st * cr
    res[last] = pts[sb[last], 3]  # the end of every segment is its end point exactly
    samples[body] = res
    group = sub[seg_of]  # subpath of every sample
    # merge consecutive equal points, each against the previous point (kept or not)
    keep = np.ones(total, dtype=bool)
    diff = np.abs(samples[1:] - samples[:-1]) > 1e-12
    keep[1:] = (diff[:, 0] | diff[:, 1]) | (group[1:] != group[:-1])
    samples, group = samples[keep], group[keep]
    gstart = np.flatnonzero(np.r_[True, group[1:] != group[:-1]])
    gend = np.r_[gstart[1:], len(group)]
    gid = group[gstart]
    count = gend - gstart
    a, b = samples[gstart], samples[gend - 1]
    meet = (np.abs(a[:, 0] - b[:, 0]) <= 1e-9 + 1e-5 * np.abs(b[:, 0])) & (np.abs(a[:, 1] - b[:, 1]) <= 1e-9 + 1e-5 * np.abs(b[:, 1]))
    closed = closed_flag[gid] | ((count >= 4) & meet)
    drop = closed & (count > 1) & meet
    gend = gend - drop
    count = gend - gstart
    finite = np.isfinite(samples).all(axis=1)
    bad = np.r_[0, np.cumsum(~finite)]
    ok = (count >= 2) & (bad[gend] == bad[gstart])
    curved_sub = np.zeros(len(closed_flag), dtype=bool)
    np.logical_or.at(curved_sub, sub, is_curve)
    elem_of_sub = np.repeat(np.arange(k), nsub)
    if plus_zero:
        samples = samples + 0.0
    g_ok = gid[ok]
    for e, s0, s1, cl, cv in zip(elem_of_sub[g_ok].tolist(), gstart[ok].tolist(), gend[ok].tolist(), closed[ok].tolist(), curved_sub[g_ok].tolist()):
        out[e].append((samples[s0:s1], cl, cv))
    return out
