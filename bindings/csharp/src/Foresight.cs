// foresight's C# binding: the public API over Native.cs. Every Try* method returns the
// library's Status and writes its result (default on a refusal); the method of the same name
// without "Try" returns the result and throws ForesightException on a refusal. No method of the
// per-frame path allocates: structs are passed by reference, arrays (trajectories, firing
// solutions, dead-reckoning batches) are the caller's, passed as a pinned pointer to their
// first element, never copied.
// Units: metres, seconds, radians; +Y up, +Z forward (Axes.cs for Unity and Godot).

using System;
using System.Numerics;
using System.Runtime.InteropServices;
using Microsoft.Win32.SafeHandles;

namespace Foresight
{
    /// <summary>A call the library refused: <see cref="Status"/> says why.</summary>
    public sealed class ForesightException : Exception
    {
        /// <summary>Why the input was refused.</summary>
        public Status Status { get; private set; }

        /// <summary>An exception for <paramref name="status"/> raised by
        /// <paramref name="operation"/>, with the library's message.</summary>
        public ForesightException(Status status, string operation)
            : base(operation + ": " + Library.Message(status) + " (" + status + ")")
        {
            Status = status;
        }

        internal static void ThrowUnlessOk(Status status, string operation)
        {
            if (status != Status.Ok) throw new ForesightException(status, operation);
        }
    }

    /// <summary>The native library as a whole: its ABI version and its status messages.</summary>
    public static class Library
    {
        /// <summary>The ABI version this binding was written for (FS_ABI_VERSION).</summary>
        public const uint ExpectedAbiVersion = 1;

        /// <summary>The ABI version of the loaded <c>foresight_c</c> library.</summary>
        public static uint AbiVersion { get { return Native.fs_abi_version(); } }

        /// <summary>True when the loaded library has the ABI this binding expects.</summary>
        public static bool IsCompatible { get { return AbiVersion == ExpectedAbiVersion; } }

        /// <summary>Loads the library and checks its ABI version; call it once at start-up.
        /// Throws DllNotFoundException when the library is missing and NotSupportedException
        /// on a version mismatch.</summary>
        public static void EnsureCompatible()
        {
            uint version = AbiVersion;
            if (version != ExpectedAbiVersion)
                throw new NotSupportedException("foresight_c has ABI version " + version + ", this binding needs " +
                                                ExpectedAbiVersion);
        }

        /// <summary>The library's short English description of <paramref name="status"/>
        /// (fs_status_message), e.g. "time must be >= 0". Allocates the string.</summary>
        public static string Message(Status status)
        {
            return Marshal.PtrToStringAnsi(Native.fs_status_message(status));
        }
    }

    /// <summary>Characters: constant velocity and constant acceleration (character.h).</summary>
    public static class Characters
    {
        /// <summary>Constant velocity: position p + v t, velocity unchanged.</summary>
        /// <param name="start">The current state (finite).</param>
        /// <param name="time">Horizon [Units: s] [Limit: >= 0, finite].</param>
        /// <param name="result">The predicted state (default on a refusal).</param>
        /// <returns>Ok, NonFiniteInput, NegativeTime or NonFiniteResult.</returns>
        public static Status TryPredictLinear(PointState start, float time, out PointState result)
        {
            result = default(PointState);
            return Native.fs_predict_linear(ref start, time, out result);
        }

        /// <summary>Constant velocity (see TryPredictLinear); throws ForesightException.</summary>
        public static PointState PredictLinear(PointState start, float time)
        {
            PointState result;
            ForesightException.ThrowUnlessOk(TryPredictLinear(start, time, out result), "PredictLinear");
            return result;
        }

        /// <summary>Constant acceleration: position p + v t + a t^2 / 2, velocity v + a t.</summary>
        /// <param name="start">The current state (finite).</param>
        /// <param name="acceleration">Constant, world axes [Units: m/s^2].</param>
        /// <param name="time">Horizon [Units: s] [Limit: >= 0, finite].</param>
        /// <param name="result">The predicted state (default on a refusal).</param>
        /// <returns>Ok, NonFiniteInput, NegativeTime or NonFiniteResult.</returns>
        public static Status TryPredictAccelerated(PointState start, Vector3 acceleration, float time,
                                                   out PointState result)
        {
            result = default(PointState);
            return Native.fs_predict_accelerated(ref start, new Vector3Native(acceleration), time, out result);
        }

        /// <summary>Constant acceleration (see TryPredictAccelerated); throws ForesightException.</summary>
        public static PointState PredictAccelerated(PointState start, Vector3 acceleration, float time)
        {
            PointState result;
            ForesightException.ThrowUnlessOk(TryPredictAccelerated(start, acceleration, time, out result),
                                             "PredictAccelerated");
            return result;
        }
    }

    /// <summary>Vehicles turning at a constant angular velocity (vehicle.h).</summary>
    public static class Vehicles
    {
        /// <summary>The defaults: Body frame, forward +Z (Unity's forward).</summary>
        public static VehicleSettings DefaultSettings { get { return Native.fs_vehicle_settings_default(); } }

        /// <summary>The defaults with Godot's forward axis -Z.</summary>
        public static VehicleSettings GodotSettings
        {
            get
            {
                VehicleSettings s = Native.fs_vehicle_settings_default();
                s.Forward = Axes.GodotForward;
                return s;
            }
        }

        /// <summary>The reference article's loop of <paramref name="iterations"/> equal steps.</summary>
        /// <param name="start">The current state (finite, non-zero orientation).</param>
        /// <param name="time">[Units: s] [Limit: >= 0, finite].</param>
        /// <param name="iterations">[Limit: 1 .. 1048576]; the article uses 4.</param>
        /// <param name="settings">Frame and forward axis (DefaultSettings).</param>
        /// <param name="result">The state after <paramref name="time"/> (default on a refusal).</param>
        /// <returns>Ok, InvalidSetting, NonFiniteInput, NegativeTime, InvalidIterations,
        /// ZeroQuaternion, ZeroVector or NonFiniteResult.</returns>
        public static Status TryPredictIterative(VehicleState start, float time, int iterations,
                                                 VehicleSettings settings, out VehicleState result)
        {
            result = default(VehicleState);
            return Native.fs_predict_vehicle_iterative(ref start, time, iterations, ref settings, out result);
        }

        /// <summary>The iterative loop (see TryPredictIterative); throws ForesightException.</summary>
        public static VehicleState PredictIterative(VehicleState start, float time, int iterations,
                                                    VehicleSettings settings)
        {
            VehicleState result;
            ForesightException.ThrowUnlessOk(TryPredictIterative(start, time, iterations, settings, out result),
                                             "PredictIterative");
            return result;
        }

