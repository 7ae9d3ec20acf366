"""Merge the per-world pickles of several ``benchmarks/worlds_strips.py --raw R`` runs (one
world each, so that a long acceptance run keeps what it measured) into one, for ``--from-raw``.

``python benchmarks/spi19p_merge_raw.py OUT R1 R2 ...`` (method ornament): writes
``OUT.ornament.pkl``; then ``python benchmarks/worlds_strips.py --methods ornament
--from-raw OUT --out F``.
"""

from __future__ import annotations

import pickle
import sys


def main() -> None:
    out, *ins = sys.argv[1:]
    meta: dict = {}
    per: dict = {}
    for r in ins:
        with open(f"{r}.ornament.pkl", "rb") as fh:
            raw = pickle.load(fh)
        m = raw["world"]
        if not meta:
            meta = dict(m, variants=[], spacings={})
        assert m["kinds"] == meta["kinds"], (r, m["kinds"], meta["kinds"])
        meta["variants"] += m.get("variants", [])
        meta["spacings"].update(m.get("spacings", {}))
        for mode, ws in raw["per"].items():
            per.setdefault(mode, []).extend(ws)
    with open(f"{out}.ornament.pkl", "wb") as fh:
        pickle.dump({"world": meta, "per": per}, fh)
    print(f"{out}.ornament.pkl: {sum(len(v) for v in per.values())} worlds, {meta['variants']}")


if __name__ == "__main__":
    main()
