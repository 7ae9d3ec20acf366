"""Digests of ``strew.grow`` outputs, to check that a speed change leaves every byte alone.

Each row is the element count and a SHA-256 digest (first 16 hex digits) of the output's
positions (``xy`` as float64) and the WKB of its shapes. Cases (first argument):
``fixed`` -- stones, tiles and hexagonal scales, 2,000 elements, relaxation on and off;
``hexflow`` -- the hexagonal lattice in flow mode along a field turning 90 degrees, in
regions 20, 30 and 45 spacings wide (two thirds as high), relaxation on and off;
``structure`` -- the 12 flow cases of ``benchmarks/grow.py --structure --flow-only``;
``alternates`` -- its 7 alternate start points; ``modes`` -- rotation mode, a repeat tile,
the spray, a boundary stroke, two and three sizes and bricks with a priority, smaller,
relaxation on and off; ``all`` -- all of them.

Run: ``PYTHONPATH=src python benchmarks/grow_hashes.py fixed a.json`` on two trees and
compare the two JSON files (the structure cases' tables also print; the CPU time goes to
stderr).
"""

from __future__ import annotations

import hashlib
import json
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))


def digest(out) -> str:
    import shapely

    h = hashlib.sha256()
    h.update(np.ascontiguousarray(out.xy, dtype=float).tobytes())
    h.update(b"".join(shapely.to_wkb(np.asarray(out.geometry))))
    return h.hexdigest()[:16]


def main() -> None:
    import strew.grow as SG
    from strew import Region
    from strew.grow import analyze
    from strew.grow._exemplars import hex_exemplar, stone_exemplar, tile_exemplar

    which = sys.argv[1] if len(sys.argv) > 1 else "all"
    orig = SG.grow
    rows: dict[str, list] = {}
    t0 = time.process_time()
    if which in ("fixed", "all"):
        for name, f in (
            ("stones", stone_exemplar),
            ("tiles", tile_exemplar),
            ("hex", hex_exemplar),
        ):
            ref = analyze(f())
            for relax in (True, False):
                out = orig(ref, count=2000, rng=1, relax=relax)
                rows[f"{name} 2000 relax {relax}"] = [len(out), digest(out)]
    if which in ("hexflow", "all"):
        ref = analyze(hex_exemplar())
        sp = ref.mean_edge
        for W in (20, 30, 45):
            w = W * sp

            def field(p, w=w):
                a = np.radians(90.0) * np.clip(np.asarray(p)[:, 0] / w, 0, 1)
                return np.c_[np.cos(a), np.sin(a)]

            for relax in (True, False):
                out = orig(
                    ref,
                    rng=1,
                    relax=relax,
                    region=Region.rectangle(w, W * 2 / 3 * sp),
                    mode="flow",
                    flow=field,
                )
                rows[f"hexflow {W} relax {relax}"] = [len(out), digest(out)]
    if which in ("modes", "all"):
        # the other modes and tools, smaller: rotation mode, a repeat tile, two and three
        # sizes, bricks with a priority, the spray tool, a boundary stroke
        from grow import _suite_exemplar

        hexr, stones = analyze(hex_exemplar()), analyze(stone_exemplar())
        sp = hexr.mean_edge
        cases = [
            ("rotate stones 600", stones, dict(count=600, mode="rotate")),
            ("rotate hex 600", hexr, dict(count=600, mode="rotate")),
            ("periodic hex", hexr, dict(region=Region.rectangle(10 * sp, 4 * np.sqrt(3) * sp), periodic=True)),
            ("periodic stones", stones, dict(region=Region.rectangle(12 * sp, 12 * sp), periodic=True)),
            ("spray stones", stones, dict(spray=np.c_[np.linspace(0, 40 * sp, 20), 5 * sp * np.sin(np.linspace(0, 3, 20))], spray_radius=4 * sp)),
            ("boundary hex", hexr, dict(region=Region.rectangle(24 * sp, 16 * sp), boundary=[np.c_[np.linspace(2, 22, 9) * sp, np.linspace(2, 6, 9) * sp]])),
        ]
        for name in ("two_sizes", "three_sizes", "bricks"):
            ex = _suite_exemplar(name)
            if ex is not None:
                x0, y0, x1, y1 = ex.region.bounds
                prio = {"brick_red": 1, "brick_ochre": 0} if name == "bricks" else None
                cases.append((f"{name}", ex, dict(region=Region.rectangle(2.5 * (x1 - x0), 2.5 * (y1 - y0)), priority=prio)))
        for label, ref, kw in cases:
            for relax in (True, False):
                out = orig(ref, rng=2, relax=relax, **kw)
                rows[f"{label} relax {relax}"] = [len(out), digest(out)]
    for case in ("structure", "alternates"):
        if which not in (case, "all"):
            continue
        import grow as B

        def hashed(*a, case=case, k=[0], **kw):  # noqa: B006 - the case's own counter
            out = orig(*a, **kw)
            rows[f"{case} {k[0]}"] = [len(out), digest(out)]
            k[0] += 1
            return out

        SG.grow = hashed
        try:
            # (the structure figures to a scratch file: the digests are what is compared)
            with tempfile.TemporaryDirectory() as tmp:
                B.structure(
                    str(Path(tmp) / "structure.json"),
                    flow_only=True,
                    alternates=(case == "alternates"),
                )
        finally:
            SG.grow = orig
    text = json.dumps(rows, indent=0)
    if len(sys.argv) > 2:
        Path(sys.argv[2]).write_text(text + "\n")
    print(text)
    print("cpu", time.process_time() - t0, file=sys.stderr)


if __name__ == "__main__":
    main()
