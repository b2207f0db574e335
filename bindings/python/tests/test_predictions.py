"""Predictions through the module: closed forms, and the C++ library's own numbers (the CLI)."""

import math

import numpy as np
import pytest

import foresight as fs

# A float carries 24 bits: results of the default (float) build match a closed form evaluated in
# double within a few ulps of the magnitudes involved (here up to ~20 m: 2e-6 m per ulp).
FLOAT_TOL = 1e-5
# The CLI computes positions in double, the module's default build in float (positions rounded to
# 24 bits at every step): over a flight of tens of steps and two bounces that stays within 1e-4 m.
# (A long slide to rest would amplify it further: the comparisons stop before one. The exact,
# float-for-float comparison with the C++ library is python_article_scenarios.)
CLI_TOL = 1e-4

IDENTITY = {"w": 1, "x": 0, "y": 0, "z": 0}


def test_predict_linear_is_p_plus_vt():
    out = fs.predict_linear((1, 0, 2), [3, 0, 4], 0.5)
    np.testing.assert_array_equal(out.position, [2.5, 0, 4])  # exact in binary floating point
    np.testing.assert_array_equal(out.velocity, [3, 0, 4])
    assert isinstance(out.position, np.ndarray) and out.position.shape == (3,)


def test_predict_accelerated_is_p_plus_vt_plus_half_at2():
    p, v, a, t = np.array([1.0, 2.0, 3.0]), np.array([0.5, 4.0, -1.0]), np.array([0.0, -9.81, 2.0]), 0.75
    out = fs.predict_accelerated(p, v, a, t)
    np.testing.assert_allclose(out.position, p + v * t + a * t * t / 2, atol=FLOAT_TOL)
    np.testing.assert_allclose(out.velocity, v + a * t, atol=FLOAT_TOL)


def test_characters_match_the_cli(cli_predict):
    ref = cli_predict({"predictions": [
        {"id": "w", "model": "linear", "position": [1.25, 0, 2], "velocity": [3, 0.5, 4], "time": 0.7},
        {"id": "r", "model": "accelerated", "position": [1.25, 0, 2], "velocity": [3, 0.5, 4],
         "acceleration": [0, -9.81, 2], "time": 0.7}]})
    linear = fs.predict_linear((1.25, 0, 2), (3, 0.5, 4), 0.7)
    accelerated = fs.predict_accelerated((1.25, 0, 2), (3, 0.5, 4), (0, -9.81, 2), 0.7)
    np.testing.assert_allclose(linear.position, ref["w"]["position"], atol=FLOAT_TOL)
    np.testing.assert_allclose(accelerated.position, ref["r"]["position"], atol=FLOAT_TOL)
    np.testing.assert_allclose(accelerated.velocity, ref["r"]["velocity"], atol=FLOAT_TOL)


def test_vehicle_exact_is_on_the_circle():
    # 10 m/s along +Z turning at 0.5 rad/s about +Y: a circle of radius 20 m; after 2 s, 1 rad.
    start = fs.VehicleState(velocity=(0, 0, 10), angular_velocity=(0, 0.5, 0))
    out = fs.predict_vehicle_exact(start, 2.0)
    np.testing.assert_allclose(out.position, [20 * (1 - math.cos(1.0)), 0, 20 * math.sin(1.0)], atol=FLOAT_TOL)
    np.testing.assert_allclose(out.velocity, [10 * math.sin(1.0), 0, 10 * math.cos(1.0)], atol=FLOAT_TOL)
    np.testing.assert_allclose(out.orientation, [0, math.sin(0.5), 0, math.cos(0.5)], atol=1e-6)  # unit: float ulps


def test_vehicles_match_the_cli(cli_predict):
    common = {"model": "vehicle", "position": [1, 0, -2], "velocity": [0, 0, 10], "orientation": IDENTITY,
              "angular_velocity": [0, 0.5, 0.1], "time": 2}
    ref = cli_predict({"predictions": [dict(common, id="it", method="iterative", iterations=7),
                                       dict(common, id="ex", method="exact")]})
    start = fs.VehicleState((1, 0, -2), (0, 0, 10), (0, 0, 0, 1), (0, 0.5, 0.1))
    for name, out in (("it", fs.predict_vehicle_iterative(start, 2, 7)), ("ex", fs.predict_vehicle_exact(start, 2))):
        np.testing.assert_allclose(out.position, ref[name]["position"], atol=FLOAT_TOL)
        np.testing.assert_allclose(out.velocity, ref[name]["velocity"], atol=FLOAT_TOL)
        q = ref[name]["orientation"]
        np.testing.assert_allclose(out.orientation, [q["x"], q["y"], q["z"], q["w"]], atol=1e-6)


