// The P/Invoke declarations of foresight_c.h, one per C function. Internal: the public API is in
// Foresight.cs. Every struct is blittable (Types.cs) and passed by `ref`, so the marshaller
// passes a pointer to the caller's value. Arrays are passed as `ref array[0]` (a pinned pointer
// to the first element), not as C# arrays: Mono's marshaller copies a struct array in and out
// on every call (measured: 1.7 ms for a 4096-point trajectory, against 30 us for the
// prediction itself). No call here allocates.

using System;
using System.Runtime.InteropServices;

namespace Foresight
{
    /// <summary>The C functions of foresight_c.h (the shared library <c>foresight_c</c>).</summary>
    internal static class Native
    {
        /// <summary>The library's name: <c>libforesight_c.so</c>, <c>libforesight_c.dylib</c>,
        /// <c>foresight_c.dll</c>.</summary>
        internal const string Library = "foresight_c";

        [DllImport(Library)] internal static extern uint fs_abi_version();
        [DllImport(Library)] internal static extern IntPtr fs_status_message(Status status);

        [DllImport(Library)] internal static extern Status fs_predict_linear(ref PointState start, float time, out PointState result);
        [DllImport(Library)] internal static extern Status fs_predict_accelerated(ref PointState start, Vector3Native acceleration, float time, out PointState result);

        [DllImport(Library)] internal static extern VehicleSettings fs_vehicle_settings_default();
        [DllImport(Library)] internal static extern Status fs_predict_vehicle_iterative(ref VehicleState start, float time, int iterations, ref VehicleSettings settings, out VehicleState result);
        [DllImport(Library)] internal static extern Status fs_predict_vehicle_exact(ref VehicleState start, float time, ref VehicleSettings settings, out VehicleState result);

        [DllImport(Library)] internal static extern WorldHandle fs_world_create();
        [DllImport(Library)] internal static extern void fs_world_destroy(IntPtr world);
        [DllImport(Library)] internal static extern Status fs_world_add_plane(WorldHandle world, ref PlaneShape plane, ref SurfaceMaterial material);
        [DllImport(Library)] internal static extern Status fs_world_add_plane(WorldHandle world, ref PlaneShape plane, IntPtr noMaterial);
        [DllImport(Library)] internal static extern Status fs_world_add_sphere(WorldHandle world, ref SphereShape sphere, ref SurfaceMaterial material);
        [DllImport(Library)] internal static extern Status fs_world_add_sphere(WorldHandle world, ref SphereShape sphere, IntPtr noMaterial);
        [DllImport(Library)] internal static extern Status fs_world_add_box(WorldHandle world, ref BoxShape box, ref SurfaceMaterial material);
        [DllImport(Library)] internal static extern Status fs_world_add_box(WorldHandle world, ref BoxShape box, IntPtr noMaterial);
        [DllImport(Library)] internal static extern Status fs_world_add_triangle(WorldHandle world, ref TriangleShape triangle, ref SurfaceMaterial material);
        [DllImport(Library)] internal static extern Status fs_world_add_triangle(WorldHandle world, ref TriangleShape triangle, IntPtr noMaterial);

        [DllImport(Library)] internal static extern Status fs_world_add_mesh(WorldHandle world, ref DVec3 vertices, UIntPtr vertexCount, ref uint indices, UIntPtr indexCount, out MeshReport report);
        [DllImport(Library)] internal static extern int fs_embree_available();
        [DllImport(Library)] internal static extern WorldHandle fs_world_create_embree();
        [DllImport(Library)] internal static extern Status fs_world_load_mesh(WorldHandle world, byte[] utf8Path, out MeshReport report, byte[] error, UIntPtr errorCapacity);
        [DllImport(Library)] internal static extern Status fs_world_commit(WorldHandle world, byte[] error, UIntPtr errorCapacity);
        [DllImport(Library)] internal static extern WorldHandle fs_world_create_callback(NativeCast cast, IntPtr context);

        /// <summary>fs_cast_function.</summary>
        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        internal delegate int NativeCast(IntPtr context, ref SegmentCast cast, ref CastHit hit);

        [DllImport(Library)] internal static extern ProjectileSettings fs_projectile_settings_default();
        [DllImport(Library)] internal static extern UIntPtr fs_trajectory_capacity(float time, ref ProjectileSettings settings);
        [DllImport(Library)] internal static extern Status fs_predict_projectile(DVec3 position, Vector3Native velocity, float time, ref ProjectileSettings settings, WorldHandle world, ref TrajectoryPoint points, UIntPtr capacity, out ProjectileResult result);
        [DllImport(Library)] internal static extern Status fs_predict_projectile(DVec3 position, Vector3Native velocity, float time, ref ProjectileSettings settings, IntPtr noWorld, ref TrajectoryPoint points, UIntPtr capacity, out ProjectileResult result);

