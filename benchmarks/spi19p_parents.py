"""Ornament spirals across tile borders: what each tile's cut does with a spiral's parent (issue 19.4).

``python benchmarks/spi19p_parents.py --tag TAG --tiles 100,112 [--pattern spirals]``
runs ``benchmarks/orn19m_willow.py make`` (same worlds, same npz files, ``orn19m_TAG_T*.npz``;
analyse them with its ``analyze``) and, in every tile's cut (strew.tiles._keep_groups),
also the cut by the public ``parent`` column (the rule up to 9dffc62, on the same tile's
rows): per world, the rows the tiles cut, those placed at their parent's row by each
rule, the rows the two rules keep differently, and the kept rows whose parent row the
tile drops (orphans). ``--no-holes`` (a diagnosis): the finished tiles hand over no
circles (strew.tiles._ornament_holes returns none). Writes ``benchmarks/results/spi19p_parents_TAG.json``.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))


def _orphans(arr, kept, parent) -> int:
    el = np.asarray(arr["element"], np.int64)
    row_of = {int(e): i for i, e in enumerate(el.tolist())}
    pr = np.array([row_of.get(int(p), -1) for p in np.asarray(parent, np.int64).tolist()], np.int64)
    return int((kept & (pr >= 0) & ~kept[np.maximum(pr, 0)]).sum())


def main() -> None:
    import orn19m_willow as M

    import strew.tiles as T
    from strew.ornament._context import PARENT_COLUMN

    argv = sys.argv[1:]
    if "--no-holes" in argv:  # a diagnosis: the finished tiles hand over no circles (_ornament_holes)
        argv.remove("--no-holes")
        T._ornament_holes = lambda *a, **k: []
    tag = argv[argv.index("--tag") + 1]
    stats: dict = {}
    cur: dict = {}
    orig = T._keep_groups

    def keep_groups(arr, keep, t, job, links):
        k = orig(arr, keep, t, job, links)
        if PARENT_COLUMN in arr.columns and len(arr):
            new_par = np.asarray(arr[PARENT_COLUMN], np.int64)
            old = arr.without_columns(PARENT_COLUMN)
            k_old = orig(old, keep, t, job, links)
            _, inv = np.unique(np.asarray(arr["ornament_group"]), return_inverse=True)
            tips = np.ones(len(arr), bool)
            at_new = T._at_parent(arr, inv, tips)[inv] >= 0
            at_old = T._at_parent(old, inv, tips)[inv] >= 0
            c = cur.setdefault("tiles", [])
            c.append(dict(tile=t.index, rows=len(arr), kept_new=int(k.sum()), kept_old=int(k_old.sum()),
                          differ=int((k != k_old).sum()), at_parent_new=int(at_new.sum()), at_parent_old=int(at_old.sum()),
                          orphans_new=_orphans(arr, k, new_par), orphans_old=_orphans(arr, k_old, new_par)))
        return k

    T._keep_groups = keep_groups
    orig_print = print

    def hook(*a, **kw):  # M.make prints one line per world: close that world's figures
        orig_print(*a, **kw)
        line = " ".join(str(x) for x in a)
        if " T " in line and cur.get("tiles"):
            tot = {k: sum(d[k] for d in cur["tiles"]) for k in cur["tiles"][0] if k != "tile"}
            stats[line.split(":")[0]] = tot
            orig_print("   cut:", json.dumps(tot), flush=True)
            cur.clear()

    M.print = hook  # type: ignore[attr-defined]
    sys.argv = [sys.argv[0], "make", *argv]
    M.main()
    out = HERE / "results" / f"spi19p_parents_{tag}.json"
    out.write_text(json.dumps({"command": "python benchmarks/spi19p_parents.py " + " ".join(argv), "worlds": stats}, indent=1) + "\n")
    orig_print(f"wrote {out}")


if __name__ == "__main__":
    main()