def test_vehicle_world_frame_and_forward_axis():
    # Forward +X, turning about world +Y: the same circle turned by 90 degrees.
    settings = fs.VehicleSettings(frame=fs.AngularFrame.World, forward=(1, 0, 0))
    out = fs.predict_vehicle_exact(fs.VehicleState(velocity=(10, 0, 0), angular_velocity=(0, 0.5, 0)), 2.0, settings)
    np.testing.assert_allclose(out.position, [20 * math.sin(1.0), 0, -20 * (1 - math.cos(1.0))], atol=FLOAT_TOL)
    assert fs.signed_vehicle_speed((-3, 0, -4), (0, 0, 1)) == -5


def test_orientation_helpers():
    q = fs.predict_orientation((0, 0, 0, 1), (0, math.pi / 2, 0), 1.0)  # 90 degrees about +Y
    np.testing.assert_allclose(q, [0, math.sqrt(0.5), 0, math.sqrt(0.5)], atol=1e-6)
    r = fs.rotation_from_angular_velocity((0, 0, 0), 3.0)
    np.testing.assert_array_equal(r, [0, 0, 0, 1])  # zero angular velocity: the identity, exactly
    np.testing.assert_allclose(fs.compose_rotation(q, q), [0, 1, 0, 0], atol=1e-6)
    np.testing.assert_allclose(fs.normalize_quaternion((0, 0, 0, 2)), [0, 0, 0, 1])


def test_free_flight_apex_is_the_parabolas():
    # Thrown up at 9.81 m/s under 9.81 m/s^2: apex 4.905 m above the start at t = 1 s.
    result = fs.predict_projectile((0, 1, 0), (2, 9.81, 0), 1.0)
    np.testing.assert_allclose(result.position, [2, 1 + 4.905, 0], atol=FLOAT_TOL)
    np.testing.assert_allclose(result.velocity, [2, 0, 0], atol=FLOAT_TOL)
    t = result.trajectory
    assert t.events[0] == fs.TrajectoryEvent.Start and t.events[-1] == fs.TrajectoryEvent.End
    assert t.events.dtype == np.uint8
    assert t.positions.shape == (len(t), 3) and t.velocities.shape == (len(t), 3) and t.normals.shape == (len(t), 3)
    # Exact records a point per 0.02 s step: 0, 0.02, ..., 1.0 (51 points, the last is End).
    assert len(t) == 51
    np.testing.assert_allclose(t.times, np.arange(51) * 0.02, atol=1e-6)  # float times: ulps of 1 s
    expected_y = 1 + 9.81 * t.times.astype(np.float64) - 9.81 / 2 * t.times.astype(np.float64) ** 2
    np.testing.assert_allclose(t.positions[:, 1], expected_y, atol=FLOAT_TOL)


def test_bounce_on_a_floor_reflects_with_restitution():
    # Dropped from 1.25 m: hits the floor at t = sqrt(2.5 / 9.81) with speed sqrt(2 g h), leaves at half.
    world = fs.StaticWorld()
    world.add_plane((0, 1, 0), 0)
    result = fs.predict_projectile((0, 1.25, 0), (0, 0, 0), 0.6, fs.ProjectileSettings(restitution=0.5), world)
    bounce = np.flatnonzero(result.trajectory.events == int(fs.TrajectoryEvent.Bounce))[0]
    t_hit = math.sqrt(2 * 1.25 / 9.81)
    assert result.trajectory.times[bounce] == pytest.approx(t_hit, abs=1e-6)  # float time
    np.testing.assert_allclose(result.trajectory.velocities[bounce], [0, 0.5 * math.sqrt(2 * 9.81 * 1.25), 0],
                               atol=FLOAT_TOL)
    np.testing.assert_allclose(result.trajectory.normals[bounce], [0, 1, 0])
    assert result.bounces == 1


