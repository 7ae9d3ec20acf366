"""orn19m_willow._world with the kinds in one order for every world (helper w70d): a world whose rows were
concatenated in another order (w70d's three sweeps) lists its kinds in another order, and w67d_judge / w60d_bias
index every world's kinds by the first world's list. ``python benchmarks/w70d_canon.py w67d_judge.py ARGS...`` runs
that script with the wrapper installed."""
from __future__ import annotations

import runpy
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
CANON = ["vine", "twig", "leaf", "flower", "quote"]


def install() -> None:
    import orn19m_willow as W

    orig = W._world
    if getattr(orig, "_w70d", False):
        return

    def world(path):
        w = orig(path)
        ks = list(w["kinds"])
        canon = CANON + [k for k in ks if k not in CANON]
        m = np.array([canon.index(k) for k in ks], np.int64)
        w["kind"] = m[np.asarray(w["kind"], np.int64)] if len(w["kind"]) else np.asarray(w["kind"], np.int64)
        dk = np.asarray(w["dkind"], np.int64)
        w["dkind"] = np.where(dk >= 0, m[np.maximum(dk, 0)], -1) if len(dk) else dk
        w["kinds"] = canon
        return w

    world._w70d = True
    W._world = world


if __name__ == "__main__":
    install()
    script = sys.argv[1]
    sys.argv = [str(HERE / script), *sys.argv[2:]]
    runpy.run_path(str(HERE / script), run_name="__main__")
