"""Finding the best matching reference element (Ijiri et al. 2008, §5.2, §5.3).

Target and reference neighbours are ordered counter-clockwise. The set ``F`` of
matchings pairs the target neighbours ``t_0 .. t_{T-1}`` with consecutive reference
neighbours ``r_k .. r_{k+T-1}`` (cyclically), one matching per start ``k``: no skipping,
no flipping. Each matching is scored by Eq. 2 and a reference by the minimum over ``F``
(Eq. 3). References with fewer neighbours than the target are skipped.
"""

from __future__ import annotations

import numba
import numpy as np

__all__ = ["MODES", "match_references", "matching_set", "order_target", "W1", "W2", "W3"]

#: rotation modes (§5.3) and their codes in the kernel
MODES = {"fixed": 0, "rotate": 1, "flow": 2}
#: §5.2: "We set w1 = 1.0, w2 = 1.0, and w3 = 100.0"
W1, W2, W3 = 1.0, 1.0, 100.0


def matching_set(n_target: int, n_reference: int) -> list[list[tuple[int, int]]]:
    """The set F of cyclic matchings without skipping or flipping (§5.2, Fig. 4).

    Returns one list of ``(target index, reference index)`` pairs per start ``k``;
    empty when the reference has fewer neighbours than the target.

    Examples
    --------
    >>> len(matching_set(4, 6)), matching_set(2, 3)[2]
    (6, [(0, 2), (1, 0)])
    """
    if n_target > n_reference:
        return []
    return [[(i, (k + i) % n_reference) for i in range(n_target)] for k in range(n_reference)]


def order_target(rel: np.ndarray) -> np.ndarray:
    """Counter-clockwise order of target neighbours, starting at the boundary (§5.2).

    The target neighbourhood of a seed is partial; it starts with the neighbour that
    follows the largest angular gap, so that consecutive neighbours are matched to
    consecutive reference neighbours.

    Parameters
    ----------
    rel : (T, 2) float
        Neighbour positions relative to the seed.

    Returns
    -------
    (T,) int
    """
    if len(rel) == 0:
        return np.zeros(0, dtype=np.intp)
    a = np.arctan2(rel[:, 1], rel[:, 0]).tolist()
    order = sorted(range(len(a)), key=a.__getitem__)
    t = len(order)
    best, start = -1.0, 0
    for q in range(t):
        nxt = a[order[(q + 1) % t]] + (2 * np.pi if q == t - 1 else 0.0)
        gap = nxt - a[order[q]]
        if gap > best:
            best, start = gap, (q + 1) % t
    return np.asarray(order[start:] + order[:start], dtype=np.intp)


@numba.njit(cache=True)
def _ring_cost(ref_rel, ref_kind, r, nr, k, t_rel, t_kind, th, w1, w2):  # pragma: no cover - compiled
    """Eq. 3's w1 and w2 terms: reference ring ``r`` turned by ``th``, shifted by ``k``, against the target."""
    c = np.cos(th)
    s = np.sin(th)
    e = 0.0
    for i in range(t_rel.shape[0]):
        j = (k + i) % nr
        px = c * ref_rel[r, j, 0] - s * ref_rel[r, j, 1]
        py = s * ref_rel[r, j, 0] + c * ref_rel[r, j, 1]
        dx = t_rel[i, 0] - px
        dy = t_rel[i, 1] - py
        e += w1 * np.sqrt(dx * dx + dy * dy)
        if t_kind[i] != ref_kind[r, j]:
            e += w2
    return e


