"""Benchmark of painting a repeat tile in the studio (issue 18 point 4).

A studio session (:class:`strew.studio._session.Session`, the messages the browser sends)
paints a whole rectangular tile with rows of strokes, with the repeat view on (strokes
run 20 units past the side edges and wrap) and off (the baseline: the same rows inside
the rectangle), same seed and size. Tools: the generative brush (synth, Davison et al.
2018, §5.4), the spray (grow, Ijiri et al. 2008, §5.1) and the filler (one click).
Each scene is judged by :func:`strew.metrics.repeat_report` as a tile laid side by side:
``wrap_ov`` / ``in_ov`` overlaps across the wrap / inside the tile (repeat: must be 0),
``edge_dens`` / ``edge_cov`` the density / coverage of the strips along the tile's edges
over the interior's (1 is seamless; a tile painted without wrapping thins out there),
``seam_fid`` the median local fidelity score (against the exemplar) of windows
straddling the seams over the interior windows', ``seam_fail`` / ``int_fail`` the share
of seam / interior windows that fail.
Columns ``r_`` repeat view, ``p_`` plain; figures are means over ``--seeds`` seeds
(overlaps: the worst seed); ``time_ratio`` is the median over seeds of repeat / plain
wall time of the painting, from the same run.

    python benchmarks/studio_repeat.py [--quick] [--seeds 3] [--only brush,spray,fill]
"""

from __future__ import annotations

import shutil
import statistics
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np  # noqa: E402
from _runner import Bench, parse_args  # noqa: E402

from strew import load, metrics  # noqa: E402
from strew.studio._session import Session  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]


def _cases(quick: bool) -> list[tuple[str, Path, float, float, float]]:
    """(label, exemplar, W, H, stroke radius)."""
    k = 0.75 if quick else 1.0
    return [
        ("pebbles", ROOT / "examples" / "synth" / "pebbles.json", round(200 * k), round(160 * k), 25.0),
        ("scales", ROOT / "examples" / "exemplars" / "scales.svg", round(300 * k), round(240 * k), 30.0),
    ]


def _paint(tool: str, exemplar: Path, w: float, h: float, radius: float, seed: int, repeat: bool) -> tuple[float, Any]:
    with tempfile.TemporaryDirectory() as d:
        root = Path(d)
        shutil.copy(exemplar, root / exemplar.name)
        s = Session(root, seed=seed, size=(w, h))
        s.handle({"type": "load_exemplar", "path": exemplar.name})
        if repeat:
            s.handle({"type": "settings", "repeat": True})
        t0 = time.perf_counter()
        if tool == "fill":
            s.handle({"type": "fill", "point": [[0.5 * w, 0.5 * h]]})
        else:
            pad = 20.0 if repeat else -5.0  # past the edges (they wrap), or inside them
            xs = np.arange(-pad, w + pad, 10.0)
            for y in np.arange(0.5 * radius, h, 1.2 * radius):
                pts = [[float(x), float(y)] for x in xs]
                s.handle({"type": "stroke_start", "tool": tool, "radius": radius, "points": pts[:1]})
                for i in range(1, len(pts), 4):
                    s.handle({"type": "stroke_move", "points": pts[i:i + 4]})
                s.handle({"type": "stroke_end"})
        dt = time.perf_counter() - t0
        return dt, s.scene()


def _figures(prefix: str, arr: Any, tile: Any, exemplar: Any) -> dict[str, Any]:
    r = metrics.repeat_report(arr, exemplar, tile=tile)
    return {
        f"{prefix}n": r["count"],
        f"{prefix}wrap_ov": r["overlaps"]["across"],
        f"{prefix}in_ov": r["overlaps"]["inside"],
        f"{prefix}edge_dens": r["density"]["ratio"],
        f"{prefix}edge_cov": r["coverage"]["ratio"],
        f"{prefix}seam_fid": r["fidelity"]["ratio"],
        f"{prefix}seam_fail": r["fidelity"]["seam_failing"],
        f"{prefix}int_fail": r["fidelity"]["interior_failing"],
    }


def main() -> int:
    def extra(p: Any) -> None:
        p.add_argument("--only", default=None, help="comma-separated tools (brush, spray, fill)")
        p.add_argument("--seeds", type=int, default=3, help="seeds per case (figures are their means)")
        p.set_defaults(repeat=1)

    args = parse_args(__doc__.splitlines()[0], extra)
    tools = args.only.split(",") if args.only else ["brush", "spray", "fill"]
    seeds = range(1, 1 + (1 if args.quick else max(1, args.seeds)))
    bench = Bench("studio_repeat", "painting a tile in the studio: repeat view vs plain", baseline="repeat view off, same seed, size and strokes",
                  json_path=args.json)
    for label, exemplar, w, h, radius in _cases(args.quick):
        _paint("brush", exemplar, w, h, radius, 0, True)  # warm-up: compiles the kernels
        for tool in tools:
            figs, ratios = [], []
            for seed in seeds:
                t_r, tile = _paint(tool, exemplar, w, h, radius, seed, True)
                t_p, flat = _paint(tool, exemplar, w, h, radius, seed, False)
                ratios.append(t_r / t_p if t_p > 0 else float("nan"))
                ex = load(exemplar)
                figs.append({**_figures("r_", tile, (0.0, 0.0, w, h), ex), **_figures("p_", flat, (0.0, 0.0, w, h), ex)})
            row: dict[str, Any] = {"size": f"{w:g}x{h:g}", "seeds": len(figs), "time_ratio": statistics.median(ratios)}
            for key in figs[0]:
                vals = [f[key] for f in figs]
                row[key] = max(vals) if key.endswith("_ov") else float(np.nanmean(vals))
            bench.row(f"{label} {tool}", **row)
    bench.finish()
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
