"""Helper sp (issue 13 point 1): why does growth lay a pebble down alone?

For every element of kind KIND that growth (the loop of ``_grow.grow``, Algorithm 1) copies, the
copy it came from (seed s, candidate c, §5.1) is examined: its exemplar partners are the exemplar's
KIND elements within the exemplar's 90 % nn decile (q90) of it. The tag says what became of the
nearest partner in that same copy (best outcome first):

  placed      copied in the same step
  refused_par offered and passing the static checks, but its parent (a stone) was not copied
  refused     offered, static checks passed, hit another copy of the same step (place_proposals)
  conflict_O  offered, in the domain, but intersects O (_split_conflicts / _crowded / _not_owned)
  out_domain  offered, overlaps free space, outside the region
  no_free     offered, overlaps no free-space point
  used        in n(c) but paired with an output element already there (not re-copied)
  not_in_nb   the partner is outside n(c)
  ex_lone     the exemplar element has no KIND partner within q90 at all

At the end of growth (before _complete_anchor_rings) the KIND elements away from the region's
edge are split into lone (no KIND element within q90, as syn18_far_stages counts) and the rest, and
the tags of each group are counted.

    PYTHONPATH=src:benchmarks python benchmarks/sp_lone_cause.py two_sizes:5:11:1,2 [--kind pebble] [--off]
        [--param optimize="'none'"]
"""
import argparse
import inspect
import sys
import textwrap
from collections import Counter

import numpy as np
import shapely
from scipy.spatial import cKDTree

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite
from synth_variants import _harder
from syn13z_rows import nnq

import strew.synth._grow as G
import strew.synth._state as S
from strew import Region
from strew.synth import synthesize

TAGS = ["placed", "refused_par", "refused", "conflict_O", "out_domain", "no_free", "used", "not_in_nb", "ex_lone", "untracked"]
CTX = {}

# -- a per-element tag that follows compaction ------------------------------------------
S._STORAGE = S._STORAGE + ("_dtag", "_duid", "_dpart", "_dexd")
UID = [0]
_init = S.SynthState.__init__


def _init2(self, *a, **k):
    self._dtag = np.full(256, len(TAGS) - 1, np.int64)
    self._duid = np.zeros(256, np.int64)
    self._dpart = np.full(256, -1, np.int64)
    self._dexd = np.zeros(256)
    _init(self, *a, **k)


S.SynthState.__init__ = _init2
_add = S.SynthState.add


def _add2(self, src, pos, **k):
    idx = _add(self, src, pos, **k)
    self._dtag[idx] = len(TAGS) - 1
    self._duid[idx] = np.arange(UID[0], UID[0] + len(idx))
    self._dpart[idx] = -1
    UID[0] += len(idx)
    return idx


S.SynthState.add = _add2


def _partners(prep):
    """Exemplar partners of each KIND element: KIND elements within q90 (one exemplar)."""
    if "partners" in CTX:
        return
    kq = int(prep.skind[prep.kind == list(prep.shapes).index(CTX["kname"])][0])
    mine = np.flatnonzero(prep.skind == kq)
    tree = cKDTree(prep.pos[mine])
    partners = {}
    for e in mine:
        near = mine[tree.query_ball_point(prep.pos[e], CTX["q90"])]
        partners[int(e)] = near[near != e]
    CTX.update(skind=kq, partners=partners)
    print(f"   exemplar {CTX['kname']}s without a partner within q90: {sum(len(v) == 0 for v in partners.values())}/{len(partners)}")


def _diag(L):
    state, prep = L["state"], L["prep"]
    _partners(prep)
    new, new_idx, ex, ppos = L["new"], L["new_idx"], L["ex"], L["ppos"]
    if len(new) == 0:
        return
    kq = CTX["skind"]
    partners = CTX["partners"]
    out_ptr, cands = L["out_ptr"], L["cands"]
    k = cands.shape[1]
    valid, bd, ok, okp, placed, pslot = L["valid"], L["before_domain"], L["ok"], L["okp"], L["placed"], L["pslot"]
    for e_i, t in zip(new, new_idx):
        e = ex[t]
        if prep.skind[e] != kq:
            continue
        ps = partners[e]
        if len(ps) == 0:
            state._dtag[e_i] = TAGS.index("ex_lone")
            continue
        b = int(np.searchsorted(out_ptr, t, "right") - 1)
        i, j = divmod(b, k)
        c = cands[i, j]
        lo, hi = out_ptr[b], out_ptr[b] + L["count"][b]
        blk = np.arange(lo, hi)
        m = blk[np.isin(ex[blk], ps)]
        best = 99
        bestd = np.inf
        for u in m:
            if placed[u]:
                s = 0
                dd = float(np.hypot(*(prep.pos[ex[u]] - prep.pos[e])))
                if dd < bestd:
                    bestd = dd
                    hit = np.flatnonzero(new_idx == u)
                    state._dpart[e_i] = state._duid[new[hit[0]]]
                    state._dexd[e_i] = dd
            elif okp[u]:
                p = pslot[u]
                s = 1 if (p == -2 or (p >= 0 and not placed[p])) else 2
            elif ok[u]:
                s = 3
            elif bd[u]:
                s = 4
            elif valid[u]:
                s = 5
            else:
                s = 5
            best = min(best, s)
        if best == 99:
            nb = prep.nb_idx[prep.nb_ptr[c]:prep.nb_ptr[c + 1]]
            best = 6 if np.isin(ps, nb).any() or np.isin(c, ps) else 7
        state._dtag[e_i] = best