        /// <summary>The exact arc: a circle of radius |v| / |w| for w across the forward axis.</summary>
        /// <param name="start">The current state (finite, non-zero orientation).</param>
        /// <param name="time">[Units: s] [Limit: >= 0, finite].</param>
        /// <param name="settings">Frame and forward axis (DefaultSettings).</param>
        /// <param name="result">The state after <paramref name="time"/> (default on a refusal).</param>
        /// <returns>Ok, InvalidSetting, NonFiniteInput, NegativeTime, ZeroQuaternion, ZeroVector
        /// or NonFiniteResult.</returns>
        public static Status TryPredictExact(VehicleState start, float time, VehicleSettings settings,
                                             out VehicleState result)
        {
            result = default(VehicleState);
            return Native.fs_predict_vehicle_exact(ref start, time, ref settings, out result);
        }

        /// <summary>The exact arc (see TryPredictExact); throws ForesightException.</summary>
        public static VehicleState PredictExact(VehicleState start, float time, VehicleSettings settings)
        {
            VehicleState result;
            ForesightException.ThrowUnlessOk(TryPredictExact(start, time, settings, out result), "PredictExact");
            return result;
        }
    }

    /// <summary>Owns a native fs_world (and a callback world's handler, freed after it).</summary>
    internal sealed class WorldHandle : SafeHandleZeroOrMinusOneIsInvalid
    {
        /// <summary>A callback world's handler, pinned for the native world's life.</summary>
        internal GCHandle Handler;

        /// <summary>An empty handle, filled by the marshaller.</summary>
        public WorldHandle() : base(true) {}

        protected override bool ReleaseHandle()
        {
            Native.fs_world_destroy(handle);
            if (Handler.IsAllocated) Handler.Free();
            return true;
        }
    }

    /// <summary>A game's own ray or sphere cast answering a callback world (its physics
    /// engine's: Unity's Physics.SphereCast, Godot's PhysicsDirectSpaceState). Return true and
    /// fill <paramref name="hit"/> on a hit, false when the cast hits nothing. Report the closest
    /// surface the segment enters (moving against its normal); a segment that starts on a
    /// surface and moves into it hits at fraction 0. Called on the predicting thread, about once
    /// per step. An exception is caught and reported as an invalid hit (the prediction returns
    /// InvalidCallbackHit).</summary>
    public delegate bool CastHandler(SegmentCast cast, ref CastHit hit);

    /// <summary>Marks a static method that native code calls (Unity's IL2CPP needs it; the
    /// attribute is recognised by its name).</summary>
    [AttributeUsage(AttributeTargets.Method)]
    internal sealed class MonoPInvokeCallbackAttribute : Attribute
    {
        /// <summary>The delegate type of the callback.</summary>
        public MonoPInvokeCallbackAttribute(Type type) { Type = type; }

        /// <summary>The delegate type of the callback.</summary>
        public Type Type { get; private set; }
    }

    /// <summary>A static collision world (fs_world): planes, spheres, boxes, triangles. Dispose
    /// it (or let the finalizer free it); no prediction may use it while shapes are added or it
    /// is disposed. Using a disposed world throws ObjectDisposedException.</summary>
    public sealed class World : IDisposable
    {
        internal readonly WorldHandle Handle;

        /// <summary>A new, empty world. Allocates; throws OutOfMemoryException when the native
        /// allocation fails.</summary>
        public World()
        {
            Handle = Native.fs_world_create();
            if (Handle.IsInvalid) throw new OutOfMemoryException("fs_world_create");
        }

        private World(WorldHandle handle) { Handle = handle; }

        /// <summary>True when this library was built with the Embree backend.</summary>
        public static bool EmbreeAvailable { get { return Native.fs_embree_available() != 0; } }

        /// <summary>A world for large levels: meshes in an Embree BVH plus the built-in shapes.
        /// Add shapes and meshes, then call Commit once before predicting (and again after
        /// adding more). Throws NotSupportedException when the library has no Embree backend,
        /// OutOfMemoryException when the allocation fails.</summary>
        public static World CreateEmbree()
        {
            if (!EmbreeAvailable) throw new NotSupportedException("foresight_c was built without the Embree backend");
            WorldHandle h = Native.fs_world_create_embree();
            if (h.IsInvalid) throw new OutOfMemoryException("fs_world_create_embree");
            return new World(h);
        }

        // Native code calls this for every cast of a callback world; `context` is the GCHandle
        // of the world's handler. Static (IL2CPP), and no exception crosses into native code.
        private static readonly Native.NativeCast Trampoline = Cast;

        [MonoPInvokeCallback(typeof(Native.NativeCast))]
        private static int Cast(IntPtr context, ref SegmentCast cast, ref CastHit hit)
        {
            try
            {
                CastHandler handler = (CastHandler)GCHandle.FromIntPtr(context).Target;
                return handler(cast, ref hit) ? 1 : 0;
            }
            catch (Exception)
            {
                hit.Fraction = float.NaN;  // an invalid hit: the prediction returns InvalidCallbackHit
                return 1;
            }
        }

        /// <summary>A world whose casts <paramref name="handler"/> answers: how a game lets its
        /// own physics engine answer. Shapes cannot be added to it (InvalidSetting). Every hit is
        /// checked: a prediction that receives an invalid one returns InvalidCallbackHit. The
        /// handler stays alive until the world is disposed.</summary>
        public static World CreateCallback(CastHandler handler)
        {
            if (handler == null) throw new ArgumentNullException("handler");
            GCHandle pinned = GCHandle.Alloc(handler);
            WorldHandle h = Native.fs_world_create_callback(Trampoline, GCHandle.ToIntPtr(pinned));
            if (h.IsInvalid)
            {
                pinned.Free();
                throw new OutOfMemoryException("fs_world_create_callback");
            }
            h.Handler = pinned;
            return new World(h);
        }

        /// <summary>True once disposed.</summary>
        public bool IsDisposed { get { return Handle.IsClosed; } }

        /// <summary>Frees the native world (idempotent).</summary>
        public void Dispose() { Handle.Dispose(); }

        /// <summary>Adds an indexed triangle mesh (three indices per triangle, two-sided, no
        /// material of its own). Brute force in a plain world (a few thousand triangles); in an
        /// Embree world into its BVH (call Commit afterwards). The whole mesh is refused for a
        /// non-finite vertex (NonFiniteInput), an index count not a multiple of 3, an index out
        /// of range or no usable triangle (DegenerateShape); degenerate triangles are skipped
        /// and counted.</summary>
        /// <param name="vertices">[Units: m]</param>
        /// <param name="indices">Three per triangle, into <paramref name="vertices"/>.</param>
        /// <param name="report">The counts (default on a refusal).</param>
        /// <returns>Ok, NullPointer (a null array), NonFiniteInput, DegenerateShape,
        /// InvalidSetting (a callback world) or OutOfMemory.</returns>
        public Status TryAddMesh(DVec3[] vertices, uint[] indices, out MeshReport report)
        {
            report = default(MeshReport);
            if (vertices == null || indices == null) return Status.NullPointer;
            if (vertices.Length == 0 || indices.Length == 0) return Status.DegenerateShape;
            return Native.fs_world_add_mesh(Handle, ref vertices[0], new UIntPtr((uint)vertices.Length), ref indices[0],
                                            new UIntPtr((uint)indices.Length), out report);
        }

