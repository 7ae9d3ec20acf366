"""Untiled hierarchy before/after (helper hie19u, issue 19.4): ``PYTHONPATH=TREE/src python
benchmarks/hie19u_untiled.py OUT_PREFIX [--side 200]`` grows ``grow_ornament("hierarchy",
side x side, rng=1)``, prints its element count, kind counts and the digest of
benchmarks/spi19p_identity.py (x, y, rotation, kind, public columns, parts' points), and
writes OUT_PREFIX.png (1024 px) and OUT_PREFIX.json. Run it on two trees and compare."""

import json
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))


def main() -> None:
    import strew
    from strew.io.png import to_png
    from strew.ornament import grow_ornament
    from spi19p_identity import digest

    out = sys.argv[1]
    side = float(sys.argv[sys.argv.index("--side") + 1]) if "--side" in sys.argv else 200.0
    t0 = time.process_time()
    arr = grow_ornament("hierarchy", strew.Region.rectangle(side, side), rng=1)
    cpu = time.process_time() - t0
    kinds = {k: int((arr.kind == i).sum()) for i, k in enumerate(arr.kinds)}
    res = {"tree": strew.__file__, "side": side, "elements": len(arr), "kinds": kinds, "digest": digest(arr), "cpu_s": cpu}
    Path(out + ".png").write_bytes(to_png(arr, width=1024))
    Path(out + ".json").write_text(json.dumps(res, indent=1))
    print(json.dumps(res))


if __name__ == "__main__":
    main()
