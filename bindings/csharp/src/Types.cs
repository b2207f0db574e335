// The structs and enumerations of foresight_c.h, field for field. Each struct is
// LayoutKind.Explicit with the size and offsets documented in the header (tests/BindingTests.cs
// checks them against the header's comments with Marshal.SizeOf and Marshal.OffsetOf), and is
// blittable: fs_vec3 is System.Numerics.Vector3, fs_quat is System.Numerics.Quaternion (both
// x, y, z floats, w last), fs_dvec3 is DVec3, int32_t enumerations are C# enums over int.
// Units: metres, seconds, radians; +Y up, +Z forward (Axes.cs for Unity and Godot).

using System;
using System.Numerics;
using System.Runtime.InteropServices;

namespace Foresight
{
    /// <summary>The outcome of a call (fs_status): <see cref="Ok"/> or why the input was
    /// refused. <see cref="Library.Message"/> gives the library's text for each.</summary>
    public enum Status
    {
        /// <summary>Success.</summary>
        Ok = 0,
        /// <summary>A position, vector, quaternion or scalar is NaN or infinite.</summary>
        NonFiniteInput = 1,
        /// <summary>A prediction time is below zero.</summary>
        NegativeTime = 2,
        /// <summary>A time step is zero, negative or not finite.</summary>
        InvalidStep = 3,
        /// <summary>An iteration count is below 1 or above 1048576.</summary>
        InvalidIterations = 4,
        /// <summary>Restitution is outside [0, 1].</summary>
        InvalidRestitution = 5,
        /// <summary>Friction is negative.</summary>
        InvalidFriction = 6,
        /// <summary>A radius is negative (projectiles) or not positive (spheres).</summary>
        InvalidRadius = 7,
        /// <summary>A quaternion has zero length.</summary>
        ZeroQuaternion = 8,
        /// <summary>A vector that must have a direction (normal, forward axis) is zero.</summary>
        ZeroVector = 9,
        /// <summary>A triangle with no area, a box with a non-positive half extent.</summary>
        DegenerateShape = 10,
        /// <summary>The prediction would take more steps than MaxSteps.</summary>
        TooManySteps = 11,
        /// <summary>The prediction hit MaxEvents (bounces and contact changes).</summary>
        TooManyEvents = 12,
        /// <summary>The inputs are valid but so large that the result overflows.</summary>
        NonFiniteResult = 13,
        /// <summary>A dead-reckoning algorithm outside 1 to 9.</summary>
        InvalidAlgorithm = 14,
        /// <summary>A speed is zero, negative or not finite.</summary>
        InvalidSpeed = 15,
        /// <summary>A fuse time is zero, negative or not finite.</summary>
        InvalidFuse = 16,
        /// <summary>A settings field (an enumeration too) is outside its range.</summary>
        InvalidSetting = 17,
        /// <summary>A time is earlier than the previous call's.</summary>
        TimeWentBackwards = 18,
        /// <summary>A dead-reckoning receiver has no update yet.</summary>
        NoUpdate = 19,
        /// <summary>Beyond the precision envelope (a position beyond 1e5 m, a speed above 1e6 m/s).</summary>
        OutOfRange = 20,
        /// <summary>The trajectory needs more points than the buffer holds; the result and the
        /// first points are written (<see cref="ProjectileResult.TrajectoryNeeded"/>).</summary>
        BufferTooSmall = 1000,
        /// <summary>A required argument is null. Nothing is written.</summary>
        NullPointer = 1001,
        /// <summary>Memory ran out while adding a shape; the world is emptied.</summary>
        OutOfMemory = 1002,
        /// <summary>A callback world's cast returned an invalid hit (not bound in C# yet).</summary>
        InvalidCallbackHit = 1003,
        /// <summary>The Embree backend refused a mesh file or a BVH build (not bound in C# yet).</summary>
        BackendFailed = 1004,
    }

    /// <summary>A position [Units: m] in double precision (fs_dvec3). 24 bytes.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 24)]
    public struct DVec3 : IEquatable<DVec3>
    {
        /// <summary>[Units: m]</summary>
        [FieldOffset(0)] public double X;
        /// <summary>[Units: m]</summary>
        [FieldOffset(8)] public double Y;
        /// <summary>[Units: m]</summary>
        [FieldOffset(16)] public double Z;

        /// <summary>A position from its coordinates [Units: m].</summary>
        public DVec3(double x, double y, double z)
        {
            X = x;
            Y = y;
            Z = z;
        }

        /// <summary>The float vector widened (exact).</summary>
        public static implicit operator DVec3(Vector3 v) { return new DVec3(v.X, v.Y, v.Z); }

        /// <summary>Rounded to float [Units: m] (loses precision beyond a few km).</summary>
        public Vector3 ToVector3() { return new Vector3((float)X, (float)Y, (float)Z); }

        /// <summary>True when every coordinate is equal (bitwise equal for non-NaN values).</summary>
        public bool Equals(DVec3 other) { return X == other.X && Y == other.Y && Z == other.Z; }
        /// <summary>See <see cref="Equals(DVec3)"/>.</summary>
        public override bool Equals(object obj) { return obj is DVec3 && Equals((DVec3)obj); }
        /// <summary>A hash of the coordinates.</summary>
        public override int GetHashCode() { return X.GetHashCode() ^ (Y.GetHashCode() * 397) ^ (Z.GetHashCode() * 7919); }
        /// <summary>"(x, y, z)".</summary>
        public override string ToString() { return "(" + X + ", " + Y + ", " + Z + ")"; }
    }

    /// <summary>fs_vec3 passed by value (the C functions taking an fs_vec3 argument): three
    /// floats, kept apart from System.Numerics.Vector3 so that no runtime's SIMD treatment of
    /// Vector3 can change how it is passed.</summary>
    [StructLayout(LayoutKind.Sequential)]
    internal struct Vector3Native
    {
        internal float X, Y, Z;
        internal Vector3Native(Vector3 v)
        {
            X = v.X;
            Y = v.Y;
            Z = v.Z;
        }
    }

    // ---- Characters ------------------------------------------------------------------------

    /// <summary>Position and velocity of a moving point (fs_point_state). 40 bytes: Position 0,
    /// Velocity 24, Reserved 36.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 40)]
    public struct PointState
    {
        /// <summary>[Units: m]</summary>
        [FieldOffset(0)] public DVec3 Position;
        /// <summary>[Units: m/s]</summary>
        [FieldOffset(24)] public Vector3 Velocity;
        /// <summary>Padding: ignored, written as 0.</summary>
        [FieldOffset(36)] public float Reserved;