        /// <summary>TryAddMesh, throwing ForesightException.</summary>
        public MeshReport AddMesh(DVec3[] vertices, uint[] indices)
        {
            MeshReport report;
            ForesightException.ThrowUnlessOk(TryAddMesh(vertices, indices, out report), "AddMesh");
            return report;
        }

        private static string ErrorText(byte[] error)
        {
            int n = Array.IndexOf(error, (byte)0);
            return System.Text.Encoding.UTF8.GetString(error, 0, n < 0 ? error.Length : n);
        }

        /// <summary>Loads a mesh file into an Embree world: Wavefront OBJ (.obj) or glTF 2.0
        /// (.gltf, .glb), by extension. Allocates (a load-time call).</summary>
        /// <param name="path">The file.</param>
        /// <param name="report">The counts (default on a refusal).</param>
        /// <param name="error">Why, on BackendFailed (the file named); else empty.</param>
        /// <returns>Ok, NullPointer, InvalidSetting (not an Embree world, an unknown extension)
        /// or BackendFailed.</returns>
        public Status TryLoadMesh(string path, out MeshReport report, out string error)
        {
            report = default(MeshReport);
            error = "";
            if (path == null) return Status.NullPointer;
            byte[] utf8 = System.Text.Encoding.UTF8.GetBytes(path + "\0");
            byte[] text = new byte[512];
            Status s = Native.fs_world_load_mesh(Handle, utf8, out report, text, new UIntPtr((uint)text.Length));
            if (s != Status.Ok) error = ErrorText(text);
            return s;
        }

        /// <summary>TryLoadMesh, throwing ForesightException (its message includes the reason).</summary>
        public MeshReport LoadMesh(string path)
        {
            MeshReport report;
            string error;
            Status s = TryLoadMesh(path, out report, out error);
            if (s != Status.Ok) throw new ForesightException(s, "LoadMesh(" + path + ")" + (error.Length > 0 ? ": " + error : ""));
            return report;
        }

        /// <summary>Builds an Embree world's BVH; needed before predicting, after the last add.
        /// Other worlds have nothing to build: Ok. Not thread-safe with predictions.</summary>
        /// <param name="error">Why, on BackendFailed (the world then answers by brute force).</param>
        /// <returns>Ok or BackendFailed.</returns>
        public Status TryCommit(out string error)
        {
            byte[] text = new byte[512];
            Status s = Native.fs_world_commit(Handle, text, new UIntPtr((uint)text.Length));
            error = s == Status.Ok ? "" : ErrorText(text);
            return s;
        }

        /// <summary>TryCommit, throwing ForesightException.</summary>
        public void Commit()
        {
            string error;
            Status s = TryCommit(out error);
            if (s != Status.Ok) throw new ForesightException(s, "Commit: " + error);
        }

        /// <summary>Adds a plane; nothing is added unless Ok.</summary>
        /// <returns>Ok, NonFiniteInput, ZeroVector, InvalidRestitution or OutOfMemory.</returns>
        public Status TryAddPlane(PlaneShape plane) { return Native.fs_world_add_plane(Handle, ref plane, IntPtr.Zero); }

        /// <summary>Adds a plane with its own material (used by the Engine method).</summary>
        public Status TryAddPlane(PlaneShape plane, SurfaceMaterial material)
        {
            return Native.fs_world_add_plane(Handle, ref plane, ref material);
        }

        /// <summary>Adds the plane dot(normal, x) = distance [Units: m]; throws ForesightException.</summary>
        public void AddPlane(Vector3 normal, double distance)
        {
            PlaneShape p = new PlaneShape { Normal = normal, Distance = distance };
            ForesightException.ThrowUnlessOk(TryAddPlane(p), "AddPlane");
        }

        /// <summary>Adds a sphere; nothing is added unless Ok.</summary>
        /// <returns>Ok, NonFiniteInput, InvalidRadius, InvalidRestitution or OutOfMemory.</returns>
        public Status TryAddSphere(SphereShape sphere) { return Native.fs_world_add_sphere(Handle, ref sphere, IntPtr.Zero); }

        /// <summary>Adds a sphere with its own material.</summary>
        public Status TryAddSphere(SphereShape sphere, SurfaceMaterial material)
        {
            return Native.fs_world_add_sphere(Handle, ref sphere, ref material);
        }

        /// <summary>Adds a sphere of <paramref name="radius"/> [Units: m]; throws ForesightException.</summary>
        public void AddSphere(DVec3 center, float radius)
        {
            SphereShape s = new SphereShape { Center = center, Radius = radius };
            ForesightException.ThrowUnlessOk(TryAddSphere(s), "AddSphere");
        }

        /// <summary>Adds a box; nothing is added unless Ok.</summary>
        /// <returns>Ok, NonFiniteInput, DegenerateShape, InvalidRadius, ZeroQuaternion,
        /// InvalidRestitution or OutOfMemory.</returns>
        public Status TryAddBox(BoxShape box) { return Native.fs_world_add_box(Handle, ref box, IntPtr.Zero); }

        /// <summary>Adds a box with its own material.</summary>
        public Status TryAddBox(BoxShape box, SurfaceMaterial material) { return Native.fs_world_add_box(Handle, ref box, ref material); }

        /// <summary>Adds a box [Units: m]; throws ForesightException.</summary>
        public void AddBox(DVec3 center, Vector3 halfExtents, Quaternion orientation)
        {
            BoxShape b = new BoxShape { Center = center, HalfExtents = halfExtents, Orientation = orientation };
            ForesightException.ThrowUnlessOk(TryAddBox(b), "AddBox");
        }

        /// <summary>Adds a two-sided triangle; nothing is added unless Ok.</summary>
        /// <returns>Ok, NonFiniteInput, DegenerateShape, InvalidRestitution or OutOfMemory.</returns>
        public Status TryAddTriangle(TriangleShape triangle)
        {
            return Native.fs_world_add_triangle(Handle, ref triangle, IntPtr.Zero);
        }

        /// <summary>Adds a triangle with its own material.</summary>
        public Status TryAddTriangle(TriangleShape triangle, SurfaceMaterial material)
        {
            return Native.fs_world_add_triangle(Handle, ref triangle, ref material);
        }

        /// <summary>Adds the triangle a, b, c [Units: m]; throws ForesightException.</summary>
        public void AddTriangle(DVec3 a, DVec3 b, DVec3 c)
        {
            TriangleShape t = new TriangleShape { A = a, B = b, C = c };
            ForesightException.ThrowUnlessOk(TryAddTriangle(t), "AddTriangle");
        }
    }

