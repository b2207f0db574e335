#pragma once
/// @file compare_command.h
/// `foresight compare`: the projectile predictions ("stepped", the article's loop, and "exact")
/// measured against a rigid-body simulation in Bullet Physics, the ground truth.
///
/// For each projectile of a scenario (or of the built-in scenes with --builtin), a Bullet
/// btRigidBody sphere (foresight::simulateProjectileRigidBody, backends/bullet) is thrown in a
/// Bullet world holding the same shapes and meshes, with the same gravity, restitution and
/// friction, at `frequency` Hz; the same throw is predicted with both methods, as a sphere of
/// the same radius (a point projectile, radius 0, is compared as a sphere of 0.02 m: a rigid
/// body needs a size). Errors reported per method:
/// - landing: distance and time between the first impacts;
/// - at the fuse: distance between the positions at the prediction's `time`;
/// - bounces: the number of bounces whose approach speed is at least kBounceSpeed, and the
///   largest time difference between the k-th bounces of prediction and simulation.
/// The simulation's own step error is shown beside them: the same throw simulated at 4 times
/// the frequency, and the distance between the two simulations.

#include <string>

namespace foresight_cli {

/// Impacts slower than this along the normal are contact, not bounces [Units: m/s].
inline constexpr double kBounceSpeed = 0.5;

/// Options of `foresight compare`.
struct CompareOptions {
    float frequency = 960.0f;  ///< Bullet's internal step rate [Units: Hz] [Limit: 240 .. 100000].
    bool spin = false;         ///< let the simulated sphere rotate (default: locked, like a point mass).
    bool builtin = false;      ///< the built-in scenes instead of a file; prints the table of docs/results.md.
    std::string jsonFile;      ///< also write the full comparison as JSON here ("-": standard output).
    /// With a name (jolt, physx, rapier, ammo, bullet, godot3, godot3-bullet, box2d): run the
    /// scenario's projectiles in that real engine instead of Bullet (compareEngineCommand).
    std::string engine;
    /// The engine harnesses' folder (tests/engines/ of the source tree by default).
    std::string harnessDir;
};

/// `foresight compare FILE --engine NAME`: every projectile of the scenario is run in the real
/// engine through its harness (tests/engines/README.md: Node.js for jolt, physx, rapier and ammo;
/// godot3-server for godot3 and godot3-bullet; foresight_engine_harness for bullet and box2d),
/// beside the engine-matched prediction (ProjectileMethod::Engine with that engine's profile; a
/// prediction that already has the method and the engine keeps its own profile, damping
/// included), and the exact and stepped ones. The world may hold planes (sent as boxes 2 m thick
/// and 2 km wide) and boxes; spheres, triangles and meshes are refused. Prints a table per
/// projectile: the first contact step on each side, the largest distance before it, and the
/// distances from the engine's end to the three predictions'. Returns 0, 2 for bad input or a
/// runtime that is not installed (the message says which), 1 when the harness fails.
int compareEngineCommand(const std::string& file, const CompareOptions& options);

/// `foresight compare FILE` (or --builtin). Returns the exit status: 0, 2 for invalid input or
/// usage (and when foresight was built without Bullet), 1 for an internal error.
int compareCommand(const std::string& file, const CompareOptions& options);

}  // namespace foresight_cli
