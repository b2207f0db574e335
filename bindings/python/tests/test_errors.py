"""Refused input raises foresight.Error (a ValueError) naming the problem; nothing crashes, no NaN."""

import math

import numpy as np
import pytest

import foresight as fs


def test_error_is_a_value_error():
    assert issubclass(fs.Error, ValueError)


def test_negative_time_carries_the_status_message():
    with pytest.raises(fs.Error) as error:
        fs.predict_linear((0, 0, 0), (1, 0, 0), -1)
    assert fs.status_message(fs.Status.NegativeTime) in str(error.value)
    assert "predict_linear" in str(error.value) and "NegativeTime" in str(error.value)


@pytest.mark.parametrize("call", [
    lambda: fs.predict_linear((math.nan, 0, 0), (1, 0, 0), 1),
    lambda: fs.predict_accelerated((0, 0, 0), (1, 0, 0), (0, math.inf, 0), 1),
    lambda: fs.predict_linear((0, 0, 0), (1, 0, 0), math.nan),
    lambda: fs.predict_projectile((0, 0, 0), np.array([0, np.nan, 0]), 1),
    lambda: fs.predict_vehicle_exact(fs.VehicleState(velocity=(0, 0, math.nan)), 1),
    lambda: fs.predict_dead_reckoning(fs.DeadReckoningState(position=(0, math.nan, 0)), 1),
    lambda: fs.aim_projectile((0, 0, 0), (0, 0, 10), speed=math.nan),
])
def test_nan_is_refused(call):
    with pytest.raises(ValueError, match="NonFiniteInput"):
        call()


@pytest.mark.parametrize("value", [(1, 2), [1, 2, 3, 4], np.zeros((3, 1)), np.zeros((2, 3)), "abc", None, 5])
def test_wrong_shapes_name_the_argument(value):
    with pytest.raises(ValueError, match="velocity"):
        fs.predict_linear((0, 0, 0), value, 1)


def test_vectors_accept_tuples_lists_and_arrays():
    for v in ((3, 0, 4), [3, 0, 4], np.array([3, 0, 4]), np.array([3, 0, 4], dtype=np.float32)):
        np.testing.assert_array_equal(fs.predict_linear((0, 0, 0), v, 1).position, [3, 0, 4])


@pytest.mark.parametrize("call, status", [
    (lambda: fs.predict_vehicle_iterative(fs.VehicleState(), 1, 0), "InvalidIterations"),
    (lambda: fs.predict_vehicle_exact(fs.VehicleState(orientation=(0, 0, 0, 0)), 1), "ZeroQuaternion"),
    (lambda: fs.predict_vehicle_exact(fs.VehicleState(), 1, fs.VehicleSettings(forward=(0, 0, 0))), "ZeroVector"),
    (lambda: fs.predict_projectile((0, 0, 0), (0, 0, 1), 1, fs.ProjectileSettings(restitution=2)),
     "InvalidRestitution"),
    (lambda: fs.predict_projectile((0, 0, 0), (0, 0, 1), 1, fs.ProjectileSettings(step=0)), "InvalidStep"),
    (lambda: fs.predict_projectile((0, 0, 0), (0, 0, 1), -1), "NegativeTime"),
    (lambda: fs.predict_projectile((0, 0, 0), (0, 0, 1e7), 1), "OutOfRange"),
    (lambda: fs.StaticWorld().add_sphere((0, 0, 0), -1), "InvalidRadius"),
    (lambda: fs.StaticWorld().add_triangle((0, 0, 0), (1, 0, 0), (2, 0, 0)), "DegenerateShape"),
    (lambda: fs.StaticWorld().add_plane((0, 0, 0)), "ZeroVector"),
    (lambda: fs.predict_orientation((0, 0, 0, 0), (0, 1, 0), 1), "ZeroQuaternion"),
    (lambda: fs.aim_projectile((0, 0, 0), (0, 0, 10), constraint=fs.AimConstraint.ApexAboveStart, apex_height=2,
                               gravity=(0, 0, 0)), "ZeroVector"),
])
def test_library_refusals(call, status):
    with pytest.raises(fs.Error, match=status):
        call()