    /// <summary>Projectiles under constant gravity, bouncing off a World (projectile.h).</summary>
    public static class Projectiles
    {
        /// <summary>The C++ defaults (the reference article's): Exact, gravity (0, -9.81, 0),
        /// step 0.02 s, restitution 0.5, frictionless point, engine Jolt.</summary>
        public static ProjectileSettings DefaultSettings { get { return Native.fs_projectile_settings_default(); } }

        /// <summary>A trajectory buffer size that holds a Stepped or Engine trajectory of
        /// <paramref name="time"/> [Units: s], and an Exact one with up to 64 bounces and
        /// contact changes; 0 when the input is refused.</summary>
        public static int TrajectoryCapacity(float time, ProjectileSettings settings)
        {
            ulong n = (ulong)Native.fs_trajectory_capacity(time, ref settings);
            return n > int.MaxValue ? int.MaxValue : (int)n;
        }

        /// <summary>Predicts a projectile. Allocates nothing: the trajectory goes into
        /// <paramref name="points"/>, pinned during the call.</summary>
        /// <param name="position">Start [Units: m] (the sphere's centre when Radius > 0).</param>
        /// <param name="velocity">Start velocity [Units: m/s] [Limit: &lt;= 1e6 m/s].</param>
        /// <param name="time">Prediction time, e.g. a fuse [Units: s] [Limit: >= 0, finite].</param>
        /// <param name="settings">Method and physical parameters.</param>
        /// <param name="world">What to bounce off; null: nothing.</param>
        /// <param name="points">The trajectory buffer, or null for none (capacity its length).</param>
        /// <param name="result">The outcome, written on Ok and BufferTooSmall (default otherwise).</param>
        /// <returns>Ok; BufferTooSmall (result and the first points written, see
        /// TrajectoryNeeded); InvalidSetting, NonFiniteInput, InvalidStep, InvalidRestitution,
        /// InvalidFriction, InvalidRadius, NegativeTime, OutOfRange, TooManySteps, TooManyEvents
        /// or NonFiniteResult.</returns>
        public static Status TryPredict(DVec3 position, Vector3 velocity, float time, ProjectileSettings settings,
                                        World world, TrajectoryPoint[] points, out ProjectileResult result)
        {
            // An empty buffer passes a pointer the library does not read (capacity 0).
            if (points == null || points.Length == 0)
                return Predict(position, velocity, time, ref settings, world, ref noPoints, 0, out result);
            return Predict(position, velocity, time, ref settings, world, ref points[0], points.Length, out result);
        }

        // Never written: the library reads no point when the capacity is 0.
        private static TrajectoryPoint noPoints;

        private static Status Predict(DVec3 position, Vector3 velocity, float time, ref ProjectileSettings settings,
                                      World world, ref TrajectoryPoint first, int capacity, out ProjectileResult result)
        {
            result = default(ProjectileResult);
            UIntPtr n = new UIntPtr((uint)capacity);
            Vector3Native v = new Vector3Native(velocity);
            if (world == null)
                return Native.fs_predict_projectile(position, v, time, ref settings, IntPtr.Zero, ref first, n, out result);
            return Native.fs_predict_projectile(position, v, time, ref settings, world.Handle, ref first, n, out result);
        }

        /// <summary>Predicts a projectile without a trajectory (see TryPredict).</summary>
        public static Status TryPredict(DVec3 position, Vector3 velocity, float time, ProjectileSettings settings,
                                        World world, out ProjectileResult result)
        {
            return TryPredict(position, velocity, time, settings, world, null, out result);
        }

        /// <summary>Predicts a projectile (see TryPredict); throws ForesightException on any
        /// status but Ok (BufferTooSmall too).</summary>
        public static ProjectileResult Predict(DVec3 position, Vector3 velocity, float time,
                                               ProjectileSettings settings, World world = null,
                                               TrajectoryPoint[] points = null)
        {
            ProjectileResult result;
            ForesightException.ThrowUnlessOk(TryPredict(position, velocity, time, settings, world, points, out result),
                                             "PredictProjectile");
            return result;
        }

#if NETSTANDARD2_1_OR_GREATER || NETCOREAPP2_1_OR_GREATER || UNITY_2021_2_OR_NEWER || FORESIGHT_SPAN
        /// <summary>TryPredict into a Span (a stackalloc'd or pooled buffer); the same contract.</summary>
        public static Status TryPredict(DVec3 position, Vector3 velocity, float time, ProjectileSettings settings,
                                        World world, Span<TrajectoryPoint> points, out ProjectileResult result)
        {
            if (points.IsEmpty) return Predict(position, velocity, time, ref settings, world, ref noPoints, 0, out result);
            return Predict(position, velocity, time, ref settings, world, ref MemoryMarshal.GetReference(points),
                           points.Length, out result);
        }
#endif
    }

    /// <summary>Engine profiles: a game's own engine settings for the Engine method
    /// (engine_profile.h), and where a game draws a fixed-step body between its steps.</summary>
    public static class EngineProfiles
    {
        /// <summary>The documented defaults of <paramref name="engine"/> (docs/engines.md);
        /// an engine outside the enumeration gives Jolt's.</summary>
        public static EngineProfile Default(PhysicsEngine engine) { return Native.fs_engine_profile_default(engine); }

        /// <summary>Bullet as ammo.js 0.0.10 carries it (Bullet 2.83): Bullet's profile with no
        /// restitution threshold, friction warm-started by 0.85 and erp2 0.8 (docs/engines.md).</summary>
        public static EngineProfile AmmoJs() { return Native.fs_engine_profile_ammo_js(); }

        /// <summary>Checks every field of <paramref name="profile"/>.</summary>
        /// <returns>Ok, NonFiniteInput, InvalidStep (timestep) or InvalidSetting.</returns>
        public static Status Validate(EngineProfile profile) { return Native.fs_validate_engine_profile(ref profile); }

        /// <summary>TrajectoryCapacity for the Engine method with <paramref name="profile"/>
        /// [Units: s for time]; 0 when the input is refused.</summary>
        public static int TrajectoryCapacity(float time, ProjectileSettings settings, EngineProfile profile)
        {
            ulong n = (ulong)Native.fs_trajectory_capacity_with_profile(time, ref settings, ref profile);
            return n > int.MaxValue ? int.MaxValue : (int)n;
        }

        /// <summary>Projectiles.TryPredict with <paramref name="profile"/> as the engine of the
        /// Engine method (settings.Engine is then ignored; other methods ignore the profile,
        /// which must still be valid). Allocates nothing.</summary>
        /// <returns>As Projectiles.TryPredict, and the refusals of Validate.</returns>
        public static Status TryPredict(DVec3 position, Vector3 velocity, float time, ProjectileSettings settings,
                                        EngineProfile profile, World world, TrajectoryPoint[] points,
                                        out ProjectileResult result)
        {
            if (points == null || points.Length == 0)
                return Predict(position, velocity, time, ref settings, ref profile, world, ref noPoints, 0, out result);
            return Predict(position, velocity, time, ref settings, ref profile, world, ref points[0], points.Length,
                           out result);
        }

