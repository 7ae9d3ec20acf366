"""Fields over the plane: flow fields interpolated from strokes.

A flow field gives a direction at every point. :func:`flow_field` builds one from
strokes the user drew: the unit tangents of the strokes, sampled along them, are the
constraints, and radial basis functions fill the plane in between (Ijiri et al. 2008,
§3, after Esch et al. 2007), with :class:`scipy.interpolate.RBFInterpolator`.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

import numpy as np

from ._errors import InputError

__all__ = ["FlowField", "flow_field", "resample_polyline"]


def resample_polyline(points: np.ndarray, spacing: float) -> tuple[np.ndarray, np.ndarray]:
    """Points every ``spacing`` along a polyline, with the unit tangent at each.

    Parameters
    ----------
    points : (n, 2) float
    spacing : float

    Returns
    -------
    samples : (m, 2) float
    tangents : (m, 2) float
        Unit vectors along the direction of travel.
    """
    p = np.asarray(points, dtype=float)
    seg = np.diff(p, axis=0)
    length = np.linalg.norm(seg, axis=1)
    keep = length > 0
    seg, length = seg[keep], length[keep]
    if len(seg) == 0:
        return np.zeros((0, 2)), np.zeros((0, 2))
    start = p[:-1][keep]
    cum = np.r_[0.0, np.cumsum(length)]
    total = cum[-1]
    m = max(2, int(np.ceil(total / spacing)) + 1)
    s = np.linspace(0, total, m)
    k = np.clip(np.searchsorted(cum, s, side="right") - 1, 0, len(seg) - 1)
    t = (s - cum[k]) / length[k]
    samples = start[k] + t[:, None] * seg[k]
    tangents = seg[k] / length[k, None]
    return samples, tangents


class FlowField:
    """A direction field interpolated from stroke tangents with radial basis functions.

    Call it with points ``(m, 2)`` to get unit directions ``(m, 2)``; :meth:`angle`
    gives the direction as an angle in radians (``atan2(dy, dx)``).

    Parameters
    ----------
    samples : (k, 2) float
        Constraint positions along the strokes.
    tangents : (k, 2) float
        Unit tangents there.
    smoothing : float
        RBF smoothing (0 interpolates exactly).
    kernel : str
        :class:`scipy.interpolate.RBFInterpolator` kernel.
    neighbors : int, optional
        Local RBF with this many nearest constraints (faster for many samples).
    """

    def __init__(
        self,
        samples: np.ndarray,
        tangents: np.ndarray,
        *,
        smoothing: float = 1e-3,
        kernel: str = "thin_plate_spline",
        neighbors: int | None = None,
    ) -> None:
        from scipy.interpolate import RBFInterpolator

        samples = np.asarray(samples, dtype=float).reshape(-1, 2)
        tangents = np.asarray(tangents, dtype=float).reshape(-1, 2)
        if len(samples) == 0:
            raise InputError("flow: no stroke to build a flow field from")
        self.samples = samples
        self.tangents = tangents
        if len(samples) < 3:
            # too few constraints for an RBF with a linear tail: the field is constant
            self._const = tangents.mean(axis=0)
            self._rbf = None
        else:
            self._const = None
            try:
                self._rbf = RBFInterpolator(samples, tangents, kernel=kernel, smoothing=smoothing, neighbors=neighbors)
            except np.linalg.LinAlgError:
                # Collinear constraints (one straight stroke): a kernel with a constant
                # tail instead of a linear one keeps the system solvable.
                self._rbf = RBFInterpolator(samples, tangents, kernel="linear", degree=0, smoothing=smoothing, neighbors=neighbors)

    def __call__(self, points: np.ndarray | Sequence[float]) -> np.ndarray:
        """(m, 2) unit directions at ``points`` (m, 2)."""
        p = np.asarray(points, dtype=float).reshape(-1, 2)
        v = np.tile(self._const, (len(p), 1)) if self._rbf is None else self._rbf(p)
        n = np.linalg.norm(v, axis=1, keepdims=True)
        fallback = np.where(n > 1e-12, n, 1.0)
        v = np.where(n > 1e-12, v / fallback, np.array([1.0, 0.0]))
        return v

    def angle(self, points: np.ndarray | Sequence[float]) -> np.ndarray:
        """(m,) direction angles in radians at ``points`` (m, 2)."""
        v = self(points)
        return np.arctan2(v[:, 1], v[:, 0])


def flow_field(strokes: Iterable[np.ndarray], *, spacing: float | None = None, smoothing: float = 1e-3, kernel: str = "thin_plate_spline") -> FlowField:
    """Flow field from strokes: RBF interpolation of their tangents (Ijiri et al. §3).

    Parameters
    ----------
    strokes : iterable of (n, 2) float
        Polylines; their direction of travel is the flow direction.
    spacing : float, optional
        Distance between tangent samples along each stroke; by default 1/20 of the
        strokes' overall extent.
    smoothing, kernel
        Passed to :class:`scipy.interpolate.RBFInterpolator`.

    Returns
    -------
    FlowField

    Examples
    --------
    >>> f = flow_field([np.array([[0.0, 0.0], [10.0, 0.0]])])
    >>> f([[5.0, 30.0]]).round(6).tolist()
    [[1.0, 0.0]]
    """
    polys = [np.asarray(s, dtype=float).reshape(-1, 2) for s in strokes]
    polys = [p for p in polys if len(p) >= 2 and np.any(np.linalg.norm(np.diff(p, axis=0), axis=1) > 0)]
    if not polys:
        raise InputError("flow: no stroke with two distinct points to build a flow field from")
    allp = np.concatenate(polys)
    if not np.all(np.isfinite(allp)):
        raise InputError("flow: NaN or inf coordinate in a stroke")
    if spacing is None:
        spacing = max(float(np.ptp(allp, axis=0).max()) / 20.0, 1e-9)
    samples, tangents = zip(*(resample_polyline(p, spacing) for p in polys))
    s = np.concatenate(samples)
    t = np.concatenate(tangents)
    # Exact duplicates make the RBF system singular (strokes meeting end to end).
    _, first = np.unique(np.round(s, 9), axis=0, return_index=True)
    first = np.sort(first)
    neighbors = 64 if len(first) > 400 else None
    return FlowField(s[first], t[first], smoothing=smoothing, kernel=kernel, neighbors=neighbors)
