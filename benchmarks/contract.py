"""Cost of the method contract (issue 15): spec validation, free region and provenance.

Each method's public entry point (validation, ``context``, ``stamp``: input and region
content hashes) against its internal call on the same checked arguments and seed, in one
interleaved run; and ``strew rerun`` against the original command. The ratio printed is
public / internal (1.0: the contract costs nothing).

    python benchmarks/contract.py [--quick] [--repeat N]
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np
from _runner import Bench, median_time, parse_args

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    opts = parse_args(__doc__)
    repeat = 3 if opts.quick else max(opts.repeat, 5)
    import strew
    from strew import Region, Shape
    from strew._method import content_hash, seed_record
    from strew.pack import SPEC as PACK
    from strew.pack import pack
    from strew.pack._pack import _pack_into

    bench = Bench("contract", "method contract overhead", baseline="the internal call on checked arguments", json_path=opts.json)
    shapes = {"bar": Shape.rectangle(6, 3)}
    region = Region.rectangle(160, 120)
    prm = PACK.validate({"max_failures": 100})
    prm["fits"] = 48
    public = lambda: pack(shapes, region, rng=1, max_failures=100)  # noqa: E731
    internal = lambda: _pack_into(shapes, region, gen=seed_record(1)[0], progress=None, should_cancel=None, **prm)  # noqa: E731
    t_pub, a = median_time(public, repeat=repeat)
    t_int, b = median_time(internal, repeat=repeat)
    assert len(a) == len(b)
    bench.row(f"pack 160x120 ({len(a)} elements)", median_s=t_pub, internal_s=t_int, ratio=t_pub / t_int)
    ctx = a.select(np.arange(0, len(a), 3))
    t_ctx, c = median_time(lambda: pack(shapes, region, rng=1, max_failures=100, context=ctx), repeat=repeat)
    bench.row(f"pack around {len(ctx)} context elements ({len(c)} placed)", median_s=t_ctx, internal_s=t_int, ratio=t_ctx / t_int)
    big = strew.concat([a] * max(1, 10_000 // max(len(a), 1)))
    t_hash, _ = median_time(lambda: content_hash(big), repeat=repeat)
    bench.row(f"content_hash of {len(big)} elements", median_s=t_hash, internal_s=t_int, ratio=t_hash / t_int)
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "o.json"
        cmd = [sys.executable, "-m", "strew", "pack", str(ROOT / "examples/pack/leaf.json"), "--size", "120x90", "--seed", "1", "-q", "-o", str(out)]
        t_cmd, _ = median_time(lambda: subprocess.run(cmd, check=True, capture_output=True), repeat=repeat)
        rerun = [sys.executable, "-m", "strew", "rerun", str(out), "-q"]
        t_rerun, _ = median_time(lambda: subprocess.run(rerun, check=True, capture_output=True), repeat=repeat)
    bench.row("strew rerun (identical bytes) vs the command", median_s=t_rerun, internal_s=t_cmd, ratio=t_rerun / t_cmd)
    bench.finish()


if __name__ == "__main__":
    main()