        private static Status Predict(DVec3 position, Vector3 velocity, float time, ref ProjectileSettings settings,
                                      ref EngineProfile profile, World world, ref TrajectoryPoint first, int capacity,
                                      out ProjectileResult result)
        {
            result = default(ProjectileResult);
            UIntPtr n = new UIntPtr((uint)capacity);
            Vector3Native v = new Vector3Native(velocity);
            if (world == null)
                return Native.fs_predict_projectile_with_profile(position, v, time, ref settings, ref profile, IntPtr.Zero,
                                                                 ref first, n, out result);
            return Native.fs_predict_projectile_with_profile(position, v, time, ref settings, ref profile, world.Handle,
                                                             ref first, n, out result);
        }

        /// <summary>TryPredict with a profile, throwing ForesightException on any status but Ok.</summary>
        public static ProjectileResult Predict(DVec3 position, Vector3 velocity, float time, ProjectileSettings settings,
                                               EngineProfile profile, World world = null, TrajectoryPoint[] points = null)
        {
            ProjectileResult result;
            ForesightException.ThrowUnlessOk(TryPredict(position, velocity, time, settings, profile, world, points,
                                                        out result),
                                             "PredictProjectileWithProfile");
            return result;
        }

        // Never written: the library reads no point when the capacity is 0.
        private static TrajectoryPoint noPoints;

        /// <summary>Where a game draws a fixed-step trajectory (Engine or Stepped: Start, then
        /// one point per step; its first <paramref name="count"/> points) at
        /// <paramref name="renderTime"/> [Units: s].</summary>
        /// <param name="trajectory">The points a prediction wrote.</param>
        /// <param name="count">How many to use (ProjectileResult.TrajectorySize).</param>
        /// <param name="step">The trajectory's step [Units: s]: the profile's Timestep (Engine)
        /// or settings.Step (Stepped).</param>
        /// <param name="renderTime">[Units: s] since the start.</param>
        /// <param name="smoothing">How the game draws between steps.</param>
        /// <param name="position">The position drawn [Units: m] (default on a refusal).</param>
        /// <returns>Ok, InvalidStep (no points, or a bad step), NonFiniteInput or InvalidSetting.</returns>
        public static Status TryRenderedPosition(TrajectoryPoint[] trajectory, int count, float step, float renderTime,
                                                 RenderSmoothing smoothing, out DVec3 position)
        {
            position = default(DVec3);
            int n = trajectory == null ? 0 : Math.Max(0, Math.Min(count, trajectory.Length));
            if (n == 0)
                return Native.fs_rendered_position(ref noPoints, UIntPtr.Zero, step, renderTime, smoothing, out position);
            return Native.fs_rendered_position(ref trajectory[0], new UIntPtr((uint)n), step, renderTime, smoothing,
                                               out position);
        }

        /// <summary>TryRenderedPosition, throwing ForesightException.</summary>
        public static DVec3 RenderedPosition(TrajectoryPoint[] trajectory, int count, float step, float renderTime,
                                             RenderSmoothing smoothing)
        {
            DVec3 position;
            ForesightException.ThrowUnlessOk(TryRenderedPosition(trajectory, count, step, renderTime, smoothing,
                                                                 out position),
                                             "RenderedPosition");
            return position;
        }
    }

    /// <summary>Aiming a projectile at a moving target in free space (aim.h).</summary>
    public static class Aim
    {
        /// <summary>The most firing solutions any constraint has (FS_MAX_FIRING_SOLUTIONS).</summary>
        public const int MaxFiringSolutions = 4;

        /// <summary>The C++ defaults: from the origin, Speed constraint with speed 0, gravity
        /// (0, -9.81, 0), MaxTime 60 s.</summary>
        public static AimShot DefaultShot { get { return Native.fs_aim_shot_default(); } }

        /// <summary>Every firing solution with a flight time in (0, MaxTime], earliest first,
        /// into <paramref name="solutions"/> (MaxFiringSolutions entries hold them all).</summary>
        /// <param name="shot">Launch point, constraint, gravity and time limit.</param>
        /// <param name="target">The target's motion.</param>
        /// <param name="solutions">Receives the earliest solutions (null: none asked for).</param>
        /// <param name="count">The number written (0: unreachable, not an error).</param>
        /// <returns>Ok, InvalidSetting, NonFiniteInput, NegativeTime, ZeroVector or NonFiniteResult.</returns>
        public static Status TryAim(AimShot shot, AimTarget target, FiringSolution[] solutions, out int count)
        {
            UIntPtr n;
            Status s = solutions == null || solutions.Length == 0
                           ? Native.fs_aim_projectile(ref shot, ref target, ref noSolutions, UIntPtr.Zero, out n)
                           : Native.fs_aim_projectile(ref shot, ref target, ref solutions[0],
                                                      new UIntPtr((uint)solutions.Length), out n);
            count = s == Status.Ok ? (int)(ulong)n : 0;
            return s;
        }

        // Never written: the library writes no solution when the capacity is 0.
        private static FiringSolution noSolutions;

        /// <summary>TryAim, throwing ForesightException; returns the number of solutions.</summary>
        public static int AimAt(AimShot shot, AimTarget target, FiringSolution[] solutions)
        {
            int count;
            ForesightException.ThrowUnlessOk(TryAim(shot, target, solutions, out count), "Aim");
            return count;
        }
    }

    /// <summary>Danger (danger.h): where and when a predicted grenade is dangerous, when a path
    /// comes close, and when a vehicle reaches a character. The projectile functions read a
    /// trajectory a prediction wrote: its first <c>count</c> points (ProjectileResult.TrajectorySize).
    /// The library converts it in a per-thread buffer that keeps its size: the first call with
    /// N points on a thread allocates natively, later calls with at most N points do not.</summary>
    public static class Danger
    {
        // Never read: the library refuses a count of 0 before reading any point.
        private static TrajectoryPoint noPoints;

        private static int Count(TrajectoryPoint[] trajectory, int count)
        {
            return trajectory == null ? 0 : Math.Max(0, Math.Min(count, trajectory.Length));
        }

        private static ref TrajectoryPoint First(TrajectoryPoint[] trajectory, int n)
        {
            if (n == 0) return ref noPoints;
            return ref trajectory[0];
        }

        /// <summary>The projectile's position at <paramref name="time"/> [Units: s], on the
        /// parabola between the points around it.</summary>
        /// <returns>Ok, InvalidStep (no points, decreasing times), NonFiniteInput,
        /// InvalidSetting, OutOfMemory or NonFiniteResult.</returns>
        public static Status TryPositionOnTrajectory(TrajectoryPoint[] trajectory, int count, float time, out DVec3 position)
        {
            position = default(DVec3);
            int n = Count(trajectory, count);
            return Native.fs_position_on_trajectory(ref First(trajectory, n), new UIntPtr((uint)n), time, out position);
        }

