"""Choosing and placing (Ijiri et al. 2008, §5.2–5.4): the best matching reference
element for a seed, fitting its position, and its 1-ring's unpaired elements as new seeds.

Split out of :mod:`strew.grow._growth` (issue 15).
"""

from __future__ import annotations

import heapq
import math
from collections.abc import Sequence
from typing import Any

import numpy as np
import shapely

from ._analysis import SKEW_ANGLE
from ._match import match_references, order_target
from ._objects import (
    ELEMENT,
    SEED,
)
from ._place_kernels import slot_probe
from ._spacing import KEEP_SHARE


def _skewed(p: Sequence[float], q: Sequence[float], r: Sequence[float]) -> bool:
    """True when triangle pqr has an angle of 2π/3 or more (§4's skewed triangles)."""
    a2 = (q[0] - r[0]) ** 2 + (q[1] - r[1]) ** 2
    b2 = (p[0] - r[0]) ** 2 + (p[1] - r[1]) ** 2
    c2 = (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2
    a, b, c = math.sqrt(a2), math.sqrt(b2), math.sqrt(c2)
    # cos(angle) <= -1/2 at any vertex
    return b2 + c2 - a2 <= -b * c + 1e-12 or a2 + c2 - b2 <= -a * c + 1e-12 or a2 + b2 - c2 <= -a * b + 1e-12




#: up to this many values np.mean sums one after another from 0.0 (numpy's pairwise
#: sum takes eight at a time only from eight on), so a Python sum in order over the
#: count is np.mean to the bit (``_Place.choose``'s carried frame; checked in
#: tests/grow/test_grow_g70v_flow_kernels.py)
_MEAN_EXACT = 7

class _Place:
    """The seed priority (§5.1), matching (§5.2, §5.3) and placement (§5.4)."""

    def seed_priority(self, i: int) -> float:
        # Extra seeds (no symbol id, §5.4e) take the lowest priority: they fill gaps.
        k = self.kind[i]
        return self.none_prio if k < 0 else float(self.kind_prio[k])

    def outranked(self, i: int) -> bool:
        """§5.1: grow only seeds of the highest priority within 5 * l."""
        if not self.use_prio:
            return False
        k = self.kind[i]
        pi = self.none_prio if k < 0 else self.kind_prio_list[k]  # seed_priority(i), inlined
        if pi >= self.top_prio:
            return False  # nothing ranks above the highest priority
        x, y = self.xy[i]
        r2 = (5 * self.l) ** 2
        xy = self.xy
        # the live seeds above the lowest priority, on a grid of cells 5 l wide: nine
        # cells to look at instead of the hundred of the fine grid
        h = self.hcell
        cx, cy = math.floor(x / h), math.floor(y / h)
        hg = self.hgrid
        kind = self.kind
        state = self.state
        kp = self.kind_prio_list
        none = self.none_prio
        oo = self.orig_of
        spray = self.spray_area
        # The answer is whether any seed holds i back: first the one that did when i was
        # last deferred, if it still would be met below (listed in one of the nine cells,
        # and passing the same tests); a seed is deferred some four times on average, and
        # this spares most of the scans (issue 14 point 5)
        # kinds whose share behind this seed is already the reference's: their seeds do
        # not hold it back (see _prio_full; asked once per kind and call)
        full: dict[int, bool] = {}
        gate = self.p.priority_share and self.canopy_ref_share is not None
        j = self.outranker.get(i)
        if j is not None and j != i and state[j] == SEED and oo[j] != i:
            kj = kind[j]
            px, py = xy[j]
            jx, jy = math.floor(px / h), math.floor(py / h)
            if ((none if kj < 0 else kp[kj]) > pi and (px - x) ** 2 + (py - y) ** 2 <= r2
                    and -1 <= jx - cx <= 1 and -1 <= jy - cy <= 1 and j in hg.get((jx, jy), ())
                    and (spray is None or shapely.contains_xy(spray, px, py))
                    and not (gate and self._prio_full(i, kj, full))):
                return True
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                cell = hg.get((cx + dx, cy + dy))
                if not cell:
                    continue
                for j in cell:
                    if j == i or state[j] != SEED or oo[j] == i:
                        continue
                    kj = kind[j]
                    if (none if kj < 0 else kp[kj]) <= pi:  # seed_priority(j), inlined
                        continue
                    px, py = xy[j]
                    if (px - x) ** 2 + (py - y) ** 2 > r2:
                        continue
                    # a seed outside the spray area cannot grow now: it does not hold
                    # others back (they would wait for it, and the spray would stall)
                    if spray is not None and not shapely.contains_xy(spray, px, py):
                        continue
                    if gate and self._prio_full(i, kj, full):
                        continue
                    self.outranker[i] = j
                    return True
        return False

    def _prio_full(self, i: int, b: int, full: dict[int, bool]) -> bool:
        """Does kind ``b`` already hold the reference's share of the settled elements
        behind seed ``i`` (:meth:`canopy_full`), so that its seeds lose their §5.1
        priority over ``i``? ``full`` caches the answer per kind within one call.

        Departs from §5.1 (larger elements first, always). With the larger kinds first,
        a medium kind that is the reference's majority lost its places to the large
        seeds its own rings propose: ``--harder`` three sizes 20:120:20 grew the medium
        stones at 0.83-0.95 of the exemplar's density and the large ones at 1.09-1.18
        (h7, variant seeds 12-30, seed 1), density[medium] failing 4 of 6 seeds on
        h7s30 (0.137-0.174 against 0.126); with no priority at all 0.97-1.00 and
        0.89-0.97, as the generator at the output's size (1.06 and 0.91), but the
        small-stone majorities (300:20:10) lost their larger kinds. Gated at the share
        the canopy gates its conversions at (``canopy_share``, ``canopy_share_z``,
        ``canopy_few_z``), the largest kind keeps its priority over a seed of a middle
        kind short of its own share (:meth:`_kind_short`) only while it is under it.
        (helper g43m, ``benchmarks/g43m_kinds.py``.) With two sizes the small kind's
        seeds are gated so too (helper g45f, ``benchmarks/g45f_steps.py``: the stones'
        surplus was made by the priority itself, in the growth steps before any hole
        fill, and with no priority at all the share was the reference's).
        """
        if b < 0 or self.size_level[b] != self.top_level:
            # only the largest kind (as _over_smaller_seeds): gating the middle kind let
            # the small ones crowd it where they are the majority (300:20:10, h0s27:
            # nn[medium>small] 0.087 against 0.075)
            return False
        v = full.get(b)
        if v is None:
            v = full[b] = self._kind_short(i) and self.canopy_full(i, b)
        return v

    def _kind_short(self, i: int) -> bool:
        """Is seed ``i``'s kind's share of the settled elements behind it (as
        :meth:`canopy_full` counts them) under the reference's by more than
        ``canopy_share_z`` binomial standard deviations? (Only such a seed is let past
        a full larger kind's seeds, :meth:`_prio_full`: where the small stones are the
        majority (300:20:10, ``--harder`` h0s27) letting every kind past the large seeds
        lost nn[medium>small], 5/6 -> 1/6 seeds. With two sizes, where there is no
        middle kind, the smallest kind's seeds are asked too, unless they are grit:
        ``small_past``.)"""
        a = int(self.kind[i])
        ref = self.canopy_ref_share
        if a < 0 or ref is None or not ref[a] > 0 or (self.size_level[a] <= float(self.size_level.min()) and not self.small_past):
            # a middle kind only: small stones let past the large seeds where they are
            # short still lost h0s27 (nn[medium>small] at seeds 2-4 of 1-4). With two
            # sizes the smallest kind is let past too (helper g45f): the stones' seeds
            # took every place their rings proposed before the pebbles' seeds there, and
            # the growth made 0.53-0.55 stones behind its front where the reference has
            # 0.47-0.49 (--harder two_sizes h0s32: fraction[stone] 0.0735-0.0833 against
            # 0.0596, 0/6 seeds; the large kind over the reference's share on most h0
            # draws at variants 7-30, benchmarks/results/g45f_bias_h0_*.txt). There is
            # no middle kind for the small ones to crowd. Not where the small kind is grit
            # (under SMALL_PAST_RATIO of the large radius, ``small_past``): there the
            # priority is what fills the stones' gaps, and grit let past took the
            # stones' places (EDGE two_sizes p2s27, p2s30).
            return False
        k = self._settled_behind(i)
        m = 0 if k is None else len(k)
        if m * ref[a] < 2:
            return False
        q = float(ref[a])
        return bool(np.count_nonzero(k == a) < m * (q - self.p.canopy_share_z * math.sqrt(q * (1 - q) / m)))

    def release_deferred(self, i: int) -> None:
        if not self.deferred:
            return
        x, y = self.xy[i]
        r2 = (5 * self.l) ** 2
        xy = self.xy
        if self.tile is not None:  # on the torus: the nearest images
            _, _, w, h = self.tile
            near = [j for j in self.deferred if self.state[j] == SEED
                    and (d := (xy[j][0] - x - w * round((xy[j][0] - x) / w), xy[j][1] - y - h * round((xy[j][1] - y) / h)))
                    and d[0] ** 2 + d[1] ** 2 <= r2]
        else:
            # the deferred seeds in the nine cells (5 l wide) around i
            h = self.hcell
            cx, cy = math.floor(x / h), math.floor(y / h)
            dg = self.dgrid
            state = self.state
            near = [j for dx in (-1, 0, 1) for dy in (-1, 0, 1) for j in dg.get((cx + dx, cy + dy), ())
                    if (xy[j][0] - x) ** 2 + (xy[j][1] - y) ** 2 <= r2 and state[j] == SEED]
        for j in sorted(near):
            if j in self.deferred:
                self._undefer(j)
                heapq.heappush(self.heap, (math.hypot(self.xy[j][0] - self.origin[0], self.xy[j][1] - self.origin[1]), j))

    def missing_larger(self, s: int) -> list[int]:
        """Larger kinds with no element or seed where the reference always has one.

        Not in the paper. With kinds of several sizes (stones ringed by pebbles) the
        larger ones come only from the rings of placed elements (§5.4); where their seeds
        die (overlaps, the priority wait of §5.1) no ring proposes another, and the small
        ones fill a gap in the larger kind that the reference never has: three sizes grew
        small stones up to 30 units from the nearest large one where the reference has at
        most 23. A seed of kind ``a`` that has no element or seed of a larger kind ``b``
        within :attr:`reach_larger` ``[a, b]`` (a quantile of the reference's distances
        from ``a`` to its nearest ``b``) is first tried as a ``b`` (largest kind first).
        """
        k = int(self.kind[s])
        if k < 0:
            return []  # an extra seed of Fig. 6e fills a gap; it has no kind to miss a larger one
        row = self.reach_larger[k]
        want = np.flatnonzero(np.isfinite(row))
        if len(want) == 0:
            return []
        x, y = self.xy[s]
        r = float(row[want].max())
        have = set()
        for o in self.near(x, y, r):
            b = int(self.kind[o])
            if self.orig_of[o] != s and b >= 0 and (self.xy[o][0] - x) ** 2 + (self.xy[o][1] - y) ** 2 <= row[b] ** 2:
                have.add(b)
        out = [int(b) for b in want if int(b) not in have]
        out.sort(key=lambda b: -self.size_level[b])
        return out

    def choose(self, s: int) -> tuple[int, int, float] | None:
        """§5.2: the reference element minimising Eq. 3 for seed ``s``."""
        # §5.2: w(e_tar) are the seed's immediate neighbours. We take the placed elements
        # among them only: seeds have no sub-id yet and their positions are guesses.
        nb = [j for j in self.adj[s] if self.state[j] == ELEMENT]
        ps = self.pos[s]
        if nb:
            rel = self.pos[nb] - ps
            order = order_target(rel)
            nb_arr = np.asarray(nb)[order]
            rel = rel[order]
            if self.tile is not None and len(nb_arr) >= 3:
                nb_arr, rel = self._one_arc(nb_arr, rel)
        else:
            nb_arr = np.zeros(0, dtype=np.int64)
            rel = np.zeros((0, 2))
        k = self.kind[s]
        cand = self.all_candidates
        if k >= 0 and self.kind_has_candidates[k]:
            # §5.2: a seed with a symbol id examines only references of that id. A kind that
            # occurs only on the exemplar's boundary has no reference: any element may go.
            cand = self.kind_candidates[k]
        n_max = self._ring_max.get(int(k))
        if n_max is None:
            n_max = self._ring_max[int(k)] = int(self.rings["n"][cand].max()) if cand.any() else 0
        if 0 < n_max < len(nb_arr):
            # Not in the paper: a seed that waited (§5.1 priority) or sits where fronts
            # meet can be joined to more placed neighbours than any reference ring has,
            # and then matched none and died, leaving a hole (bricks with a priority: one
            # brick missing). Its nearest n_max neighbours are matched.
            near = np.sort(np.argsort(np.hypot(rel[:, 0], rel[:, 1]), kind="stable")[:n_max])
            nb_arr, rel = nb_arr[near], rel[near]
            order = order_target(rel)
            nb_arr, rel = nb_arr[order], rel[order]
        flow_theta = 0.0
        if self.mode_code == 2:
            v = self.p.flow(ps[None, :])[0]
            flow_theta = math.atan2(v[1], v[0])
        frame_theta, frame_w = 0.0, 0.0
        mode = self.p.mode
        if self.mode_code == 1 and len(nb_arr):
            # the neighbours' reference frames (their Eq. 4 rotations), circular mean
            f = self.frame[nb_arr]
            frame_theta = math.atan2(float(np.sin(f).sum()), float(np.cos(f).sum()))
            frame_w = self.p.frame_weight * self.l
        elif self.mode_code == 2 and self.p.flow_fit:
            # §5.3 turns the reference to the flow direction exactly. We fit the rotation
            # to the placed neighbours as in rotation mode, held within max_turn of the
            # flow direction and charged for the turn away from it: where the field bends
            # the neighbours' lattice then bends with it gradually, instead of each
            # element taking the field's angle and leaving holes and overlaps between
            # neighbours that took different ones.
            frame_theta, frame_w, mode = flow_theta, self.p.frame_weight * self.l, "rotate"
            if len(nb_arr) and self.p.flow_carry:
                # Not in the paper: the fit alone keeps the neighbours' frame, so the
                # lattice lags the field by max_turn, ahead of the field where growth
                # runs against its turn and behind it where growth runs with it; the
                # two meet in seams. The fitted frame is carried on by the field's turn
                # from the neighbours to the seed (the target is turned by it before the
                # fit): the lattice turns with the field.
                # the field at each neighbour where it was placed (``_bent_ring``)
                fa = self._flow_at
                got = [fa.get(j) for j in nb_arr.tolist()]
                if len(got) <= _MEAN_EXACT and None not in got:
                    # (the same sums in Python floats: np.mean of up to seven values is
                    # their sum from 0.0 in order over the count, and np.round at no
                    # decimals rounds half to even as round() does; the numpy calls
                    # cost more than the sums. Issue 14 point 5, g70v)
                    tot = 0.0
                    for v in got:
                        d = v - flow_theta
                        tot += d - math.pi * round(d / math.pi)
                    carry = -(tot / len(got))
                else:
                    va = np.array([math.nan if v is None else v for v in got])
                    miss = np.isnan(va)
                    if miss.any():
                        v = np.asarray(self.p.flow(self.pos[nb_arr[miss]]), dtype=float)
                        va[miss] = np.arctan2(v[:, 1], v[:, 0])
                    # a line field: the neighbours' mean direction with the seed's sign
                    dd = va - flow_theta
                    dd = dd - np.pi * np.round(dd / np.pi)
                    carry = -float(np.mean(dd))
                if abs(carry) > 1e-12:
                    cc, ss = math.cos(carry), math.sin(carry)
                    turned = np.empty_like(rel)  # (np.c_ costs more than the turn)
                    turned[:, 0] = cc * rel[:, 0] - ss * rel[:, 1]
                    turned[:, 1] = ss * rel[:, 0] + cc * rel[:, 1]
                    rel = turned
        err, shift, theta = match_references(
            self.rings,
            rel,
            self.kind[nb_arr],
            self.sub[nb_arr],
            mode=mode,
            flow_theta=flow_theta,
            candidates=cand,
            weights=self.p.weights,
            frame_theta=frame_theta,
            frame_weight=frame_w,
            max_turn=self.p.flow_max_turn if self.mode_code == 2 else self.max_turn,
            keep_frame=self.p.keep_frame if self.mode_code == 1 else 0,
        )
        best = float(err.min()) if len(err) else math.inf
        self._last_err = err
        if not math.isfinite(best):
            return None
        # Equally good references (e.g. every one for the very first seed) are chosen at
        # random from ``rng``; the paper does not say how it breaks ties.
        ties = np.flatnonzero(err <= best + 1e-9 * (1.0 + best))
        a = int(ties[0]) if len(ties) == 1 else int(ties[self.rng.integers(len(ties))])
        self._last_nb = nb_arr
        self._last_pick = (shift, theta)
        return a, int(shift[a]), float(theta[a])

    def place_next(self, s: int, pick: tuple[int, int, float]) -> bool:
        """Seed ``s`` of a thin kind whose chosen element overlapped: the next references.

        Not in the paper, which tests no overlaps (§5.2 takes the one reference that
        minimises Eq. 3). The overlap guard of :meth:`place` kills the seed, and for thin
        kinds (sticks) the overlap is mostly the chosen element's own orientation crossing
        a neighbour's, not the seed's place: on sticks p0s21 (seed 1) 831 of 1,604
        placements were refused so, against 742 placed, and the output was 0.875 of the
        exemplar's density. Up to :data:`THIN_RETRY` next references by Eq. 3 error (finite
        only) are tried at the seed's place, best first, until one fits: the §5.2
        minimum over the references whose element overlaps nothing. Fixed mode only: in
        rotation mode (§5.3) the retries took sticks' suite case from 15 s to 73 s (1,245
        to 1,540 elements) where it passed without them.
        """
        from ._growth import THIN_RETRY

        if self.mode_code != 0 or not self._overlapped or THIN_RETRY <= 0 or not self.thin[int(self.ex_kind[self.ref_ids[pick[0]]])]:
            return False
        err = self._last_err
        shift, theta = self._last_pick
        x0, y0 = float(self.xy[s][0]), float(self.xy[s][1])
        order = np.argsort(err, kind="stable")
        tried = 0
        for a in order.tolist():
            if tried >= THIN_RETRY or not math.isfinite(float(err[a])):
                break
            if a == pick[0]:
                continue
            tried += 1
            self._move(s, x0, y0)
            self._overlapped = False
            self._out_of_domain = False
            if self.place(s, a, int(shift[a]), float(theta[a])):
                return True
        self._move(s, x0, y0)
        return False

    def _one_arc(self, nb: np.ndarray, rel: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The longest run of placed neighbours without a gap wider than :attr:`arc_gap`.

        Not in the paper. §5.2 matches the target's neighbours, in angular order, to
        consecutive ring slots (no skipping). In the plane the placed neighbours of a
        seed lie on one arc of the front; on the torus, where the front meets itself, a
        seed has neighbours from both sides with empty slots between them, and matching
        them to consecutive slots pulls the seed off the lattice (scales_hex in a tile
        that is a multiple of its periods: 32 of 400 elements off by up to a quarter
        spacing). The longest arc is matched; the others are met again as the ring's
        seeds merge with them (Fig. 6b), which pairs them with their own slots.
        """
        ang = np.arctan2(rel[:, 1], rel[:, 0])
        gaps = np.mod(np.diff(ang), 2 * np.pi)
        cut = np.flatnonzero(gaps > self.arc_gap) + 1
        if len(cut) == 0:
            return nb, rel
        bounds = np.r_[0, cut, len(nb)]
        q = int(np.argmax(np.diff(bounds)))
        sel = slice(int(bounds[q]), int(bounds[q + 1]))
        return nb[sel], rel[sel]

    def canopy_full(self, s: int, b: int) -> bool:
        """Is kind ``b``'s share of the settled elements already the reference's?

        Not in the paper (nor is the canopy, :meth:`missing_larger`). A seed that misses
        a larger kind fills a gap in it, but where the growth already makes that kind at
        the reference's share the conversions come on top: three sizes drawn 1:1.5:3
        (--harder 3, variant seed 12) grew 9.8 large stones per 1e4 against the
        reference's 8.4 (8.5 without the canopy), while the suite's three sizes needs it
        (6.8 against 7.06, 6.0 without). The share is counted among the elements behind
        the growth front (nearer the initial seed, by :attr:`canopy_settle`, than ``s``:
        at the front the larger kinds, which grow first (§5.1), are over-represented)
        and at least :attr:`canopy_wall` from the region's edge, against the reference's
        by the same minus sampling (:meth:`_canopy_share_setup`); until that sample
        should hold 2 of kind ``b``, or where the reference counts too few of ``b`` to
        know its share (``CANOPY_MIN_REF``), the seed converts as before, unless
        ``canopy_few_z`` gates such a kind at an upper bound of its share
        (:attr:`canopy_few_share`).
        """
        ref = self.canopy_ref_share
        if ref is None:
            return False
        if not ref[b] > 0 and self.canopy_few_share is not None:
            # a kind counted too few of to know its share: its share's upper bound
            ref = self.canopy_few_share
        if not ref[b] > 0:
            return False
        k = self._settled_behind(s)
        if k is None or len(k) * ref[b] < 2:
            return False
        # the sample's own spread (binomial, ``canopy_share_z`` standard deviations) is
        # allowed: near the initial seed the first few hundred elements drew shares of
        # 0.13-0.16 large where the reference has 0.127 and the pattern ends at 0.11, and a
        # gate at the bare share left gaps there (the suite's three sizes, seed 1:
        # nn[small>large] 0.162 against 0.127)
        q = ref[b]
        n = len(k)
        return bool(np.count_nonzero(k == b) >= n * (self.p.canopy_share * q + self.p.canopy_share_z * math.sqrt(q * (1 - q) / n)))

    def _settled_behind(self, s: int) -> np.ndarray | None:
        """Kinds of the canopy's settled sample behind seed ``s`` (nearer the initial seed
        by :attr:`canopy_settle`), shape (m,); None where ``s`` is within that distance."""
        self._settle_update()
        x, y = self.xy[s]
        r = math.hypot(x - self.origin[0], y - self.origin[1]) - self.canopy_settle
        if r <= 0:
            return None
        n = self._settle_n
        return self._settle_k[:n][self._settle_r[:n] <= r]

    def _settle_update(self) -> None:
        """Append the elements placed since the last call to the canopy's settled sample."""
        new = self.order[self._settle_seen:]
        self._settle_seen = len(self.order)
        if not new:
            return
        kinds = np.asarray([self.kind[i] for i in new], dtype=np.int64)
        pts = np.asarray([self.xy[i] for i in new], dtype=float)
        keep = kinds >= 0
        vk = self.void_kind
        keep[keep] &= ~vk[kinds[keep]]
        w = self.canopy_wall
        if w > 0 and self.region is not None:
            if self.region_box is not None:
                x0, y0, x1, y1 = self.region_box
                edge = np.minimum.reduce([pts[:, 0] - x0, x1 - pts[:, 0], pts[:, 1] - y0, y1 - pts[:, 1]])
            else:
                edge = shapely.distance(self.region.geometry.boundary, shapely.points(pts))
            keep &= edge >= w
        r = np.hypot(pts[keep, 0] - self.origin[0], pts[keep, 1] - self.origin[1])
        m = len(r)
        n = self._settle_n
        if n + m > len(self._settle_r):
            size = max(2 * len(self._settle_r), n + m)
            self._settle_r = np.resize(self._settle_r, size)
            self._settle_k = np.resize(self._settle_k, size)
        self._settle_r[n:n + m] = r
        self._settle_k[n:n + m] = kinds[keep]
        self._settle_n = n + m

    def try_larger(self, s: int) -> bool:
        """Place seed ``s`` as a larger kind it misses (:meth:`missing_larger`); True when placed.

        Sets :attr:`_refused_far` where a seed of the smallest kind should die instead
        (``GrowParams.canopy_refuse``).
        """
        self._refused_far = False
        kinds = self.missing_larger(s)
        if not kinds:
            return False
        own = int(self.kind[s])
        ox, oy = self.xy[s]
        for b in kinds:
            if not self.kind_has_candidates[b] or self.canopy_full(s, b):
                continue
            self.kind[s] = b
            pick = self.choose(s)
            if pick is not None and self.place(s, *pick, reach=self.p.canopy_reach * self.l):
                return True
            self.kind[s] = own
            if self.xy[s] != (ox, oy):
                self._move(s, ox, oy)
            f = self.p.canopy_refuse
            known = self.canopy_refuse_ok
            if (f is not None and own >= 0 and self.size_level[b] == self.top_level
                    and self.size_level[own] == self.size_level.min() and known is not None and known[b]):
                # Not in the paper (§5.4 places the seed as its own kind). The largest
                # kind's lattice had a hole here that small stones filled before a large
                # seed came, and a large one then no longer fitted (too_close_in_kind):
                # small stones beyond the reference's reach of every large one (three
                # sizes h6s13: 103 of 818, 97 from refused conversions). The small seed
                # dies and leaves the hole open: a later seed there (a neighbour's ring
                # proposes one) may become the large stone. Only the smallest kind: with
                # the middle kind too, rows whose reference counts few of it lost it
                # (density[medium], nn[medium>large]; benchmarks/results/g26t_canopy_refuse.md).
                # Only where the reference counts enough large stones over its frame
                # (CANOPY_MIN_REF; h6s13 counts 24, fewer than 20 beyond the wall reach
                # that canopy_full counts in): with 15 (h12s17) the holes
                # left became large stones on top of a share already above the
                # reference's, and nn[large>small] failed (2 of 3 seeds).
                r = f * float(self.reach_larger[own, b])
                if not any(int(self.kind[o]) == b and self.state[o] == ELEMENT
                           and (self.xy[o][0] - ox) ** 2 + (self.xy[o][1] - oy) ** 2 <= r * r for o in self.near(ox, oy, r)):
                    self._refused_far = True
        return False

    def try_smaller(self, s: int) -> bool:
        """Place seed ``s``, whose element crossed a boundary stroke, as a smaller kind; True when placed.

        Not in the paper, whose boundary tool only stops growth. A seed of a large kind
        by the region's edge or a boundary stroke, where its element would reach across,
        died and left a gap the size of that element, which nothing filled: a closed
        stroke around stones with pebbles was filled to 0.83-0.87 of its inside (the
        inside away from the stroke at the exemplar's density). The seed is tried as
        each smaller kind, largest first, as :meth:`try_larger` tries larger ones.
        Only at strokes: at the region's edge, which crops the pattern as the
        exemplar's frame does, the fidelity suite's three sizes lost a seed's worth
        (nn[small>large] failed on seed 3 too).
        """
        own = int(self.kind[s])
        if own < 0:
            return False
        lv = self.size_level
        smaller = [b for b in range(self.n_kinds) if lv[b] < lv[own] and self.kind_has_candidates[b]]
        smaller.sort(key=lambda b: -lv[b])
        ox, oy = self.xy[s]
        for b in smaller:
            self.kind[s] = b
            pick = self.choose(s)
            if pick is not None and self.place(s, *pick):
                return True
            self.kind[s] = own
            if self.xy[s] != (ox, oy):
                self._move(s, ox, oy)
        return False

    def place(self, s: int, a: int, k: int, th: float, reach: float | None = None) -> bool:
        """§5.4: replace seed ``s`` by reference ``a`` and put its unpaired ring out as seeds."""
        p = self.p
        if self.rep is not None and self.order:
            # throttled poll of should_cancel, before this step changes anything (a seed
            # that refuses its placements costs lookups but no growth step)
            self.rep.tick(len(self.order))
        r = int(self.ref_ids[a])
        kind = int(self.ex_kind[r])
        n_ring = int(self.rings["n"][a])
        c, sn = math.cos(th), math.sin(th)
        rel = self.rings["rel"][a, :n_ring]
        nb = self._last_nb
        if len(nb) >= 2 or (reach is not None and len(nb) >= 1):
            self._fit_position(s, nb, rel, k, c, sn, reach)
        x, y = self.xy[s]
        rot = float(self.ex_rot[r]) + th
        scale = float(self.ex_scale[r])
        if p.jitter_rotation > 0:
            rot += float(self.rng.uniform(-p.jitter_rotation, p.jitter_rotation))
        if p.jitter_scale > 0:
            scale *= float(1.0 + self.rng.uniform(-p.jitter_scale, p.jitter_scale))
        # an element as close to one of its own kind (or another) as the reference never
        # has them is refused, like the seeds of too_close_in_kind
        if self.too_close_in_kind(x, y, kind, s, (ELEMENT,), placing=True):
            return False
        if self.ref_nn is not None and self.crowds_reference_nn(x, y, s, r):
            return False
        if self.gap_ratio[kind] > 0 and self.crowds_own_kind(x, y, kind, scale, s):
            return False
        if self.several_sizes and not self.lean_ok(s, a, k, th, x, y, kind):
            return False
        g = self.element_geometry(kind, x, y, rot, scale)
        # Not in the paper: an element must lie wholly inside the region and off the
        # boundary strokes (the paper stops growth at them; an element whose centre is
        # inside could still reach across).
        if not self.fits_domain(g):
            # (a boundary stroke, not the region's edge: see try_smaller)
            self._out_of_domain = self.boundary is not None and bool(shapely.intersects(self.boundary, g))
            return False
        # Not in the paper: a placement that would overlap an element is refused (the
        # seed dies), so that an exemplar without overlaps grows a pattern without any.
        if p.avoid_overlaps and self.overlaps_any(g, kind, x, y, scale):
            self._overlapped = True
            # Fixed mode without priorities: only where the slot is enclosed (at most
            # ``nudge_open`` of its ring's slots unplaced). The nudge is for slots that
            # closed in (fronts that met; with §5.1's priorities, low-priority seeds
            # among placed ones). In the open front a nudged element is off the lattice,
            # later seeds fit their positions to it (_fit_position) and the offset
            # spreads until two fronts meet out of step: bricks seed 5 grew a seam half
            # a course out of step (regularity 0.060 against 0.05) from 4 nudges with
            # 2-4 of 6 slots placed. In rotation mode each element's turn moves its
            # ring a little and the nudge keeps those overlaps from leaving holes
            # (without it bricks rotate seeds 1, 2, 4 failed).
            if (p.nudge_open is not None and self.mode_code == 0 and not self.use_prio
                    and sum(self.state[o] == ELEMENT for o in self.adj[s]) < n_ring - p.nudge_open):
                return False
            moved = self._nudge(s, kind, x, y, rot, scale)
            if moved is None:
                return False
            x, y, g = moved
        # Not in the paper: §5.2's collision test per pair of kinds (the reference's least
        # gaps between them, ``_Grower._pair_gaps``; fixed mode)
        if p.avoid_overlaps and self.pair_gap_max[kind] > 0 and self.crowds_gap(g, kind, x, y, scale, s):
            return False
        self._unhigh(s)
        self.state[s] = ELEMENT
        self.kind[s] = kind
        self.sub[s] = r
        self.rot[s] = rot
        self.scl[s] = scale
        self.refslot[s] = a
        self.frame[s] = th
        self.geom[s] = g
        self.color[s] = self._color(r) if self.want_color else None
        if self.tile is not None:
            self._sync(s)
        self.order.append(s)
        self.dirty.add(s)

        ring_pos = np.empty((n_ring, 2))
        ring_pos[:, 0] = x + c * rel[:, 0] - sn * rel[:, 1]
        ring_pos[:, 1] = y + sn * rel[:, 0] + c * rel[:, 1]
        if self.mode_code == 2 and p.flow_bend > 0:
            rel = self._bent_ring(s, x, y, rel, ring_pos, c, sn)
            c, sn = 1.0, 0.0
            ring_pos[:, 0] = x + rel[:, 0]
            ring_pos[:, 1] = y + rel[:, 1]
        ring_kind = self.rings["kind"][a, :n_ring].tolist()
        ring_xy = ring_pos.tolist()
        slot_of: dict[int, int] = {}
        for i, j in enumerate(nb.tolist()):
            slot_of[j] = (k + i) % n_ring
        paired = set(slot_of.values())
        gap_min = self.ring_gap_min[a]
        plane = self.tile is None
        if plane:
            over_on, l_short, top_level = bool(self.over_smaller), float(self.l_short), float(self.top_level)
            size_level, pair_short, pair_short_max = self.size_level, self.pair_short, self.pair_short_max
        xy = self.xy
        ang_of: dict[int, float] = {}
        fixed = self.mode_code == 0
        two_pi = 2 * math.pi
        # (crosses_boundary without a boundary is False, and crosses_edges in the plane
        # is GrowIndex.crosses_plane: called directly in the loops below, which run for
        # every slot of every placed element; the same answers, issue 14 point 5)
        bnd = self.boundary is not None
        index = self.index
        oo = self.orig_of
        # New seeds (Fig. 2g) with the heuristics of Fig. 6 (b)-(d).
        for j in range(n_ring):
            if j in paired:
                continue
            cx, cy = ring_xy[j]
            if not self.in_domain(cx, cy):
                continue
            if bnd and self.crosses_boundary((x, y), (cx, cy)):
                self.fixed[s] = True  # Eq. 6: elements at user boundaries are constrained
                continue
            # (b) merge with an object within l_short
            # a slot of the largest kind is not lost to seeds of smaller kinds (§5.1)
            if plane:
                # the three tests below in one compiled call (the same answers: issue 14
                # point 5; _place_kernels.slot_probe)
                pts = index.points
                _, o, tc = slot_probe(cx, cy, s, ring_kind[j], over_on, l_short, size_level, top_level, pair_short, pair_short_max,
                                         index.cell, pts.head, pts.ent, pts.cur, pts.ext, index.pos, index.state, self.kind, index.out)
                if tc:
                    continue
                close = o >= 0
            else:
                over = self.over_smaller and ring_kind[j] >= 0 and self.size_level[ring_kind[j]] == self.top_level and self._over_smaller_seeds(s, cx, cy, ring_kind[j])
                close = self.near(cx, cy, self.l_short) if not over else []
                close = [o for o in close if self.orig_of[o] != s]
                if not close and not over and self.too_close_in_kind(cx, cy, ring_kind[j], s):
                    continue
                if close:
                    o = min(close, key=lambda o: (self.xy[o][0] - cx) ** 2 + (self.xy[o][1] - cy) ** 2)
            if close:
                if not self.has_edge(s, o):
                    po = self.xy[o]
                    if (not (index.crosses_plane(oo[s], (x, y), oo[o], po) if plane else self.crosses_edges(s, (x, y), o, po))
                            and not (bnd and self.crosses_boundary((x, y), po))):
                        self.add_edge(s, o)
                        slot_of.setdefault(o, j)
                continue
            # (c) angle check against the neighbours already around s. The "original
            # angle" is taken as the smaller of the two reference ring angles beside slot j.
            # A neighbour that no slot of this ring pairs with has no corresponding angle
            # in the ring (the paper's Fig. 6c compares edges of the ring shape): it
            # refuses the slot only where the triangle (s, slot, neighbour) is skewed in
            # the sense of §4. Not in the paper. The bricks' centres are nearly
            # cocircular in fours, so the reference's Delaunay rings (§4) mix horizontal
            # and vertical edges; a ring without the horizontal edges has 82-96 degree
            # gaps, and a horizontal neighbour 40 degrees from a diagonal slot refused
            # that slot although slot and neighbour lie a lattice spacing apart: the
            # Fig. 6e extra seed then filled the gap off the lattice, and a seam of
            # courses out of step grew from it (bricks rotate seed 4: Eq. 5 179 against
            # a tolerance of 45.9). Only in the rotating modes: in fixed mode the rule
            # changed irregular exemplars (three sizes seed 2: nn[small>large] 0.130 against a
            # tolerance of 0.127), and fixed bricks passed without it.
            ang = math.atan2(cy - y, cx - x)
            too_close = False
            half = 0.5 * gap_min[j]
            for o in self.adj[s]:
                # (each neighbour's angle about s once per placement: the slots ask the
                # same neighbours in turn, and no object moves in this loop; the same
                # values, issue 14 point 5)
                a_o = ang_of.get(o)
                if a_o is None:
                    po = xy[o]
                    a_o = ang_of[o] = math.atan2(po[1] - y, po[0] - x)
                d = abs(a_o - ang)
                d = min(d, two_pi - d)
                if d < half and (fixed or o in slot_of or _skewed((x, y), (cx, cy), xy[o])):
                    too_close = True
                    break
            if too_close:
                continue
            # (d) edge collision
            if index.crosses_plane(oo[s], (x, y), -2, (cx, cy)) if plane else self.crosses_edges(s, (x, y), None, (cx, cy)):
                continue
            t = self.new_object(cx, cy, ring_kind[j])
            self.add_edge(s, t)
            slot_of[t] = j
        # (h) edges between consecutive ring members, and (e) extra seeds on long ones
        self._ring_edges(s, a, slot_of, rel, c, sn)
        # ring targets r_ji for the relaxation (§5.5)
        tgt = {}
        rel_l = rel.tolist()
        far = p.ring_target_far
        if far is None and self.mode_code == 1:
            far = p.rotate_target_far
        for o, j in slot_of.items():
            if o in self.adj[s]:
                rx, ry = rel_l[j]
                tx, ty = c * rx - sn * ry, sn * rx + c * ry
                if far is not None:
                    # a neighbour paired with a slot it stands far from is not that
                    # slot's member: its edge keeps its current shape (see
                    # GrowParams.ring_target_far; departs from §5.5)
                    ox, oy = self.xy[o]
                    if (ox - x - tx) ** 2 + (oy - y - ty) ** 2 > far * far * (tx * tx + ty * ty):
                        continue
                tgt[o] = (tx, ty)
        self.target[s] = tgt
        self.ring_n[s] = n_ring
        return True

    def crowds_reference_nn(self, x: float, y: float, s: int, r: int) -> bool:
        """Would reference element ``r`` at (x, y) lie nearer a placed element than the
        larger of their two reference elements' nearest-neighbour distances, times ``KEEP_SHARE``?

        Not in the paper: unsaturated exemplars only (:mod:`strew.grow._spacing`; §5.4 (b)
        merges within ``l_short`` alone, and a ring slot in the empty part of a
        neighbour's ring was placed there: the sparse stones came 22 % denser).
        """
        nn = self.ref_nn
        rs = float(nn[r])
        xy, sub, orig_of = self.xy, self.sub, self.orig_of
        for o in self.near(x, y, self.ref_nn_max, (ELEMENT,)):
            if orig_of[o] == s:
                continue
            d = KEEP_SHARE * max(rs, float(nn[sub[orig_of[o]]]))
            ox, oy = xy[o]
            if (ox - x) ** 2 + (oy - y) ** 2 < d * d:
                return True
        return False

    def crowds_own_kind(self, x: float, y: float, kind: int, scale: float, s: int) -> bool:
        """Would an element of ``kind`` and ``scale`` at (x, y) come nearer one of its kind
        than the reference ever has two, for their sizes?

        Not in the paper (which has no overlap or distance test). Exemplars of one kind
        with scattered scales (stones 1 +- 0.2) keep a gap between bounding discs; the
        overlap guard tests the outlines, which fit closer, and ``pair_close`` is one
        distance for all sizes: the lower deciles of the stones' nearest distances lay
        1.2-1.8 units below the reference's (nn[stone>stone] 0.055 against 0.05 on the
        exemplar drawn with seed 1, seeds 1-3 all failing). The bound is :attr:`gap_ratio` (the reference's smallest
        distance over the two scaled radii) times the two radii, less 5 %. Only for
        exemplars of one kind: with two or three sizes it held pebbles and bars apart
        (nn[pebble>pebble] failed 2 of 3 seeds of two_sizes' seed-1 draw, nn[dot>bar]
        one of stripes').
        """
        f = 0.95 * self.gap_ratio[kind] * self.kind_radius[kind]
        scl = self.scl
        xy = self.xy
        for o in self.near(x, y, f * (scale + self.max_scale), (ELEMENT,)):
            if self.kind[o] != kind or self.orig_of[o] == s:
                continue
            d = f * (scale + scl[o])
            if (xy[o][0] - x) ** 2 + (xy[o][1] - y) ** 2 < d * d:
                return True
        return False

    def _over_smaller_seeds(self, s: int, cx: float, cy: float, kind: int) -> bool:
        """Do only seeds of smaller kinds keep a ring slot of ``kind`` at (cx, cy) from
        becoming a seed?

        §5.1 after [WZS98]: larger elements are placed first and smaller ones fill the
        spaces later. §5.4 (b) merges a new seed into any object within ``l_short``,
        and :meth:`too_close_in_kind` drops it near one of another kind, whatever the two
        kinds: a slot of the largest kind that a ring proposed where a seed of a small
        kind already waits was lost to that seed, which then grew as a small element.
        On three sizes (1:2:4), 275 large slots of one run were lost so; the pattern
        held 6.3 large stones per 10^4 square units away from its edge against 7.6 in
        the reference's interior, and small stones lay too far from the large ones
        (nn[small>large] 0.143 and 0.137 against a tolerance of 0.127, seeds 1 and 2). Such a slot of the largest kind
        becomes a seed beside the small ones: with the size priority (§5.1) it grows
        first, and the small seeds it crowds die when their turn comes
        (:meth:`too_close_in_kind` on placing). Not for the middle kinds: letting them
        over small seeds too took the small stones' share from 0.651 to 0.596-0.609 on
        the exemplar drawn with seed 1 (fraction and density[small] failed).

        True when at least one object blocks the slot and every one is a seed of a
        smaller kind (or an extra seed of Fig. 6e).
        """
        lv = self.size_level
        r = max(self.l_short, float(self.pair_short_max[kind]))
        hit = False
        for o in self.near(cx, cy, r):
            if self.orig_of[o] == s:
                continue
            ko = int(self.kind[o])
            d2 = (self.xy[o][0] - cx) ** 2 + (self.xy[o][1] - cy) ** 2
            if d2 >= self.l_short ** 2 and (ko < 0 or d2 >= self.pair_short[kind, ko] ** 2):
                continue
            if self.state[o] != SEED or (ko >= 0 and lv[ko] >= lv[kind]):
                return False
            hit = True
        return hit

    def _bent_ring(self, s: int, x: float, y: float, rel: np.ndarray, ring_pos: np.ndarray, c: float, sn: float) -> np.ndarray:
        """The ring offsets turned with the flow field between the element and each slot.

        Not in the paper: §5.3 turns the whole reference neighbourhood by the field at
        the element being placed, so each of its ring members is predicted in that one
        frame; where the field turns, the members ahead sit off the lattice that will be
        grown there (their own neighbourhoods are turned by the field at them) and the
        mismatch piles up as strain and holes. Each offset is turned further by
        ``flow_bend`` times the field's turn from the element to the predicted slot (a
        half: the chord of a curving row follows the field at its midpoint).

        Returns the offsets in the plane's frame, shape (n_ring, 2).
        """
        pts = np.empty((len(ring_pos) + 1, 2))  # (np.vstack and np.c_ cost more than the turn)
        pts[0] = (x, y)
        pts[1:] = ring_pos
        v = np.asarray(self.p.flow(pts), dtype=float)
        a = np.arctan2(v[:, 1], v[:, 0])
        self._flow_at[s] = float(a[0])  # for the frame carried on from s (``choose``)
        d = a[1:] - a[0]
        d = d - np.pi * np.rint(d / np.pi)  # a line field: +-pi/2 (direction sign free; np.round's values)
        t = math.atan2(sn, c) + self.p.flow_bend * d
        ct, st = np.cos(t), np.sin(t)
        out = np.empty((len(rel), 2))
        out[:, 0] = ct * rel[:, 0] - st * rel[:, 1]
        out[:, 1] = st * rel[:, 0] + ct * rel[:, 1]
        return out

    def _nudge(self, s: int, kind: int, x: float, y: float, rot: float, scale: float) -> tuple[float, float, Any] | None:
        """A place near ``(x, y)`` where the element of seed ``s`` overlaps nothing, or None.

        Not in the paper (which does not test overlaps). In a tight tiling the slot a
        seed fills is bounded by elements placed around it, each fitted to its own
        neighbours; where they closed in by a little (a seed that waited for §5.1's
        priority, or fronts that met), the element overlapped one of them, the seed died
        and left a hole of a whole element (bricks with a priority). Up to 16 offsets of
        at most ``nudge * l_short`` are tried, nearest first, with the checks of
        :meth:`_fit_position`; the first that fits is taken.
        """
        reach = self.p.nudge * self.l_short
        if reach <= 0:
            return None
        # (the outline's coordinates about its centre once, as element_geometry computes
        # them, and the objects any of the offsets can touch once: the same tests, fewer
        # lookups)
        base = self.turned_ring(kind, rot, scale) if self.local_ring[kind] is not None else None
        pool = self.overlap_pool(kind, x, y, scale, reach)
        nbrs = [(o, self.xy[o]) for o in self.adj[s]]
        # the offsets at every distance that pass the point tests, nearest first; then
        # their outlines in one shapely call, the region test in another and the overlap
        # tests in a third (the tests are pure: the first offset that passes them all is
        # the one the distance-by-distance loop took; issue 14 point 5)
        pts = []
        for f in (0.25, 0.5, 0.75, 1.0):
            for q in range(4):
                t = 0.5 * math.pi * q + 0.25 * math.pi * (f * 4 % 2)
                nx, ny = x + f * reach * math.cos(t), y + f * reach * math.sin(t)
                if not self.in_domain(nx, ny) or self.crosses_boundary((x, y), (nx, ny)):
                    continue
                if self.spray_area is not None and not shapely.contains_xy(self.spray_area, nx, ny):
                    continue
                if any(self.crosses_edges(s, (nx, ny), o, po) or self.crosses_boundary((nx, ny), po) for o, po in nbrs):
                    continue
                if self.too_close_in_kind(nx, ny, kind, s, (ELEMENT,), placing=True):
                    continue
                pts.append((nx, ny))
        if not pts:
            return None
        if base is not None:
            # (the same sums as base + np.array([nx, ny]) offset by offset)
            gs = list(shapely.polygons(base[None, :, :] + np.array(pts)[:, None, :]))
        else:
            gs = [self.element_geometry(kind, nx, ny, rot, scale) for nx, ny in pts]
        fits = self.fits_domain_many(gs).tolist()
        ok = [q for q, fit in enumerate(fits) if fit]
        hits = self.overlaps_pool_many([gs[q] for q in ok], kind, [pts[q] for q in ok], scale, pool)
        for q, hit in zip(ok, hits):
            if hit:
                continue
            nx, ny = pts[q]
            self._move(s, nx, ny)
            return nx, ny, gs[q]
        return None

    def _fit_position(self, s: int, nb: np.ndarray, rel: np.ndarray, k: int, c: float, sn: float, reach: float | None = None) -> None:
        """Move seed ``s`` to where the chosen ring fits its placed neighbours best.

        Not in the paper, which keeps the seed where the element that made it put it:
        the seed's position is then one neighbour's noisy ring offset, and the noise of
        near-regular references adds up from element to element along the growth, so
        rows wander and close up (§5.5 relaxes it only afterwards). The least-squares
        position for the chosen ring, ``mean_i (x_i - R r_{f(i)})``, is the minimiser of
        Eq. 5 for the new element alone with its neighbours held (Eq. 6). The move is
        kept within ``fit_reach * l_short`` and within the region, boundaries and
        connectivity.
        """
        n_ring = len(rel)
        rel_l = rel.tolist()
        xy = self.xy
        fx = fy = 0.0
        for i, o in enumerate(nb.tolist()):
            rx, ry = rel_l[(k + i) % n_ring]
            px, py = xy[o]
            fx += px - (c * rx - sn * ry)
            fy += py - (sn * rx + c * ry)
        fx /= len(nb)
        fy /= len(nb)
        ox, oy = self.xy[s]
        d2 = (fx - ox) ** 2 + (fy - oy) ** 2
        if d2 <= (1e-9 * self.l) ** 2:
            return  # already there (a perfect lattice): nothing to check
        if reach is None:
            reach = self.p.fit_reach * self.l_short
        if d2 > reach**2 or not self.in_domain(fx, fy):
            return
        if self.crosses_boundary((ox, oy), (fx, fy)):
            return
        if self.spray_area is not None and not shapely.contains_xy(self.spray_area, fx, fy):
            return
        plane, bnd, oo = self.tile is None, self.boundary is not None, self.orig_of
        if plane and not bnd:
            # (the edge tests of every neighbour in one compiled call: the same answers,
            # some 4.5 calls fewer per placement; g70v, issue 14 point 5)
            nbrs = list(self.adj[s])
            if self.index.crosses_plane_any(oo[s], (fx, fy), [oo[o] for o in nbrs], [xy[o] for o in nbrs]):
                return
            self._move(s, fx, fy)
            return
        for o in self.adj[s]:
            po = xy[o]
            if ((self.index.crosses_plane(oo[s], (fx, fy), oo[o], po) if plane else self.crosses_edges(s, (fx, fy), o, po))
                    or (bnd and self.crosses_boundary((fx, fy), po))):
                return
        self._move(s, fx, fy)

    def _ring_edges(self, s: int, a: int, slot_of: dict[int, int], rel: np.ndarray, c: float, sn: float) -> None:
        xy = self.xy
        x, y = xy[s]
        adj = self.adj
        nbrs = list(adj[s])
        if len(nbrs) < 2:
            return
        angs = [math.atan2(xy[o][1] - y, xy[o][0] - x) for o in nbrs]
        order = sorted(range(len(nbrs)), key=angs.__getitem__)
        m = len(order)
        rel_l = None
        # (has_edge in the plane, inlined: this loop runs for every pair of neighbours
        # of every placed element; issue 14 point 5)
        plane = self.tile is None
        bnd, oo = self.boundary is not None, self.orig_of
        for q in range(m):
            ia, ib = order[q], order[(q + 1) % m]
            oa, ob = nbrs[ia], nbrs[ib]
            gap = (angs[ib] - angs[ia]) % (2 * math.pi)
            if m == 2 and q == 1:
                break
            if gap <= 1e-9 or gap >= math.pi - 1e-9 or (ob in adj[oa] if plane else self.has_edge(oa, ob)):
                continue
            pa = xy[oa]
            pb = xy[ob]
            ja, jb = slot_of.get(oa), slot_of.get(ob)
            if ja is not None and jb is not None:
                # (the same value as np.hypot(*(rel[ja] - rel[jb])), without the arrays)
                if rel_l is None:
                    rel_l = rel.tolist()
                (xa, ya), (xb, yb) = rel_l[ja], rel_l[jb]
                orig = float(np.hypot(xa - xb, ya - yb))
            else:
                # Fig. 6e compares with the corresponding edge of the reference ring; a
                # pair that does not come from this ring has none: take the ring's
                # longest edge (its mean made extra seeds in every gap a reference with
                # long and short edges has, e.g. between clusters)
                orig = float(self.ring_edge_max[a])
            L = math.hypot(pa[0] - pb[0], pa[1] - pb[1])
            if L > 1.5 * orig and not (self.extra_ring_only and (ja is None or jb is None) and gap > SKEW_ANGLE + 1e-6):
                # (GrowParams.extra_ring_only: on lattices in fixed mode, a pair this ring
                # did not make across a gap wider than §4's skew angle gets no extra
                # seed; departs from Fig. 6e, §5.4)
                # (e) l_long = 1.5 * original length: an extra seed on the bisector, at the
                # average length of the two adjacent edges, without a symbol id
                mid = angs[ia] + 0.5 * gap
                la = math.hypot(pa[0] - x, pa[1] - y)
                lb = math.hypot(pb[0] - x, pb[1] - y)
                d = 0.5 * (la + lb)
                ex, ey = float(x + d * math.cos(mid)), float(y + d * math.sin(mid))
                if not self.in_domain(ex, ey) or self.crosses_boundary((x, y), (ex, ey)):
                    continue
                if self.near(ex, ey, self.l_short):
                    continue
                if self.crosses_edges(s, (x, y), None, (ex, ey)):
                    continue
                t = self.new_object(ex, ey, -1)
                self.add_edge(s, t)
                for o, po in ((oa, pa), (ob, pb)):
                    # (f) edges that would collide are left out; the paper instead joins
                    # the objects found inside triangle (e_tar, s0, s1), which Fig. 6f
                    # shows but the text does not specify.
                    if not self.crosses_edges(o, po, t, (ex, ey)) and not self.crosses_boundary(po, (ex, ey)):
                        self.add_edge(o, t)
            elif not _skewed((x, y), pa, pb):
                # the new edge closes triangle (s, a, b); like §4 we keep no skewed triangle
                if (not (self.index.crosses_plane(oo[oa], pa, oo[ob], pb) if plane else self.crosses_edges(oa, pa, ob, pb))
                        and not (bnd and self.crosses_boundary(pa, pb))):
                    self.add_edge(oa, ob)