        [DllImport(Library)] internal static extern EngineProfile fs_engine_profile_default(PhysicsEngine engine);
        [DllImport(Library)] internal static extern EngineProfile fs_engine_profile_ammo_js();
        [DllImport(Library)] internal static extern Status fs_validate_engine_profile(ref EngineProfile profile);
        [DllImport(Library)] internal static extern UIntPtr fs_trajectory_capacity_with_profile(float time, ref ProjectileSettings settings, ref EngineProfile profile);
        [DllImport(Library)] internal static extern Status fs_predict_projectile_with_profile(DVec3 position, Vector3Native velocity, float time, ref ProjectileSettings settings, ref EngineProfile profile, WorldHandle world, ref TrajectoryPoint points, UIntPtr capacity, out ProjectileResult result);
        [DllImport(Library)] internal static extern Status fs_predict_projectile_with_profile(DVec3 position, Vector3Native velocity, float time, ref ProjectileSettings settings, ref EngineProfile profile, IntPtr noWorld, ref TrajectoryPoint points, UIntPtr capacity, out ProjectileResult result);
        [DllImport(Library)] internal static extern Status fs_rendered_position(ref TrajectoryPoint trajectory, UIntPtr count, float step, float renderTime, RenderSmoothing smoothing, out DVec3 result);

        [DllImport(Library)] internal static extern AimShot fs_aim_shot_default();
        [DllImport(Library)] internal static extern Status fs_aim_projectile(ref AimShot shot, ref AimTarget target, ref FiringSolution solutions, UIntPtr capacity, out UIntPtr count);

        [DllImport(Library)] internal static extern Status fs_position_on_trajectory(ref TrajectoryPoint trajectory, UIntPtr count, float time, out DVec3 result);
        [DllImport(Library)] internal static extern Status fs_compute_danger_zone(ref TrajectoryPoint trajectory, UIntPtr count, ref ProjectileDanger danger, out DangerZone result);
        [DllImport(Library)] internal static extern Status fs_is_point_safe(ref TrajectoryPoint trajectory, UIntPtr count, ref ProjectileDanger danger, DVec3 point, float time, out int safe);
        [DllImport(Library)] internal static extern Status fs_find_danger_start(ref TrajectoryPoint trajectory, UIntPtr count, ref ProjectileDanger danger, DVec3 point, out DangerStart result);
        [DllImport(Library)] internal static extern Status fs_find_path_approach(ref TrajectoryPoint trajectory, UIntPtr count, DVec3 point, float distance, float fromTime, float untilTime, out DangerStart result);
        [DllImport(Library)] internal static extern Status fs_find_closest_path_approach(ref TrajectoryPoint trajectory, UIntPtr count, DVec3 point, float fromTime, float untilTime, out ClosestApproach result);
        [DllImport(Library)] internal static extern VehicleBody fs_vehicle_body_default();
        [DllImport(Library)] internal static extern CharacterBody fs_character_body_default();
        [DllImport(Library)] internal static extern ApproachSettings fs_approach_settings_default();
        [DllImport(Library)] internal static extern Status fs_compute_vehicle_separation(ref VehicleBody vehicle, ref CharacterBody character, float time, out float separation);
        [DllImport(Library)] internal static extern Status fs_find_vehicle_contact(ref VehicleBody vehicle, ref CharacterBody character, float horizon, ref ApproachSettings settings, out VehicleContact result);
        [DllImport(Library)] internal static extern Status fs_find_closest_vehicle_approach(ref VehicleBody vehicle, ref CharacterBody character, float horizon, ref ApproachSettings settings, out ClosestApproach result);

        [DllImport(Library)] internal static extern ThrowPlanRequest fs_throw_plan_request_default();
        [DllImport(Library)] internal static extern UIntPtr fs_throw_plan_scratch_size(ref ThrowPlanRequest request);
        [DllImport(Library)] internal static extern Status fs_plan_throw(ref ThrowPlanRequest request, WorldHandle world, ref ThrowPlan plans, UIntPtr capacity, ref TrajectoryPoint scratch, UIntPtr scratchCapacity, out ThrowPlanResult result);
        [DllImport(Library)] internal static extern Status fs_plan_throw(ref ThrowPlanRequest request, IntPtr noWorld, ref ThrowPlan plans, UIntPtr capacity, ref TrajectoryPoint scratch, UIntPtr scratchCapacity, out ThrowPlanResult result);

        [DllImport(Library)] internal static extern IntPtr fs_dr_algorithm_name(DeadReckoningAlgorithm algorithm);
        [DllImport(Library)] internal static extern Status fs_dr_predict(ref DeadReckoningState state, float time, out DeadReckoningResult result);
        [DllImport(Library)] internal static extern Status fs_dr_predict_batch(ref DeadReckoningState states, ref double timestamps, UIntPtr count, double time, ref DeadReckoningResult results, out UIntPtr refused);
        [DllImport(Library)] internal static extern ReceiverSettings fs_dr_receiver_settings_default();
        [DllImport(Library)] internal static extern Status fs_dr_receiver_create(ref ReceiverSettings settings, out ReceiverHandle receiver);
        [DllImport(Library)] internal static extern void fs_dr_receiver_destroy(IntPtr receiver);
        [DllImport(Library)] internal static extern Status fs_dr_receiver_receive(ReceiverHandle receiver, double timestamp, ref DeadReckoningState state, double receiveTime, out UpdateOutcome outcome);
        [DllImport(Library)] internal static extern Status fs_dr_receiver_sample(ReceiverHandle receiver, double time, out ReceivedPose pose);
        [DllImport(Library)] internal static extern Status fs_dr_receiver_get_counters(ReceiverHandle receiver, out ReceiverCounters counters);
        [DllImport(Library)] internal static extern void fs_dr_receiver_reset(ReceiverHandle receiver);

        // Raw NULL-pointer forms, for the tests of the C API's own refusals.
        [DllImport(Library, EntryPoint = "fs_predict_linear")] internal static extern Status fs_predict_linear_raw(IntPtr start, float time, IntPtr result);
    }
}