        /// <summary>A state from a position [Units: m] and a velocity [Units: m/s].</summary>
        public PointState(DVec3 position, Vector3 velocity)
        {
            Position = position;
            Velocity = velocity;
            Reserved = 0;
        }
    }

    // ---- Vehicles --------------------------------------------------------------------------

    /// <summary>The axes of a vehicle's angular velocity (FS_FRAME_*).</summary>
    public enum AngularFrame
    {
        /// <summary>The vehicle's own axes: q' = q r (the reference article).</summary>
        Body = 0,
        /// <summary>World axes: q' = r q.</summary>
        World = 1,
    }

    /// <summary>A vehicle's kinematic state (fs_vehicle_state). 64 bytes: Position 0, Velocity
    /// 24, Orientation 36, AngularVelocity 52.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 64)]
    public struct VehicleState
    {
        /// <summary>[Units: m], world axes.</summary>
        [FieldOffset(0)] public DVec3 Position;
        /// <summary>[Units: m/s], world axes.</summary>
        [FieldOffset(24)] public Vector3 Velocity;
        /// <summary>Local-to-world; non-zero (normalised by the library).</summary>
        [FieldOffset(36)] public Quaternion Orientation;
        /// <summary>[Units: rad/s], in the axes of <see cref="VehicleSettings.Frame"/>.</summary>
        [FieldOffset(52)] public Vector3 AngularVelocity;

        /// <summary>A state from its fields (units as the fields').</summary>
        public VehicleState(DVec3 position, Vector3 velocity, Quaternion orientation, Vector3 angularVelocity)
        {
            Position = position;
            Velocity = velocity;
            Orientation = orientation;
            AngularVelocity = angularVelocity;
        }
    }

    /// <summary>How to read a VehicleState (fs_vehicle_settings). 16 bytes: Frame 0, Forward 4.
    /// <see cref="Vehicles.DefaultSettings"/> gives the defaults (Body, +Z).</summary>
    [StructLayout(LayoutKind.Explicit, Size = 16)]
    public struct VehicleSettings
    {
        /// <summary>The angular velocity's axes (default Body).</summary>
        [FieldOffset(0)] public AngularFrame Frame;
        /// <summary>Local forward axis [Limit: non-zero, finite]; default +Z, Godot's is -Z
        /// (<see cref="Axes.GodotForward"/>).</summary>
        [FieldOffset(4)] public Vector3 Forward;
    }

    // ---- Collision worlds ------------------------------------------------------------------

    /// <summary>A surface's own material (fs_material), used by the Engine method only. 8 bytes:
    /// Restitution 0, Friction 4.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 8)]
    public struct SurfaceMaterial
    {
        /// <summary>[Limit: 0 .. 1, or negative: none]</summary>
        [FieldOffset(0)] public float Restitution;
        /// <summary>[Limit: >= 0, or negative: none]</summary>
        [FieldOffset(4)] public float Friction;
    }

    /// <summary>A one-sided infinite plane dot(Normal, x) = Distance, solid behind (fs_plane).
    /// 24 bytes: Normal 0, Reserved 12, Distance 16.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 24)]
    public struct PlaneShape
    {
        /// <summary>[Limit: non-zero, finite]; normalised when added (Distance with it).</summary>
        [FieldOffset(0)] public Vector3 Normal;
        /// <summary>Padding: ignored.</summary>
        [FieldOffset(12)] public float Reserved;
        /// <summary>dot(Normal, x) on the plane [Units: m with a unit normal].</summary>
        [FieldOffset(16)] public double Distance;
    }

    /// <summary>A solid sphere (fs_sphere). 32 bytes: Center 0, Radius 24, Reserved 28.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 32)]
    public struct SphereShape
    {
        /// <summary>[Units: m]</summary>
        [FieldOffset(0)] public DVec3 Center;
        /// <summary>[Units: m] [Limit: > 0]</summary>
        [FieldOffset(24)] public float Radius;
        /// <summary>Padding: ignored.</summary>
        [FieldOffset(28)] public float Reserved;
    }

    /// <summary>A solid box rotated about its centre (fs_box). 56 bytes: Center 0, HalfExtents
    /// 24, Orientation 36, Rounding 52.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 56)]
    public struct BoxShape
    {
        /// <summary>[Units: m]</summary>
        [FieldOffset(0)] public DVec3 Center;
        /// <summary>Along the box's local axes [Units: m] [Limit: > 0].</summary>
        [FieldOffset(24)] public Vector3 HalfExtents;
        /// <summary>Local-to-world; non-zero.</summary>
        [FieldOffset(36)] public Quaternion Orientation;
        /// <summary>Radius of rounded edges and corners [Units: m] [Limit: 0 .. smallest half extent].</summary>
        [FieldOffset(52)] public float Rounding;
    }

    /// <summary>A two-sided triangle (fs_triangle). 72 bytes: A 0, B 24, C 48.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 72)]
    public struct TriangleShape
    {
        /// <summary>A vertex [Units: m].</summary>
        [FieldOffset(0)] public DVec3 A;
        /// <summary>A vertex [Units: m].</summary>
        [FieldOffset(24)] public DVec3 B;
        /// <summary>A vertex [Units: m].</summary>
        [FieldOffset(48)] public DVec3 C;
    }

    /// <summary>What adding a mesh did (fs_mesh_report). 24 bytes: Triangles 0,
    /// DegenerateTriangles 8, FirstDegenerateTriangle 16.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 24)]
    public struct MeshReport
    {
        /// <summary>Triangles added.</summary>
        [FieldOffset(0)] public ulong Triangles;
        /// <summary>Triangles skipped (no area, or a sliver).</summary>
        [FieldOffset(8)] public ulong DegenerateTriangles;
        /// <summary>0-based index in the mesh of the first skipped one.</summary>
        [FieldOffset(16)] public ulong FirstDegenerateTriangle;
    }

    /// <summary>A cast a callback world answers (fs_segment_cast): a segment, or a sphere swept
    /// along it. 40 bytes: Origin 0, Displacement 24, Radius 36.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 40)]
    public struct SegmentCast
    {
        /// <summary>Start, the sphere's centre [Units: m].</summary>
        [FieldOffset(0)] public DVec3 Origin;
        /// <summary>End minus start [Units: m]; never zero-length.</summary>
        [FieldOffset(24)] public Vector3 Displacement;
        /// <summary>Swept sphere radius [Units: m]; 0 casts a point (a ray).</summary>
        [FieldOffset(36)] public float Radius;
    }

