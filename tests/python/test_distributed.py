"""billiards.distributed on a local Dask cluster of two worker processes: the local batch's bits."""

import numpy as np
import pytest

import billiards

distributed = pytest.importorskip("distributed")


def test_the_cluster_plays_the_local_batch_bit_for_bit():
    import billiards.distributed as bd

    table = billiards.pool_table("8ft")
    physics = billiards.PoolPhysics()
    count = 30
    layouts = np.stack([billiards.rack(table, physics, "8ball", 0.001, k) for k in range(count)])
    cues = billiards.cues(speed=np.linspace(2, 8, count), up_offset=np.linspace(-0.4, 0.4, count))
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            remote = bd.play_shots(client, table, physics, layouts, cues, chunk_size=7, events=True)
            assert len(client.scheduler_info()["workers"]) == 2
    local = billiards.play_shots(table, physics, layouts, cues, events=True)
    assert np.array_equal(remote.balls.view(np.uint8), local.balls.view(np.uint8))
    assert np.array_equal(remote.event_count, local.event_count) and np.array_equal(remote.time, local.time)
    assert all(np.array_equal(a.view(np.uint8), b.view(np.uint8)) for a, b in zip(remote.events, local.events))
