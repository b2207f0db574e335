// The C# binding's tests: a console program (no test framework), run by CTest with mono:
//
//   mono BindingTests.exe path/to/include/foresight/foresight_c.h
//
// It checks every binding call against closed forms (p + v t, p + v t + a t^2 / 2, a vehicle's
// circle, a throw's parabola and its impact, the low and high aiming arcs, the dead-reckoning
// models, a receiver's extrapolation limit), bad input (NaN, negative time, null, invalid
// enumerations: the right Status and ForesightException), every struct's size and field
// offsets against the header's layout, that the per-frame calls allocate nothing, and that
// creating and disposing worlds and receivers (or leaving them to the finalizer) does not
// grow the process. Prints each failed check and exits with 1; prints a summary otherwise.

using System;
using System.Collections.Generic;
using System.IO;
using System.Numerics;
using System.Reflection;
using System.Runtime.InteropServices;
using System.Text.RegularExpressions;
using Foresight;

internal static class BindingTests
{
    private static int checks;
    private static int failures;

    // Float results of double computations: the library computes in float (positions rounded
    // to float on the way in), so values of order 1 to 100 carry float rounding, ~1e-7
    // relative per operation; 1e-5 relative leaves room for a few dozen operations.
    private const double Tol = 1e-5;
    private const double G = 9.81;

    private static void Check(bool condition, string what)
    {
        ++checks;
        if (condition) return;
        ++failures;
        Console.Error.WriteLine("check failed: " + what);
    }

    // |actual - expected| <= tolerance * max(1, |expected|)
    private static void Near(double actual, double expected, double tolerance, string what)
    {
        Check(Math.Abs(actual - expected) <= tolerance * Math.Max(1.0, Math.Abs(expected)),
              what + " = " + actual.ToString("R") + ", expected " + expected.ToString("R"));
    }

    private static void Is(Status actual, Status expected, string what)
    {
        Check(actual == expected, what + " returned " + actual + ", expected " + expected);
    }

    private static void Throws(Action action, Status expected, string what)
    {
        try
        {
            action();
            Check(false, what + " did not throw");
        }
        catch (ForesightException e)
        {
            Check(e.Status == expected, what + " threw " + e.Status + ", expected " + expected);
            Check(e.Message.Contains(Library.Message(expected)), what + ": message '" + e.Message + "'");
        }
    }

    private static Vector3 V(double x, double y, double z) { return new Vector3((float)x, (float)y, (float)z); }

    // ---- Layout: every struct against the header -------------------------------------------

    private static readonly Dictionary<string, Type> CTypes = new Dictionary<string, Type> {
        { "fs_vec3", typeof(Vector3) }, { "fs_dvec3", typeof(DVec3) }, { "fs_quat", typeof(Quaternion) },
        { "fs_point_state", typeof(PointState) }, { "fs_vehicle_state", typeof(VehicleState) },
        { "fs_vehicle_settings", typeof(VehicleSettings) }, { "fs_material", typeof(SurfaceMaterial) },
        { "fs_plane", typeof(PlaneShape) }, { "fs_sphere", typeof(SphereShape) }, { "fs_box", typeof(BoxShape) },
        { "fs_triangle", typeof(TriangleShape) }, { "fs_projectile_settings", typeof(ProjectileSettings) },
        { "fs_trajectory_point", typeof(TrajectoryPoint) }, { "fs_projectile_result", typeof(ProjectileResult) },
        { "fs_aim_shot", typeof(AimShot) }, { "fs_aim_target", typeof(AimTarget) },
        { "fs_firing_solution", typeof(FiringSolution) }, { "fs_dr_state", typeof(DeadReckoningState) },
        { "fs_dr_result", typeof(DeadReckoningResult) }, { "fs_dr_receiver_settings", typeof(ReceiverSettings) },
        { "fs_dr_pose", typeof(ReceivedPose) }, { "fs_engine_profile", typeof(EngineProfile) },
        { "fs_projectile_danger", typeof(ProjectileDanger) }, { "fs_danger_zone", typeof(DangerZone) },
        { "fs_danger_start", typeof(DangerStart) }, { "fs_closest_approach", typeof(ClosestApproach) },
        { "fs_vehicle_body", typeof(VehicleBody) }, { "fs_character_body", typeof(CharacterBody) },
        { "fs_approach_settings", typeof(ApproachSettings) },
        { "fs_throw_plan_budget", typeof(ThrowPlanBudget) }, { "fs_throw_plan_request", typeof(ThrowPlanRequest) },
        { "fs_throw_plan", typeof(ThrowPlan) },
        { "fs_mesh_report", typeof(MeshReport) }, { "fs_segment_cast", typeof(SegmentCast) }, { "fs_cast_hit", typeof(CastHit) }, { "fs_throw_plan_result", typeof(ThrowPlanResult) }, { "fs_vehicle_contact", typeof(VehicleContact) }, { "fs_dr_receiver_counters", typeof(ReceiverCounters) },
    };

    private static readonly Dictionary<string, int[]> CFieldTypes = new Dictionary<string, int[]> {
        // size, alignment
        { "float", new[] { 4, 4 } }, { "int32_t", new[] { 4, 4 } }, { "uint32_t", new[] { 4, 4 } },
        { "double", new[] { 8, 8 } }, { "uint64_t", new[] { 8, 8 } }, { "fs_vec3", new[] { 12, 4 } },
        { "fs_quat", new[] { 16, 4 } }, { "fs_dvec3", new[] { 24, 8 } },
    };

    // Parts of the C API the binding does not cover (none now): their structs and functions.
    // Anything added to the header and not listed here fails this test until it is bound.
    private static readonly HashSet<string> NotBoundStructs = new HashSet<string>();
    private static readonly HashSet<string> NotBoundFunctions = new HashSet<string>();

    // Every FS_API function of the header has a P/Invoke declaration (or is listed as not bound).
    private static void TestEntryPoints(string header)
    {
        HashSet<string> declared = new HashSet<string>();
        foreach (MethodInfo m in typeof(Native).GetMethods(BindingFlags.Static | BindingFlags.NonPublic))
        {
            object[] attributes = m.GetCustomAttributes(typeof(DllImportAttribute), false);
            if (attributes.Length == 0) continue;
            string entry = ((DllImportAttribute)attributes[0]).EntryPoint;
            declared.Add(string.IsNullOrEmpty(entry) ? m.Name : entry);
        }
        int functions = 0;
        foreach (Match m in Regex.Matches(header, @"FS_API\s+[^;(]*?\b(fs_\w+)\s*\("))
        {
            string name = m.Groups[1].Value;
            ++functions;
            if (NotBoundFunctions.Contains(name)) Check(!declared.Contains(name), name + " is bound: take it off the list");
            else Check(declared.Contains(name), name + ": no P/Invoke declaration");
        }
        Check(functions >= 40, "functions found in the header: " + functions);
    }