    /// <summary>The first hit of a SegmentCast, filled by a callback world's handler
    /// (fs_cast_hit). Before the call: Fraction 1, Position the segment's end, Normal +Y,
    /// Restitution and Friction -1 (no material of its own). 48 bytes: Fraction 0,
    /// Restitution 4, Position 8, Normal 32, Friction 44.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 48)]
    public struct CastHit
    {
        /// <summary>Where along the segment [Limit: 0 .. 1]: Origin + Fraction * Displacement.</summary>
        [FieldOffset(0)] public float Fraction;
        /// <summary>The surface's own restitution [Limit: 0 .. 1, or negative: none].</summary>
        [FieldOffset(4)] public float Restitution;
        /// <summary>The sphere's centre at the hit [Units: m] [Limit: finite].</summary>
        [FieldOffset(8)] public DVec3 Position;
        /// <summary>Surface normal facing against the motion [Limit: non-zero, finite].</summary>
        [FieldOffset(32)] public Vector3 Normal;
        /// <summary>The surface's own friction [Limit: >= 0, or negative: none].</summary>
        [FieldOffset(44)] public float Friction;
    }

    // ---- Projectiles -----------------------------------------------------------------------

    /// <summary>The projectile integrators (FS_METHOD_*).</summary>
    public enum ProjectileMethod
    {
        /// <summary>Event driven: exact impact times, sliding and resting (default).</summary>
        Exact = 0,
        /// <summary>The reference article's fixed-step loop.</summary>
        Stepped = 1,
        /// <summary>Step for step as the physics engine <see cref="ProjectileSettings.Engine"/>.</summary>
        Engine = 2,
    }

    /// <summary>The engines the Engine method follows (FS_ENGINE_*).</summary>
    public enum PhysicsEngine
    {
        /// <summary>Plain semi-implicit Euler at 60 Hz.</summary>
        Custom = 0,
        /// <summary>Jolt Physics 5 (default).</summary>
        Jolt = 1,
        /// <summary>PhysX 4/5 with Unity's defaults.</summary>
        PhysX = 2,
        /// <summary>Rapier, 4 solver sub-steps.</summary>
        Rapier = 3,
        /// <summary>Bullet's btDiscreteDynamicsWorld.</summary>
        Bullet = 4,
        /// <summary>Godot 3 with GodotPhysics.</summary>
        Godot3 = 5,
        /// <summary>Godot 3 with Bullet.</summary>
        Godot3Bullet = 6,
        /// <summary>Box2D v2.4 (motion in the x-y plane).</summary>
        Box2D = 7,
    }

    /// <summary>How to predict a projectile (fs_projectile_settings). 48 bytes: Method 0,
    /// Gravity 4, Step 16, Restitution 20, Friction 24, Radius 28, MaxBounces 32, MaxSteps 36,
    /// MaxEvents 40, Engine 44. <see cref="Projectiles.DefaultSettings"/> gives the defaults.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 48)]
    public struct ProjectileSettings
    {
        /// <summary>The integrator (default Exact).</summary>
        [FieldOffset(0)] public ProjectileMethod Method;
        /// <summary>[Units: m/s^2], world axes (default (0, -9.81, 0)).</summary>
        [FieldOffset(4)] public Vector3 Gravity;
        /// <summary>Time step [Units: s] [Limit: > 0] (default 0.02).</summary>
        [FieldOffset(16)] public float Step;
        /// <summary>Coefficient of restitution [Limit: 0 .. 1] (default 0.5).</summary>
        [FieldOffset(20)] public float Restitution;
        /// <summary>Coulomb friction [Limit: >= 0] (default 0).</summary>
        [FieldOffset(24)] public float Friction;
        /// <summary>0: a point; > 0: a sphere [Units: m] (default 0).</summary>
        [FieldOffset(28)] public float Radius;
        /// <summary>Bounces allowed; the next impact ends the prediction (default uint.MaxValue).</summary>
        [FieldOffset(32)] public uint MaxBounces;
        /// <summary>Work cap: more steps give TooManySteps (default 1048576).</summary>
        [FieldOffset(36)] public uint MaxSteps;
        /// <summary>Work cap (Exact): impacts and contact changes (default 65536).</summary>
        [FieldOffset(40)] public uint MaxEvents;
        /// <summary>The engine of the Engine method (default Jolt); checked always.</summary>
        [FieldOffset(44)] public PhysicsEngine Engine;
    }

    /// <summary>What a trajectory point marks (FS_EVENT_*).</summary>
    public enum TrajectoryEvent
    {
        /// <summary>The initial state (t = 0).</summary>
        Start = 0,
        /// <summary>A step boundary.</summary>
        Step = 1,
        /// <summary>An impact (velocity after it); has a normal.</summary>
        Bounce = 2,
        /// <summary>Came to rest (Exact only).</summary>
        Rest = 3,
        /// <summary>The prediction stopped at this impact (MaxBounces); has a normal.</summary>
        Hit = 4,
        /// <summary>The final state at the prediction time.</summary>
        End = 5,
    }

    /// <summary>A point of a predicted trajectory (fs_trajectory_point). 56 bytes: Time 0,
    /// Event 4, Position 8, Velocity 32, Normal 44.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 56)]
    public struct TrajectoryPoint
    {
        /// <summary>Since the start [Units: s].</summary>
        [FieldOffset(0)] public float Time;
        /// <summary>What the point marks.</summary>
        [FieldOffset(4)] public TrajectoryEvent Event;
        /// <summary>[Units: m]</summary>
        [FieldOffset(8)] public DVec3 Position;
        /// <summary>[Units: m/s]; after the bounce for Bounce.</summary>
        [FieldOffset(32)] public Vector3 Velocity;
        /// <summary>Surface normal for Bounce and Hit; else zero.</summary>
        [FieldOffset(44)] public Vector3 Normal;
    }