        /// <summary>TryPositionOnTrajectory, throwing ForesightException.</summary>
        public static DVec3 PositionOnTrajectory(TrajectoryPoint[] trajectory, int count, float time)
        {
            DVec3 p;
            ForesightException.ThrowUnlessOk(TryPositionOnTrajectory(trajectory, count, time, out p), "PositionOnTrajectory");
            return p;
        }

        /// <summary>The danger zone: the position at the fuse time, the blast radius, the fuse time.</summary>
        /// <returns>Ok, the trajectory's refusals, InvalidFuse, InvalidRadius or NonFiniteResult.</returns>
        public static Status TryComputeDangerZone(TrajectoryPoint[] trajectory, int count, ProjectileDanger danger,
                                                  out DangerZone zone)
        {
            zone = default(DangerZone);
            int n = Count(trajectory, count);
            return Native.fs_compute_danger_zone(ref First(trajectory, n), new UIntPtr((uint)n), ref danger, out zone);
        }

        /// <summary>TryComputeDangerZone, throwing ForesightException.</summary>
        public static DangerZone ComputeDangerZone(TrajectoryPoint[] trajectory, int count, ProjectileDanger danger)
        {
            DangerZone z;
            ForesightException.ThrowUnlessOk(TryComputeDangerZone(trajectory, count, danger, out z), "ComputeDangerZone");
            return z;
        }

        /// <summary>Whether <paramref name="point"/> [Units: m] is safe at <paramref name="time"/>
        /// [Units: s]: outside the blast from the fuse time on, farther than ContactRadius
        /// from the projectile before it.</summary>
        /// <returns>Ok or TryComputeDangerZone's refusals (safe is then false).</returns>
        public static Status TryIsPointSafe(TrajectoryPoint[] trajectory, int count, ProjectileDanger danger, DVec3 point,
                                            float time, out bool safe)
        {
            int n = Count(trajectory, count);
            int flag;
            Status s = Native.fs_is_point_safe(ref First(trajectory, n), new UIntPtr((uint)n), ref danger, point, time,
                                               out flag);
            safe = s == Status.Ok && flag != 0;
            return s;
        }

        /// <summary>TryIsPointSafe, throwing ForesightException.</summary>
        public static bool IsPointSafe(TrajectoryPoint[] trajectory, int count, ProjectileDanger danger, DVec3 point,
                                       float time)
        {
            bool safe;
            ForesightException.ThrowUnlessOk(TryIsPointSafe(trajectory, count, danger, point, time, out safe), "IsPointSafe");
            return safe;
        }

        /// <summary>When danger starts at <paramref name="point"/> [Units: m].</summary>
        /// <returns>Ok or TryComputeDangerZone's refusals.</returns>
        public static Status TryFindDangerStart(TrajectoryPoint[] trajectory, int count, ProjectileDanger danger,
                                                DVec3 point, out DangerStart start)
        {
            start = default(DangerStart);
            int n = Count(trajectory, count);
            return Native.fs_find_danger_start(ref First(trajectory, n), new UIntPtr((uint)n), ref danger, point,
                                               out start);
        }

        /// <summary>TryFindDangerStart, throwing ForesightException.</summary>
        public static DangerStart FindDangerStart(TrajectoryPoint[] trajectory, int count, ProjectileDanger danger,
                                                  DVec3 point)
        {
            DangerStart d;
            ForesightException.ThrowUnlessOk(TryFindDangerStart(trajectory, count, danger, point, out d), "FindDangerStart");
            return d;
        }

        /// <summary>The earliest time in [fromTime, untilTime] [Units: s] at which the projectile
        /// comes within <paramref name="distance"/> [Units: m] of <paramref name="point"/>.</summary>
        /// <returns>Ok, the trajectory's refusals or InvalidRadius.</returns>
        public static Status TryFindPathApproach(TrajectoryPoint[] trajectory, int count, DVec3 point, float distance,
                                                 float fromTime, float untilTime, out DangerStart start)
        {
            start = default(DangerStart);
            int n = Count(trajectory, count);
            return Native.fs_find_path_approach(ref First(trajectory, n), new UIntPtr((uint)n), point, distance, fromTime,
                                                untilTime, out start);
        }

        /// <summary>TryFindPathApproach, throwing ForesightException.</summary>
        public static DangerStart FindPathApproach(TrajectoryPoint[] trajectory, int count, DVec3 point, float distance,
                                                   float fromTime, float untilTime)
        {
            DangerStart d;
            ForesightException.ThrowUnlessOk(TryFindPathApproach(trajectory, count, point, distance, fromTime, untilTime,
                                                                 out d),
                                             "FindPathApproach");
            return d;
        }

        /// <summary>The projectile's closest approach to <paramref name="point"/> over
        /// [fromTime, untilTime] [Units: s].</summary>
        /// <returns>Ok, the trajectory's refusals or NonFiniteResult.</returns>
        public static Status TryFindClosestPathApproach(TrajectoryPoint[] trajectory, int count, DVec3 point,
                                                        float fromTime, float untilTime, out ClosestApproach approach)
        {
            approach = default(ClosestApproach);
            int n = Count(trajectory, count);
            return Native.fs_find_closest_path_approach(ref First(trajectory, n), new UIntPtr((uint)n), point, fromTime,
                                                        untilTime, out approach);
        }

        /// <summary>TryFindClosestPathApproach, throwing ForesightException.</summary>
        public static ClosestApproach FindClosestPathApproach(TrajectoryPoint[] trajectory, int count, DVec3 point,
                                                              float fromTime, float untilTime)
        {
            ClosestApproach a;
            ForesightException.ThrowUnlessOk(TryFindClosestPathApproach(trajectory, count, point, fromTime, untilTime,
                                                                        out a),
                                             "FindClosestPathApproach");
            return a;
        }

        /// <summary>The C++ VehicleBody defaults (identity orientation, at rest, box (0.9, 0.7, 2.2)).</summary>
        public static VehicleBody DefaultVehicleBody { get { return Native.fs_vehicle_body_default(); } }

        /// <summary>The C++ CharacterBody defaults (a sphere of radius 0.4 m at rest at the origin).</summary>
        public static CharacterBody DefaultCharacterBody { get { return Native.fs_character_body_default(); } }

        /// <summary>The C++ ApproachSettings defaults (tolerance 1e-3 m, 65536 evaluations).</summary>
        public static ApproachSettings DefaultApproachSettings { get { return Native.fs_approach_settings_default(); } }

