"""What a Dask world costs besides its tiles (issue 19.5): one task per tile, one graph
message, a local cluster with its housekeeping made rare."""

from __future__ import annotations

import pytest

import strew
from strew import tiles as tiles_mod
from strew.tiles import plan, tiled

pytest.importorskip("dask.distributed")

SHAPES = {"bar": strew.Shape.rectangle(3, 1.5), "disc": strew.Shape.circle(1.0, 16)}


@pytest.mark.slow
def test_one_task_per_tile_sent_in_one_graph(monkeypatch):
    from distributed.diagnostics.plugin import SchedulerPlugin

    class Count(SchedulerPlugin):
        def __init__(self) -> None:
            self.graphs = 0
            self.run: set[str] = set()

        def update_graph(self, scheduler, *, keys, **kwargs):
            self.graphs += 1

        def transition(self, key, start, finish, *args, **kwargs):
            if finish == "memory" and str(key).startswith("strew-"):
                self.run.add(str(key))

    count = Count()
    connect = tiles_mod._connect

    def watched(*args, **kwargs):
        client, cluster = connect(*args, **kwargs)
        cluster.scheduler.add_plugin(count)
        return client, cluster

    monkeypatch.setattr(tiles_mod, "_connect", watched)
    size, tile = (120.0, 90.0), 30.0  # 4 x 3 tiles
    arr = tiled("pack", SHAPES, size, tile_size=tile, seed=5, workers=2, processes=False)
    ntiles = len(plan(size, tile)[0])
    # before: a task per tile and one per border band, each submitted on its own
    # (12 tiles: 22 tasks, each in its own graph update)
    assert len(count.run) == ntiles and all(k.startswith("strew-tile-") for k in count.run)
    assert count.graphs == 1
    assert arr.equals(tiled("pack", SHAPES, size, tile_size=tile, seed=5, workers=1))


@pytest.mark.slow
def test_local_cluster_workers_get_the_rare_housekeeping():
    import dask

    before = dask.config.get("distributed.admin.tick.interval")
    client, cluster = tiles_mod._connect(None, 1, True, 10.0)
    try:
        got = client.run(lambda: (dask.config.get("distributed.admin.tick.interval"),
                                  dask.config.get("distributed.worker.profile.enabled")))
    finally:
        client.close()
        cluster.close()
    assert list(got.values()) == [("1s", False)]
    # the settings stay with the cluster: this process's configuration is unchanged
    assert dask.config.get("distributed.admin.tick.interval") == before != "1s"
