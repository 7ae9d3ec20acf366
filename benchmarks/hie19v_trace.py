"""Every rule try of a hierarchy world, tiled or untiled (issue 19.4, helper hie19v).

``PYTHONPATH=TREE/src python benchmarks/hie19v_trace.py make --tag TAG --tiles 94
--pattern hierarchy --overlaps [--untiled]`` runs ``benchmarks/hie19u_vines.py make``
(the world's npz in benchmarks/results/orn19m_TAG_T94.npz) with
``strew.ornament._engine._Grower._try`` wrapped, and writes
``benchmarks/results/hie19v_trace_TAG_T94.npz``: per try the run (one per tile, in run
order), the region's bounds, the phase, the empty circle (x, y, r), the raised radius the
rule saw (_handed_over), success, the first child's type, the parent's type, whether
the parent is a context element (a finished neighbour's), the parent's and the child's
bounding-circle centres. Nothing in the library changes.
``... analyze TAG [TAG ...]``: see :func:`analyze`.
"""

from __future__ import annotations

import runpy
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
RES = HERE / "results"


def make() -> None:
    import strew.ornament._engine as E

    rows: list = []
    runs: list = []
    orig = E._Grower._try

    def _try(self, goal, candidates, shift=None, circle=None):
        if not runs or runs[-1][0] is not self:
            runs.append((self, tuple(float(v) for v in self.region.bounds)))
        n0 = len(self.elements)
        ok = orig(self, goal, candidates, shift, circle)
        c = goal if circle is None else circle
        new = self.elements[n0:]
        if new:
            ch = new[0]
            par = ch.parent
            ptype, pctx, ctype = (par.type if par is not None else ""), bool(getattr(par, "context", False)), ch.type
            px, py = par.proxies[0].bounding_circle()[:2] if par is not None else (np.nan, np.nan)
            qx, qy = ch.proxies[0].bounding_circle()[:2]
        else:
            ptype, pctx, ctype = "", False, ""
            px = py = qx = qy = np.nan
        rows.append((len(runs) - 1, str(self.state.phase), float(c.center[0]), float(c.center[1]), float(c.radius),
                     float(goal.radius), bool(ok), ctype, ptype, pctx, float(px), float(py), float(qx), float(qy)))
        return ok

    E._Grower._try = _try
    tag = sys.argv[sys.argv.index("--tag") + 1]
    tiles = sys.argv[sys.argv.index("--tiles") + 1]
    sys.argv = [str(HERE / "hie19u_vines.py")] + sys.argv[1:]
    try:
        runpy.run_path(str(HERE / "hie19u_vines.py"), run_name="__main__")
    finally:
        a = list(zip(*rows)) if rows else [[]] * 14
        np.savez_compressed(RES / f"hie19v_trace_{tag}_T{float(tiles):g}.npz", run=np.array(a[0], int), phase=np.array(a[1], str),
                            cx=np.array(a[2]), cy=np.array(a[3]), r=np.array(a[4]), raised=np.array(a[5]), ok=np.array(a[6], bool),
                            ctype=np.array(a[7], str), ptype=np.array(a[8], str), pctx=np.array(a[9], bool),
                            px=np.array(a[10]), py=np.array(a[11]), qx=np.array(a[12]), qy=np.array(a[13]),
                            bounds=np.array([b for _, b in runs], float).reshape(-1, 4))


if __name__ == "__main__":
    if sys.argv[1:2] == ["make"]:
        make()


def _sd(x, y, side, tile):
    sys.path.insert(0, str(HERE))
    from orn19m_willow import _sd as sd

    return sd(np.asarray(x, float), np.asarray(y, float), side, tile)