    /// <summary>The outcome of a projectile prediction (fs_projectile_result). 80 bytes:
    /// Position 0, Velocity 24, Time 36, Bounces 40, at_rest 44, stopped_at_hit 48, HitNormal
    /// 52, TrajectorySize 64, TrajectoryNeeded 72.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 80)]
    public struct ProjectileResult
    {
        /// <summary>Final position [Units: m].</summary>
        [FieldOffset(0)] public DVec3 Position;
        /// <summary>Final velocity [Units: m/s].</summary>
        [FieldOffset(24)] public Vector3 Velocity;
        /// <summary>Time reached [Units: s].</summary>
        [FieldOffset(36)] public float Time;
        /// <summary>Bounces applied.</summary>
        [FieldOffset(40)] public uint Bounces;
        [FieldOffset(44)] private int atRest;
        [FieldOffset(48)] private int stoppedAtHit;
        /// <summary>Normal of the last impact (zero if none).</summary>
        [FieldOffset(52)] public Vector3 HitNormal;
        /// <summary>Points written into the buffer.</summary>
        [FieldOffset(64)] public ulong TrajectorySize;
        /// <summary>Points of the whole trajectory; more than TrajectorySize if truncated.</summary>
        [FieldOffset(72)] public ulong TrajectoryNeeded;

        /// <summary>True when (Exact) the projectile came to rest on a surface.</summary>
        public bool AtRest { get { return atRest != 0; } }
        /// <summary>True when the prediction ended at an impact (MaxBounces reached).</summary>
        public bool StoppedAtHit { get { return stoppedAtHit != 0; } }
    }

    // ---- Engine profiles -------------------------------------------------------------------

    /// <summary>Where the damping factor goes in an engine step (FS_DAMPING_ORDER_*).</summary>
    public enum DampingOrder
    {
        /// <summary>v = (v + g dt) d (Jolt, PhysX, Rapier).</summary>
        GravityThenDamping = 0,
        /// <summary>v = v d + g dt (Bullet, Godot 3, Box2D).</summary>
        DampingThenGravity = 1,
    }

    /// <summary>The damping factor d per step for a coefficient c (FS_DAMPING_LAW_*).</summary>
    public enum DampingLaw
    {
        /// <summary>d = 1.</summary>
        None = 0,
        /// <summary>d = max(0, 1 - c dt) (Jolt, PhysX, Godot 3).</summary>
        LinearClamped = 1,
        /// <summary>d = 1 / (1 + c dt) (Rapier, Box2D).</summary>
        Rational = 2,
        /// <summary>d = (1 - min(c, 1))^dt (Bullet).</summary>
        Power = 3,
    }

    /// <summary>How two materials' coefficients combine (FS_COMBINE_*).</summary>
    public enum CombineRule
    {
        /// <summary>(a + b) / 2.</summary>
        Average = 0,
        /// <summary>min(a, b).</summary>
        Min = 1,
        /// <summary>max(a, b).</summary>
        Max = 2,
        /// <summary>a b.</summary>
        Multiply = 3,
        /// <summary>sqrt(a b).</summary>
        GeometricMean = 4,
        /// <summary>clamp(a + b, 0, 1).</summary>
        SumClamped = 5,
    }

    /// <summary>Which velocity a bounce reflects (FS_RESTITUTION_BASE_*).</summary>
    public enum RestitutionBase
    {
        /// <summary>The velocity at the start of the step (Jolt, Rapier, Bullet).</summary>
        StepStart = 0,
        /// <summary>After that step's gravity and damping (PhysX, Godot 3, Box2D).</summary>
        AfterGravity = 1,
    }

    /// <summary>What a body's first step does (FS_FIRST_STEP_*).</summary>
    public enum FirstStep
    {
        /// <summary>Like every other step.</summary>
        Normal = 0,
        /// <summary>p += v dt only (Godot 3 GodotPhysics).</summary>
        NoGravity = 1,
        /// <summary>v = v d; p += v dt (Godot 3 with Bullet).</summary>
        DampingOnly = 2,
    }

    /// <summary>When a contact starts to act (FS_CONTACT_*).</summary>
    public enum ContactModel
    {
        /// <summary>Within ContactDistance at a step's start (most engines).</summary>
        Speculative = 0,
        /// <summary>Once overlapping at a step's start (Godot 3 GodotPhysics).</summary>
        Penetration = 1,
    }

    /// <summary>How an engine steps a sphere and answers its contacts (fs_engine_profile;
    /// engine_profile.h and docs/engines.md explain each field). Start from
    /// <see cref="EngineProfiles.Default"/> and set what the game changes, typically Timestep
    /// (Unity's Time.fixedDeltaTime, Godot's 1 / physics_ticks_per_second) and LinearDamping
    /// (Unity's Rigidbody.drag, Godot's linear_damp). 100 bytes, every field 4 bytes.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 100)]
    public struct EngineProfile
    {
        /// <summary>Which engine the values describe.</summary>
        [FieldOffset(0)] public PhysicsEngine Engine;
        /// <summary>Fixed step [Units: s] [Limit: 1e-5 .. 1].</summary>
        [FieldOffset(4)] public float Timestep;
        /// <summary>Equal sub-steps per step [Limit: 1 .. 64].</summary>
        [FieldOffset(8)] public uint Substeps;
        /// <summary>Where damping goes in a step.</summary>
        [FieldOffset(12)] public DampingOrder Order;
        /// <summary>The damping law.</summary>
        [FieldOffset(16)] public DampingLaw Damping;
        /// <summary>The body's linear damping [Units: 1/s] [Limit: >= 0].</summary>
        [FieldOffset(20)] public float LinearDamping;
        /// <summary>A project default added to it [Units: 1/s] [Limit: >= 0].</summary>
        [FieldOffset(24)] public float AddedLinearDamping;
        /// <summary>[Units: 1/s] [Limit: >= 0].</summary>
        [FieldOffset(28)] public float AngularDamping;
        /// <summary>What the first step does.</summary>
        [FieldOffset(32)] public FirstStep FirstStep;
        /// <summary>No bounce at or below this approach speed [Units: m/s] [Limit: >= 0].</summary>
        [FieldOffset(36)] public float RestitutionThreshold;
        /// <summary>Which velocity a bounce reflects.</summary>
        [FieldOffset(40)] public RestitutionBase RestitutionBase;
        /// <summary>How a surface's own restitution combines.</summary>
        [FieldOffset(44)] public CombineRule RestitutionCombine;
        /// <summary>How a surface's own friction combines.</summary>
        [FieldOffset(48)] public CombineRule FrictionCombine;
        /// <summary>When a contact starts to act.</summary>
        [FieldOffset(52)] public ContactModel Contact;
        /// <summary>Speculative contact distance [Units: m] [Limit: >= 0].</summary>
        [FieldOffset(56)] public float ContactDistance;
        /// <summary>Penetration left alone [Units: m] [Limit: >= 0].</summary>
        [FieldOffset(60)] public float PenetrationSlop;
        /// <summary>Fraction of the penetration removed per step [Limit: 0 .. 1].</summary>
        [FieldOffset(64)] public float PositionCorrection;
        /// <summary>1: the correction is a velocity kept by the body (Bullet, Godot 3); else 0.</summary>
        [FieldOffset(68)] public int CorrectionIsVelocity;
        /// <summary>Bullet's split impulse fraction [Limit: 0 .. 1].</summary>
        [FieldOffset(72)] public float SplitImpulseCorrection;
        /// <summary>Warm-started fraction of friction [Limit: 0 .. 1].</summary>
        [FieldOffset(76)] public float FrictionWarmStart;
        /// <summary>Speed cap [Units: m/s] [Limit: > 0].</summary>
        [FieldOffset(80)] public float MaxLinearSpeed;
        /// <summary>Distance cap per step [Units: m] [Limit: > 0].</summary>
        [FieldOffset(84)] public float MaxStepDistance;
        /// <summary>1: motion in the x-y plane only (Box2D); else 0.</summary>
        [FieldOffset(88)] public int Planar;
        /// <summary>1: a rolling solid sphere; 0: rotation locked.</summary>
        [FieldOffset(92)] public int Rotates;
        /// <summary>1: the world's surfaces are an engine triangle mesh (Bullet); else 0.</summary>
        [FieldOffset(96)] public int TriangleMesh;
    }

