"""Issue 13 point 1 (helper s27o): an exemplar of one size class whose generator threw its
kind to saturation gets the output's rooms too, up to its exemplar's density
(``_grow.fill_room``, ``ROOM_ONE_CLASS``)."""

from __future__ import annotations

from strew_testing import fidelity_suite

from strew import Region
from strew.metrics import fidelity
from strew.synth import synthesize


def test_saturated_one_kind_stones_fill_the_rooms_up_to_their_density():
    # stones of radius 8, 300 asked (the generator fits 59: saturated; --harder stones h3,
    # variant seed 19). At main cd304c2, seeds 1 and 2 at 3.5x: density 0.913 and 0.910
    # of the exemplar's, nn[stone>stone] 0.077 and 0.082 against a tolerance of 0.073
    # (every decile too far); now 0.946 and 0.962, 0.058 and 0.056
    ex = fidelity_suite().make_exemplar("stones", rng=19, radius=8.0, count=300)
    x0, y0, x1, y1 = ex.region.bounds
    for seed in (1, 2):
        out = synthesize(ex, Region.rectangle(3.5 * (x1 - x0), 3.5 * (y1 - y0)), rng=seed, measure=False)
        rep = fidelity(ex, out, eq5=False, local=False)
        d = rep.metrics["density[stone]"]
        ratio = d.result / d.exemplar
        # the rooms are filled, but not beyond the exemplar's density (the cap)
        assert 0.93 <= ratio <= 1.03, (seed, ratio)
        assert rep.metrics["nn[stone>stone]"].passed, (seed, rep.metrics["nn[stone>stone]"].value)


def test_one_class_rooms_wait_for_growth_to_finish(monkeypatch):
    # helper s28o: growth cut short (a brush segment's max_iterations) leaves open circles
    # at its front; the one-kind rule must not fill them (on the studio's tiles stroke it
    # put 1-3 elements there and the stroke finished at 0.935 of one grown fully), but
    # once growth finishes it takes the rooms of the whole unfinished part. Same exemplar
    # as above at 2.5x: the unbounded fill's room fill adds 24-26 at seeds 1-3; at 8
    # iterations s27o's rule added 24-26 at the open front and none at the finish
    from strew.synth import _grow, new_state

    ex = fidelity_suite().make_exemplar("stones", rng=19, radius=8.0, count=300)
    x0, y0, x1, y1 = ex.region.bounds
    calls = []
    orig = _grow.fill_room

    def traced(state, room=None, since=0):
        front = bool(state.horizon.any())
        got = orig(state, room, since)
        calls.append((front, got))
        return got

    monkeypatch.setattr(_grow, "fill_room", traced)
    st = new_state(ex, Region.rectangle(2.5 * (x1 - x0), 2.5 * (y1 - y0)), rng=1)
    _grow.fill(st, max_iterations=8)
    assert st.horizon.any()  # cut short
    assert calls and all(got == 0 for front, got in calls if front), calls
    calls.clear()
    _grow.grow(st)
    assert not st.horizon.any()
    # the finished output's rooms are filled (on main the rule does not exist: 0)
    assert sum(got for _, got in calls) >= 5, calls
