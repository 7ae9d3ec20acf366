"""Fill-gap on a distance field above REF_PIXELS (issue 19.6): k x P candidates a round.

A fine ``resolution`` makes a small region's field larger than REF_PIXELS, so the
scaled rounds run at a small cost; the result keeps fill-gap's guarantees and its
density, and a field at REF_PIXELS or below runs the paper's P (checked by counting
candidates tried per round: a round of the paper's tries at most P).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from strew import Region, load_shapes
from strew.metrics import outside, overlaps
from strew.pack import pack
from strew.pack._pack import REF_PIXELS

LEAF = Path(__file__).resolve().parents[2] / "examples" / "pack" / "leaf.json"


def test_large_field_rounds_scale_and_keep_guarantees() -> None:
    shapes = load_shapes(LEAF)
    region = Region.rectangle(300, 260)
    res = float(np.sqrt(300 * 260 / (4 * REF_PIXELS)))  # a field of about 4 x REF_PIXELS
    p = 20
    fine = pack(shapes, region, rng=3, resolution=res, candidates=p)
    plain = pack(shapes, region, rng=3, candidates=p)
    info_f, info_p = fine.meta["pack"], plain.meta["pack"]
    # k P candidates a round (k about 4): more than P tried a round on average, which P
    # candidates a round cannot give
    assert info_f["trials"] / info_f["rounds"] > p
    assert info_p["trials"] / info_p["rounds"] <= p
    assert len(overlaps(fine)[0]) == 0
    assert not np.any(outside(fine, region))
    # the density of the paper's rounds, within 5%
    assert abs(len(fine) / len(plain) - 1.0) < 0.05
    # same seed, same bytes
    again = pack(shapes, region, rng=3, resolution=res, candidates=p)
    assert np.array_equal(np.asarray(again.xy), np.asarray(fine.xy))
    assert np.array_equal(np.asarray(again.rotation), np.asarray(fine.rotation))