    /// <summary>How a game shows a body between its fixed physics steps (FS_RENDER_*).</summary>
    public enum RenderSmoothing
    {
        /// <summary>The last completed step.</summary>
        None = 0,
        /// <summary>Between the last two steps, one step behind (Unity, Godot 4 interpolation).</summary>
        Interpolate = 1,
        /// <summary>The last step moved on with its velocity (Unity's extrapolation).</summary>
        Extrapolate = 2,
    }

    // ---- Aim -------------------------------------------------------------------------------

    /// <summary>What fixes the launch velocity besides meeting the target (FS_AIM_*).</summary>
    public enum AimConstraint
    {
        /// <summary>|velocity| = Speed (low and high arc).</summary>
        Speed = 0,
        /// <summary>The velocity's part across gravity has length Speed.</summary>
        HorizontalSpeed = 1,
        /// <summary>The apex is ApexHeight above the launch point.</summary>
        ApexAboveStart = 2,
        /// <summary>The apex is ApexHeight above the hit point.</summary>
        ApexAboveTarget = 3,
    }

    /// <summary>The shooter and the shot's constraint (fs_aim_shot). 56 bytes: From 0,
    /// Constraint 24, Speed 28, ApexHeight 32, Gravity 36, MaxTime 48, Reserved 52.
    /// <see cref="Aim.DefaultShot"/> gives the defaults.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 56)]
    public struct AimShot
    {
        /// <summary>Launch point [Units: m].</summary>
        [FieldOffset(0)] public DVec3 From;
        /// <summary>The constraint (default Speed).</summary>
        [FieldOffset(24)] public AimConstraint Constraint;
        /// <summary>Launch speed [Units: m/s] for Speed and HorizontalSpeed (default 0).</summary>
        [FieldOffset(28)] public float Speed;
        /// <summary>The apex's height along -gravity [Units: m] for the apex constraints.</summary>
        [FieldOffset(32)] public float ApexHeight;
        /// <summary>[Units: m/s^2], world axes (default (0, -9.81, 0)).</summary>
        [FieldOffset(36)] public Vector3 Gravity;
        /// <summary>Latest flight time reported [Units: s] (default 60).</summary>
        [FieldOffset(48)] public float MaxTime;
        /// <summary>Padding: ignored.</summary>
        [FieldOffset(52)] public float Reserved;
    }

    /// <summary>A target moving as p + v t + a t^2 / 2 (fs_aim_target). 48 bytes: Position 0,
    /// Velocity 24, Acceleration 36.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 48)]
    public struct AimTarget
    {
        /// <summary>At t = 0 [Units: m].</summary>
        [FieldOffset(0)] public DVec3 Position;
        /// <summary>[Units: m/s]</summary>
        [FieldOffset(24)] public Vector3 Velocity;
        /// <summary>[Units: m/s^2]</summary>
        [FieldOffset(36)] public Vector3 Acceleration;
    }

    /// <summary>One way to hit the target (fs_firing_solution). 48 bytes: Velocity 0, Time 12,
    /// Hit 16, Elevation 40, Reserved 44.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 48)]
    public struct FiringSolution
    {
        /// <summary>Launch velocity [Units: m/s].</summary>
        [FieldOffset(0)] public Vector3 Velocity;
        /// <summary>Flight time to the hit [Units: s].</summary>
        [FieldOffset(12)] public float Time;
        /// <summary>Where projectile and target meet [Units: m].</summary>
        [FieldOffset(16)] public DVec3 Hit;
        /// <summary>Launch angle above the plane across gravity [Units: rad].</summary>
        [FieldOffset(40)] public float Elevation;
        /// <summary>Padding: written as 0.</summary>
        [FieldOffset(44)] public float Reserved;
    }

    // ---- Danger ----------------------------------------------------------------------------

    /// <summary>A predicted grenade as a danger (fs_projectile_danger). 12 bytes: FuseTime 0,
    /// BlastRadius 4, ContactRadius 8.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 12)]
    public struct ProjectileDanger
    {
        /// <summary>When it explodes [Units: s] [Limit: >= 0].</summary>
        [FieldOffset(0)] public float FuseTime;
        /// <summary>Radius of the blast around its centre [Units: m] [Limit: >= 0].</summary>
        [FieldOffset(4)] public float BlastRadius;
        /// <summary>Before the fuse, a point this close to the projectile is unsafe; 0: nothing
        /// is dangerous before the fuse [Units: m] [Limit: >= 0].</summary>
        [FieldOffset(8)] public float ContactRadius;
    }

    /// <summary>Where and when a projectile explodes (fs_danger_zone). 32 bytes: Center 0,
    /// Radius 24, Time 28.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 32)]
    public struct DangerZone
    {
        /// <summary>The projectile's position at the fuse time [Units: m].</summary>
        [FieldOffset(0)] public DVec3 Center;
        /// <summary>The blast radius [Units: m].</summary>
        [FieldOffset(24)] public float Radius;
        /// <summary>The fuse time; dangerous from then on [Units: s].</summary>
        [FieldOffset(28)] public float Time;
    }