@numba.njit(cache=True)
def _match_kernel(ref_rel, ref_kind, ref_n, ref_sub, cand, t_rel, t_kind, t_sub, mode, flow_theta, frame_theta, frame_w, max_turn, keep_frame, w1, w2, w3, out_err, out_shift, out_theta):  # pragma: no cover - compiled
    R = ref_rel.shape[0]
    T = t_rel.shape[0]
    for r in range(R):
        out_err[r] = np.inf
        out_shift[r] = -1
        out_theta[r] = 0.0
        nr = ref_n[r]
        if not cand[r] or nr < T:
            continue
        # w3 * subid: a target neighbour with the same sub-id as this reference element
        pen = 0.0
        for i in range(T):
            if t_sub[i] == ref_sub[r]:
                pen += w3
        best = np.inf
        best_k = 0
        best_th = 0.0
        for k in range(nr):
            th = 0.0
            if mode == 1 and T == 1 and frame_w > 0.0:
                th = frame_theta  # one neighbour fixes no rotation: keep its frame
            elif mode == 1 and T > 0:
                # Eq. 4: the rotation minimising the positional difference (shape
                # matching [MHTG05]). With two or more neighbours both point sets are
                # centred first, as in [MHTG05]: the seed's own position is a guess
                # (an extra seed of Fig. 6e sits on a bisector), and a rotation about it
                # would turn the element to absorb that error.
                cx = 0.0
                cy = 0.0
                qx = 0.0
                qy = 0.0
                if T >= 2:
                    for i in range(T):
                        j = (k + i) % nr
                        cx += t_rel[i, 0]
                        cy += t_rel[i, 1]
                        qx += ref_rel[r, j, 0]
                        qy += ref_rel[r, j, 1]
                    cx /= T
                    cy /= T
                    qx /= T
                    qy /= T
                a = 0.0
                b = 0.0
                for i in range(T):
                    j = (k + i) % nr
                    px = ref_rel[r, j, 0] - qx
                    py = ref_rel[r, j, 1] - qy
                    tx = t_rel[i, 0] - cx
                    ty = t_rel[i, 1] - cy
                    a += px * tx + py * ty
                    b += px * ty - py * tx
                th = np.arctan2(b, a)
            elif mode == 1:
                th = frame_theta  # no target neighbour: the neighbours' frame, if any
            elif mode == 2:
                th = flow_theta
            e = _ring_cost(ref_rel, ref_kind, r, nr, k, t_rel, t_kind, th, w1, w2)
            if mode == 1 and frame_w > 0.0:
                # departure from Eq. 4 (see match_references): the turn away from the
                # frame of the neighbouring elements costs, and is held within max_turn
                d = th - frame_theta
                d = d - 2.0 * np.pi * np.floor(d / (2.0 * np.pi) + 0.5)
                clamped = False
                if d > max_turn:
                    d = max_turn
                    clamped = True
                elif d < -max_turn:
                    d = -max_turn
                    clamped = True
                th = frame_theta + d
                e = _ring_cost(ref_rel, ref_kind, r, nr, k, t_rel, t_kind, th, w1, w2)
                e += frame_w * max(T, 1) * abs(d)
                if (T < keep_frame or (clamped and keep_frame > 0)) and d != 0.0:
                    # the turn is charged linearly, so the best turn for this matching
                    # is either the fitted one or none: with few target neighbours (a
                    # fit from two is mostly noise) keeping the neighbours' frame is a
                    # candidate too. Without it bricks tumbled by up to max_turn in
                    # patches (Eq. 5 of the fidelity suite failed 5/5); with it for
                    # every count, rows lost the small turns that absorb their noise.
                    e0 = _ring_cost(ref_rel, ref_kind, r, nr, k, t_rel, t_kind, frame_theta, w1, w2)
                    if e0 <= e:
                        e = e0
                        th = frame_theta
            if e < best:
                best = e
                best_k = k
                best_th = th
        out_err[r] = best + pen
        out_shift[r] = best_k
        out_theta[r] = best_th


def match_references(
    rings: dict[str, np.ndarray],
    target_rel: np.ndarray,
    target_kind: np.ndarray,
    target_sub: np.ndarray,
    *,
    mode: str = "fixed",
    flow_theta: float = 0.0,
    candidates: np.ndarray | None = None,
    weights: tuple[float, float, float] = (W1, W2, W3),
    frame_theta: float = 0.0,
    frame_weight: float = 0.0,
    max_turn: float = np.pi,
    keep_frame: int = 0,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """ERROR(w(e_tar), w(e_ref)) of Eq. 3 for every reference element.

    Parameters
    ----------
    rings : dict
        :meth:`Reference.ring_arrays` (``rel`` (r, K, 2), ``kind``, ``sub`` (r, K),
        ``n`` (r,), ``ids`` (r,)).
    target_rel : (T, 2) float
        Target neighbours relative to the seed, in the order of :func:`order_target`.
    target_kind, target_sub : (T,) int
        Their symbol ids and sub-ids.
    mode : {"fixed", "rotate", "flow"}
        §5.3 rotation mode.
    flow_theta : float
        Flow direction at the seed (radians), for ``mode="flow"``.
    candidates : (r,) bool, optional
        References allowed (a seed with a symbol id admits only that kind).
    weights : (w1, w2, w3)
    frame_theta, frame_weight : float
        Rotation mode only: the rotation of the neighbouring elements' reference frames
        (radians) and the error per radian and per target neighbour of turning away from
        it. Not in the paper: Eq. 4 alone is blind to the lattice's symmetry (a square
        ring fits as well turned by 90°, one neighbour fits any turn) and lets noise in
        near-regular rings turn each element a little, so the frame drifts and patches
        grow at different angles. With a weight of about the mean edge length, a turn
        costs what displacing every neighbour by that arc would. 0 gives Eq. 4.
    max_turn : float
        With ``frame_weight > 0``: the largest turn away from ``frame_theta`` (radians);
        a fit beyond it is evaluated at the limit.
    keep_frame : int
        With ``frame_weight > 0`` and fewer than ``keep_frame`` target neighbours, each
        matching is also evaluated without a turn (at ``frame_theta``), and the cheaper
        of the two is kept. 0: never.

    Returns
    -------
    error : (r,) float
        ``inf`` for skipped references.
    shift : (r,) int
        The best matching ``f_k``: target ``i`` pairs with reference neighbour ``(k + i) % n``.
    theta : (r,) float
        Rotation applied to the reference ring (0 in ``fixed`` mode).
    """
    R = len(rings["n"])
    cand = np.ones(R, dtype=np.bool_) if candidates is None else np.asarray(candidates, dtype=np.bool_)
    err = np.empty(R)
    shift = np.empty(R, dtype=np.int64)
    theta = np.empty(R)
    t_rel = np.ascontiguousarray(target_rel, dtype=np.float64).reshape(-1, 2)
    _match_kernel(
        rings["rel"],
        rings["kind"],
        rings["n"],
        rings["ids"],
        cand,
        t_rel,
        np.ascontiguousarray(target_kind, dtype=np.int64),
        np.ascontiguousarray(target_sub, dtype=np.int64),
        MODES[mode],
        float(flow_theta),
        float(frame_theta),
        float(frame_weight),
        float(max_turn),
        int(keep_frame),
        float(weights[0]),
        float(weights[1]),
        float(weights[2]),
        err,
        shift,
        theta,
    )
    return err, shift, theta
