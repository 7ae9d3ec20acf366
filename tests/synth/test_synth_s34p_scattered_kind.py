"""Issue 13 point 1 (helper s34p): a kind scattered among a more numerous kind of its
own size class keeps to itself at most that kind's closest approach
(``_prepare._free_scattered``), so its few exemplar elements' far spacing does not thin
it out in the output."""

from __future__ import annotations

import numpy as np
from strew_testing import fidelity_suite

from strew import Region
from strew.metrics import fidelity
from strew.synth import as_selection, prepare, synthesize


def _few_pebbles():
    # --harder two_sizes h9 at variant seed 24: pebbles 0.85 of the stones, so one size
    # class; 120 pebbles asked, 5 fit among the 40 stones, their closest approach 81
    return fidelity_suite().make_exemplar("two_sizes", rng=24, ratio=0.85, n_large=40, n_small=120)


def test_scattered_kind_has_no_self_spacing_but_the_others_keep_theirs():
    ex = _few_pebbles()
    p = prepare(as_selection(ex))
    names = list(ex.shapes)
    peb, sto = names.index("pebble"), names.index("stone")
    kind_of = {int(k): int(s) for k, s in zip(p.kind, p.skind)}
    pk, sk = kind_of[peb], kind_of[sto]
    assert len(np.unique(p.size_class)) == 1 and np.sum(p.skind == pk) * 3 <= np.sum(p.skind == sk)
    # main: 0.95 x 81 = 76.9; the stones keep 0.95 x 26.1 = 24.8 (collision bound 21.9)
    assert p.min_dist[pk, pk] <= p.min_dist[sk, sk], p.min_dist
    # the common kind and the pair keep the exemplar's closest approach
    assert p.min_dist[sk, sk] > 20.0 and p.min_dist[sk, pk] > 20.0, p.min_dist
    # a rare kind of its own size class (clusters' discs, spaced 84 apart) keeps its spacing
    cl = fidelity_suite().make_exemplar("clusters", rng=24, large=14.0, small=4.0, cluster_spacing=84.0, ring_min=6, ring_max=8)
    q = prepare(as_selection(cl))
    disc = {int(k): int(s) for k, s in zip(q.kind, q.skind)}[list(cl.shapes).index("disc")]
    assert q.min_dist[disc, disc] > 60.0, q.min_dist


def test_few_scattered_pebbles_keep_their_share_beside_stones():
    # at 3.5x, seeds 1 and 2: pebbles per stone 0.54 and 0.49 of the exemplar's on main
    # (nn[stone>pebble] 0.581 and 0.640 against 0.531: failing); now 1.00 and 0.81
    # (0.386 and 0.439, passing)
    ex = _few_pebbles()
    kn = np.asarray(ex.kind_names)
    share = np.sum(kn == "pebble") / np.sum(kn == "stone")
    x0, y0, x1, y1 = ex.region.bounds
    for seed in (1, 2):
        out = synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed, measure=False)
        ok = np.asarray(out.kind_names)
        got = np.sum(ok == "pebble") / np.sum(ok == "stone") / share
        assert got >= 0.7, (seed, got)
        m = fidelity(ex, out, eq5=False, local=False).metrics["nn[stone>pebble]"]
        assert m.passed, (seed, m.value, m.tolerance)
