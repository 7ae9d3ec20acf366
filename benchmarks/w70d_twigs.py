"""Where the border twigs go (issue 19 point 4, helper w70d): per 1 s bin of signed distance (negative: the finished
tile's side), pooled over the tile sizes given, for each world tag:
  twigs / flowers in the world, split by placer (the tile the row lies in, an earlier tile, a later tile);
  twigs / flowers dropped by the tile on the earlier side and by the later tile (the keep rules of sweep 1);
  the flowers phase's tries centred in the bin (hie15_tries): count, ok, mean radius, by the run's tile (earlier /
  later side's tile) -- runs mapped to tiles in the serial order (phase by phase, index order; sweep 1 after sweep 0).
``python benchmarks/w70d_twigs.py --tags w67dctl,w67dM,w69dVK0O --tiles 36,40,44``
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"
sys.path.insert(0, str(HERE))


def _order():
    tiles = [(j * 4 + i, (j % 2) * 2 + i % 2) for j in range(4) for i in range(4)]
    return [ix for ph in range(4) for ix, p in tiles if p == ph]


def phase_of(u):
    u = np.asarray(u, np.int64)
    return ((u // 4) % 2) * 2 + (u % 4) % 2


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--tags", default="w67dctl,w67dM,w69dVK0O")
    ap.add_argument("--tiles", required=True)
    ap.add_argument("--seed", type=int, default=19)
    args = ap.parse_args()
    import orn19m_willow as W
    import w70d_canon

    w70d_canon.install()

    edges = np.arange(-3.0, 3.01, 1.0)
    nb = len(edges) - 1
    order = _order()
    for tag in args.tags.split(","):
        acc = {}
        for tile in args.tiles.split(","):
            p = RES / f"orn19m_{tag}_s{args.seed}_T{tile}.npz"
            q = RES / f"hie15_tries_{tag}_s{args.seed}_T{tile}.npz"
            if not p.exists():
                continue
            w = W._world(p)
            kinds = w["kinds"]
            b = np.digitize(w["sd"], edges) - 1
            eph = phase_of(w["unit"])
            pl = np.asarray(w["placer"], np.int64)
            pph = np.where(pl >= 0, phase_of(np.maximum(pl, 0)), -1)
            for kname in ("twig", "flower", "vine", "leaf"):
                k = kinds.index(kname)
                m = w["inside"] & (w["kind"] == k)
                for lab, sel in (("all", m), ("own", m & ((pl == w["unit"]) | (pl < 0))), ("by_earlier", m & (pl >= 0) & (pph < eph)), ("by_later", m & (pl >= 0) & (pph > eph))):
                    acc.setdefault((kname, lab), np.zeros(nb))[:] += np.bincount(b[sel & (b >= 0) & (b < nb)], minlength=nb)[:nb]
                bd = np.digitize(w["dsd"], edges) - 1
                dt = np.asarray(np.load(p)["dtile"], np.int64)
                if len(dt):
                    dph, uph = phase_of(dt), phase_of(w["dunit"])
                    md = w["dinside"] & (w["dkind"] == k) & (bd >= 0) & (bd < nb)
                    acc.setdefault((kname, "dropped_by_earlier_tile"), np.zeros(nb))[:] += np.bincount(bd[md & ((dph < uph) | ((dt == w["dunit"]) & (w["dsd"] < 0)))], minlength=nb)[:nb]
                    acc.setdefault((kname, "dropped_by_later_tile"), np.zeros(nb))[:] += np.bincount(bd[md & ((dph > uph) | ((dt == w["dunit"]) & (w["dsd"] >= 0)))], minlength=nb)[:nb]
            if q.exists():
                z = np.load(q)
                num = z["num"]
                ph, x, y, r, run, ok = num[:, 0], num[:, 1], num[:, 2], num[:, 3], num[:, 5].astype(int), num[:, 7].astype(bool)
                m = ph == 1
                _, sd = W._sd(x[m], y[m], w["side"], w["tile"])
                tb = np.digitize(sd / w["s"], edges) - 1
                if run.max() > 0:
                    tix = np.array(order * 2)[run[m] % 32] if run.max() < 32 else np.full(m.sum(), -1)
                    side_earlier = phase_of(tix) < phase_of(W_unit(x[m], y[m], w["tile"]))
                    own = tix == W_unit(x[m], y[m], w["tile"])
                    first = (sd < 0)
                    # the tile on the earlier side of the border = the one whose phase is lower
                    earlier_tile = np.where(own, first, side_earlier)
                else:
                    earlier_tile = np.zeros(m.sum(), bool)
                okm, rr = ok[m], r[m]
                for lab, sel in (("tries_earlier_tile", earlier_tile), ("tries_later_tile", ~earlier_tile) if run.max() > 0 else ("tries_one_run", ~earlier_tile)):
                    v = (tb >= 0) & (tb < nb) & sel
                    acc.setdefault(("fl", lab), np.zeros(nb))[:] += np.bincount(tb[v], minlength=nb)[:nb]
                    acc.setdefault(("fl", lab + "_ok"), np.zeros(nb))[:] += np.bincount(tb[v & okm], minlength=nb)[:nb]
                    acc.setdefault(("fl", lab + "_rsum"), np.zeros(nb))[:] += np.bincount(tb[v & okm], weights=rr[v & okm], minlength=nb)[:nb]
        print(f"\n== {tag} (tiles {args.tiles}); bins " + " ".join(f"[{edges[i]:+.0f},{edges[i+1]:+.0f})" for i in range(nb)))
        for key, v in acc.items():
            if key[1].endswith("_rsum"):
                continue
            line = f"  {key[0]:6s} {key[1]:26s} " + " ".join(f"{int(a):7d}" for a in v)
            if key[1].endswith("_ok"):
                rs = acc[(key[0], key[1][:-3] + "_rsum")]
                line += "   mean r of ok: " + " ".join(f"{a / max(c, 1):5.2f}" for a, c in zip(rs, v))
            print(line)


def W_unit(x, y, tile):
    return (np.clip(np.floor(y / tile), 0, 3) * 4 + np.clip(np.floor(x / tile), 0, 3)).astype(np.int64)


if __name__ == "__main__":
    main()