    private static FieldInfo FindField(Type type, string cName)
    {
        string key = cName.Replace("_", "").ToLowerInvariant();
        foreach (FieldInfo f in type.GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic))
            if (f.Name.ToLowerInvariant() == key) return f;
        return null;
    }

    private static void TestLayout(string headerPath)
    {
        string header = File.ReadAllText(headerPath);
        // A struct: its /// comment block, then typedef struct name { body } name;
        Regex structs = new Regex(@"((?:[ \t]*///[^\n]*\n)+)typedef struct (fs_\w+) \{(.*?)\n\} \2;", RegexOptions.Singleline);
        int seen = 0;
        foreach (Match m in structs.Matches(header))
        {
            string comment = Regex.Replace(m.Groups[1].Value, @"[ \t]*///", " ");
            string name = m.Groups[2].Value;
            Type type;
            if (NotBoundStructs.Contains(name))
            {
                Check(!CTypes.ContainsKey(name), name + " is bound: take it off the list");
                continue;
            }
            if (!CTypes.TryGetValue(name, out type))
            {
                Check(false, "no C# type for " + name);
                continue;
            }
            ++seen;
            Match size = Regex.Match(comment, @"(\d+)\s+bytes,\s+alignment\s+(\d+)");
            Check(size.Success, name + ": the header gives no size");
            int csSize = Marshal.SizeOf(type);
            if (size.Success) Check(csSize == int.Parse(size.Groups[1].Value), name + ": C# size " + csSize + ", header " + size.Groups[1].Value);

            // Documented offsets: "a at 0, b at 24" or "a 0, b 4" after the colon.
            Dictionary<string, int> documented = new Dictionary<string, int>();
            int colon = size.Success ? comment.IndexOf(':', size.Index) : -1;
            if (colon >= 0)
            {
                string list = comment.Substring(colon + 1);
                int end = list.IndexOf('.');
                if (end >= 0) list = list.Substring(0, end);
                foreach (Match pair in Regex.Matches(list, @"(\w+)\s+(?:at\s+)?(\d+)"))
                    documented[pair.Groups[1].Value] = int.Parse(pair.Groups[2].Value);
            }

            // The body's fields, laid out by the C rules (natural alignment, in order).
            int offset = 0, maxAlign = 1;
            foreach (string rawLine in m.Groups[3].Value.Split('\n'))
            {
                string line = rawLine;
                int c = line.IndexOf("///", StringComparison.Ordinal);
                if (c >= 0) line = line.Substring(0, c);
                line = line.Trim();
                if (line.Length == 0 || !line.EndsWith(";")) continue;
                line = line.TrimEnd(';');
                int space = line.IndexOf(' ');
                string cType = line.Substring(0, space);
                int[] sa;
                if (!CFieldTypes.TryGetValue(cType, out sa))
                {
                    Check(false, name + ": unknown field type " + cType);
                    continue;
                }
                foreach (string fieldName in line.Substring(space + 1).Split(','))
                {
                    string f = fieldName.Trim();
                    int count = 1;  // a C array field "name[N]": N elements, one C# field of N times the size
                    Match array = Regex.Match(f, @"^(\w+)\[(\d+)\]$");
                    if (array.Success)
                    {
                        f = array.Groups[1].Value;
                        count = int.Parse(array.Groups[2].Value);
                    }
                    offset = (offset + sa[1] - 1) / sa[1] * sa[1];
                    maxAlign = Math.Max(maxAlign, sa[1]);
                    FieldInfo field = FindField(type, f);
                    Check(field != null, name + "." + f + ": no C# field");
                    if (field != null)
                    {
                        int csOffset = (int)Marshal.OffsetOf(type, field.Name);
                        Check(csOffset == offset, name + "." + f + ": C# offset " + csOffset + ", C " + offset);
                        int documentedOffset;
                        if (documented.TryGetValue(f, out documentedOffset))
                            Check(documentedOffset == offset, name + "." + f + ": documented " + documentedOffset + ", C " + offset);
                        Type ft = field.FieldType.IsEnum ? Enum.GetUnderlyingType(field.FieldType) : field.FieldType;
                        Check(Marshal.SizeOf(ft) == sa[0] * count, name + "." + f + ": C# field size " + Marshal.SizeOf(ft));
                    }
                    offset += sa[0] * count;
                }
            }
            offset = (offset + maxAlign - 1) / maxAlign * maxAlign;
            Check(offset == csSize, name + ": C size " + offset + ", C# " + csSize);
            CFieldTypes[name] = new[] { offset, maxAlign };  // for the structs that nest this one
            foreach (string d in documented.Keys)
                Check(FindField(type, d) != null, name + ": documented field " + d + " missing in C#");
        }
        Check(seen == CTypes.Count, "structs in the header: " + seen + ", C# types: " + CTypes.Count);
    }

    // ---- Library, statuses -----------------------------------------------------------------

    private static void TestLibrary()
    {
        Library.EnsureCompatible();
        Check(Library.AbiVersion == Library.ExpectedAbiVersion && Library.IsCompatible, "ABI version");
        Check(Library.Message(Status.Ok) == "ok", "message ok");
        Check(Library.Message(Status.NegativeTime) == "time must be >= 0", "message NegativeTime");
        Check(Library.Message((Status)555) == "unknown status", "message unknown");
        foreach (Status s in Enum.GetValues(typeof(Status)))
            Check(Library.Message(s) != "unknown status" && Library.Message(s).Length > 0, "message of " + s);
        // No P/Invoke takes a C# array of structs: Mono's marshaller copies those in and out on
        // every call (1.7 ms for a 4096-point trajectory); they go as `ref array[0]`. (Byte
        // arrays, for the mesh loader's path and error text, are pinned.)
        foreach (MethodInfo m in typeof(Native).GetMethods(BindingFlags.Static | BindingFlags.NonPublic))
            foreach (ParameterInfo p in m.GetParameters())
                Check(!p.ParameterType.IsArray || p.ParameterType.GetElementType().IsPrimitive,
                      m.Name + "(" + p.Name + ") takes an array of structs");
        // The C API's own NULL check (the binding never passes NULL where one is required).
        Is(Native.fs_predict_linear_raw(IntPtr.Zero, 1.0f, IntPtr.Zero), Status.NullPointer, "fs_predict_linear(NULL)");
    }

    // ---- Characters ------------------------------------------------------------------------

    private static void TestCharacters()
    {
        PointState start = new PointState(new DVec3(1, 2, 3), V(4, -1, 0.5));
        const double t = 1.5;
        PointState r = Characters.PredictLinear(start, (float)t);
        Near(r.Position.X, 1 + 4 * t, Tol, "linear x");
        Near(r.Position.Y, 2 - 1 * t, Tol, "linear y");
        Near(r.Position.Z, 3 + 0.5 * t, Tol, "linear z");
        Check(r.Velocity == V(4, -1, 0.5) && r.Reserved == 0, "linear velocity");

        Vector3 a = V(0, -G, 2);
        r = Characters.PredictAccelerated(start, a, (float)t);
        Near(r.Position.X, 1 + 4 * t, Tol, "accelerated x");
        Near(r.Position.Y, 2 - t - G * t * t / 2, Tol, "accelerated y");
        Near(r.Position.Z, 3 + 0.5 * t + 2 * t * t / 2, Tol, "accelerated z");
        Near(r.Velocity.Y, -1 - G * t, Tol, "accelerated vy");
        Near(r.Velocity.Z, 0.5 + 2 * t, Tol, "accelerated vz");

        PointState untouched;
        Is(Characters.TryPredictLinear(start, -1, out untouched), Status.NegativeTime, "linear(-1)");
        Check(untouched.Position.X == 0 && untouched.Velocity == Vector3.Zero, "refused result is default");
        Is(Characters.TryPredictLinear(start, float.NaN, out untouched), Status.NonFiniteInput, "linear(NaN)");
        PointState nan = start;
        nan.Position.Y = double.NaN;
        Is(Characters.TryPredictLinear(nan, 1, out untouched), Status.NonFiniteInput, "linear(NaN position)");
        Is(Characters.TryPredictAccelerated(start, V(0, float.NaN, 0), 1, out untouched), Status.NonFiniteInput,
           "accelerated(NaN)");
        Is(Characters.TryPredictAccelerated(start, a, -0.1f, out untouched), Status.NegativeTime, "accelerated(-0.1)");
        Throws(() => Characters.PredictLinear(start, -1), Status.NegativeTime, "PredictLinear(-1)");
        Throws(() => Characters.PredictAccelerated(start, a, float.PositiveInfinity), Status.NonFiniteInput,
               "PredictAccelerated(inf)");
    }

    // ---- Vehicles --------------------------------------------------------------------------

    private static void TestVehicles()
    {
        VehicleSettings d = Vehicles.DefaultSettings;
        Check(d.Frame == AngularFrame.Body && d.Forward == Axes.Forward, "vehicle defaults");
        Check(Vehicles.GodotSettings.Forward == Axes.GodotForward, "Godot forward");

        // 10 m/s along +Z turning at 0.5 rad/s about +Y for 2 s: a circle of radius 20 m,
        // heading angle 1 rad: position (r (1 - cos 1), 0, r sin 1), velocity 10 (sin 1, 0, cos 1).
        VehicleState start = new VehicleState(new DVec3(0, 0, 0), V(0, 0, 10), Quaternion.Identity, V(0, 0.5, 0));
        VehicleState e = Vehicles.PredictExact(start, 2, d);
        Near(e.Position.X, 20 * (1 - Math.Cos(1)), Tol, "arc x");
        Near(e.Position.Z, 20 * Math.Sin(1), Tol, "arc z");
        Near(e.Position.Y, 0, Tol, "arc y");
        Near(e.Velocity.X, 10 * Math.Sin(1), Tol, "arc vx");
        Near(e.Velocity.Z, 10 * Math.Cos(1), Tol, "arc vz");
        Near(e.Orientation.Y, Math.Sin(0.5), Tol, "arc q.y");
        Near(e.Orientation.W, Math.Cos(0.5), Tol, "arc q.w");

        // The article's 4-step loop: each step moves then turns by w t / 4 = 0.25 rad, so the
        // position is the sum of 5 (sin(0.25 k), 0, cos(0.25 k)) for k = 0..3.
        VehicleState it = Vehicles.PredictIterative(start, 2, 4, d);
        double sx = 0, sz = 0;
        for (int k = 0; k < 4; ++k)
        {
            sx += 5 * Math.Sin(0.25 * k);
            sz += 5 * Math.Cos(0.25 * k);
        }
        Near(it.Position.X, sx, Tol, "iterative x");
        Near(it.Position.Z, sz, Tol, "iterative z");
        Near(it.Velocity.X, 10 * Math.Sin(1), Tol, "iterative vx");

        // Godot: forward -Z, moving along it; turning about +Y turns -Z towards -X:
        // position r (-(1 - cos 1), 0, -sin 1).
        VehicleState godot = new VehicleState(new DVec3(0, 0, 0), V(0, 0, -10), Quaternion.Identity, V(0, 0.5, 0));
        VehicleState ge = Vehicles.PredictExact(godot, 2, Vehicles.GodotSettings);
        Near(ge.Position.X, -20 * (1 - Math.Cos(1)), Tol, "Godot arc x");
        Near(ge.Position.Z, -20 * Math.Sin(1), Tol, "Godot arc z");

        VehicleState r;
        Is(Vehicles.TryPredictExact(start, -1, d, out r), Status.NegativeTime, "exact(-1)");
        Is(Vehicles.TryPredictIterative(start, 1, 0, d, out r), Status.InvalidIterations, "iterative(0 iterations)");
        VehicleSettings bad = d;
        bad.Frame = (AngularFrame)7;
        Is(Vehicles.TryPredictExact(start, 1, bad, out r), Status.InvalidSetting, "exact(frame 7)");
        bad = d;
        bad.Forward = Vector3.Zero;
        Is(Vehicles.TryPredictExact(start, 1, bad, out r), Status.ZeroVector, "exact(zero forward)");
        VehicleState zero = start;
        zero.Orientation = new Quaternion(0, 0, 0, 0);
        Is(Vehicles.TryPredictIterative(zero, 1, 4, d, out r), Status.ZeroQuaternion, "iterative(zero quaternion)");
        zero = start;
        zero.AngularVelocity.X = float.NaN;
        Is(Vehicles.TryPredictExact(zero, 1, d, out r), Status.NonFiniteInput, "exact(NaN)");
        Throws(() => Vehicles.PredictIterative(start, float.NaN, 4, d), Status.NonFiniteInput, "PredictIterative(NaN)");
        Throws(() => Vehicles.PredictExact(start, 1, bad), Status.ZeroVector, "PredictExact(zero forward)");
    }

    // ---- Worlds and projectiles ------------------------------------------------------------

    private static double ImpactTime(double y0, double vy, double height)
    {
        double a = 0.5 * G, c = height - y0;
        return (vy + Math.Sqrt(vy * vy - 4 * a * c)) / (2 * a);
    }

    private static void TestWorld()
    {
        using (World w = new World())
        {
            Is(w.TryAddPlane(new PlaneShape { Normal = Axes.Up }), Status.Ok, "add plane");
            Is(w.TryAddPlane(new PlaneShape { Normal = Axes.Up, Distance = 1 }, new SurfaceMaterial { Restitution = 0.3f, Friction = -1 }),
               Status.Ok, "add plane with material");
            Is(w.TryAddPlane(new PlaneShape { Normal = Vector3.Zero }), Status.ZeroVector, "add zero plane");
            Is(w.TryAddPlane(new PlaneShape { Normal = Axes.Up }, new SurfaceMaterial { Restitution = 2 }), Status.InvalidRestitution,
               "add plane restitution 2");
            Is(w.TryAddSphere(new SphereShape { Center = new DVec3(0, 1, 0), Radius = 1 }), Status.Ok, "add sphere");
            Is(w.TryAddSphere(new SphereShape { Center = new DVec3(0, 1, 0), Radius = 1 }, new SurfaceMaterial { Restitution = 0.1f }),
               Status.Ok, "add sphere with material");
            Is(w.TryAddSphere(new SphereShape { Center = new DVec3(0, 1, 0), Radius = 0 }), Status.InvalidRadius, "add sphere r 0");
            Is(w.TryAddSphere(new SphereShape { Center = new DVec3(double.NaN, 1, 0), Radius = 1 }), Status.NonFiniteInput,
               "add NaN sphere");
            BoxShape box = new BoxShape { Center = new DVec3(0, 1, 0), HalfExtents = V(1, 1, 1), Orientation = Quaternion.Identity };
            Is(w.TryAddBox(box), Status.Ok, "add box");
            Is(w.TryAddBox(box, new SurfaceMaterial { Restitution = 0.2f, Friction = 0.3f }), Status.Ok, "add box with material");
            BoxShape flat = box;
            flat.HalfExtents = V(1, 0, 1);
            Is(w.TryAddBox(flat), Status.DegenerateShape, "add flat box");
            BoxShape spun = box;
            spun.Orientation = new Quaternion(0, 0, 0, 0);
            Is(w.TryAddBox(spun), Status.ZeroQuaternion, "add box zero quaternion");
            TriangleShape tri = new TriangleShape { A = new DVec3(0, 0, 0), B = new DVec3(1, 0, 0), C = new DVec3(0, 0, 1) };
            Is(w.TryAddTriangle(tri), Status.Ok, "add triangle");
            Is(w.TryAddTriangle(tri, new SurfaceMaterial { Restitution = 0.5f }), Status.Ok, "add triangle with material");
            TriangleShape line = tri;
            line.C = new DVec3(2, 0, 0);
            Is(w.TryAddTriangle(line), Status.DegenerateShape, "add degenerate triangle");
            w.AddPlane(Axes.Up, -5);
            w.AddSphere(new DVec3(0, -5, 0), 0.5f);
            w.AddBox(new DVec3(0, -5, 0), V(1, 1, 1), Quaternion.Identity);
            w.AddTriangle(new DVec3(0, -6, 0), new DVec3(1, -6, 0), new DVec3(0, -6, 1));
            Throws(() => w.AddPlane(Vector3.Zero, 0), Status.ZeroVector, "AddPlane(zero)");
            Throws(() => w.AddSphere(new DVec3(0, 0, 0), -1), Status.InvalidRadius, "AddSphere(-1)");
            Throws(() => w.AddBox(new DVec3(0, 0, 0), V(0, 1, 1), Quaternion.Identity), Status.DegenerateShape, "AddBox(flat)");
            Throws(() => w.AddTriangle(new DVec3(0, 0, 0), new DVec3(0, 0, 0), new DVec3(0, 0, 0)), Status.DegenerateShape,
                   "AddTriangle(point)");
            Check(!w.IsDisposed, "world alive");
        }
        World disposed = new World();
        disposed.Dispose();
        disposed.Dispose();  // idempotent
        Check(disposed.IsDisposed, "world disposed");
        bool threw = false;
        try
        {
            disposed.TryAddPlane(new PlaneShape { Normal = Axes.Up });
        }
        catch (ObjectDisposedException)
        {
            threw = true;
        }
        Check(threw, "a disposed world throws ObjectDisposedException");
    }

    private static void TestProjectiles()
    {
        ProjectileSettings s = Projectiles.DefaultSettings;
        Check(s.Method == ProjectileMethod.Exact && s.Gravity == V(0, -9.81, 0) && s.Step == 0.02f, "projectile defaults");
        Check(s.Restitution == 0.5f && s.Friction == 0 && s.Radius == 0 && s.MaxBounces == uint.MaxValue, "defaults 2");
        Check(s.MaxSteps == 1048576 && s.MaxEvents == 65536 && s.Engine == PhysicsEngine.Jolt, "defaults 3");
        Check(Projectiles.TrajectoryCapacity(1.2f, s) == 60 + 3 + 128, "capacity");
        Check(Projectiles.TrajectoryCapacity(-1, s) == 0, "capacity(-1)");

        // Free flight: p + v t + g t^2 / 2, a point every 0.02 s.
        TrajectoryPoint[] points = new TrajectoryPoint[256];
        DVec3 p = new DVec3(1, 2, -3);
        Vector3 v = V(4, 6, 1.5);
        const double t = 1.2;
        foreach (ProjectileMethod method in new[] { ProjectileMethod.Exact, ProjectileMethod.Stepped })
        {
            s.Method = method;
            ProjectileResult r = Projectiles.Predict(p, v, (float)t, s, null, points);
            Near(r.Time, t, Tol, method + " time");
            Near(r.Position.X, 1 + 4 * t, Tol, method + " x");
            Near(r.Position.Y, 2 + 6 * t - G * t * t / 2, Tol, method + " y");
            Near(r.Position.Z, -3 + 1.5 * t, Tol, method + " z");
            Near(r.Velocity.Y, 6 - G * t, Tol, method + " vy");
            Check(r.Bounces == 0 && !r.AtRest && !r.StoppedAtHit, method + " no bounce");
            Check(r.TrajectorySize == 61 && r.TrajectoryNeeded == 61, method + " 61 points");
            Check(points[0].Event == TrajectoryEvent.Start && points[0].Position.Equals(p), method + " start point");
            Check(points[60].Event == TrajectoryEvent.End, method + " end point");
            for (int i = 1; i < 61; ++i)
            {
                double ti = points[i].Time;
                Near(ti, 0.02 * i, Tol, method + " point time");
                Near(points[i].Position.Y, 2 + 6 * ti - G * ti * ti / 2, Tol, method + " point y");
            }
        }
        s.Method = ProjectileMethod.Exact;
        ProjectileResult noTrajectory;
        Is(Projectiles.TryPredict(p, v, (float)t, s, null, out noTrajectory), Status.Ok, "no trajectory");
        Check(noTrajectory.TrajectorySize == 0 && noTrajectory.TrajectoryNeeded == 61, "no trajectory: needed 61");

        // A floor: the first impact at the parabola's root, then the vertical speed halved.
        using (World world = new World())
        {
            world.AddPlane(Axes.Up, 0);
            double root = ImpactTime(2, 5, 0);
            s.MaxBounces = 0;
            ProjectileResult hit = Projectiles.Predict(new DVec3(0, 2, 0), V(3, 5, 0), 5, s, world, points);
            Check(hit.StoppedAtHit && hit.Bounces == 0, "stopped at hit");
            Near(hit.Time, root, Tol, "impact time");
            Near(hit.Position.X, 3 * root, Tol, "impact x");
            Near(hit.Position.Y, 0, Tol, "impact y");
            Check(hit.HitNormal == Axes.Up, "impact normal");
            Check(points[(int)hit.TrajectorySize - 1].Event == TrajectoryEvent.Hit, "hit point");
            s.MaxBounces = uint.MaxValue;
            ProjectileResult bounced = Projectiles.Predict(new DVec3(0, 2, 0), V(3, 5, 0), 2, s, world, points);
            Check(bounced.Bounces >= 1, "bounced");
            int b = Array.FindIndex(points, q => q.Event == TrajectoryEvent.Bounce);
            Check(b > 0, "a bounce point");
            if (b > 0)
            {
                Near(points[b].Time, root, Tol, "bounce time");
                Near(points[b].Velocity.Y, -0.5 * (5 - G * root), Tol, "bounce vy");
                Check(points[b].Normal == Axes.Up, "bounce normal");
            }
            // Every engine runs and bounces.
            s.Method = ProjectileMethod.Engine;
            foreach (PhysicsEngine engine in Enum.GetValues(typeof(PhysicsEngine)))
            {
                s.Engine = engine;
                ProjectileResult r = Projectiles.Predict(new DVec3(0, 2, 0), V(3, 5, 0), 2, s, world, points);
                Check(r.Bounces >= 1 && r.Position.Y > -0.1, "engine " + engine);
            }
            s = Projectiles.DefaultSettings;

            // A short buffer: BufferTooSmall, the result and the first points written.
            TrajectoryPoint[] few = new TrajectoryPoint[4];
            ProjectileResult truncated;
            Is(Projectiles.TryPredict(new DVec3(0, 2, 0), V(3, 5, 0), 2, s, world, few, out truncated),
               Status.BufferTooSmall, "short buffer");
            Check(truncated.TrajectorySize == 4 && truncated.TrajectoryNeeded > 4, "truncated sizes");
            Check(few[0].Event == TrajectoryEvent.Start && truncated.Bounces >= 1, "truncated content");
            Throws(() => Projectiles.Predict(new DVec3(0, 2, 0), V(3, 5, 0), 2, s, world, few), Status.BufferTooSmall,
                   "Predict(short buffer)");

#if FORESIGHT_SPAN
            // A Span over part of an array: the points land in that part.
            TrajectoryPoint[] big = new TrajectoryPoint[300];
            ProjectileResult sr;
            Is(Projectiles.TryPredict(new DVec3(0, 2, 0), V(3, 5, 0), 1, s, world, new Span<TrajectoryPoint>(big, 10, 200), out sr),
               Status.Ok, "span");
            Check(sr.TrajectorySize > 2 && big[10].Event == TrajectoryEvent.Start && big[9].Time == 0 &&
                  big[9].Event == TrajectoryEvent.Start && big[10 + (int)sr.TrajectorySize - 1].Event == TrajectoryEvent.End,
                  "span slice written");
            Check(big[10 + (int)sr.TrajectorySize].Time == 0, "nothing written past the trajectory");
            Is(Projectiles.TryPredict(new DVec3(0, 2, 0), V(3, 5, 0), 1, s, world, Span<TrajectoryPoint>.Empty, out sr),
               Status.Ok, "empty span");
            Check(sr.TrajectorySize == 0 && sr.TrajectoryNeeded > 2, "empty span: no trajectory");
            Is(Projectiles.TryPredict(new DVec3(0, 2, 0), V(3, 5, 0), 1, s, world, new Span<TrajectoryPoint>(big, 0, 2), out sr),
               Status.BufferTooSmall, "short span");
#endif

            // Refusals.
            ProjectileResult r2;
            Is(Projectiles.TryPredict(p, v, -1, s, world, points, out r2), Status.NegativeTime, "projectile(-1)");
            Check(r2.TrajectorySize == 0 && r2.Position.X == 0, "refused result is default");
            Is(Projectiles.TryPredict(p, V(float.NaN, 0, 0), 1, s, world, points, out r2), Status.NonFiniteInput, "projectile(NaN)");
            Is(Projectiles.TryPredict(new DVec3(2e5, 0, 0), v, 1, s, world, points, out r2), Status.OutOfRange, "projectile(2e5 m)");
            ProjectileSettings bad = s;
            bad.Method = (ProjectileMethod)3;
            Is(Projectiles.TryPredict(p, v, 1, bad, world, points, out r2), Status.InvalidSetting, "method 3");
            bad = s;
            bad.Engine = (PhysicsEngine)(-1);
            Is(Projectiles.TryPredict(p, v, 1, bad, world, points, out r2), Status.InvalidSetting, "engine -1");
            bad = s;
            bad.Step = 0;
            Is(Projectiles.TryPredict(p, v, 1, bad, world, points, out r2), Status.InvalidStep, "step 0");
            bad = s;
            bad.Restitution = 1.5f;
            Is(Projectiles.TryPredict(p, v, 1, bad, world, points, out r2), Status.InvalidRestitution, "restitution 1.5");
            bad = s;
            bad.Friction = -1;
            Is(Projectiles.TryPredict(p, v, 1, bad, world, points, out r2), Status.InvalidFriction, "friction -1");
            bad = s;
            bad.Radius = -1;
            Is(Projectiles.TryPredict(p, v, 1, bad, world, points, out r2), Status.InvalidRadius, "radius -1");
            bad = s;
            bad.Method = ProjectileMethod.Stepped;
            bad.MaxSteps = 10;
            Is(Projectiles.TryPredict(p, v, 1, bad, world, points, out r2), Status.TooManySteps, "max steps 10");
            Throws(() => Projectiles.Predict(p, v, float.NaN, s, world), Status.NonFiniteInput, "Predict(NaN)");
        }
    }

    // ---- Engine profiles -------------------------------------------------------------------

    private static void TestEngineProfiles()
    {
        foreach (PhysicsEngine engine in Enum.GetValues(typeof(PhysicsEngine)))
        {
            EngineProfile d = EngineProfiles.Default(engine);
            Check(d.Engine == engine && d.Timestep > 0 && d.Substeps >= 1, "profile default " + engine);
            Is(EngineProfiles.Validate(d), Status.Ok, "validate default " + engine);
        }
        EngineProfile ammo = EngineProfiles.AmmoJs();
        Check(ammo.Engine == PhysicsEngine.Bullet && ammo.RestitutionThreshold == 0 && ammo.FrictionWarmStart == 0.85f &&
                  ammo.SplitImpulseCorrection == 0.8f,
              "profile AmmoJs");
        // The Custom profile is plain semi-implicit Euler: after n steps of dt,
        // v = v0 + g n dt and p = p0 + v0 n dt + g dt^2 n (n + 1) / 2.
        EngineProfile custom = EngineProfiles.Default(PhysicsEngine.Custom);
        custom.Timestep = 0.01f;
        Check(custom.Damping == DampingLaw.None || custom.LinearDamping == 0, "Custom: no damping");
        ProjectileSettings s = Projectiles.DefaultSettings;
        s.Method = ProjectileMethod.Engine;
        TrajectoryPoint[] points = new TrajectoryPoint[EngineProfiles.TrajectoryCapacity(1, s, custom)];
        Check(points.Length >= 101, "capacity with profile " + points.Length);
        ProjectileResult r = EngineProfiles.Predict(new DVec3(0, 10, 0), V(2, 3, 0), 1, s, custom, null, points);
        int n = (int)Math.Round(r.Time / 0.01);
        double dt = custom.Timestep;
        Check(r.TrajectorySize == (ulong)n + 1 && n == 100, "one point per step: " + r.TrajectorySize);
        // Float accumulation over 100 steps: a few float ulps per step at values near 10.
        Near(r.Position.Y, 10 + 3 * n * dt - G * dt * dt * n * (n + 1) / 2, 1e-5, "Euler y");
        Near(r.Position.X, 2 * n * dt, 1e-5, "Euler x");
        Near(r.Velocity.Y, 3 - G * n * dt, 1e-5, "Euler vy");
        // Jolt's default profile gives what the Jolt engine name gives, bit for bit.
        using (World world = new World())
        {
            world.AddPlane(Axes.Up, 0);
            s.Engine = PhysicsEngine.Jolt;
            ProjectileResult byName = Projectiles.Predict(new DVec3(0, 2, 0), V(3, 5, 0), 2, s, world);
            ProjectileResult byProfile =
                EngineProfiles.Predict(new DVec3(0, 2, 0), V(3, 5, 0), 2, s, EngineProfiles.Default(PhysicsEngine.Jolt), world);
            Check(byName.Position.Equals(byProfile.Position) && byName.Velocity == byProfile.Velocity &&
                  byName.Bounces == byProfile.Bounces, "profile Jolt == engine Jolt");
        }
        // Refusals.
        EngineProfile bad = custom;
        bad.Timestep = 0;
        Is(EngineProfiles.Validate(bad), Status.InvalidStep, "timestep 0");
        bad = custom;
        bad.Substeps = 0;
        Is(EngineProfiles.Validate(bad), Status.InvalidSetting, "substeps 0");
        bad = custom;
        bad.Order = (DampingOrder)5;
        Is(EngineProfiles.Validate(bad), Status.InvalidSetting, "order 5");
        bad = custom;
        bad.LinearDamping = float.NaN;
        Is(EngineProfiles.Validate(bad), Status.NonFiniteInput, "damping NaN");
        ProjectileResult no;
        Is(EngineProfiles.TryPredict(new DVec3(0, 2, 0), V(3, 5, 0), 1, s, bad, null, points, out no), Status.NonFiniteInput,
           "predict with a NaN profile");
        Throws(() => EngineProfiles.Predict(new DVec3(0, 2, 0), V(3, 5, 0), -1, s, custom), Status.NegativeTime,
               "Predict with profile (-1)");
        Check(EngineProfiles.TrajectoryCapacity(-1, s, custom) == 0, "capacity with profile (-1)");

        // Rendered position: None shows the last completed step; Interpolate lies between the
        // two steps before the render time.
        int count = (int)r.TrajectorySize;
        DVec3 shown = EngineProfiles.RenderedPosition(points, count, 0.01f, 0.505f, RenderSmoothing.None);
        Check(shown.Equals(points[50].Position), "render None = step 50");
        shown = EngineProfiles.RenderedPosition(points, count, 0.01f, 0.505f, RenderSmoothing.Interpolate);
        Check(shown.Y <= Math.Max(points[49].Position.Y, points[50].Position.Y) + 1e-9 &&
              shown.Y >= Math.Min(points[49].Position.Y, points[50].Position.Y) - 1e-9 && shown.X > points[49].Position.X &&
              shown.X < points[50].Position.X, "render Interpolate between steps 49 and 50");
        shown = EngineProfiles.RenderedPosition(points, count, 0.01f, 0.505f, RenderSmoothing.Extrapolate);
        Near(shown.X, points[50].Position.X + points[50].Velocity.X * 0.005, Tol, "render Extrapolate x");
        DVec3 p;
        Is(EngineProfiles.TryRenderedPosition(points, 0, 0.01f, 0.5f, RenderSmoothing.None, out p), Status.InvalidStep, "no points");
        Is(EngineProfiles.TryRenderedPosition(null, 5, 0.01f, 0.5f, RenderSmoothing.None, out p), Status.InvalidStep, "null points");
        Is(EngineProfiles.TryRenderedPosition(points, count, 0, 0.5f, RenderSmoothing.None, out p), Status.InvalidStep, "step 0");
        Is(EngineProfiles.TryRenderedPosition(points, count, 0.01f, float.NaN, RenderSmoothing.None, out p),
           Status.NonFiniteInput, "render NaN");
        Is(EngineProfiles.TryRenderedPosition(points, count, 0.01f, 0.5f, (RenderSmoothing)7, out p), Status.InvalidSetting,
           "smoothing 7");
        Throws(() => EngineProfiles.RenderedPosition(points, count, -1, 0.5f, RenderSmoothing.None), Status.InvalidStep,
               "RenderedPosition(step -1)");
    }

    // ---- Danger ----------------------------------------------------------------------------

    private static void TestDanger()
    {
        // Free flight from (0, 10, 0) at (2, 0, 0) for 2 s: p(t) = (2 t, 10 - g t^2 / 2, 0).
        TrajectoryPoint[] points = new TrajectoryPoint[256];
        ProjectileResult r = Projectiles.Predict(new DVec3(0, 10, 0), V(2, 0, 0), 2, Projectiles.DefaultSettings, null, points);
        int n = (int)r.TrajectorySize;
        DVec3 p = Danger.PositionOnTrajectory(points, n, 1.01f);
        double t = 1.01f;
        Near(p.X, 2 * t, Tol, "position on trajectory x");
        Near(p.Y, 10 - G * t * t / 2, Tol, "position on trajectory y");
        ProjectileDanger grenade = new ProjectileDanger { FuseTime = 1.5f, BlastRadius = 3, ContactRadius = 0 };
        DangerZone zone = Danger.ComputeDangerZone(points, n, grenade);
        Near(zone.Center.X, 3, Tol, "zone x");
        Near(zone.Center.Y, 10 - G * 1.5 * 1.5 / 2, Tol, "zone y");
        Check(zone.Radius == 3 && zone.Time == 1.5f, "zone radius and time");
        Check(!Danger.IsPointSafe(points, n, grenade, zone.Center, 1.6f), "the centre after the fuse is unsafe");
        Check(Danger.IsPointSafe(points, n, grenade, zone.Center, 1.4f), "the centre before the fuse is safe");
        Check(Danger.IsPointSafe(points, n, grenade, new DVec3(100, 0, 0), 1.6f), "far away is safe");
        DangerStart start = Danger.FindDangerStart(points, n, grenade, zone.Center);
        Check(start.Ever && start.Time == 1.5f, "danger starts at the fuse: " + start.Time);
        Check(!Danger.FindDangerStart(points, n, grenade, new DVec3(100, 0, 0)).Ever, "never dangerous far away");
        // The path passes (2, 10 - g/2, 0) at t = 1; a point 0.5 m beside it along z.
        DVec3 beside = new DVec3(2, 10 - G / 2, 0.5);
        ClosestApproach closest = Danger.FindClosestPathApproach(points, n, beside, 0, 2);
        Near(closest.Distance, 0.5, 1e-4, "closest distance");  // float positions near 10 m, 1e-6 relative
        Near(closest.Time, 1, 1e-3, "closest time");  // a flat minimum: the time is found to ~sqrt(float eps)
        DangerStart approach = Danger.FindPathApproach(points, n, beside, 0.6f, 0, 2);
        Check(approach.Ever && approach.Time < 1 && approach.Time > 0.9f, "within 0.6 m shortly before t = 1: " + approach.Time);
        Check(!Danger.FindPathApproach(points, n, beside, 0.4f, 0, 2).Ever, "never within 0.4 m");
        DVec3 q;
        Is(Danger.TryPositionOnTrajectory(points, 0, 1, out q), Status.InvalidStep, "no points");
        Is(Danger.TryPositionOnTrajectory(null, 3, 1, out q), Status.InvalidStep, "null trajectory");
        Is(Danger.TryPositionOnTrajectory(points, n, float.NaN, out q), Status.NonFiniteInput, "position(NaN)");
        ProjectileDanger bad = grenade;
        bad.FuseTime = -1;
        DangerZone z;
        Is(Danger.TryComputeDangerZone(points, n, bad, out z), Status.InvalidFuse, "fuse -1");
        bad = grenade;
        bad.BlastRadius = -1;
        bool safe;
        Is(Danger.TryIsPointSafe(points, n, bad, zone.Center, 1, out safe), Status.InvalidRadius, "blast -1");
        Check(!safe, "refused: not safe");
        DangerStart ds;
        Is(Danger.TryFindPathApproach(points, n, beside, -1, 0, 2, out ds), Status.InvalidRadius, "distance -1");
        Throws(() => Danger.ComputeDangerZone(points, n, bad), Status.InvalidRadius, "ComputeDangerZone(blast -1)");

        // A car at 10 m/s along +Z (box half extents (0.9, 0.7, 2.2)) and a person 20 m ahead
        // (sphere 0.4 m): separation 20 - 2.2 - 0.4 - 10 t, contact at t = 1.74 s.
        VehicleBody car = Danger.DefaultVehicleBody;
        Check(car.HalfExtents == V(0.9, 0.7, 2.2) && car.State.Orientation == Quaternion.Identity, "vehicle body defaults");
        car.State.Velocity = V(0, 0, 10);
        CharacterBody person = Danger.DefaultCharacterBody;
        Check(person.Radius == 0.4f, "character defaults");
        person.Position = new DVec3(0, 0, 20);
        ApproachSettings settings = Danger.DefaultApproachSettings;
        Check(settings.Tolerance == 1e-3f && settings.MaxEvaluations == 65536, "approach defaults");
        Near(Danger.ComputeVehicleSeparation(car, person, 0), 17.4, Tol, "separation at 0");
        Near(Danger.ComputeVehicleSeparation(car, person, 1), 7.4, Tol, "separation at 1");
        VehicleContact contact = Danger.FindVehicleContact(car, person, 5, settings);
        // Never later than the true contact, within the tolerance (1e-3 m at 10 m/s: 1e-4 s).
        Check(contact.Contact && contact.Time <= 1.74 + 1e-5 && contact.Time >= 1.74 - 2e-4, "contact at 1.74 s: " + contact.Time);
        ClosestApproach near = Danger.FindClosestVehicleApproach(car, person, 1, settings);
        Near(near.Distance, 7.4, 1e-3, "closest within 1 s");  // the query's tolerance
        Near(near.Time, 1, 1e-3, "closest at the horizon");
        Check(!Danger.FindVehicleContact(car, person, 1, settings).Contact, "no contact within 1 s");
        float sep;
        Is(Danger.TryComputeVehicleSeparation(car, person, -1, out sep), Status.NegativeTime, "separation(-1)");
        VehicleBody flat = car;
        flat.HalfExtents = V(0, 1, 1);
        Is(Danger.TryComputeVehicleSeparation(flat, person, 0, out sep), Status.DegenerateShape, "flat car");
        CharacterBody ghost = person;
        ghost.Radius = -1;
        Is(Danger.TryComputeVehicleSeparation(car, ghost, 0, out sep), Status.InvalidRadius, "radius -1");
        ApproachSettings lazy = settings;
        lazy.Tolerance = 0;
        VehicleContact vc;
        Is(Danger.TryFindVehicleContact(car, person, 5, lazy, out vc), Status.InvalidStep, "tolerance 0");
        Throws(() => Danger.FindClosestVehicleApproach(car, person, float.NaN, settings), Status.NonFiniteInput,
               "FindClosestVehicleApproach(NaN)");
    }

    // ---- Throw planning --------------------------------------------------------------------

    private static void TestThrowPlanner()
    {
        ThrowPlanRequest request = ThrowPlanner.DefaultRequest;
        Check(request.AcceptanceRadius == 0.5f && request.FuseTime == 3 && request.MaxSpeed == 20 && request.MaxPlans == 3,
              "plan request defaults");
        Check(request.Budget.AzimuthSamples == 16 && request.Budget.MaxPredictions == 400 &&
              request.Settings.Method == ProjectileMethod.Exact, "plan budget defaults");
        using (World world = new World())
        {
            world.AddPlane(Axes.Up, 0);
            request.Start = new DVec3(0, 1.5, 0);
            request.Target = new DVec3(0, 0, 12);
            request.Settings.Radius = 0.05f;
            request.Settings.Friction = 0.4f;
            ThrowPlan[] plans = new ThrowPlan[4];
            TrajectoryPoint[] scratch = new TrajectoryPoint[ThrowPlanner.ScratchSize(request)];
            Check(scratch.Length > 0, "scratch size");
            ThrowPlanResult result = ThrowPlanner.Plan(request, world, plans, scratch);
            Check(result.PlanCount >= 1 && result.PlanCount <= 3 && result.Predictions > 0, "plans found: " + result.PlanCount);
            // The forward model confirms each plan, bit for bit.
            for (int i = 0; i < (int)result.PlanCount; ++i)
            {
                ProjectileResult drawn =
                    Projectiles.Predict(request.Start, plans[i].LaunchVelocity, request.FuseTime, request.Settings, world);
                Check(drawn.Position.Equals(plans[i].FinalPosition) && drawn.Bounces == plans[i].Bounces, "plan " + i + " drawn");
                double dx = drawn.Position.X - 0, dy = drawn.Position.Y - 0, dz = drawn.Position.Z - 12;
                double distance = Math.Sqrt(dx * dx + dy * dy + dz * dz);
                Check(distance <= 0.5 + 1e-6, "plan " + i + " within the acceptance radius: " + distance);
                Near(plans[i].Distance, distance, Tol, "plan distance");
                Check(plans[i].LaunchVelocity.Length() <= 20 * (1 + 1e-6), "plan speed within MaxSpeed");
            }
            ThrowPlanResult none = ThrowPlanner.Plan(request, world, null);
            Check(none.PlanCount == 0, "no plan buffer: none written");
            ThrowPlanResult r;
            ThrowPlanRequest bad = request;
            bad.FuseTime = 0;
            Is(ThrowPlanner.TryPlan(bad, world, plans, scratch, out r), Status.InvalidFuse, "fuse 0");
            bad = request;
            bad.AcceptanceRadius = 0;
            Is(ThrowPlanner.TryPlan(bad, world, plans, scratch, out r), Status.InvalidRadius, "acceptance 0");
            bad = request;
            bad.MaxSpeed = 0;
            Is(ThrowPlanner.TryPlan(bad, world, plans, scratch, out r), Status.InvalidSpeed, "max speed 0");
            bad = request;
            bad.Settings.Method = (ProjectileMethod)9;
            Is(ThrowPlanner.TryPlan(bad, world, plans, scratch, out r), Status.InvalidSetting, "method 9");
            Check(ThrowPlanner.ScratchSize(bad) == 0, "scratch size of a refused request");
            bad = request;
            bad.Target.X = double.NaN;
            Throws(() => ThrowPlanner.Plan(bad, world, plans), Status.NonFiniteInput, "Plan(NaN target)");
        }
    }

    // ---- Meshes, Embree and callback worlds ------------------------------------------------

    // A drop from height h onto y = 0, stopped at the first impact: t = sqrt(2 h / g).
    private static void CheckDrop(World world, string what)
    {
        ProjectileSettings s = Projectiles.DefaultSettings;
        s.MaxBounces = 0;
        ProjectileResult r;
        Is(Projectiles.TryPredict(new DVec3(0.3, 5, 0.2), V(0, 0, 0), 3, s, world, out r), Status.Ok, what);
        Check(r.StoppedAtHit && r.HitNormal == Axes.Up, what + ": stopped on the floor");
        Near(r.Time, Math.Sqrt(2 * 5 / G), Tol, what + ": impact time");
        Near(r.Position.Y, 0, Tol, what + ": impact height");
    }

    private static readonly DVec3[] FloorVertices = {
        new DVec3(-50, 0, -50), new DVec3(50, 0, -50), new DVec3(50, 0, 50), new DVec3(-50, 0, 50),
    };
    private static readonly uint[] FloorIndices = { 0, 2, 1, 0, 3, 2 };

    private static void TestMeshAndCallbackWorlds()
    {
        using (World world = new World())
        {
            MeshReport report = world.AddMesh(FloorVertices, FloorIndices);
            Check(report.Triangles == 2 && report.DegenerateTriangles == 0, "mesh: 2 triangles");
            CheckDrop(world, "mesh floor");
            MeshReport rep;
            Is(world.TryAddMesh(FloorVertices, new uint[] { 0, 1, 2, 3 }, out rep), Status.DegenerateShape, "4 indices");
            Is(world.TryAddMesh(FloorVertices, new uint[] { 0, 1, 9 }, out rep), Status.DegenerateShape, "index 9");
            DVec3[] nan = (DVec3[])FloorVertices.Clone();
            nan[1].Y = double.NaN;
            Is(world.TryAddMesh(nan, FloorIndices, out rep), Status.NonFiniteInput, "NaN vertex");
            Is(world.TryAddMesh(null, FloorIndices, out rep), Status.NullPointer, "null vertices");
            MeshReport skipped = world.AddMesh(new[] { new DVec3(0, 0, 0), new DVec3(1, 0, 0), new DVec3(0, 0, 1), new DVec3(2, 0, 0) },
                                               new uint[] { 0, 1, 3, 0, 2, 1 });
            Check(skipped.Triangles == 1 && skipped.DegenerateTriangles == 1 && skipped.FirstDegenerateTriangle == 0,
                  "a degenerate triangle skipped and counted");
            string error;
            Is(world.TryCommit(out error), Status.Ok, "commit a plain world");
            MeshReport loaded;
            Is(world.TryLoadMesh("floor.obj", out loaded, out error), Status.InvalidSetting, "load into a plain world");
        }

        if (World.EmbreeAvailable)
        {
            string dir = Path.Combine(Path.GetTempPath(), "foresight-csharp-" + System.Diagnostics.Process.GetCurrentProcess().Id);
            Directory.CreateDirectory(dir);
            try
            {
                string obj = Path.Combine(dir, "floor.obj");
                File.WriteAllText(obj, "v -50 0 -50\nv 50 0 -50\nv 50 0 50\nv -50 0 50\nf 1 3 2\nf 1 4 3\n");
                using (World embree = World.CreateEmbree())
                {
                    MeshReport report = embree.LoadMesh(obj);
                    Check(report.Triangles == 2, "OBJ: 2 triangles");
                    embree.Commit();
                    CheckDrop(embree, "Embree OBJ floor");
                    MeshReport none;
                    string error;
                    Is(embree.TryLoadMesh(Path.Combine(dir, "missing.obj"), out none, out error), Status.BackendFailed, "missing file");
                    Check(error.Contains("missing.obj"), "the error names the file: " + error);
                    Is(embree.TryLoadMesh(Path.Combine(dir, "floor.txt"), out none, out error), Status.InvalidSetting, "extension");
                    bool threw = false;
                    try
                    {
                        embree.LoadMesh(Path.Combine(dir, "missing.obj"));
                    }
                    catch (ForesightException e)
                    {
                        threw = e.Status == Status.BackendFailed && e.Message.Contains("missing.obj");
                    }
                    Check(threw, "LoadMesh(missing) throws with the reason");
                }
                using (World embree = World.CreateEmbree())
                {
                    embree.AddMesh(FloorVertices, FloorIndices);
                    embree.Commit();
                    CheckDrop(embree, "Embree mesh floor");
                }
            }
            finally
            {
                Directory.Delete(dir, true);
            }
        }

        // A callback world: the game's cast answers a floor y = 0 (rays only here).
        int calls = 0;
        CastHandler floor = (SegmentCast cast, ref CastHit hit) =>
        {
            ++calls;
            double y0 = cast.Origin.Y - cast.Radius, y1 = y0 + cast.Displacement.Y;
            if (y0 < 0 || y1 > 0 || cast.Displacement.Y >= 0) return false;
            float f = (float)(y0 / -cast.Displacement.Y);
            hit.Fraction = f;
            hit.Position = new DVec3(cast.Origin.X + f * cast.Displacement.X, cast.Origin.Y + f * cast.Displacement.Y,
                                     cast.Origin.Z + f * cast.Displacement.Z);
            hit.Normal = Axes.Up;
            return true;
        };
        using (World callback = World.CreateCallback(floor))
        {
            CheckDrop(callback, "callback floor");
            Check(calls > 0, "the handler was called");
            Is(callback.TryAddPlane(new PlaneShape { Normal = Axes.Up }), Status.InvalidSetting, "no shapes in a callback world");
        }
        CastHandler broken = (SegmentCast cast, ref CastHit hit) => { throw new InvalidOperationException("game bug"); };
        using (World callback = World.CreateCallback(broken))
        {
            ProjectileResult r;
            Is(Projectiles.TryPredict(new DVec3(0, 5, 0), V(0, 0, 0), 3, Projectiles.DefaultSettings, callback, out r),
               Status.InvalidCallbackHit, "a throwing handler");
        }
        CastHandler nanHit = (SegmentCast cast, ref CastHit hit) =>
        {
            hit.Normal = Vector3.Zero;
            return true;
        };
        using (World callback = World.CreateCallback(nanHit))
        {
            ProjectileResult r;
            Is(Projectiles.TryPredict(new DVec3(0, 5, 0), V(0, 0, 0), 3, Projectiles.DefaultSettings, callback, out r),
               Status.InvalidCallbackHit, "a zero normal");
        }
        bool nullThrew = false;
        try
        {
            World.CreateCallback(null);
        }
        catch (ArgumentNullException)
        {
            nullThrew = true;
        }
        Check(nullThrew, "CreateCallback(null) throws");
        // Handlers are released with their worlds (disposed or finalized): no growth.
        for (int i = 0; i < 20000; ++i)
        {
            World w = World.CreateCallback(floor);
            if (i % 2 == 0) w.Dispose();
        }
        GC.Collect();
        GC.WaitForPendingFinalizers();
    }

    // ---- Aim -------------------------------------------------------------------------------

    private static void TestAim()
    {
        AimShot shot = Aim.DefaultShot;
        Check(shot.Constraint == AimConstraint.Speed && shot.Speed == 0 && shot.MaxTime == 60 && shot.Gravity == V(0, -9.81, 0),
              "aim defaults");
        // A static target 20 m away at 20 m/s: tan(theta) = (s^2 -+ sqrt(s^4 - g^2 x^2)) / (g x).
        shot.Speed = 20;
        AimTarget target = new AimTarget { Position = new DVec3(20, 0, 0) };
        FiringSolution[] solutions = new FiringSolution[Aim.MaxFiringSolutions];
        int count = Aim.AimAt(shot, target, solutions);
        Check(count == 2, "two arcs");
        double sp = 20, x = 20, root = Math.Sqrt(sp * sp * sp * sp - G * G * x * x);
        double low = Math.Atan((sp * sp - root) / (G * x)), high = Math.Atan((sp * sp + root) / (G * x));
        Near(solutions[0].Time, x / (sp * Math.Cos(low)), Tol, "low arc time");
        Near(solutions[0].Elevation, low, Tol, "low arc elevation");
        Near(solutions[1].Time, x / (sp * Math.Cos(high)), Tol, "high arc time");
        Near(solutions[1].Elevation, high, Tol, "high arc elevation");
        Near(solutions[0].Velocity.Length(), 20, Tol, "launch speed");
        Near(solutions[0].Hit.X, 20, Tol, "hit x");
        // A single-entry buffer gets the earliest; null gets none; unreachable is not an error.
        FiringSolution[] one = new FiringSolution[1];
        Check(Aim.AimAt(shot, target, one) == 1 && one[0].Time == solutions[0].Time, "earliest only");
        Check(Aim.AimAt(shot, target, null) == 0, "no buffer");
        target.Position = new DVec3(1000, 0, 0);
        Check(Aim.AimAt(shot, target, solutions) == 0, "unreachable");
        int n;
        AimShot bad = shot;
        bad.Constraint = (AimConstraint)9;
        Is(Aim.TryAim(bad, target, solutions, out n), Status.InvalidSetting, "constraint 9");
        bad = shot;
        bad.MaxTime = -1;
        Is(Aim.TryAim(bad, target, solutions, out n), Status.NegativeTime, "max time -1");
        target.Velocity = V(float.NaN, 0, 0);
        Is(Aim.TryAim(shot, target, solutions, out n), Status.NonFiniteInput, "aim(NaN)");
        Check(n == 0, "refused count 0");
        Throws(() => Aim.AimAt(shot, target, solutions), Status.NonFiniteInput, "AimAt(NaN)");
    }

    // ---- Dead reckoning --------------------------------------------------------------------

    private static DeadReckoningState Dr(DeadReckoningAlgorithm algorithm)
    {
        return new DeadReckoningState {
            Position = new DVec3(1, 2, 3), Velocity = V(4, 0, -2), Acceleration = V(0, -2, 1),
            Orientation = Quaternion.Identity, Algorithm = algorithm,
        };
    }

    private static void TestDeadReckoning()
    {
        Check(DeadReckoning.AlgorithmName(DeadReckoningAlgorithm.Rvb) == "RVB", "name RVB");
        Check(DeadReckoning.AlgorithmName((DeadReckoningAlgorithm)0) == "?", "name 0");
        const double t = 0.5;
        DeadReckoningResult r = DeadReckoning.Predict(Dr(DeadReckoningAlgorithm.Fpw), (float)t);
        Near(r.Position.X, 1 + 4 * t, Tol, "FPW x");
        Near(r.Position.Z, 3 - 2 * t, Tol, "FPW z");
        r = DeadReckoning.Predict(Dr(DeadReckoningAlgorithm.Fvw), (float)t);
        Near(r.Position.Y, 2 - 2 * t * t / 2, Tol, "FVW y");
        Near(r.Position.Z, 3 - 2 * t + t * t / 2, Tol, "FVW z");
        Near(r.Velocity.Y, -2 * t, Tol, "FVW vy");
        // RPB: body velocity (0, 0, 10) turning at 0.5 rad/s about +Y: the circle of radius 20.
        DeadReckoningState rpb = Dr(DeadReckoningAlgorithm.Rpb);
        rpb.Velocity = V(0, 0, 10);
        rpb.AngularVelocity = V(0, 0.5, 0);
        r = DeadReckoning.Predict(rpb, 2);
        Near(r.Position.X, 1 + 20 * (1 - Math.Cos(1)), Tol, "RPB x");
        Near(r.Position.Z, 3 + 20 * Math.Sin(1), Tol, "RPB z");
        Near(r.Orientation.Y, Math.Sin(0.5), Tol, "RPB q.y");

        DeadReckoningResult no;
        Is(DeadReckoning.TryPredict(Dr(DeadReckoningAlgorithm.Fpw), -1, out no), Status.NegativeTime, "DR(-1)");
        Is(DeadReckoning.TryPredict(Dr(DeadReckoningAlgorithm.Fpw), float.NaN, out no), Status.NonFiniteInput, "DR(NaN)");
        Is(DeadReckoning.TryPredict(Dr((DeadReckoningAlgorithm)257), 1, out no), Status.InvalidAlgorithm, "DR(257)");
        DeadReckoningState zq = Dr(DeadReckoningAlgorithm.Fpw);
        zq.Orientation = new Quaternion(0, 0, 0, 0);
        Is(DeadReckoning.TryPredict(zq, 1, out no), Status.ZeroQuaternion, "DR(zero quaternion)");
        Throws(() => DeadReckoning.Predict(Dr(0), 1), Status.InvalidAlgorithm, "Predict(algorithm 0)");

        // Batch: ages time - timestamp (0 when stamped later); a refused entity keeps its state.
        DeadReckoningState[] states = { Dr(DeadReckoningAlgorithm.Fpw), Dr(DeadReckoningAlgorithm.Fpw), zq };
        double[] stamps = { 10, 11, 10 };
        DeadReckoningResult[] results = new DeadReckoningResult[3];
        Check(DeadReckoning.PredictBatch(states, stamps, 10.5, results) == 1, "batch refused 1");
        Near(results[0].Position.X, 1 + 4 * 0.5, Tol, "batch x");
        Check(results[1].Position.X == 1 && results[2].Position.X == 1 && results[2].Velocity.X == 4, "batch age 0, refused");
        // Each equals the single prediction bit for bit.
        DeadReckoningResult single = DeadReckoning.Predict(states[0], 0.5f);
        Check(single.Position.Equals(results[0].Position) && single.Velocity == results[0].Velocity &&
              single.Orientation == results[0].Orientation, "batch == single");
        int refused;
        Is(DeadReckoning.TryPredictBatch(states, stamps, 10.5, new DeadReckoningResult[2], out refused), Status.Ok, "short out");
        Check(refused == 1, "the state beyond the shortest counts as refused");
        Is(DeadReckoning.TryPredictBatch(null, stamps, 1, results, out refused), Status.NullPointer, "batch(null)");
        Throws(() => DeadReckoning.PredictBatch(states, null, 1, results), Status.NullPointer, "PredictBatch(null)");

        // The receiver: Snap smoothing, extrapolation limit 0.25 s.
        ReceiverSettings rs = DeadReckoning.DefaultReceiverSettings;
        Check(rs.Mode == ReceiverMode.Extrapolate && rs.Smoothing == Smoothing.ProjectiveVelocityBlending, "receiver defaults");
        Check(rs.BlendTime == 0.2f && rs.ExtrapolationLimit == 0.25f && rs.RestartAfter == 10, "receiver defaults 2");
        rs.Smoothing = Smoothing.Snap;
        using (DeadReckoningReceiver rx = new DeadReckoningReceiver(rs))
        {
            ReceivedPose pose;
            Is(rx.TrySample(0, out pose), Status.NoUpdate, "sample before any update");
            Throws(() => rx.Sample(0), Status.NoUpdate, "Sample() before any update");
            DeadReckoningState s = Dr(DeadReckoningAlgorithm.Fpw);
            Check(rx.Receive(1.0, s, 1.05) == UpdateOutcome.Snapped, "first update snaps");
            pose = rx.Sample(1.2);
            Near(pose.Position.X, 1 + 4 * 0.2, Tol, "receiver x");
            Check(!pose.Held && pose.Velocity.X == 4, "not held");
            pose = rx.Sample(2.0);
            Near(pose.Position.X, 1 + 4 * 0.25, Tol, "held x");
            Check(pose.Held, "held");
            Is(rx.TrySample(double.NaN, out pose), Status.NonFiniteInput, "sample(NaN)");
            Check(rx.Receive(1.0, s, 1.1) == UpdateOutcome.Duplicate, "duplicate");
            Check(rx.Receive(0.5, s, 1.1) == UpdateOutcome.OutOfOrder, "out of order");
            s.Velocity.X = float.NaN;
            Check(rx.Receive(1.5, s, 1.5) == UpdateOutcome.Invalid, "invalid");
            // A correction: a new update 0.5 s later moving the other way, blended... snapped here.
            DeadReckoningState back = Dr(DeadReckoningAlgorithm.Fpw);
            back.Position = new DVec3(3, 2, 3);
            back.Velocity = V(-4, 0, 0);
            Check(rx.Receive(1.5, back, 1.5) == UpdateOutcome.Snapped, "Snap smoothing snaps");
            pose = rx.Sample(1.6);
            Near(pose.Position.X, 3 - 4 * 0.1, Tol, "snapped to the new update");
            ReceiverCounters c = rx.Counters;
            Check(c.Accepted == 2 && c.Duplicates == 1 && c.OutOfOrder == 1 && c.Invalid == 1 && c.Held == 1, "counters");
            rx.Reset();
            Check(rx.Counters.Accepted == 0, "reset counters");
            Is(rx.TrySample(1, out pose), Status.NoUpdate, "reset forgets");
        }
        // Projective velocity blending: halfway through the blend the pose lies between the
        // old extrapolation and the new one (no jump at the correction).
        using (DeadReckoningReceiver rx = new DeadReckoningReceiver())
        {
            DeadReckoningState s = Dr(DeadReckoningAlgorithm.Fpw);
            rx.Receive(0, s, 0);
            ReceivedPose before = rx.Sample(0.1);
            DeadReckoningState corrected = s;
            corrected.Position = new DVec3(1.5, 2, 3);
            Check(rx.Receive(0.1, corrected, 0.1) == UpdateOutcome.Accepted, "correction accepted");
            ReceivedPose at = rx.Sample(0.1);
            Near(at.Position.X, before.Position.X, Tol, "no jump at the correction");
            ReceivedPose end = rx.Sample(0.3);  // blend over (0.2 s): the new extrapolation
            Near(end.Position.X, 1.5 + 4 * 0.2, Tol, "blend reaches the new extrapolation");
        }
        ReceiverSettings badSettings = DeadReckoning.DefaultReceiverSettings;
        badSettings.BlendTime = 0;
        DeadReckoningReceiver none;
        Is(DeadReckoningReceiver.TryCreate(badSettings, out none), Status.InvalidSetting, "receiver blend 0");
        Check(none == null, "no receiver");
        badSettings = DeadReckoning.DefaultReceiverSettings;
        badSettings.Mode = (ReceiverMode)5;
        Is(DeadReckoningReceiver.TryCreate(badSettings, out none), Status.InvalidSetting, "receiver mode 5");
        ReceiverSettings captured = badSettings;
        Throws(() => new DeadReckoningReceiver(captured), Status.InvalidSetting, "new receiver(mode 5)");
        Is(DeadReckoningReceiver.TryCreate(DeadReckoning.DefaultReceiverSettings, out none), Status.Ok, "TryCreate");
        Check(none != null && !none.IsDisposed, "created");
        none.Dispose();
        none.Dispose();
        Check(none.IsDisposed, "receiver disposed");
    }

    // ---- Allocation and leaks --------------------------------------------------------------

    private static void PerFrame(World world, TrajectoryPoint[] points, DeadReckoningReceiver rx,
                                 DeadReckoningState[] states, double[] stamps, DeadReckoningResult[] results)
    {
        ProjectileSettings s = Projectiles.DefaultSettings;
        ProjectileResult r;
        Projectiles.TryPredict(new DVec3(0, 1.6, 0), V(0, 4, 12), 3, s, world, points, out r);
#if FORESIGHT_SPAN
        Projectiles.TryPredict(new DVec3(0, 1.6, 0), V(0, 4, 12), 3, s, world, new Span<TrajectoryPoint>(points, 1, 300), out r);
#endif
        PointState ps;
        Characters.TryPredictLinear(new PointState(new DVec3(1, 2, 3), V(1, 0, 0)), 0.5f, out ps);
        Characters.TryPredictAccelerated(new PointState(new DVec3(1, 2, 3), V(1, 0, 0)), V(0, -9.81, 0), 0.5f, out ps);
        VehicleState vs;
        VehicleState start = new VehicleState(new DVec3(0, 0, 0), V(0, 0, 10), Quaternion.Identity, V(0, 0.5, 0));
        Vehicles.TryPredictExact(start, 2, Vehicles.DefaultSettings, out vs);
        Vehicles.TryPredictIterative(start, 2, 4, Vehicles.DefaultSettings, out vs);
        int n;
        FiringSolution[] sol = solutionsBuffer;
        AimShot shot = Aim.DefaultShot;
        shot.Speed = 20;
        Aim.TryAim(shot, new AimTarget { Position = new DVec3(20, 0, 0) }, sol, out n);
        DeadReckoningResult dr;
        DeadReckoning.TryPredict(states[0], 0.5f, out dr);
        int refused;
        DeadReckoning.TryPredictBatch(states, stamps, 10.5, results, out refused);
        rx.Receive(frameTime, states[0], frameTime);
        ReceivedPose pose;
        rx.TrySample(frameTime + 0.01, out pose);
        ReceiverCounters c = rx.Counters;
        frameTime += 0.02 + c.Accepted * 0;
    }

    private static readonly FiringSolution[] solutionsBuffer = new FiringSolution[Aim.MaxFiringSolutions];
    private static double frameTime;

    private static void TestNoAllocation()
    {
        using (World world = new World())
        using (DeadReckoningReceiver rx = new DeadReckoningReceiver())
        {
            world.AddPlane(Axes.Up, 0);
            world.AddBox(new DVec3(0, 1.5, 10), V(5, 1.5, 0.25), Quaternion.Identity);
            TrajectoryPoint[] points = new TrajectoryPoint[512];
            DeadReckoningState[] states = { Dr(DeadReckoningAlgorithm.Rvb), Dr(DeadReckoningAlgorithm.Fpw) };
            double[] stamps = { 10, 10.2 };
            DeadReckoningResult[] results = new DeadReckoningResult[2];
            CastHandler floor = (SegmentCast cast, ref CastHit hit) =>
            {
                double y0 = cast.Origin.Y, y1 = y0 + cast.Displacement.Y;
                if (y0 < 0 || y1 > 0 || cast.Displacement.Y >= 0) return false;
                hit.Fraction = (float)(y0 / -cast.Displacement.Y);
                hit.Position = new DVec3(cast.Origin.X, 0, cast.Origin.Z);
                hit.Normal = Axes.Up;
                return true;
            };
            World callback = World.CreateCallback(floor);
            ProjectileSettings s = Projectiles.DefaultSettings;
            ProjectileResult r;
            for (int i = 0; i < 100; ++i)  // JIT, marshalling stubs
            {
                PerFrame(world, points, rx, states, stamps, results);
                Projectiles.TryPredict(new DVec3(0, 5, 0), V(1, 0, 0), 2, s, callback, points, out r);
            }
            long before = GC.GetAllocatedBytesForCurrentThread();
            for (int i = 0; i < 1000; ++i)
            {
                PerFrame(world, points, rx, states, stamps, results);
                Projectiles.TryPredict(new DVec3(0, 5, 0), V(1, 0, 0), 2, s, callback, points, out r);  // a callback world
            }
            long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
            Check(allocated == 0, "the per-frame calls allocated " + allocated + " bytes in 1000 frames");
            callback.Dispose();
        }
    }

    private static long ResidentBytes()
    {
        string[] statm = File.ReadAllText("/proc/self/statm").Split(' ');
        return long.Parse(statm[1]) * 4096;
    }

    private static void Cycle(int i)
    {
        World w = new World();
        for (int k = 0; k < 16; ++k)
            w.AddTriangle(new DVec3(k, 0, 0), new DVec3(k + 1, 0, 0), new DVec3(k, 0, 1));
        DeadReckoningReceiver rx = new DeadReckoningReceiver();
        rx.Receive(0, Dr(DeadReckoningAlgorithm.Fpw), 0);
        // Half disposed, half left to the finalizer.
        if (i % 2 == 0)
        {
            w.Dispose();
            rx.Dispose();
        }
    }

    private static void Round(int cycles)
    {
        for (int i = 0; i < cycles; ++i) Cycle(i);
        GC.Collect();
        GC.WaitForPendingFinalizers();
        GC.Collect();
    }

    private static void TestNoLeaks()
    {
        if (!File.Exists("/proc/self/statm")) return;  // Linux only
        // The first round sets the plateau: objects left to the finalizer keep their native
        // memory until a collection runs, so the peak depends on the round's size, not on
        // the number of rounds. Later rounds must stay on it.
        const int cycles = 20000, rounds = 3;
        Round(cycles);
        long before = ResidentBytes();
        for (int r = 0; r < rounds; ++r) Round(cycles);
        long grown = ResidentBytes() - before;
        // A leak would keep each cycle's world (16 triangles, over 1 KB) and receiver (its
        // 32-update buffer, about 3 KB), half of them at least: over 100 MB for 60000 cycles.
        // Measured without a leak: under 1 MB (allocator and managed-heap noise); 8 MB leaves room.
        Check(grown < 8L << 20, "RSS grew by " + (grown >> 10) + " KB over " + rounds * cycles + " world and receiver cycles");
        Console.WriteLine("leak check: RSS " + (grown >= 0 ? "+" : "") + (grown >> 10) + " KB over " + rounds * cycles +
                          " world and receiver cycles after a first round of " + cycles);
    }

    private static int Main(string[] args)
    {
        if (args.Length < 1)
        {
            Console.Error.WriteLine("usage: mono BindingTests.exe path/to/foresight_c.h");
            return 2;
        }
        TestLibrary();
        TestLayout(args[0]);
        TestEntryPoints(File.ReadAllText(args[0]));
        TestCharacters();
        TestVehicles();
        TestWorld();
        TestProjectiles();
        TestEngineProfiles();
        TestDanger();
        TestThrowPlanner();
        TestMeshAndCallbackWorlds();
        TestAim();
        TestDeadReckoning();
        TestNoAllocation();
        TestNoLeaks();
        Console.WriteLine("csharp binding: " + checks + " checks, " + failures + " failed");
        return failures == 0 ? 0 : 1;
    }
}
