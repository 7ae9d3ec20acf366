"""ornament's raster ``resolution`` (a cell count) is ``cells``; pack's ``resolution``
stays a pixel side (issue 15: one meaning per name). The old keyword and flag still work
for one release, with a warning naming the new one, and give the same output."""

from __future__ import annotations

import json

import numpy as np
import pytest

from strew.cli import main
from strew.ornament import grow_ornament
from strew.region import Region


def test_cells_and_the_deprecated_resolution_grow_the_same_ornament():
    region = Region.rectangle(40, 30)
    new = grow_ornament("dots", region, rng=2, cells=96)
    with pytest.warns(DeprecationWarning, match="resolution is renamed cells"):
        old = grow_ornament("dots", region, rng=2, resolution=96)
    assert len(new) > 3
    for a, b in ((new.x, old.x), (new.y, old.y), (new.rotation, old.rotation)):
        assert np.array_equal(a, b)
    assert new.meta["params"]["cells"] == old.meta["params"]["cells"] == 96
    assert "resolution" not in new.meta["params"]
    default = grow_ornament("dots", region, rng=2)
    assert isinstance(default.meta["params"]["cells"], int)  # the engine's resolved default


def test_both_names_at_once_is_an_error():
    from strew import InputError

    with pytest.raises(InputError, match="cells"), pytest.warns(DeprecationWarning):
        grow_ornament("dots", Region.rectangle(40, 30), rng=2, cells=96, resolution=96)


def test_cli_old_flag_warns_and_matches(tmp_path, capsys):
    a, b = tmp_path / "a.json", tmp_path / "b.json"
    assert main(["ornament", "dots", "--size", "40x30", "--seed", "2", "--cells", "96", "-q", "-o", str(a)]) == 0
    capsys.readouterr()
    assert main(["ornament", "dots", "--size", "40x30", "--seed", "2", "--resolution", "96", "-q", "-o", str(b)]) == 0
    assert "--resolution is renamed --cells" in capsys.readouterr().err
    ea, eb = (json.loads(p.read_text())["elements"] for p in (a, b))
    assert ea == eb
    assert main(["ornament", "dots", "--size", "40x30", "--cells", "96", "--resolution", "96", "-o", str(b)]) == 2