@pytest.mark.parametrize("method", ["stepped", "exact", "engine", "ammo"])
def test_projectiles_match_the_cli(cli_predict, method):
    world = {"planes": [{"normal": [0, 1, 0], "distance": 0}],
             "boxes": [{"center": [0, 1.5, 10], "half_extents": [5, 1.5, 0.25], "orientation": IDENTITY,
                        "restitution": 0.2, "friction": 0.6}],
             "spheres": [{"center": [3, 0, 3], "radius": 1}],
             "triangles": [[[-6, 0.01, 0], [-5, 0.01, 0], [-6, 0.01, 1]]]}
    scenario = {"id": "g", "model": "projectile", "method": "engine" if method == "ammo" else method,
                "position": [0, 1.6, 0], "velocity": [0.5, 4, 12], "time": 1.5, "restitution": 0.5, "friction": 0.3, "radius": 0.05}
    settings = fs.ProjectileSettings(restitution=0.5, friction=0.3, radius=0.05)
    settings.method = {"stepped": fs.ProjectileMethod.Stepped, "exact": fs.ProjectileMethod.Exact,
                       "engine": fs.ProjectileMethod.Engine, "ammo": fs.ProjectileMethod.Engine}[method]
    if method == "engine":
        scenario["engine"] = {"profile": "bullet", "linear_damping": 0.3}
        profile = fs.engine_profile(fs.PhysicsEngine.Bullet)
        profile.linear_damping = 0.3  # an overridden field reaches the library
        settings.engine = profile
    if method == "ammo":  # the scenario format's "ammo" profile is the library's ammo_js_profile()
        scenario["engine"] = {"profile": "ammo", "linear_damping": 0.3}
        profile = fs.ammo_js_profile()
        assert profile.friction_warm_start == pytest.approx(0.85) and profile.restitution_threshold == 0
        profile.linear_damping = 0.3
        settings.engine = profile
    ref = cli_predict({"world": world, "predictions": [scenario]})["g"]

    w = fs.StaticWorld()
    w.add_plane((0, 1, 0), 0)
    w.add_box((0, 1.5, 10), (5, 1.5, 0.25), material=fs.SurfaceMaterial(restitution=0.2, friction=0.6))
    w.add_sphere((3, 0, 3), 1)
    w.add_triangle((-6, 0.01, 0), (-5, 0.01, 0), (-6, 0.01, 1))
    assert len(w) == 4
    result = fs.predict_projectile((0, 1.6, 0), (0.5, 4, 12), 1.5, settings, w)
    assert result.bounces == ref["bounces"] and result.bounces >= 2  # the wall, then the floor
    assert result.at_rest == ref["at_rest"]
    assert len(result.trajectory) == len(ref["trajectory"])
    np.testing.assert_allclose(result.position, ref["position"], atol=CLI_TOL)
    np.testing.assert_allclose(result.velocity, ref["velocity"], atol=CLI_TOL)
    np.testing.assert_allclose(result.trajectory.positions, [p["position"] for p in ref["trajectory"]], atol=CLI_TOL)
    names = [e.name.lower() for e in fs.TrajectoryEvent.__members__.values()]
    assert [names[e] for e in result.trajectory.events] == [p["event"] for p in ref["trajectory"]]


def test_engine_profile_fields_change_the_flight():
    settings = fs.ProjectileSettings(method=fs.ProjectileMethod.Engine, engine=fs.engine_profile(fs.PhysicsEngine.Jolt))
    plain = fs.predict_projectile((0, 0, 0), (0, 0, 10), 1.0, settings)
    profile = settings.engine
    profile.linear_damping = 0.5
    settings.engine = profile
    damped = fs.predict_projectile((0, 0, 0), (0, 0, 10), 1.0, settings)
    assert damped.position[2] < plain.position[2] - 1  # 0.5/s of damping loses metres in 1 s
    assert fs.engine_name(fs.PhysicsEngine.PhysX) == "physx"
    assert settings.engine.timestep == pytest.approx(1 / 60)


def test_cast_segment():
    w = fs.StaticWorld()
    w.add_plane((0, 1, 0), 0)
    hit = w.cast_segment((0, 2, 0), (0, -4, 0))
    assert hit.fraction == pytest.approx(0.5)
    np.testing.assert_array_equal(hit.normal, [0, 1, 0])
    assert w.cast_segment((0, 2, 0), (0, 1, 0)) is None
    assert "CastHit(fraction=0.5" in repr(hit)


