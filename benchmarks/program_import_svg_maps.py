"""Issue 15 point 5: how far the maps of the example scripts (examples/program) move
when ``import_svg`` reads through another revision's SVG reading.

Every panel of every ``fig*.py`` is run at its ``demo_size`` (the gallery's; 800 where a
script names none) with seed 0, once with the working tree's strew and once with the
baseline's (``--base PATH``: the root of a checkout of another revision, e.g.
``git worktree add /tmp/base REV``; its own ``examples/program`` is run, so scripts edited
together with the reader are compared as they were), each in a subprocess. Printed per
panel: faces, edges and vertices of both maps, and the Hausdorff distance between their
edge sets (every edge sampled every 0.25 units, each sample's distance to the other
map's edges, the largest of both directions); "identical" where every edge is equal.
Writes ``benchmarks/results/program_import_svg_maps.json``.

    python benchmarks/program_import_svg_maps.py --base /tmp/base
"""

from __future__ import annotations

import argparse
import json
import os
import pickle
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
import shapely

ROOT = Path(__file__).resolve().parents[1]

WORKER = r"""
import pickle, runpy, sys
from pathlib import Path
from strew.program import run_script
ex, out = Path(sys.argv[1]), sys.argv[2]
res = {}
for script in sorted(ex.glob("fig*.py")):
    g = runpy.run_path(str(script))
    size = int(g.get("demo_size", 800))
    for name in g.get("demo_panels", ["arrangement"]):
        pm, _ = run_script(script, size=size, seed=0, name=name)
        res[f"{script.stem}:{name}"] = dict(size=size, edges=[e.points.copy() for e in pm.edges], n_faces=pm.n_faces,
                                           n_edges=pm.n_edges, n_vertices=pm.n_vertices)
pickle.dump(res, open(out, "wb"))
"""


def _maps(root: Path, tmp: Path, tag: str) -> dict:
    out = tmp / f"{tag}.pkl"
    env = {**os.environ, "PYTHONPATH": str(root / "src")}
    subprocess.run([sys.executable, "-c", WORKER, str(root / "examples" / "program"), str(out)], env=env, check=True)
    with open(out, "rb") as f:
        return pickle.load(f)


def _directed(a: list[np.ndarray], b: list[np.ndarray]) -> float:
    """Largest distance from a point of ``a``'s edges (sampled every 0.25) to ``b``'s edges."""
    la = [shapely.LineString(e) for e in a if len(e) >= 2]
    lb = [shapely.LineString(e) for e in b if len(e) >= 2]
    if not la or not lb:
        return float("inf") if la or lb else 0.0
    pts = shapely.get_coordinates(shapely.segmentize(shapely.MultiLineString(la), 0.25))
    _, d = shapely.STRtree(lb).query_nearest(shapely.points(pts), return_distance=True, all_matches=False)
    return float(d.max())


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--base", required="--quick" not in sys.argv, type=Path, help="root of a checkout of the baseline revision")
    ap.add_argument("--quick", action="store_true", help="run_all.py's check: skips without --base")
    args = ap.parse_args()
    if args.base is None:  # --quick without --base
        print("program_import_svg_maps: skipped: it compares this tree's maps with a baseline checkout's (--base PATH), which has no default")
        sys.exit(3)  # _runner.SKIPPED
    with tempfile.TemporaryDirectory() as tmp:
        old = _maps(args.base.resolve(), Path(tmp), "base")
        new = _maps(ROOT, Path(tmp), "new")
    rows = []
    for key in old:
        a, b = old[key], new[key]
        same = len(a["edges"]) == len(b["edges"]) and all(x.shape == y.shape and np.array_equal(x, y) for x, y in zip(a["edges"], b["edges"]))
        h = 0.0 if same else max(_directed(a["edges"], b["edges"]), _directed(b["edges"], a["edges"]))
        row = dict(panel=key, size=a["size"], identical=same, hausdorff=h,
                   **{f"{k}_{w}": m[k] for w, m in (("base", a), ("new", b)) for k in ("n_faces", "n_edges", "n_vertices")})
        rows.append(row)
        what = "identical" if same else f"Hausdorff {h:.3g}"
        print(f"{key:36s} size {a['size']:5d}  faces {a['n_faces']:4d} -> {b['n_faces']:4d}  edges {a['n_edges']:4d} -> {b['n_edges']:4d}  {what}")
    out = ROOT / "benchmarks" / "results" / "program_import_svg_maps.json"
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(dict(base=str(args.base), rows=rows), indent=1))
    print(f"wrote {out.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