def test_engine_profile_out_of_range():
    settings = fs.ProjectileSettings(method=fs.ProjectileMethod.Engine)
    profile = settings.engine
    profile.substeps = 0
    settings.engine = profile
    with pytest.raises(fs.Error, match="InvalidSetting"):
        fs.predict_projectile((0, 0, 0), (0, 0, 1), 1, settings)
    with pytest.raises(fs.Error, match="InvalidSetting"):
        profile.validate()


def test_dead_reckoning_batch_shapes_and_bad_entities():
    n = 4
    ok = dict(algorithms=np.full(n, 2), positions=np.zeros((n, 3)), velocities=np.ones((n, 3)),
              accelerations=np.zeros((n, 3)), orientations=np.tile([0, 0, 0, 1.0], (n, 1)),
              angular_velocities=np.zeros((n, 3)), timestamps=np.zeros(n))
    positions, _, _, refused = fs.predict_dead_reckoning_batch(**ok, time=2.0)
    assert refused == 0
    np.testing.assert_array_equal(positions, np.full((n, 3), 2.0))
    with pytest.raises(ValueError, match=r"velocities: expected shape \(4, 3\), got \(4, 2\)"):
        fs.predict_dead_reckoning_batch(**dict(ok, velocities=np.zeros((n, 2))), time=1.0)
    with pytest.raises(ValueError, match=r"timestamps"):
        fs.predict_dead_reckoning_batch(**dict(ok, timestamps=np.zeros(n + 1)), time=1.0)
    # A NaN or a bad algorithm in one entity: refused and counted, kept as given (no NaN out).
    bad = dict(ok, positions=np.array([[0, 0, 0], [np.nan, 0, 0], [0, 0, 0], [0, 0, 0]]),
               algorithms=np.array([2, 2, 42, 2]))
    positions, velocities, orientations, refused = fs.predict_dead_reckoning_batch(**bad, time=2.0)
    assert refused == 2
    np.testing.assert_array_equal(positions[2], [0, 0, 0])
    assert np.isfinite(positions[[0, 2, 3]]).all()
    batch = fs.DeadReckoningBatch(n)
    with pytest.raises(fs.Error, match="entity 1"):
        batch.set_all(**bad)
    with pytest.raises(ValueError, match="expected 4 entities"):
        batch.set_all(**{k: v[:3] for k, v in ok.items()})
    with pytest.raises(ValueError, match="capacity"):
        batch.set(4, fs.DeadReckoningState(), 0.0)
    with pytest.raises(ValueError):
        batch.extrapolate(math.nan)
    with pytest.raises(ValueError):
        batch.extrapolate(1.0, -1.0)
    # Algorithms given as enum members work too.
    batch.set_all(**dict(ok, algorithms=[fs.DeadReckoningAlgorithm.FPW] * n))
    assert batch.extrapolate(3.0) == 0
    np.testing.assert_array_equal(batch.positions, np.full((n, 3), 3.0))


def test_infinite_and_huge_times_are_refused_without_allocating():
    with pytest.raises(fs.Error, match="NonFiniteInput"):
        fs.predict_projectile((0, 0, 0), (0, 0, 1), math.inf)
    # 1e9 s at 0.02 s steps is 5e10 steps: over max_steps (2^20), refused before any work.
    with pytest.raises(fs.Error, match="TooManySteps"):
        fs.predict_projectile((0, 0, 0), (0, 0, 1), 1e9, fs.ProjectileSettings(method=fs.ProjectileMethod.Stepped))


def test_numbers_beyond_the_float_range_are_refused():
    # 1e300 does not fit a float: it is taken as infinity, which the library refuses.
    with pytest.raises(fs.Error, match="NonFiniteInput"):
        fs.predict_linear((0, 0, 0), (1e300, 0, 0), 1)
    with pytest.raises(fs.Error, match="NonFiniteInput"):
        fs.predict_linear((0, 0, 0), (1, 0, 0), 1e300)