def test_aim_static_target_both_arcs():
    # A target 20 m away on flat ground at 20 m/s: sin(2 theta) = g d / v^2.
    solutions = fs.aim_projectile((0, 0, 0), (0, 0, 20), speed=20)
    assert len(solutions) == 2
    low, high = solutions
    angle = 0.5 * math.asin(9.81 * 20 / 400)
    assert low.elevation == pytest.approx(angle, abs=1e-6)  # float radians
    assert high.elevation == pytest.approx(math.pi / 2 - angle, abs=1e-6)
    assert np.linalg.norm(low.velocity) == pytest.approx(20, abs=FLOAT_TOL)
    # Flown by predict_projectile, the low arc meets the target.
    flown = fs.predict_projectile((0, 0, 0), low.velocity, low.time)
    np.testing.assert_allclose(flown.position, [0, 0, 20], atol=1e-4)  # float velocity rounding over 20 m
    assert fs.aim_projectile((0, 0, 0), (0, 0, 1000), speed=20) == []


def test_dead_reckoning_matches_the_cli(cli_predict):
    state = {"id": "tank", "model": "dead_reckoning", "algorithm": "RVB", "position": [0, 0, 0],
             "velocity": [8, 0, 0], "acceleration": [2, 0, 0], "orientation": IDENTITY,
             "angular_velocity": [0, 0, 0.785398], "time": 2}
    ref = cli_predict({"predictions": [state]})["tank"]
    out = fs.predict_dead_reckoning(fs.DeadReckoningState(fs.DeadReckoningAlgorithm.RVB, (0, 0, 0), (8, 0, 0),
                                                          (2, 0, 0), (0, 0, 0, 1), (0, 0, 0.785398)), 2)
    np.testing.assert_allclose(out.position, ref["position"], atol=FLOAT_TOL)
    np.testing.assert_allclose(out.velocity, ref["velocity"], atol=FLOAT_TOL)
    q = ref["orientation"]
    np.testing.assert_allclose(out.orientation, [q["x"], q["y"], q["z"], q["w"]], atol=1e-6)


def random_entities(n, seed=6):
    rng = np.random.default_rng(seed)
    algorithms = rng.integers(1, 10, n)
    positions = rng.uniform(-1000, 1000, (n, 3))
    velocities = rng.uniform(-10, 10, (n, 3))
    accelerations = rng.uniform(-3, 3, (n, 3))
    angles = rng.uniform(-3.14, 3.14, n)
    orientations = np.stack([np.zeros(n), np.sin(angles / 2), np.zeros(n), np.cos(angles / 2)], axis=1)
    angular = rng.uniform(-2, 2, (n, 3))
    timestamps = 100.0 - rng.uniform(0, 0.25, n)
    return algorithms, positions, velocities, accelerations, orientations, angular, timestamps


def test_dead_reckoning_batch_equals_single_calls():
    arrays = random_entities(500)
    positions, velocities, orientations, refused = fs.predict_dead_reckoning_batch(*arrays, 100.0)
    assert refused == 0 and positions.shape == (500, 3) and orientations.shape == (500, 4)
    for i in range(0, 500, 7):
        state = fs.DeadReckoningState(fs.DeadReckoningAlgorithm(int(arrays[0][i])), arrays[1][i], arrays[2][i],
                                      arrays[3][i], arrays[4][i], arrays[5][i])
        one = fs.predict_dead_reckoning(state, np.float32(100.0 - arrays[6][i]))
        # predictDeadReckoningBatch is documented bit-identical to predictDeadReckoning at that age.
        np.testing.assert_array_equal(positions[i], one.position)
        np.testing.assert_array_equal(velocities[i], one.velocity)
        np.testing.assert_array_equal(orientations[i], one.orientation)


def test_soa_batch_within_the_documented_contract():
    n = 1000
    arrays = random_entities(n)
    batch = fs.DeadReckoningBatch(n)
    batch.set_all(*arrays)
    assert batch.extrapolate(100.0, 0.25) == 0
    reference, ref_velocities, _, _ = fs.predict_dead_reckoning_batch(*arrays, 100.0)
    speed = np.linalg.norm(arrays[2], axis=1) + np.linalg.norm(arrays[3], axis=1) * 0.25
    # replication.h: position within 1e-6 (|v| t + |a| t^2 / 2) plus 2 ulps of the position
    # (body-axis integrals use a float sine and cosine); bounded here by 1e-6 |v| + 2 ulps at 1000 m.
    tolerance = 1e-6 * speed[:, None] + 2 * np.spacing(np.float32(1000))
    assert np.all(np.abs(batch.positions - reference) <= tolerance)
    assert not batch.positions.flags.writeable
    # A second frame overwrites the same views.
    view = batch.positions
    batch.extrapolate(100.1, 0.25)
    assert view is batch.positions or np.shares_memory(view, batch.positions)
    one = fs.DeadReckoningState(fs.DeadReckoningAlgorithm.FPW, (1, 2, 3), (1, 0, 0))
    batch.set(3, one, 99.0)
    batch.extrapolate(100.0)
    np.testing.assert_allclose(batch.positions[3], [2, 2, 3])