def analyze(tags: list[str], width: float = 2.0) -> dict:
    """Per world: which kinds the rule successes grew into the circles of each radius band
    (r in [8, 10), [10, 12), [12, 16), >= 16: the vines phase's; [5, 8): the flowers
    phase's) whose centre lies within ``width`` s of a tile border (tiled: split by side
    and by the tile that placed them, own or the neighbour's; untiled: the same lines), and
    within the interior (|d| >= 3 s); counts per s^2 of the strip's area (from the world's
    npz: kept elements only, by the empty circle their success grew into, ornament_goal).
    And from the trace: the vines-phase tries by radius band and how many failed, on the
    later side; the vines near a border whose parent lies across it."""
    out: dict = {}
    bands = [(8, 10), (10, 12), (12, 16), (16, 1e9), (5, 8), (2.5, 5), (0, 2.5)]
    for tag in tags:
        for p in sorted(RES.glob(f"orn19m_{tag}_T*.npz")):
            z = np.load(p)
            side, tile, halo, _ = z["meta"]
            x, y, kind, gr = z["x"], z["y"], z["kind"], z["goal_r"]
            kinds = [str(k) for k in z["kinds"]]
            s = 1.0 / np.sqrt(len(x) / side**2)
            margin = max(halo, 3 * s)
            ins = (x >= margin) & (x <= side - margin) & (y >= margin) & (y <= side - margin)
            d, sd = _sd(x, y, side, tile)
            d, sd = d / s, sd / s
            g = np.arange(0.125, side, 0.25)
            gx, gy = np.meshgrid(g, g)
            gx, gy = gx.ravel(), gy.ravel()
            gok = (gx >= margin) & (gx <= side - margin) & (gy >= margin) & (gy <= side - margin)
            gd, gsd = _sd(gx[gok], gy[gok], side, tile)
            gd, gsd = gd / s, gsd / s
            unit = (np.clip(np.floor(y / tile), 0, 3) * 4 + np.clip(np.floor(x / tile), 0, 3)).astype(int)
            other = (z["tile"] >= 0) & (z["tile"] != unit)
            res: dict = {}
            regions = {"interior": (ins & (d >= 3), (gd >= 3).sum()),
                       "finished side": (ins & (d < width) & (sd < 0), ((gd < width) & (gsd < 0)).sum()),
                       "later side": (ins & (d < width) & (sd > 0), ((gd < width) & (gsd > 0)).sum())}
            for name, (m, ga) in regions.items():
                area = ga * 0.0625 / s**2
                for who, mm in (("all", m), ("own", m & ~other), ("neighbour's", m & other)):
                    if who != "all" and z["tile"].max() < 0:
                        continue
                    row = {}
                    for lo, hi in bands:
                        b = mm & (gr >= lo) & (gr < hi)
                        row[f"r{lo:g}-{hi:g}"] = {k: round(float((b & (kind == i)).sum() / area), 4) for i, k in enumerate(kinds)}
                    res[f"{name}, {who}"] = row
            tp = RES / p.name.replace("orn19m_", "hie19v_trace_")
            if tp.exists():
                t = np.load(tp)
                td, tsd = _sd(t["cx"], t["cy"], side, tile)
                td, tsd = td / s, tsd / s
                vp = t["phase"] == "vines"
                near = td < width
                # the tile of each run: the one whose rectangle its region holds whole
                b = t["bounds"]
                rt = np.full(len(b), -1)
                for k, (x0, y0, x1, y1) in enumerate(b):
                    for ti in range(16):
                        a0, b0 = (ti % 4) * tile, (ti // 4) * tile
                        if x0 <= a0 + 1e-6 and y0 <= b0 + 1e-6 and a0 + tile <= x1 + 1e-6 and b0 + tile <= y1 + 1e-6:
                            rt[k] = ti if rt[k] == -1 else -2  # -2: the whole world (untiled)
                tun = (np.clip(np.floor(t["cy"] / tile), 0, 3) * 4 + np.clip(np.floor(t["cx"] / tile), 0, 3)).astype(int)
                own = (rt[t["run"]] == tun) | (rt[t["run"]] == -2)
                for lab, m in (("later side, own run", near & (tsd > 0) & own), ("later side, finished run", near & (tsd > 0) & ~own),
                               ("finished side, own run", near & (tsd < 0) & own), ("interior", td >= 3)):
                    row = {}
                    for lo, hi in bands[:4]:
                        b = m & vp & (t["r"] >= lo) & (t["r"] < hi)
                        row[f"r{lo:g}-{hi:g}"] = dict(tries=int(b.sum()), failed=int((b & ~t["ok"]).sum()),
                                                     vine=int((b & (t["ctype"] == "vine")).sum()))
                    res[f"trace vines phase, {lab}"] = row
                # vines whose centre lies within `width` s of a line and whose parent's lies across it
                v = t["ok"] & (t["ctype"] == "vine")
                _, psd = _sd(t["px"], t["py"], side, tile)
                qd, qsd = _sd(t["qx"], t["qy"], side, tile)
                qd, qsd, psd = qd / s, qsd / s, psd / s
                for lab, m in (("later side", v & (qd < width) & (qsd > 0)), ("finished side", v & (qd < width) & (qsd < 0))):
                    res[f"trace vines near, {lab}: parent across"] = [int((m & (np.sign(psd) != np.sign(qsd))).sum()), int(m.sum())]
            out[p.name] = res
            print(p.name, f"s {s:.3f}")
            for k, v in res.items():
                print(f"  {k}: {v}")
    return out


if __name__ == "__main__" and sys.argv[1:2] == ["analyze"]:
    import json

    args = [a for a in sys.argv[2:] if not a.startswith("--")]
    o = sys.argv[sys.argv.index("--out") + 1] if "--out" in sys.argv else None
    w = float(sys.argv[sys.argv.index("--width") + 1]) if "--width" in sys.argv else 2.0
    res = analyze([a for a in args if a not in (o, str(w))], w)
    if o:
        Path(o).write_text(json.dumps(res, indent=1))
