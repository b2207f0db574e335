"""Many calls leave no memory behind (no leaked results, arrays or worlds)."""

import gc
import os

import numpy as np
import pytest

import foresight as fs


def resident_bytes():
    """The process's resident set [bytes] (Linux /proc)."""
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[1]) * 4096


def churn(count):
    world = fs.StaticWorld()
    world.add_plane((0, 1, 0), 0)
    world.add_box((0, 1.5, 10), (5, 1.5, 0.25))
    arrays = (np.full(1000, 4), np.zeros((1000, 3)), np.ones((1000, 3)), np.zeros((1000, 3)),
              np.tile([0, 0, 0, 1.0], (1000, 1)), np.full((1000, 3), 0.5), np.zeros(1000))
    for i in range(count):
        fs.predict_linear((0, 0, 0), (1, 2, 3), 0.5)
        result = fs.predict_projectile((0, 1.6, 0), (0, 4, 12), 3.0, fs.ProjectileSettings(radius=0.05), world)
        _ = result.trajectory.positions
        fs.predict_dead_reckoning_batch(*arrays, 1.0)
        batch = fs.DeadReckoningBatch(1000)
        batch.set_all(*arrays)
        batch.extrapolate(1.0)
        _ = batch.positions
        try:
            fs.predict_linear((0, 0, 0), (1, 2, 3), -1)
        except fs.Error:
            pass
        fs.StaticWorld().add_sphere((0, 0, 0), 1)


@pytest.mark.skipif(not os.path.exists("/proc/self/statm"), reason="reads the resident set from Linux /proc")
def test_no_growth_over_many_calls():
    churn(200)  # warm up: allocator pools, interned objects
    gc.collect()
    before = resident_bytes()
    churn(2000)
    gc.collect()
    growth = resident_bytes() - before
    # Each round allocates ~150 kB (a batch of 1000 entities, a trajectory of ~150 points): a leak
    # of any of them over 2000 rounds would be hundreds of MB. 4 MB allows allocator noise.
    assert growth < 4 * 1024 * 1024, growth
