"""Helper s67t: what ``_grow.fill_room`` sees on a --harder three-size row (src untouched): the
exemplar's room rates per kind (``_room_rate``: all kinds above the smallest class; the smallest
class's at ROOM_SHARE and at ROOM_SHARE_SMALLEST), ``_larger_short`` when fill_room runs, each kind's
``_room_cap`` then, and the elements fill_room added per kind.

    PYTHONPATH=src:benchmarks python benchmarks/s67t_fillroom.py three_sizes:h8s41 1,3
"""
import sys

import numpy as np

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from grow_variants import _harder_suite
from synth_variants import _harder, run

import strew.synth._grow as G

_fr = G.fill_room
LOG = []


def fill_room(state, *a, **k):
    prep = state.prep
    S = int(prep.skind.max()) + 1
    n0 = state.n
    short = G._larger_short(state)
    caps = [G._room_cap(state, q, any_class=True) for q in range(S)]
    r = _fr(state, *a, **k)
    add = np.bincount(prep.skind[state.src[n0:state.n]], minlength=S)[:S]
    LOG.append(f"    fill_room: larger_short {short} caps (to inner density) {caps} added per kind {add.tolist()}")
    return r


G.fill_room = fill_room


def main():
    cls, label = sys.argv[1].split(":")
    i, _, v = label[1:].partition("s")
    ex = _harder_suite().make_exemplar(cls, rng=int(v), **_harder()[cls][int(i)])
    for s in [int(x) for x in sys.argv[2].split(",")]:
        LOG.clear()
        run(ex, 3.5, s, None)
        from strew.synth._palette import Palette
        from strew.synth._prepare import prepare
        prep = prepare(Palette({"ex": ex}).select("ex"))
        sel = prep.selected_elements & ~prep.void
        S = int(prep.skind.max()) + 1
        names = [ex.kinds[int(prep.kind[prep.skind == q][0])] for q in range(S)]
        cnt = np.bincount(prep.skind[sel], minlength=S)[:S]
        inner_area = float(prep.domains[0].buffer(-2.0 * float(prep.rc.max())).area)
        print(f"{sys.argv[1]} seed {s}: kinds {names} counts {cnt.tolist()}")
        for lab, rr in (("larger kinds", G._room_rate(prep)), ("smallest @ROOM_SHARE", G._room_rate(prep, smallest=True)),
                        ("smallest @inf", G._room_rate(prep, smallest=True, share=G.ROOM_SHARE_SMALLEST)),
                        ("smallest @sparse", G._room_rate(prep, smallest=True, share=G.ROOM_SPARSE_SHARE))):
            print(f"    room rate {lab:22s} per 1e4 {np.round(rr * 1e4, 2)} rooms in inner / count {np.round(rr * inner_area / np.maximum(cnt * inner_area / prep.domains[0].area, 1), 3)}")
        print("\n".join(LOG), flush=True)


if __name__ == "__main__":
    main()
