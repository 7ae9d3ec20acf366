"""grow's §5.1 priority test (``_Place.outranked``) asks the seed that held a seed back
last time first (``_Grower.outranker``): the same answers as the full scan (issue 14
point 5, speed; byte-identical output)."""

from __future__ import annotations


def test_outranked_memo_same_answer(monkeypatch):
    """Every answer is the one the full scan of the nine cells gives, and the memo
    answers most of them."""
    import strew.grow._place as P
    from strew.grow import analyze, grow
    from strew.grow._exemplars import stone_exemplar

    orig = P._Place.outranked
    seen = {"calls": 0, "memo": 0}

    def checked(self, i):
        j = self.outranker.get(i)
        got = orig(self, i)
        memo = self.outranker.pop(i, None)
        full = orig(self, i)  # without the memo: the scan
        if memo is not None:
            self.outranker[i] = memo
        assert got == full
        seen["calls"] += 1
        seen["memo"] += got and j is not None and self.outranker.get(i) == j
        return got

    monkeypatch.setattr(P._Place, "outranked", checked)
    grow(analyze(stone_exemplar()), count=300, rng=2, relax=True)
    assert seen["calls"] > 500 and seen["memo"] > 0.5 * seen["calls"]
