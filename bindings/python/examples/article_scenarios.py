"""article_scenarios.py: the reference article's three scenarios through the Python module.

The twin of examples/article_scenarios.cpp: it must print exactly the same text (CTest compares
the two outputs, python_article_scenarios). The module adds no arithmetic of its own, so any
difference is a binding bug.

  1. a character: constant velocity and constant acceleration, 0.5 s ahead;
  2. a grenade thrown at a wall with a 3 s fuse, in a world of a floor plane and a wall box:
     the article's stepped loop, the exact method, and the flight as Jolt will simulate it;
  3. a turning car, 2 s ahead: the article's 4-iteration loop and the exact arc.

Numbers are printed with 6 decimals ("%.6f"; -0 is printed as 0).
Conventions: metres, seconds, radians; +Y up, +Z forward; quaternions (x, y, z, w).
"""

import sys

import foresight as fs


def number(value):
    """A number with 6 decimals; adding 0.0 turns -0 into 0."""
    return "%.6f" % (float(value) + 0.0)


def vec(label, v):
    return "%s (%s, %s, %s)" % (label, number(v[0]), number(v[1]), number(v[2]))


def character(out):
    linear = fs.predict_linear((1, 0, 2), (3, 0, 4), 0.5)
    accelerated = fs.predict_accelerated((1, 0, 2), (3, 0, 4), (0, 0, -2), 0.5)
    out.append("character\n")
    out.append(vec("  linear      position", linear.position) + vec(" velocity", linear.velocity) + "\n")
    out.append(vec("  accelerated position", accelerated.position) + vec(" velocity", accelerated.velocity) + "\n")


def grenade(out, name, settings, world):
    fuse = 3.0
    result = fs.predict_projectile((0, 1.6, 0), (0, 4, 12), fuse, settings, world)
    trajectory = result.trajectory
    out.append("%s %s: %u bounces, %u points\n" % ("grenade", name, result.bounces, len(trajectory)))
    bounces = [i for i, event in enumerate(trajectory.events) if event == fs.TrajectoryEvent.Bounce]
    for i in bounces[:3]:
        out.append("  bounce t " + number(trajectory.times[i]) + vec(" position", trajectory.positions[i])
                   + vec(" normal", trajectory.normals[i]) + "\n")
    out.append("  end    t " + number(result.time) + vec(" position", result.position)
               + vec(" velocity", result.velocity) + (" at rest" if result.at_rest else "") + "\n")


def grenades(out):
    world = fs.StaticWorld()
    world.add_plane(normal=(0, 1, 0), distance=0)
    world.add_box(center=(0, 1.5, 10), half_extents=(5, 1.5, 0.25))

    settings = fs.ProjectileSettings(restitution=0.5, friction=0.4, radius=0.05)
    settings.method = fs.ProjectileMethod.Stepped
    grenade(out, "stepped", settings, world)
    settings.method = fs.ProjectileMethod.Exact
    grenade(out, "exact", settings, world)
    settings.method = fs.ProjectileMethod.Engine
    settings.engine = fs.engine_profile(fs.PhysicsEngine.Jolt)
    grenade(out, "jolt", settings, world)


def car(out):
    start = fs.VehicleState(position=(0, 0, 0), velocity=(0, 0, 10), orientation=(0, 0, 0, 1),
                            angular_velocity=(0, 0.5, 0))
    settings = fs.VehicleSettings()
    iterated = fs.predict_vehicle_iterative(start, 2.0, 4, settings)
    exact = fs.predict_vehicle_exact(start, 2.0, settings)
    out.append("car\n")
    for label, state in (("  iterative", iterated), ("  exact    ", exact)):
        x, y, z, w = state.orientation
        out.append(vec(label, state.position) + vec(" velocity", state.velocity) + " orientation ("
                   + ", ".join(number(c) for c in (w, x, y, z)) + ")\n")


def main():
    out = []
    try:
        character(out)
        grenades(out)
        car(out)
    except fs.Error as error:
        sys.stdout.write("".join(out))
        print(error, file=sys.stderr)
        return 1
    sys.stdout.write("".join(out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
