"""Helper s27p: ring phases of synth's rings (issue 13 point 2, neighbouring rings turn in lockstep).

A ring's phase is the angle of its tiles about its hub modulo the tile step 2 pi / tiles; the
difference to each of a hub's 6 nearest hubs is given in units of the tile step (uniform phases:
mean 0.25, 20% below 0.1). Prints the exemplar's own differences, the output's, and for the
output which stage added each hub (caller of ``SynthState.add``) and its exemplar source hub:
how many neighbouring output hubs are copies of the same exemplar hub, and the phase
differences of the neighbours' source hubs (what ``_complete_anchor_rings`` puts their slots by).

    PYTHONPATH=src python benchmarks/s27p_phase.py [--scale 7.07] [--seed 5] [--off]
"""
import argparse
import collections
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy as np
from _runner import fidelity_suite
from scipy.spatial import cKDTree

from strew import Region
from strew.synth import synthesize
from strew.synth._state import SynthState

ap = argparse.ArgumentParser()
ap.add_argument("--scale", type=float, default=7.07)
ap.add_argument("--seed", type=int, default=5)
ap.add_argument("--name", default="rings")
ap.add_argument("--off", action="store_true", help="RING_PHASE_SPREAD off (main's behaviour)")
a = ap.parse_args()
if a.off:
    import strew.synth._grow as G

    G.RING_PHASE_SPREAD = False

_orig_add, _orig_re, _orig_arr = SynthState.add, SynthState.reassign, SynthState.to_arrangement
born_by = {}   # output index -> (stage, src at birth)
last = {}


def _add(self, src, pos, **kw):
    idx = _orig_add(self, src, pos, **kw)
    f = sys._getframe(1)
    stage = f.f_code.co_name
    L = f.f_locals
    gen = [None] * len(idx)
    if stage == "grow" and "new_idx" in L:
        k = np.asarray(L["new_idx"])
        ncol = max(L["cands"].shape[1], 1)
        fl = np.searchsorted(L["out_ptr"], k, "right") - 1
        si = fl // ncol
        gen = [(int(self.src[L["seeds"][a]]), int(L["cands"].ravel()[b])) for a, b in zip(si, fl)]
    for i, s, g in zip(np.asarray(idx), np.asarray(src), gen):
        born_by[int(i)] = (stage, int(s), g)
    return idx


def _arr(self, **kw):
    last["state"] = self
    last["src"] = self.src.copy()
    last["pos"] = self.pos.copy()
    return _orig_arr(self, **kw)


SynthState.add, SynthState.to_arrangement = _add, _arr

mk = fidelity_suite()
ex = mk.make_exemplar(a.name)
nt = int(ex.meta["params"]["tiles"])
rad = float(ex.meta["params"]["radius"])
step = 2 * np.pi / nt


def phases(hub, tile):
    d, j = cKDTree(hub).query(tile)
    on = np.abs(d - rad) <= 2
    ang = np.arctan2(tile[:, 1] - hub[j, 1], tile[:, 0] - hub[j, 0])
    ph = np.full(len(hub), np.nan)
    for h in range(len(hub)):
        q = ang[(j == h) & on]
        if len(q) >= 3:
            ph[h] = np.angle(np.exp(1j * nt * q).mean()) / nt
    return ph


def nbdiff(hub, ph, k=6, pairs=False):
    _, hj = cKDTree(hub).query(hub, k=k + 1)
    i = np.repeat(np.arange(len(hub)), k)
    jj = hj[:, 1:].ravel()
    p = np.abs(np.angle(np.exp(1j * nt * (ph[jj] - ph[i])))) / nt / step
    ok = np.isfinite(p)
    return (p[ok], i[ok], jj[ok]) if pairs else p[ok]


def show(tag, p):
    print(f"{tag}: n {len(p)} mean {p.mean():.3f} below 0.1 {np.mean(p < 0.1):.2f} hist {np.histogram(p, bins=5, range=(0, 0.5))[0].tolist()}")


exk = np.asarray(ex.kind_names)
exy = np.asarray(ex.xy)
exhub, extile = exy[exk == "hub"], exy[exk != "hub"]
exph = phases(exhub, extile)
print("exemplar hubs", len(exhub), "with a phase", int(np.isfinite(exph).sum()))
show("exemplar 6-nearest", nbdiff(exhub, exph))
show("exemplar 6-nearest, hubs >= 1 spacing from the frame", nbdiff(exhub, exph))