    /// <summary>When something starts (fs_danger_start). 8 bytes: ever 0, Time 4.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 8)]
    public struct DangerStart
    {
        [FieldOffset(0)] private int ever;
        /// <summary>The earliest time [Units: s] (0 when it never happens).</summary>
        [FieldOffset(4)] public float Time;

        /// <summary>True when it happens, at Time.</summary>
        public bool Ever { get { return ever != 0; } }
    }

    /// <summary>A closest approach (fs_closest_approach). 8 bytes: Distance 0, Time 4.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 8)]
    public struct ClosestApproach
    {
        /// <summary>The smallest distance [Units: m]; for vehicles the separation (negative
        /// when overlapping).</summary>
        [FieldOffset(0)] public float Distance;
        /// <summary>When it happens [Units: s].</summary>
        [FieldOffset(4)] public float Time;
    }

    /// <summary>A vehicle as an oriented box on the exact path of PredictExact
    /// (fs_vehicle_body). 104 bytes: State 0, Settings 64, HalfExtents 80, BoxCenter 92.
    /// <see cref="Danger.DefaultVehicleBody"/> gives the defaults.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 104)]
    public struct VehicleBody
    {
        /// <summary>At t = 0.</summary>
        [FieldOffset(0)] public VehicleState State;
        /// <summary>Frame of the angular velocity, forward axis.</summary>
        [FieldOffset(64)] public VehicleSettings Settings;
        /// <summary>The box, local axes [Units: m] [Limit: each > 0] (default (0.9, 0.7, 2.2)).</summary>
        [FieldOffset(80)] public Vector3 HalfExtents;
        /// <summary>The box's centre from State.Position, local axes [Units: m] (default 0).</summary>
        [FieldOffset(92)] public Vector3 BoxCenter;
    }

    /// <summary>A character: a sphere, or a capsule of constant direction, moving as
    /// p + v t + a t^2 / 2 (fs_character_body). 64 bytes: Position 0, Velocity 24,
    /// Acceleration 36, Radius 48, HalfAxis 52.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 64)]
    public struct CharacterBody
    {
        /// <summary>The centre at t = 0 [Units: m].</summary>
        [FieldOffset(0)] public DVec3 Position;
        /// <summary>[Units: m/s]</summary>
        [FieldOffset(24)] public Vector3 Velocity;
        /// <summary>[Units: m/s^2]</summary>
        [FieldOffset(36)] public Vector3 Acceleration;
        /// <summary>[Units: m] [Limit: >= 0] (default 0.4).</summary>
        [FieldOffset(48)] public float Radius;
        /// <summary>Half of the capsule's inner segment, world axes [Units: m]; zero for a sphere.</summary>
        [FieldOffset(52)] public Vector3 HalfAxis;
    }

    /// <summary>Tolerance and work cap of the vehicle queries (fs_approach_settings). 8 bytes:
    /// Tolerance 0, MaxEvaluations 4.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 8)]
    public struct ApproachSettings
    {
        /// <summary>Distance tolerance [Units: m] [Limit: > 0, finite] (default 1e-3).</summary>
        [FieldOffset(0)] public float Tolerance;
        /// <summary>Separations computed per query at most [Limit: >= 1] (default 65536).</summary>
        [FieldOffset(4)] public uint MaxEvaluations;
    }

    /// <summary>The first contact of a vehicle and a character (fs_vehicle_contact). 16 bytes:
    /// contact 0, Time 4, Separation 8, Evaluations 12.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 16)]
    public struct VehicleContact
    {
        [FieldOffset(0)] private int contact;
        /// <summary>Time of first contact [Units: s], valid when Contact.</summary>
        [FieldOffset(4)] public float Time;
        /// <summary>The separation at Time (at the horizon if none) [Units: m].</summary>
        [FieldOffset(8)] public float Separation;
        /// <summary>Separations computed.</summary>
        [FieldOffset(12)] public uint Evaluations;

        /// <summary>True when they come within the tolerance before the horizon.</summary>
        public bool Contact { get { return contact != 0; } }
    }

    // ---- Throw planning --------------------------------------------------------------------

    /// <summary>Five floats (a C <c>float[5]</c> field). 20 bytes.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 20)]
    public struct Float5
    {
        /// <summary>Element 0.</summary>
        [FieldOffset(0)] public float E0;
        /// <summary>Element 1.</summary>
        [FieldOffset(4)] public float E1;
        /// <summary>Element 2.</summary>
        [FieldOffset(8)] public float E2;
        /// <summary>Element 3.</summary>
        [FieldOffset(12)] public float E3;
        /// <summary>Element 4.</summary>
        [FieldOffset(16)] public float E4;
    }

    /// <summary>Caps on the work of the throw planner (fs_throw_plan_budget). 56 bytes:
    /// AzimuthSamples 0, ElevationSamples 4, SpeedSamples 8, Refinements 12,
    /// RefinementPredictions 16, MaxPredictions 20, MaxTotalSteps 24, GridStep 32,
    /// SeedLandingFractions 36.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 56)]
    public struct ThrowPlanBudget
    {
        /// <summary>Grid: directions around the up axis (default 16).</summary>
        [FieldOffset(0)] public uint AzimuthSamples;
        /// <summary>Grid: elevations from -30 to +75 degrees (default 5).</summary>
        [FieldOffset(4)] public uint ElevationSamples;
        /// <summary>Grid: speeds (default 3).</summary>
        [FieldOffset(8)] public uint SpeedSamples;
        /// <summary>Candidates refined at most [Limit: 1 .. 32] (default 6).</summary>
        [FieldOffset(12)] public uint Refinements;
        /// <summary>Predictions per refinement at most (default 24).</summary>
        [FieldOffset(16)] public uint RefinementPredictions;
        /// <summary>Predictions per call at most (default 400).</summary>
        [FieldOffset(20)] public uint MaxPredictions;
        /// <summary>max_predictions x steps per prediction at most (default 2^24).</summary>
        [FieldOffset(24)] public ulong MaxTotalSteps;
        /// <summary>The grid's time step (Exact) [Units: s] [Limit: >= 0; 0: the request's] (default 0.1).</summary>
        [FieldOffset(32)] public float GridStep;
        /// <summary>Seeds: first landing at these fractions of the fuse time [Limit: (0, 1]; others skipped].</summary>
        [FieldOffset(36)] public Float5 SeedLandingFractions;
    }