        /// <summary>The separation of the vehicle and the character at <paramref name="time"/>
        /// [Units: s]: exact, &lt;= 0 when they overlap [Units: m].</summary>
        /// <returns>Ok, InvalidSetting, NonFiniteInput, ZeroQuaternion, ZeroVector,
        /// DegenerateShape, InvalidRadius, NegativeTime or NonFiniteResult.</returns>
        public static Status TryComputeVehicleSeparation(VehicleBody vehicle, CharacterBody character, float time,
                                                         out float separation)
        {
            separation = default(float);
            return Native.fs_compute_vehicle_separation(ref vehicle, ref character, time, out separation);
        }

        /// <summary>TryComputeVehicleSeparation, throwing ForesightException.</summary>
        public static float ComputeVehicleSeparation(VehicleBody vehicle, CharacterBody character, float time)
        {
            float d;
            ForesightException.ThrowUnlessOk(TryComputeVehicleSeparation(vehicle, character, time, out d),
                                             "ComputeVehicleSeparation");
            return d;
        }

        /// <summary>The first time in [0, horizon] [Units: s] at which they touch (never later
        /// than the true first overlap).</summary>
        /// <returns>As TryComputeVehicleSeparation, InvalidStep (settings), TooManySteps.</returns>
        public static Status TryFindVehicleContact(VehicleBody vehicle, CharacterBody character, float horizon,
                                                   ApproachSettings settings, out VehicleContact contact)
        {
            contact = default(VehicleContact);
            return Native.fs_find_vehicle_contact(ref vehicle, ref character, horizon, ref settings, out contact);
        }

        /// <summary>TryFindVehicleContact, throwing ForesightException.</summary>
        public static VehicleContact FindVehicleContact(VehicleBody vehicle, CharacterBody character, float horizon,
                                                        ApproachSettings settings)
        {
            VehicleContact c;
            ForesightException.ThrowUnlessOk(TryFindVehicleContact(vehicle, character, horizon, settings, out c),
                                             "FindVehicleContact");
            return c;
        }

        /// <summary>The closest approach in [0, horizon] [Units: s].</summary>
        /// <returns>As TryFindVehicleContact.</returns>
        public static Status TryFindClosestVehicleApproach(VehicleBody vehicle, CharacterBody character, float horizon,
                                                           ApproachSettings settings, out ClosestApproach approach)
        {
            approach = default(ClosestApproach);
            return Native.fs_find_closest_vehicle_approach(ref vehicle, ref character, horizon, ref settings, out approach);
        }

        /// <summary>TryFindClosestVehicleApproach, throwing ForesightException.</summary>
        public static ClosestApproach FindClosestVehicleApproach(VehicleBody vehicle, CharacterBody character,
                                                                 float horizon, ApproachSettings settings)
        {
            ClosestApproach a;
            ForesightException.ThrowUnlessOk(TryFindClosestVehicleApproach(vehicle, character, horizon, settings, out a),
                                             "FindClosestVehicleApproach");
            return a;
        }
    }

    /// <summary>Throw planning (throw_planner.h): throws that put a grenade near a target when
    /// its fuse ends, bank shots included. Allocates nothing.</summary>
    public static class ThrowPlanner
    {
        // Never written: the library writes nothing through a capacity of 0.
        private static ThrowPlan noPlans;
        private static TrajectoryPoint noPoints;

        /// <summary>The C++ ThrowPlanRequest defaults (its settings: Projectiles.DefaultSettings).</summary>
        public static ThrowPlanRequest DefaultRequest { get { return Native.fs_throw_plan_request_default(); } }

        /// <summary>Scratch points that let the planner record every first impact (0 for a
        /// refused request).</summary>
        public static int ScratchSize(ThrowPlanRequest request)
        {
            ulong n = (ulong)Native.fs_throw_plan_scratch_size(ref request);
            return n > int.MaxValue ? int.MaxValue : (int)n;
        }

        /// <summary>Plans throws for <paramref name="request"/> in <paramref name="world"/> (null:
        /// nothing). To draw a plan: Projectiles.Predict(request.Start, plan.LaunchVelocity,
        /// request.FuseTime, request.Settings, world, ...).</summary>
        /// <param name="request">Start, target, fuse, speeds, forward model and budget.</param>
        /// <param name="world">What the grenade bounces off; null: nothing.</param>
        /// <param name="plans">Receives up to min(MaxPlans, length) plans, closest first.</param>
        /// <param name="scratch">Trajectory scratch of ScratchSize points to record every first
        /// impact; may be shorter or null.</param>
        /// <param name="result">What was done (default on a refusal).</param>
        /// <returns>Ok (also when nothing was found), InvalidSetting, NonFiniteInput,
        /// InvalidFuse, InvalidRadius, InvalidSpeed, InvalidIterations, InvalidStep, the
        /// settings' refusals or TooManySteps.</returns>
        public static Status TryPlan(ThrowPlanRequest request, World world, ThrowPlan[] plans, TrajectoryPoint[] scratch,
                                     out ThrowPlanResult result)
        {
            int np = plans == null ? 0 : plans.Length, ns = scratch == null ? 0 : scratch.Length;
            return Plan(ref request, world, ref FirstPlan(plans), np, ref FirstPoint(scratch), ns, out result);
        }

        private static ref ThrowPlan FirstPlan(ThrowPlan[] plans)
        {
            if (plans == null || plans.Length == 0) return ref noPlans;
            return ref plans[0];
        }

        private static ref TrajectoryPoint FirstPoint(TrajectoryPoint[] points)
        {
            if (points == null || points.Length == 0) return ref noPoints;
            return ref points[0];
        }

        private static Status Plan(ref ThrowPlanRequest request, World world, ref ThrowPlan plans, int np,
                                   ref TrajectoryPoint scratch, int ns, out ThrowPlanResult result)
        {
            result = default(ThrowPlanResult);
            if (world == null)
                return Native.fs_plan_throw(ref request, IntPtr.Zero, ref plans, new UIntPtr((uint)np), ref scratch,
                                            new UIntPtr((uint)ns), out result);
            return Native.fs_plan_throw(ref request, world.Handle, ref plans, new UIntPtr((uint)np), ref scratch,
                                        new UIntPtr((uint)ns), out result);
        }

        /// <summary>TryPlan, throwing ForesightException.</summary>
        public static ThrowPlanResult Plan(ThrowPlanRequest request, World world, ThrowPlan[] plans,
                                           TrajectoryPoint[] scratch = null)
        {
            ThrowPlanResult result;
            ForesightException.ThrowUnlessOk(TryPlan(request, world, plans, scratch, out result), "PlanThrow");
            return result;
        }
    }

    /// <summary>Network dead reckoning: the DIS models and the batch extrapolation
    /// (dead_reckoning.h, replication.h).</summary>
    public static class DeadReckoning
    {
        /// <summary>The DIS name of <paramref name="algorithm"/> ("STATIC", "FPW", ...; "?"
        /// for another value). Allocates the string.</summary>
        public static string AlgorithmName(DeadReckoningAlgorithm algorithm)
        {
            return Marshal.PtrToStringAnsi(Native.fs_dr_algorithm_name(algorithm));
        }

