"""Danger queries and throw planning: closed forms, and consistency with the predictions."""

import math

import numpy as np
import pytest

import foresight as fs

FLOAT_TOL = 1e-5  # float results: a few ulps of the ~10 m magnitudes involved


def thrown():
    world = fs.StaticWorld()
    world.add_plane((0, 1, 0), 0)
    return fs.predict_projectile((0, 1.6, 0), (0, 4, 12), 3.0, fs.ProjectileSettings(radius=0.05, friction=0.4), world)


def test_danger_zone_is_the_end_of_the_trajectory():
    result = thrown()
    zone = fs.danger_zone(result.trajectory, 3.0, 4.0)
    np.testing.assert_allclose(zone.center, result.position, atol=FLOAT_TOL)
    assert zone.radius == 4.0 and zone.time == 3.0
    blast_point = zone.center + np.array([0, 0, 3.9], dtype=np.float32)
    assert fs.find_danger_start(result.trajectory, blast_point, 3.0, 4.0) == pytest.approx(3.0)
    assert fs.is_point_safe(result.trajectory, blast_point, 2.9, 3.0, 4.0)
    assert not fs.is_point_safe(result.trajectory, blast_point, 3.0, 3.0, 4.0)
    assert fs.find_danger_start(result.trajectory, zone.center + np.array([0, 0, 50.0]), 3.0, 4.0) is None


def test_path_queries_on_free_flight():
    # Free flight (no world): the path is the parabola p + v t + g t^2 / 2.
    result = fs.predict_projectile((0, 0, 0), (0, 0, 10), 1.0)
    np.testing.assert_allclose(fs.position_on_trajectory(result.trajectory, 0.5), [0, -9.81 / 8, 5], atol=FLOAT_TOL)
    # The point (0, 0, 5) is 9.81/8 m below the path at t = 0.5 and the path descends: the closest
    # approach is near t = 0.5 at slightly less than that distance (the path's tangent tilts).
    distance, time = fs.find_closest_path_approach(result.trajectory, (0, 0, 5), 0.0, 1.0)
    assert distance < 9.81 / 8 and time == pytest.approx(0.5, abs=0.05)
    # A point on the path is reached exactly when the projectile is there.
    assert fs.find_path_approach(result.trajectory, (0, -9.81 / 8, 5), 0.0, 0.0, 1.0) == pytest.approx(0.5, abs=1e-5)


def test_vehicle_reaches_a_standing_character():
    # 10 m/s along +Z; the box's front face is 2.2 m ahead of its centre, the character a sphere of
    # radius 0.4 at 20 m: contact when 10 t = 20 - 2.2 - 0.4, t = 1.74 s.
    vehicle = fs.VehicleBody(fs.VehicleState(velocity=(0, 0, 10)))
    character = fs.CharacterBody(position=(0, 0, 20), radius=0.4)
    assert fs.vehicle_separation(vehicle, character, 0.0) == pytest.approx(17.4, abs=FLOAT_TOL)
    contact = fs.find_vehicle_contact(vehicle, character, 5.0)
    assert contact.contact
    # Conservative advancement stops within the 1 mm tolerance before the contact: <= 1e-4 s at 10 m/s.
    assert 1.74 - 1e-4 - 1e-6 <= contact.time <= 1.74 + 1e-6
    miss = fs.CharacterBody(position=(5, 0, 20), radius=0.4)
    distance, _ = fs.find_closest_vehicle_approach(vehicle, miss, 5.0)
    assert distance == pytest.approx(5 - 0.9 - 0.4, abs=2e-3)  # within the 1 mm tolerance, plus float rounding
    with pytest.raises(fs.Error, match="NegativeTime"):
        fs.find_vehicle_contact(vehicle, character, -1.0)


def test_plans_land_near_the_target():
    world = fs.StaticWorld()
    world.add_plane((0, 1, 0), 0)
    settings = fs.ProjectileSettings(radius=0.05, friction=0.4)
    plans, info = fs.plan_throw((0, 1.6, 0), (0, 0.05, 12), world, fuse_time=3.0, settings=settings)
    assert plans and info["predictions"] > 0
    for plan in plans:
        assert plan.distance <= 0.5
        assert np.linalg.norm(plan.launch_velocity) <= 20 + 1e-4  # the speed cap, float rounding
        # The plan is what predict_projectile computes for its launch velocity.
        flown = fs.predict_projectile((0, 1.6, 0), plan.launch_velocity, 3.0, settings, world)
        np.testing.assert_allclose(flown.position, plan.final_position, atol=FLOAT_TOL)
    with pytest.raises(fs.Error):
        fs.plan_throw((0, 1.6, 0), (0, 0, 12), world, fuse_time=-1)
