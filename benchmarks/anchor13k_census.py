"""Issue 13 point 1, helper anchor13k: every anchor kind (``_prepare.anchor_mask``) of the
fidelity suite's exemplars and of the variant audits' (default, VARIED, EDGE, HARDER), with
the measured properties that could tell a hub (a larger element others are arranged
around) from a rare small kind among larger ones: count ratio, area-radius ratio against
the class's most numerous kind, share of that kind leaning on the anchors, and the spread
(std/mean) of the children's distance to their anchor.

    python benchmarks/anchor13k_census.py [--json benchmarks/results/anchor13k_census.json]
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
import _variants  # noqa: E402
from grow_variants import _harder_suite  # noqa: E402
from synth_variants import _harder  # noqa: E402

from strew.synth._api import as_selection  # noqa: E402
from strew.synth._prepare import anchor_mask, area_radii, prepare  # noqa: E402


def _iqr(a: np.ndarray, b: np.ndarray) -> float:
    """Interquartile range over median of the others' distance to the nearest anchor."""
    from scipy.spatial import cKDTree

    d, _ = cKDTree(a).query(b)
    q1, med, q3 = np.percentile(d, [25, 50, 75])
    return float((q3 - q1) / med)


def cases():
    for name in _variants.fidelity_suite().NAMES:
        for v in (1, 2, 3):
            yield name, f"d{v}", v, {}
        for tag, table in (("p", _variants.VARIED), ("e", _variants.EDGE)):
            for i, kw in enumerate(table.get(name, [])):
                for v in (7, 8):
                    yield name, f"{tag}{i}s{v}", v, kw
        for i, kw in enumerate(_harder().get(name, [])):
            for v in (7, 8):
                yield name, f"h{i}s{v}", v, kw


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--json", default="benchmarks/results/anchor13k_census.json")
    ap.add_argument("--only", default=None)
    a = ap.parse_args()
    mk = _harder_suite()
    rows = []
    for name, label, v, kw in cases():
        if a.only and name not in a.only.split(","):
            continue
        ex = mk.make_exemplar(name, rng=v, **kw)
        prep = prepare(as_selection(ex))
        n = len(ex)
        anc = anchor_mask(prep.skind, prep.source, prep.size_class, prep.void)[:n]  # rarity alone
        kept = anchor_mask(prep.skind, prep.source, prep.size_class, prep.void, prep.pos)[:n]  # and stood around
        if not anc.any():
            continue
        ar = area_radii(ex)
        kind, cls, par = prep.kind[:n], prep.size_class[:n], prep.parent[:n]
        for k in np.unique(kind[anc > 0]):
            mine = (kind == k) & (anc > 0)
            c = cls[mine][0]
            same = (cls == c) & (anc == 0) & ~prep.void[:n]
            ks, cnt = np.unique(kind[same], return_counts=True)
            dom = ks[np.argmax(cnt)] if len(ks) else -1
            kids = same & (par >= 0) & np.isin(par, np.flatnonzero(mine))
            d = np.hypot(*(prep.pos[:n][kids] - prep.pos[:n][par[kids]]).T) if kids.any() else np.zeros(0)
            row = dict(case=name, variant=label, kind=int(k), n_anchor=int(mine.sum()), n_dom=int(cnt.max()) if len(cnt) else 0,
                       area_ratio=round(float(np.median(ar[mine]) / np.median(ar[kind == dom])), 3) if dom >= 0 else None,
                       lean_share=round(float(kids.sum() / max(same.sum(), 1)), 3), kids_per_anchor=round(float(kids.sum() / mine.sum()), 2),
                       child_cv=round(float(d.std() / d.mean()), 4) if len(d) else None,
                       around_iqr=round(_iqr(prep.pos[:n][mine], prep.pos[:n][same & (anc == 0)]), 4), kept=bool(kept[mine].all()))
            rows.append(row)
            print(row, flush=True)
    Path(a.json).parent.mkdir(parents=True, exist_ok=True)
    Path(a.json).write_text(json.dumps({"benchmark": "anchor13k_census", "rows": rows}, indent=1) + "\n")


if __name__ == "__main__":
    main()