        /// <summary>The C++ receiver defaults: Extrapolate, ProjectiveVelocityBlending, blend
        /// 0.2 s, half-life 0.1 s, teleport 10 m, limit 0.25 s, delay 0.1 s, skew 1 s, restart 10 s.</summary>
        public static ReceiverSettings DefaultReceiverSettings { get { return Native.fs_dr_receiver_settings_default(); } }

        /// <summary>Extrapolates <paramref name="state"/> by <paramref name="time"/> [Units: s]
        /// [Limit: >= 0, finite] with its algorithm.</summary>
        /// <returns>Ok, InvalidAlgorithm, NonFiniteInput, ZeroQuaternion, NegativeTime or
        /// NonFiniteResult.</returns>
        public static Status TryPredict(DeadReckoningState state, float time, out DeadReckoningResult result)
        {
            result = default(DeadReckoningResult);
            return Native.fs_dr_predict(ref state, time, out result);
        }

        /// <summary>TryPredict, throwing ForesightException.</summary>
        public static DeadReckoningResult Predict(DeadReckoningState state, float time)
        {
            DeadReckoningResult result;
            ForesightException.ThrowUnlessOk(TryPredict(state, time, out result), "PredictDeadReckoning");
            return result;
        }

        /// <summary>Extrapolates many entities to <paramref name="time"/> [Units: s]: results[i]
        /// is TryPredict(states[i], (float)max(time - timestamps[i], 0)) bit for bit; refused
        /// entities keep their state and are counted. As the C++ spans: when the lengths differ,
        /// the entities up to the shortest are processed and the states beyond it are counted
        /// as refused. Allocates nothing.</summary>
        /// <returns>Ok, or NullPointer when an array is null (refused is then 0).</returns>
        public static Status TryPredictBatch(DeadReckoningState[] states, double[] timestamps, double time,
                                             DeadReckoningResult[] results, out int refused)
        {
            refused = 0;
            if (states == null || timestamps == null || results == null) return Status.NullPointer;
            int count = Math.Min(states.Length, Math.Min(timestamps.Length, results.Length));
            if (count == 0)
            {
                refused = states.Length;
                return Status.Ok;
            }
            UIntPtr n;
            Status s = Native.fs_dr_predict_batch(ref states[0], ref timestamps[0], new UIntPtr((uint)count), time,
                                                  ref results[0], out n);
            if (s == Status.Ok) refused = (int)(ulong)n + (states.Length - count);
            return s;
        }

        /// <summary>TryPredictBatch, throwing ForesightException; returns the number refused.</summary>
        public static int PredictBatch(DeadReckoningState[] states, double[] timestamps, double time,
                                       DeadReckoningResult[] results)
        {
            int refused;
            ForesightException.ThrowUnlessOk(TryPredictBatch(states, timestamps, time, results, out refused),
                                             "PredictDeadReckoningBatch");
            return refused;
        }
    }

    /// <summary>Owns a native fs_dr_receiver.</summary>
    internal sealed class ReceiverHandle : SafeHandleZeroOrMinusOneIsInvalid
    {
        /// <summary>An empty handle, filled by the marshaller.</summary>
        public ReceiverHandle() : base(true) {}

        protected override bool ReleaseHandle()
        {
            Native.fs_dr_receiver_destroy(handle);
            return true;
        }
    }

    /// <summary>Shows one remote entity from the updates it receives (DeadReckoningReceiver):
    /// extrapolates or interpolates them and blends corrections. Creating it allocates (a fixed
    /// size); Receive and Sample do not. One thread at a time. Dispose it.</summary>
    public sealed class DeadReckoningReceiver : IDisposable
    {
        private readonly ReceiverHandle handle;

        private DeadReckoningReceiver(ReceiverHandle h) { handle = h; }

        /// <summary>A receiver with the default settings.</summary>
        public DeadReckoningReceiver() : this(DeadReckoning.DefaultReceiverSettings) {}

        /// <summary>A receiver with <paramref name="settings"/>; throws ForesightException
        /// (InvalidSetting, OutOfMemory).</summary>
        public DeadReckoningReceiver(ReceiverSettings settings)
        {
            ReceiverHandle h;
            Status s = Native.fs_dr_receiver_create(ref settings, out h);
            if (s != Status.Ok)
            {
                if (h != null) h.Dispose();
                throw new ForesightException(s, "DeadReckoningReceiver");
            }
            handle = h;
        }

        /// <summary>Makes a receiver after checking <paramref name="settings"/>.</summary>
        /// <returns>Ok (receiver set), InvalidSetting or OutOfMemory (receiver null).</returns>
        public static Status TryCreate(ReceiverSettings settings, out DeadReckoningReceiver receiver)
        {
            ReceiverHandle h;
            Status s = Native.fs_dr_receiver_create(ref settings, out h);
            if (s != Status.Ok)
            {
                if (h != null) h.Dispose();
                receiver = null;
                return s;
            }
            receiver = new DeadReckoningReceiver(h);
            return s;
        }

        /// <summary>True once disposed.</summary>
        public bool IsDisposed { get { return handle.IsClosed; } }

        /// <summary>Frees the native receiver (idempotent).</summary>
        public void Dispose() { handle.Dispose(); }

        /// <summary>Takes an update stamped <paramref name="timestamp"/> [Units: s] (sender
        /// clock) arriving at <paramref name="receiveTime"/> [Units: s]; bad or stale updates
        /// are dropped and counted.</summary>
        /// <returns>What was done with it.</returns>
        public UpdateOutcome Receive(double timestamp, DeadReckoningState state, double receiveTime)
        {
            UpdateOutcome outcome;
            Native.fs_dr_receiver_receive(handle, timestamp, ref state, receiveTime, out outcome);
            return outcome;
        }

        /// <summary>The pose to show at <paramref name="time"/> [Units: s].</summary>
        /// <returns>Ok, NoUpdate, NonFiniteInput or NonFiniteResult.</returns>
        public Status TrySample(double time, out ReceivedPose pose)
        {
            pose = default(ReceivedPose);
            return Native.fs_dr_receiver_sample(handle, time, out pose);
        }

        /// <summary>TrySample, throwing ForesightException.</summary>
        public ReceivedPose Sample(double time)
        {
            ReceivedPose pose;
            ForesightException.ThrowUnlessOk(TrySample(time, out pose), "Sample");
            return pose;
        }

        /// <summary>The counters since creation or the last Reset.</summary>
        public ReceiverCounters Counters
        {
            get
            {
                ReceiverCounters c;
                Native.fs_dr_receiver_get_counters(handle, out c);
                return c;
            }
        }

        /// <summary>Forgets every update and counter (the settings stay).</summary>
        public void Reset() { Native.fs_dr_receiver_reset(handle); }
    }
}