src = inspect.getsource(G.grow)
hook = "            new = state.add(ex[new_idx], ppos[new_idx])\n"
assert hook in src
src = src.replace(hook, hook + "            _SP_DIAG(locals())\n")
G._SP_DIAG = _diag
exec(compile(src, G.__file__, "exec"), G.__dict__)

END = []
_car = G._complete_anchor_rings


def _car2(state, *a, **k):
    prep = state.prep
    _partners(prep)
    kq = CTX["skind"]
    vis = np.flatnonzero(prep.skind[state.src[: state.n]] == kq)
    p = state.pos[vis]
    d = cKDTree(p).query(p, k=2)[0][:, 1]
    edge = shapely.distance(state.region.geometry.boundary, shapely.points(p))
    away = d <= edge
    lone = away & (d > CTX["q90"])
    tags = state._dtag[vis]
    END.append((Counter(tags[lone].tolist()), Counter(tags[away & ~lone].tolist()), int(lone.sum()), int(away.sum())))
    # the fate of the same-step partner of lone pebbles tagged 'placed'
    uid = {int(u): i for i, u in enumerate(state._duid[: state.n])}
    gone, far, exd, outd = 0, 0, [], []
    for i in vis[lone & (tags == 0)]:
        j = uid.get(int(state._dpart[i]))
        if j is None:
            gone += 1
            continue
        far += 1
        exd.append(state._dexd[i] / CTX["q90"])
        outd.append(float(np.hypot(*(state.pos[j] - state.pos[i]))) / CTX["q90"])
    END[-1] += (gone, far, np.array(exd), np.array(outd))
    return _car(state, *a, **k)


G._complete_anchor_rings = _car2


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("spec")
    ap.add_argument("--kind", default="pebble")
    ap.add_argument("--off", action="store_true", help="_optimize.SCATTER_BOUND = False (the spread guard as before helper sp)")
    ap.add_argument("--scale", type=float, default=3.5)
    ap.add_argument("--param", action="append", default=[], help="NAME=VALUE passed to synthesize (e.g. optimize='none')")
    a = ap.parse_args()
    if a.off:
        import strew.synth._optimize as O

        O.SCATTER_BOUND = False
    cls, h, v, seeds = a.spec.split(":")
    mk = _harder_suite()
    ex = mk.make_exemplar(cls, rng=int(v), **_harder()[cls][int(h)]) if h != "suite" else mk.make_exemplar(cls)
    q90 = float(nnq(ex, a.kind, a.kind)[-1])
    CTX.clear()
    CTX.update(kname=a.kind, q90=q90)
    x0, y0, x1, y1 = ex.region.bounds
    print(f"== {a.spec} kind {a.kind} q90 {q90:.3f}")
    for seed in [int(s) for s in seeds.split(",")]:
        END.clear()
        synthesize(ex, Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0)), rng=seed, measure=False, **{kv.split("=")[0]: eval(kv.split("=")[1]) for kv in a.param})
        lone, rest, nl, na, gone, far, exd, outd = END[0]
        print(f" seed {seed}: after growth {nl}/{na} = {nl / max(na, 1):.3f} lone")
        print("   tag          lone   others  lone share")
        for ti, tn in enumerate(TAGS):
            lo, ot = lone.get(ti, 0), rest.get(ti, 0)
            if lo or ot:
                print(f"   {tn:11s} {lo:5d} {ot:8d}  {lo / max(lo + ot, 1):.3f}")
        if far:
            print(f"   lone 'placed': partner gone {gone}, still there {far}: exemplar distance / q90 median {np.median(exd):.2f},"
                  f" now {np.median(outd):.2f} (quartiles {np.round(np.quantile(outd, [0.25, 0.75]), 2)})")


if __name__ == "__main__":
    main()