x0, y0, x1, y1 = ex.region.bounds
region = Region.rectangle(a.scale * (x1 - x0), a.scale * (y1 - y0))
out = synthesize(ex, region, rng=a.seed, measure=False)
kn = np.asarray(out.kind_names)
pos = np.asarray(out.xy)
hub, tile = pos[kn == "hub"], pos[kn != "hub"]
ph = phases(hub, tile)
print("output hubs", len(hub), "with a phase", int(np.isfinite(ph).sum()), "n", len(out))
p, i, jj = nbdiff(hub, ph, pairs=True)
show("output 6-nearest", p)
# the state's hubs: exemplar source hub and the stage that added them
st = last["state"]
prep = st.prep
spos, ssrc = last["pos"], last["src"]
ishub = np.array([prep.names[prep.source[s]] if False else True for s in ssrc])
hubk = [k for k, nm in enumerate(ex.shapes) if nm == "hub"]
print("prep kinds", getattr(prep, "kind_names", None))
# exemplar element -> its phase: its own hub's (exemplar elements in prep order are the exemplar's)
pk = np.asarray(prep.kind)
H = np.flatnonzero(np.isin(ssrc, np.flatnonzero(np.linalg.norm(prep.pos[:, None, :] - exhub[None], axis=2).min(1) < 1e-6)))
ex_idx_hub = np.flatnonzero(np.linalg.norm(prep.pos[:, None, :] - exhub[None], axis=2).min(1) < 1e-6)
hub_of = {int(e): int(np.argmin(np.linalg.norm(exhub - prep.pos[e], axis=1))) for e in ex_idx_hub}
print("state hubs", len(H))
stages = collections.Counter(born_by.get(int(h), ("?", -1, None))[0] for h in H)
print("stage that added the state's hubs", dict(stages))
changed = sum(1 for h in H if born_by.get(int(h), ("?", -1, None))[1] != int(ssrc[h]))
print("hubs whose source changed since birth", changed)
srcph = np.array([exph[hub_of[int(ssrc[h])]] for h in H])
q, qi, qj = nbdiff(spos[H], srcph, pairs=True)
show("state hubs 6-nearest, phases of their exemplar source hubs", q)
same = ssrc[H][qi] == ssrc[H][qj]
print(f"neighbour pairs copied from the same exemplar hub: {same.mean():.3f} (exemplar hubs {len(exhub)}: 1/n = {1 / len(exhub):.3f})")
show("  pairs of different source hubs", q[~same])
cnt = collections.Counter(int(s) for s in ssrc[H])
print("state hubs per exemplar source hub", sorted(cnt.values(), reverse=True))
# exemplar neighbours of a source hub among output neighbour pairs
_, exj = cKDTree(exhub).query(exhub, k=7)
exnb = set()
for r in range(len(exhub)):
    for c in exj[r, 1:]:
        exnb.add((r, int(c)))
hs = [hub_of[int(s)] for s in ssrc[H]]
isnb = np.array([(hs[x], hs[y]) in exnb for x, y in zip(qi, qj)])
print(f"neighbour pairs whose source hubs are exemplar neighbours: {isnb.mean():.3f}")

# how a hub copied as the same exemplar hub as a neighbour was generated: the seed's exemplar
# element and the matched candidate e (copied: e's neighbour), each as (kind, its exemplar hub)
def owner(e):
    """exemplar hub nearest element e and the element's kind name"""
    return (ex.shape_names[int(prep.kind[e])] if hasattr(ex, "shape_names") else int(prep.kind[e]), int(np.argmin(np.linalg.norm(exhub - prep.pos[e], axis=1))), round(float(np.min(np.linalg.norm(exhub - prep.pos[e], axis=1))), 1))
c2 = collections.Counter()
sameseed = 0
nsame = 0
for x, y in zip(qi[same], qj[same]):
    for h in (H[x], H[y]):
        st_, s0, g = born_by.get(int(h), ("?", -1, None))
        if g is None:
            continue
        nsame += 1
        sk, sh, sd = owner(g[0]); ek, eh, ed = owner(g[1])
        c2[(sk, ek, "seed-hub==src" if sh == hub_of[s0] else "", "e-hub==src" if eh == hub_of[s0] else "", "seed-hub==e-hub" if sh == eh else "")] += 1
print("same-source pair hubs (seed kind, candidate kind, flags):", nsame)
for k, v in c2.most_common(12):
    print("  ", k, v)
c3 = collections.Counter()
for h in H:
    st_, s0, g = born_by.get(int(h), ("?", -1, None))
    if g is None:
        continue
    sk, sh, sd = owner(g[0]); ek, eh, ed = owner(g[1])
    c3[(sk, ek, "seed-hub==src" if sh == hub_of[s0] else "", "e-hub==src" if eh == hub_of[s0] else "", "seed-hub==e-hub" if sh == eh else "")] += 1
print("all grown hubs:")
for k, v in c3.most_common(12):
    print("  ", k, v)
# the exemplar's hubs: ring tiles, distance to the frame, output copies
d_t, j_t = cKDTree(exhub).query(extile)
ring_n = np.bincount(j_t[np.abs(d_t - rad) <= 2], minlength=len(exhub))
fx0, fy0, fx1, fy1 = ex.region.bounds
fr = np.minimum.reduce([exhub[:, 0] - fx0, fx1 - exhub[:, 0], exhub[:, 1] - fy0, fy1 - exhub[:, 1]])
byhub = collections.Counter(hub_of[int(s)] for s in ssrc[H])
p = np.array([byhub.get(r, 0) for r in range(len(exhub))], float) / len(H)
print(f"P(same source) from the copies' frequencies alone: {np.sum(p ** 2):.3f}; observed {same.mean():.3f}")
for r in range(len(exhub)):
    print(f"  exemplar hub {r:2d} ring tiles {ring_n[r]:2d} from frame {fr[r]:5.1f} phase {exph[r] / step:+.3f} copies {byhub.get(r, 0)}")