def test_reprs_are_readable():
    assert repr(fs.predict_linear((1, 0, 2), (3, 0, 4), 0.5)) == "PointState(position=(2.5, 0.0, 4.0), velocity=(3.0, 0.0, 4.0))"
    assert repr(fs.StaticWorld()) == "StaticWorld(planes=0, spheres=0, boxes=0, triangles=0)"
    assert "ProjectileSettings(method=Exact" in repr(fs.ProjectileSettings())
    assert "engine=jolt" in repr(fs.ProjectileSettings())


def test_engine_free_flight_equals_the_engine_trajectory():
    # Free flight stepped by the Engine method and the closed form of the same recurrence agree
    # (engine_profile.h: "equal to stepping ... to within rounding"; float rounding of ~10 m).
    profile = fs.engine_profile(fs.PhysicsEngine.Rapier)
    settings = fs.ProjectileSettings(method=fs.ProjectileMethod.Engine, engine=profile)
    stepped = fs.predict_projectile((0, 2, 0), (1, 5, 8), 1.0, settings)
    position, velocity = fs.engine_free_flight(profile, (0, 2, 0), (1, 5, 8), steps=60)
    np.testing.assert_allclose(position, stepped.position, atol=FLOAT_TOL)
    np.testing.assert_allclose(velocity, stepped.velocity, atol=FLOAT_TOL)


def test_rendered_position_interpolates_between_steps():
    settings = fs.ProjectileSettings(method=fs.ProjectileMethod.Stepped, step=0.1)
    t = fs.predict_projectile((0, 0, 0), (0, 0, 10), 1.0, settings).trajectory
    # 0.25 s: two steps done (0.2 s), alpha 0.5. None: p[2]; Interpolate: halfway between p[1] and p[2].
    np.testing.assert_allclose(fs.rendered_position(t, 0.1, 0.25), t.positions[2], atol=FLOAT_TOL)
    np.testing.assert_allclose(fs.rendered_position(t, 0.1, 0.25, fs.RenderSmoothing.Interpolate),
                               (t.positions[1] + t.positions[2]) / 2, atol=FLOAT_TOL)
    with pytest.raises(fs.Error, match="InvalidStep"):
        fs.rendered_position(t, 0.0, 0.25)


def test_long_trajectories_are_whole():
    # 1500 s at 0.02 s: 75 001 points, beyond the first guess of the storage (65 536): predicted
    # again at full size. Zero gravity, at rest: every point is the start.
    settings = fs.ProjectileSettings(gravity=(0, 0, 0), method=fs.ProjectileMethod.Stepped)
    result = fs.predict_projectile((1, 2, 3), (0, 0, 0), 1500.0, settings)
    assert len(result.trajectory) == 75001
    np.testing.assert_array_equal(result.trajectory.positions[-1], [1, 2, 3])


def test_dead_reckoning_batch_reads_float32_arrays_as_float64_ones():
    # float32 arrays are read as they are (no conversion copy); the library takes floats anyway, so
    # float64 arrays holding the same float32 values give bit-identical results.
    arrays = random_entities(300)
    single = [a.astype(np.float32) if i in (1, 2, 3, 4, 5) else a for i, a in enumerate(arrays)]
    double = [a.astype(np.float64) if i in (1, 2, 3, 4, 5) else a for i, a in enumerate(single)]
    for got, expected in zip(fs.predict_dead_reckoning_batch(*single, 100.0)[:3],
                             fs.predict_dead_reckoning_batch(*double, 100.0)[:3]):
        np.testing.assert_array_equal(got, expected)
    batch = fs.DeadReckoningBatch(300)
    batch.set_all(*single)
    batch.extrapolate(100.0)
    other = fs.DeadReckoningBatch(300)
    other.set_all(*double)
    other.extrapolate(100.0)
    np.testing.assert_array_equal(batch.positions, other.positions)