    /// <summary>What to plan (fs_throw_plan_request). 176 bytes: Start 0, Target 24,
    /// AcceptanceRadius 48, FuseTime 52, MaxSpeed 56, MinSpeed 60, Settings 64, MaxPlans 112,
    /// DistinctAngle 116, Budget 120. <see cref="ThrowPlanner.DefaultRequest"/> gives the defaults.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 176)]
    public struct ThrowPlanRequest
    {
        /// <summary>Launch position (the sphere's centre) [Units: m].</summary>
        [FieldOffset(0)] public DVec3 Start;
        /// <summary>Where the grenade should be at the fuse time [Units: m].</summary>
        [FieldOffset(24)] public DVec3 Target;
        /// <summary>A plan ends within this of Target [Units: m] [Limit: > 0] (default 0.5).</summary>
        [FieldOffset(48)] public float AcceptanceRadius;
        /// <summary>Launch to blast [Units: s] [Limit: > 0] (default 3).</summary>
        [FieldOffset(52)] public float FuseTime;
        /// <summary>Launch speed cap [Units: m/s] [Limit: > 0] (default 20).</summary>
        [FieldOffset(56)] public float MaxSpeed;
        /// <summary>Lowest launch speed [Units: m/s] [Limit: 0 .. MaxSpeed] (default 0).</summary>
        [FieldOffset(60)] public float MinSpeed;
        /// <summary>The forward model (method, gravity, materials, radius, step, caps).</summary>
        [FieldOffset(64)] public ProjectileSettings Settings;
        /// <summary>Plans wanted [Limit: >= 1] (default 3).</summary>
        [FieldOffset(112)] public uint MaxPlans;
        /// <summary>Plans differ by this angle at least [Units: rad] [Limit: 0 .. pi] (default 0.1).</summary>
        [FieldOffset(116)] public float DistinctAngle;
        /// <summary>Caps on the work.</summary>
        [FieldOffset(120)] public ThrowPlanBudget Budget;
    }

    /// <summary>One throw that works (fs_throw_plan). 88 bytes: LaunchVelocity 0, Distance 12,
    /// FinalPosition 16, Bounces 40, at_rest 44, FirstImpactTime 48, FirstImpactNormal 52,
    /// FirstImpactPosition 64.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 88)]
    public struct ThrowPlan
    {
        /// <summary>[Units: m/s]; speed within [MinSpeed, MaxSpeed].</summary>
        [FieldOffset(0)] public Vector3 LaunchVelocity;
        /// <summary>From the final position to the target [Units: m].</summary>
        [FieldOffset(12)] public float Distance;
        /// <summary>Where the grenade is at the fuse time [Units: m].</summary>
        [FieldOffset(16)] public DVec3 FinalPosition;
        /// <summary>Bounces until the fuse time.</summary>
        [FieldOffset(40)] public uint Bounces;
        [FieldOffset(44)] private int atRest;
        /// <summary>[Units: s]; below 0 when none (or not recorded: scratch too small).</summary>
        [FieldOffset(48)] public float FirstImpactTime;
        /// <summary>Unit normal of the first impact; zero when none.</summary>
        [FieldOffset(52)] public Vector3 FirstImpactNormal;
        /// <summary>[Units: m]; the start when none.</summary>
        [FieldOffset(64)] public DVec3 FirstImpactPosition;

        /// <summary>True when resting on a surface at the fuse time.</summary>
        public bool AtRest { get { return atRest != 0; } }
    }

    /// <summary>What the throw planner did (fs_throw_plan_result). 32 bytes: PlanCount 0,
    /// Predictions 8, ClosestDistance 12, ClosestVelocity 16, Reserved 28.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 32)]
    public struct ThrowPlanResult
    {
        /// <summary>Plans written, closest first.</summary>
        [FieldOffset(0)] public ulong PlanCount;
        /// <summary>Forward predictions run.</summary>
        [FieldOffset(8)] public uint Predictions;
        /// <summary>Closest any tried throw came [Units: m]; float.MaxValue when none finished.</summary>
        [FieldOffset(12)] public float ClosestDistance;
        /// <summary>The launch velocity of that throw [Units: m/s].</summary>
        [FieldOffset(16)] public Vector3 ClosestVelocity;
        /// <summary>Padding: written as 0.</summary>
        [FieldOffset(28)] public float Reserved;
    }

    // ---- Dead reckoning --------------------------------------------------------------------

    /// <summary>The DIS (IEEE 1278.1) dead-reckoning models (FS_DR_*).</summary>
    public enum DeadReckoningAlgorithm
    {
        /// <summary>Does not move or turn.</summary>
        Static = 1,
        /// <summary>Fixed orientation, constant world velocity: p + v t.</summary>
        Fpw = 2,
        /// <summary>Rotating, constant world velocity.</summary>
        Rpw = 3,
        /// <summary>Rotating, constant world acceleration.</summary>
        Rvw = 4,
        /// <summary>Fixed orientation, constant world acceleration: p + v t + a t^2 / 2.</summary>
        Fvw = 5,
        /// <summary>Fixed orientation, constant body velocity.</summary>
        Fpb = 6,
        /// <summary>Rotating, constant body velocity (turns with the body).</summary>
        Rpb = 7,
        /// <summary>Rotating, constant body acceleration.</summary>
        Rvb = 8,
        /// <summary>Fixed orientation, constant body acceleration.</summary>
        Fvb = 9,
    }

    /// <summary>The state an entity last reported (fs_dr_state). 80 bytes: Position 0,
    /// Velocity 24, Acceleration 36, Orientation 48, AngularVelocity 64, Algorithm 76.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 80)]
    public struct DeadReckoningState
    {
        /// <summary>[Units: m], world axes.</summary>
        [FieldOffset(0)] public DVec3 Position;
        /// <summary>[Units: m/s]; world axes (*W models) or body axes (*B models).</summary>
        [FieldOffset(24)] public Vector3 Velocity;
        /// <summary>[Units: m/s^2]; axes as Velocity; used by RVW, FVW, RVB, FVB.</summary>
        [FieldOffset(36)] public Vector3 Acceleration;
        /// <summary>Body-to-world; non-zero.</summary>
        [FieldOffset(48)] public Quaternion Orientation;
        /// <summary>[Units: rad/s], body axes; used by RPW, RVW, RPB, RVB.</summary>
        [FieldOffset(64)] public Vector3 AngularVelocity;
        /// <summary>The model (a value outside 1 to 9 is refused: InvalidAlgorithm).</summary>
        [FieldOffset(76)] public DeadReckoningAlgorithm Algorithm;
    }

