// Axes and units. foresight uses metres, seconds, radians, +Y up and +Z forward.
//
// Unity: +Y up, +Z forward, left-handed. Its axes are foresight's, so a conversion is a
// component copy (Unity's Quaternion is x, y, z, w like System.Numerics.Quaternion, and a
// rotation about +Y turns +Z towards +X in both):
//     System.Numerics.Vector3 ToNumerics(UnityEngine.Vector3 v) => new System.Numerics.Vector3(v.x, v.y, v.z);
//     UnityEngine.Vector3 ToUnity(System.Numerics.Vector3 v) => new UnityEngine.Vector3(v.X, v.Y, v.Z);
//     UnityEngine.Vector3 ToUnity(Foresight.DVec3 p) => new UnityEngine.Vector3((float)p.X, (float)p.Y, (float)p.Z);
//     System.Numerics.Quaternion ToNumerics(UnityEngine.Quaternion q) => new System.Numerics.Quaternion(q.x, q.y, q.z, q.w);
//
// Godot 4: +Y up, -Z forward, right-handed. Positions, velocities, gravity and quaternions are
// also component copies (Godot's Quaternion is X, Y, Z, W; foresight's formulas do not depend on
// handedness); only a vehicle's forward axis differs: use Vehicles.GodotSettings (forward -Z).
//     System.Numerics.Vector3 ToNumerics(Godot.Vector3 v) => new System.Numerics.Vector3((float)v.X, (float)v.Y, (float)v.Z);
//     Godot.Vector3 ToGodot(System.Numerics.Vector3 v) => new Godot.Vector3(v.X, v.Y, v.Z);
//     System.Numerics.Quaternion ToNumerics(Godot.Quaternion q) => new System.Numerics.Quaternion((float)q.X, (float)q.Y, (float)q.Z, (float)q.W);
//
// UnityConversions and GodotConversions below are those functions as extension methods,
// compiled only inside the engines (UNITY_5_3_OR_NEWER, GODOT), so this file builds without them.

using System.Numerics;

namespace Foresight
{
    /// <summary>The axes foresight, Unity and Godot use (all +Y up, metres).</summary>
    public static class Axes
    {
        /// <summary>Up, in foresight, Unity and Godot: +Y.</summary>
        public static readonly Vector3 Up = new Vector3(0, 1, 0);

        /// <summary>foresight's and Unity's forward: +Z.</summary>
        public static readonly Vector3 Forward = new Vector3(0, 0, 1);

        /// <summary>Godot's forward (a Node3D looks along -Z): use it as a vehicle's forward axis.</summary>
        public static readonly Vector3 GodotForward = new Vector3(0, 0, -1);

        /// <summary>Earth's gravity [Units: m/s^2] along -Y, as foresight's defaults.</summary>
        public static readonly Vector3 Gravity = new Vector3(0, -9.81f, 0);
    }

#if UNITY_5_3_OR_NEWER
    /// <summary>UnityEngine types to and from foresight's (component copies: same axes).</summary>
    public static class UnityConversions
    {
        /// <summary>A Unity vector as System.Numerics.</summary>
        public static Vector3 ToNumerics(this UnityEngine.Vector3 v) { return new Vector3(v.x, v.y, v.z); }
        /// <summary>A Unity position as a foresight position [Units: m].</summary>
        public static DVec3 ToDVec3(this UnityEngine.Vector3 v) { return new DVec3(v.x, v.y, v.z); }
        /// <summary>A Unity rotation as System.Numerics.</summary>
        public static Quaternion ToNumerics(this UnityEngine.Quaternion q) { return new Quaternion(q.x, q.y, q.z, q.w); }
        /// <summary>A System.Numerics vector as Unity's.</summary>
        public static UnityEngine.Vector3 ToUnity(this Vector3 v) { return new UnityEngine.Vector3(v.X, v.Y, v.Z); }
        /// <summary>A foresight position as Unity's (rounded to float).</summary>
        public static UnityEngine.Vector3 ToUnity(this DVec3 p) { return new UnityEngine.Vector3((float)p.X, (float)p.Y, (float)p.Z); }
        /// <summary>A System.Numerics rotation as Unity's.</summary>
        public static UnityEngine.Quaternion ToUnity(this Quaternion q) { return new UnityEngine.Quaternion(q.X, q.Y, q.Z, q.W); }
    }
#endif

#if GODOT
    /// <summary>Godot types to and from foresight's (component copies; vehicles: forward -Z).</summary>
    public static class GodotConversions
    {
        /// <summary>A Godot vector as System.Numerics.</summary>
        public static Vector3 ToNumerics(this Godot.Vector3 v) { return new Vector3((float)v.X, (float)v.Y, (float)v.Z); }
        /// <summary>A Godot position as a foresight position [Units: m].</summary>
        public static DVec3 ToDVec3(this Godot.Vector3 v) { return new DVec3(v.X, v.Y, v.Z); }
        /// <summary>A Godot rotation as System.Numerics.</summary>
        public static Quaternion ToNumerics(this Godot.Quaternion q) { return new Quaternion((float)q.X, (float)q.Y, (float)q.Z, (float)q.W); }
        /// <summary>A System.Numerics vector as Godot's.</summary>
        public static Godot.Vector3 ToGodot(this Vector3 v) { return new Godot.Vector3(v.X, v.Y, v.Z); }
        /// <summary>A foresight position as Godot's.</summary>
        public static Godot.Vector3 ToGodot(this DVec3 p) { return new Godot.Vector3((float)p.X, (float)p.Y, (float)p.Z); }
        /// <summary>A System.Numerics rotation as Godot's.</summary>
        public static Godot.Quaternion ToGodot(this Quaternion q) { return new Godot.Quaternion(q.X, q.Y, q.Z, q.W); }
    }
#endif
}