    /// <summary>An extrapolated state (fs_dr_result). 56 bytes: Position 0, Velocity 24,
    /// Orientation 36, Reserved 52.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 56)]
    public struct DeadReckoningResult
    {
        /// <summary>[Units: m], world axes.</summary>
        [FieldOffset(0)] public DVec3 Position;
        /// <summary>[Units: m/s], in the input velocity's axes.</summary>
        [FieldOffset(24)] public Vector3 Velocity;
        /// <summary>Body-to-world, unit.</summary>
        [FieldOffset(36)] public Quaternion Orientation;
        /// <summary>Padding: written as 0.</summary>
        [FieldOffset(52)] public float Reserved;
    }

    /// <summary>How a receiver shows a remote entity (FS_DR_MODE_*).</summary>
    public enum ReceiverMode
    {
        /// <summary>The newest update extrapolated to now, with smoothing.</summary>
        Extrapolate = 0,
        /// <summary>InterpolationDelay in the past, between buffered updates.</summary>
        Interpolate = 1,
    }

    /// <summary>How a receiver hides corrections in Extrapolate mode (FS_DR_SMOOTH_*).</summary>
    public enum Smoothing
    {
        /// <summary>Jump to the new update's extrapolation.</summary>
        Snap = 0,
        /// <summary>Blend old to new over BlendTime.</summary>
        LinearBlend = 1,
        /// <summary>Projective velocity blending (default).</summary>
        ProjectiveVelocityBlending = 2,
        /// <summary>The offset decays with half-life DecayHalfLife.</summary>
        ExponentialDecay = 3,
    }

    /// <summary>What a receiver did with an update (FS_DR_ACCEPTED ... FS_DR_TOO_FAR_AHEAD).</summary>
    public enum UpdateOutcome
    {
        /// <summary>Applied, smoothed.</summary>
        Accepted = 0,
        /// <summary>Applied with a snap.</summary>
        Snapped = 1,
        /// <summary>Interpolate mode: stored.</summary>
        Buffered = 2,
        /// <summary>Dropped: older than what is shown.</summary>
        OutOfOrder = 3,
        /// <summary>Dropped: same timestamp as one already received.</summary>
        Duplicate = 4,
        /// <summary>Dropped: NaN or infinite fields, zero quaternion, unknown algorithm.</summary>
        Invalid = 5,
        /// <summary>Dropped: stamped more than MaxFutureSkew after its receive time.</summary>
        TooFarAhead = 6,
    }

    /// <summary>A receiver's settings (fs_dr_receiver_settings). 36 bytes: Mode 0, Smoothing 4,
    /// BlendTime 8, DecayHalfLife 12, TeleportDistance 16, ExtrapolationLimit 20,
    /// InterpolationDelay 24, MaxFutureSkew 28, RestartAfter 32.
    /// <see cref="DeadReckoning.DefaultReceiverSettings"/> gives the defaults.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 36)]
    public struct ReceiverSettings
    {
        /// <summary>Extrapolate (default) or interpolate.</summary>
        [FieldOffset(0)] public ReceiverMode Mode;
        /// <summary>Extrapolate mode's smoothing (default ProjectiveVelocityBlending).</summary>
        [FieldOffset(4)] public Smoothing Smoothing;
        /// <summary>[Units: s] [Limit: > 0, finite] (default 0.2).</summary>
        [FieldOffset(8)] public float BlendTime;
        /// <summary>[Units: s] [Limit: > 0, finite] (default 0.1).</summary>
        [FieldOffset(12)] public float DecayHalfLife;
        /// <summary>[Units: m] [Limit: > 0; infinity disables] (default 10).</summary>
        [FieldOffset(16)] public float TeleportDistance;
        /// <summary>[Units: s] [Limit: >= 0; infinity disables] (default 0.25).</summary>
        [FieldOffset(20)] public float ExtrapolationLimit;
        /// <summary>[Units: s] [Limit: > 0, finite] (default 0.1).</summary>
        [FieldOffset(24)] public float InterpolationDelay;
        /// <summary>[Units: s] [Limit: >= 0; infinity disables] (default 1).</summary>
        [FieldOffset(28)] public float MaxFutureSkew;
        /// <summary>[Units: s] [Limit: > 0; infinity disables] (default 10).</summary>
        [FieldOffset(32)] public float RestartAfter;
    }

    /// <summary>The pose a receiver shows (fs_dr_pose). 56 bytes: Position 0, Velocity 24,
    /// Orientation 36, held 52.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 56)]
    public struct ReceivedPose
    {
        /// <summary>[Units: m], world axes.</summary>
        [FieldOffset(0)] public DVec3 Position;
        /// <summary>[Units: m/s], world axes.</summary>
        [FieldOffset(24)] public Vector3 Velocity;
        /// <summary>Body-to-world, unit.</summary>
        [FieldOffset(36)] public Quaternion Orientation;
        [FieldOffset(52)] private int held;

        /// <summary>True when ExtrapolationLimit stopped the extrapolation.</summary>
        public bool Held { get { return held != 0; } }
    }

    /// <summary>A receiver's counters (fs_dr_receiver_counters). 80 bytes, ten ulongs.</summary>
    [StructLayout(LayoutKind.Explicit, Size = 80)]
    public struct ReceiverCounters
    {
        /// <summary>Updates applied or buffered.</summary>
        [FieldOffset(0)] public ulong Accepted;
        /// <summary>Updates that snapped.</summary>
        [FieldOffset(8)] public ulong Snaps;
        /// <summary>Snaps caused by TeleportDistance.</summary>
        [FieldOffset(16)] public ulong Teleports;
        /// <summary>OutOfOrder updates.</summary>
        [FieldOffset(24)] public ulong OutOfOrder;
        /// <summary>Duplicate updates.</summary>
        [FieldOffset(32)] public ulong Duplicates;
        /// <summary>Invalid updates.</summary>
        [FieldOffset(40)] public ulong Invalid;
        /// <summary>Samples that returned a held pose.</summary>
        [FieldOffset(48)] public ulong Held;
        /// <summary>Updates stamped after their receive time (within MaxFutureSkew).</summary>
        [FieldOffset(56)] public ulong FutureUpdates;
        /// <summary>TooFarAhead updates.</summary>
        [FieldOffset(64)] public ulong TooFarAhead;
        /// <summary>Older updates taken as a sender restart.</summary>
        [FieldOffset(72)] public ulong ClockRestarts;
    }
}
