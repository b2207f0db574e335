// ArticleScenarios.cs: the C# twin of examples/article_scenarios.cpp, written as a Unity or
// Godot script would use the binding (System.Numerics types, caller-owned buffers reused every
// frame). It must print exactly the same text as the C++ program (CTest compares them): the
// reference article's three scenarios, numbers with 6 decimals. Metres, seconds, radians; +Y up,
// +Z forward (Unity's axes; a Unity script converts with component copies, see Axes.cs).
//
//   mono ArticleScenarios.exe                      the scenarios
//   mono ArticleScenarios.exe --check-format       checks F6 against printf's rounding
//   mono ArticleScenarios.exe --overhead CPP_EXE   one grenade prediction through C# vs C++
//                                                  (bindings/csharp/bench/overhead.cpp)

using System;
using System.Diagnostics;
using System.Globalization;
using System.Numerics;
using System.Text;
using Foresight;

internal static class ArticleScenarios
{
    /// <summary>printf("%.6f", value + 0.0): the exact decimal value of the double, rounded to
    /// 6 decimals half to even, as glibc prints it (a negative value that rounds to zero
    /// keeps its sign: "-0.000000"). C#'s ToString("F6") is not that on every runtime: Mono and
    /// .NET Framework round a 15-digit approximation first (0.1234575, just below the tie,
    /// prints 0.123458 there, 0.123457 with printf; 1/128 prints 0.007813, printf 0.007812)
    /// and .NET Core prints -0 as "-0.000000".</summary>
    private static string F6(double value)
    {
        if (value == 0) value = 0;  // -0 prints as 0 (the C++ program adds 0.0, which a JIT may fold away)
        long bits = BitConverter.DoubleToInt64Bits(value);
        bool negative = bits < 0;
        int exponent = (int)((bits >> 52) & 0x7FF);
        long mantissa = bits & 0xFFFFFFFFFFFFFL;
        if (exponent == 0x7FF) return value.ToString(CultureInfo.InvariantCulture);  // not in this program
        if (exponent == 0) exponent = 1;
        else mantissa |= 1L << 52;
        exponent -= 1075;  // value = mantissa * 2^exponent
        BigInteger numerator = new BigInteger(mantissa) * 1000000;
        BigInteger denominator = BigInteger.One;
        if (exponent > 0) numerator <<= exponent;
        else denominator <<= -exponent;
        BigInteger remainder;
        BigInteger scaled = BigInteger.DivRem(numerator, denominator, out remainder);
        int half = (remainder * 2).CompareTo(denominator);
        if (half > 0 || (half == 0 && !scaled.IsEven)) scaled += 1;
        string digits = scaled.ToString(CultureInfo.InvariantCulture).PadLeft(7, '0');
        return (negative ? "-" : "") + digits.Substring(0, digits.Length - 6) + "." + digits.Substring(digits.Length - 6);
    }

    private static readonly StringBuilder Out = new StringBuilder();

    private static void Number(double value) { Out.Append(F6(value)); }

    private static void Vec(string label, double x, double y, double z)
    {
        Out.Append(label).Append(" (");
        Number(x);
        Out.Append(", ");
        Number(y);
        Out.Append(", ");
        Number(z);
        Out.Append(")");
    }

    private static void Vec(string label, Vector3 v) { Vec(label, v.X, v.Y, v.Z); }
    private static void Vec(string label, DVec3 v) { Vec(label, v.X, v.Y, v.Z); }

    private static void Character()
    {
        PointState now = new PointState(new DVec3(1, 0, 2), new Vector3(3, 0, 4));
        Vector3 acceleration = new Vector3(0, 0, -2);
        PointState linear = Characters.PredictLinear(now, 0.5f);
        PointState accelerated = Characters.PredictAccelerated(now, acceleration, 0.5f);
        Out.Append("character\n");
        Vec("  linear      position", linear.Position);
        Vec(" velocity", linear.Velocity);
        Out.Append("\n");
        Vec("  accelerated position", accelerated.Position);
        Vec(" velocity", accelerated.Velocity);
        Out.Append("\n");
    }

    // Allocated once, reused every prediction (a MonoBehaviour field).
    private static readonly TrajectoryPoint[] Trajectory = new TrajectoryPoint[4096];

    private static readonly DVec3 Hand = new DVec3(0, 1.6f, 0);  // 1.6f: the C++ program's RVec3(0, 1.6f, 0)
    private static readonly Vector3 Throw = new Vector3(0, 4, 12);
    private const float Fuse = 3.0f;

    private static void Grenade(string name, ProjectileSettings settings, World world)
    {
        ProjectileResult result = Projectiles.Predict(Hand, Throw, Fuse, settings, world, Trajectory);
        Out.Append("grenade ").Append(name).Append(": ").Append(result.Bounces.ToString(CultureInfo.InvariantCulture))
            .Append(" bounces, ").Append(result.TrajectorySize.ToString(CultureInfo.InvariantCulture)).Append(" points\n");
        int shown = 0;
        for (int i = 0; i < (int)result.TrajectorySize; ++i)
        {
            if (Trajectory[i].Event != TrajectoryEvent.Bounce || shown == 3) continue;
            ++shown;
            Out.Append("  bounce t ");
            Number(Trajectory[i].Time);
            Vec(" position", Trajectory[i].Position);
            Vec(" normal", Trajectory[i].Normal);
            Out.Append("\n");
        }
        Out.Append("  end    t ");
        Number(result.Time);
        Vec(" position", result.Position);
        Vec(" velocity", result.Velocity);
        Out.Append(result.AtRest ? " at rest" : "").Append("\n");
    }

    // The article's world: a floor and a wall 10 m ahead.
    private static World ArticleWorld()
    {
        World world = new World();
        world.AddPlane(Axes.Up, 0);
        world.AddBox(new DVec3(0, 1.5f, 10), new Vector3(5, 1.5f, 0.25f), Quaternion.Identity);
        return world;
    }

    private static ProjectileSettings GrenadeSettings(ProjectileMethod method)
    {
        ProjectileSettings settings = Projectiles.DefaultSettings;
        settings.Restitution = 0.5f;
        settings.Friction = 0.4f;
        settings.Radius = 0.05f;
        settings.Method = method;
        settings.Engine = PhysicsEngine.Jolt;
        return settings;
    }

    private static void Grenades()
    {
        using (World world = ArticleWorld())
        {
            Grenade("stepped", GrenadeSettings(ProjectileMethod.Stepped), world);
            Grenade("exact", GrenadeSettings(ProjectileMethod.Exact), world);
            Grenade("jolt", GrenadeSettings(ProjectileMethod.Engine), world);
        }
    }

    private static void Vehicle(string label, VehicleState state)
    {
        Vec(label, state.Position);
        Vec(" velocity", state.Velocity);
        Out.Append(" orientation (");
        Number(state.Orientation.W);
        Out.Append(", ");
        Number(state.Orientation.X);
        Out.Append(", ");
        Number(state.Orientation.Y);
        Out.Append(", ");
        Number(state.Orientation.Z);
        Out.Append(")\n");
    }

    private static void Car()
    {
        VehicleState start = new VehicleState(new DVec3(0, 0, 0), new Vector3(0, 0, 10), Quaternion.Identity,
                                              new Vector3(0, 0.5f, 0));
        VehicleSettings settings = Vehicles.DefaultSettings;
        VehicleState iterated = Vehicles.PredictIterative(start, 2.0f, 4, settings);
        VehicleState exact = Vehicles.PredictExact(start, 2.0f, settings);
        Out.Append("car\n");
        Vehicle("  iterative", iterated);
        Vehicle("  exact    ", exact);
    }

    // printf's outputs (glibc, exact) for doubles given by their bits (a runtime's own
    // double.Parse need not be correctly rounded): halfway cases near a 15-digit rounding, exact
    // ties (1/128, 3/128: half to even), tiny negatives (printed "-0.000000"), -0, a denormal.
    private static int CheckFormat()
    {
        object[][] cases = {
            new object[] { 0x3FF000008637BD06UL, "1.000001" },  // 1.0000005
            new object[] { 0x3FBF9AE924F227D0UL, "0.123457" },  // 0.1234575
            new object[] { 0x40FE240C9FCB923AUL, "123456.789012" },  // 123456.7890125
            new object[] { 0x4023FFFFEF39085FUL, "9.999999" },  // 9.9999995
            new object[] { 0xBE7AD7F29ABCAF48UL, "-0.000000" },  // -1e-07
            new object[] { 0x8000000000000000UL, "0.000000" },  // -0.0
            new object[] { 0x3F80000000000000UL, "0.007812" },  // 0.0078125
            new object[] { 0x3F98000000000000UL, "0.023438" },  // 0.0234375
            new object[] { 0xBF98000000000000UL, "-0.023438" },  // -0.0234375
            new object[] { 0x00000000000007E8UL, "0.000000" },  // 1e-320
            new object[] { 0x4023FFFFEF8EEE9BUL, "10.000000" },  // 9.99999951
        };
        int failures = 0;
        foreach (object[] c in cases)
        {
            double value = BitConverter.Int64BitsToDouble(unchecked((long)(ulong)c[0]));
            string got = F6(value);
            if (got == (string)c[1]) continue;
            ++failures;
            Console.Error.WriteLine("F6(" + value.ToString("R", CultureInfo.InvariantCulture) + ") = " + got + ", printf gives " + c[1]);
        }
        Console.WriteLine("format check: " + cases.Length + " cases, " + failures + " failed");
        return failures == 0 ? 0 : 1;
    }

    // Nanoseconds per call of the Exact grenade (floor and wall, 3 s fuse, trajectory into a
    // buffer of `capacity` points): the best of 7 runs of 20000 calls.
    private static double TimeGrenade(int capacity)
    {
        using (World world = ArticleWorld())
        {
            ProjectileSettings settings = GrenadeSettings(ProjectileMethod.Exact);
            TrajectoryPoint[] points = new TrajectoryPoint[capacity];
            ProjectileResult result;
            for (int i = 0; i < 2000; ++i) Projectiles.TryPredict(Hand, Throw, Fuse, settings, world, points, out result);
            double best = double.MaxValue;
            const int calls = 20000;
            for (int run = 0; run < 7; ++run)
            {
                Stopwatch watch = Stopwatch.StartNew();
                for (int i = 0; i < calls; ++i) Projectiles.TryPredict(Hand, Throw, Fuse, settings, world, points, out result);
                best = Math.Min(best, watch.Elapsed.TotalMilliseconds * 1e6 / calls);
            }
            return best;
        }
    }

    // Runs the C++ timing program (bindings/csharp/bench/overhead.cpp) for `capacity`; it
    // prints "cpp_ns N" and "c_api_ns N".
    private static double[] TimeCpp(string program, int capacity)
    {
        ProcessStartInfo start = new ProcessStartInfo(program, capacity.ToString(CultureInfo.InvariantCulture)) {
            UseShellExecute = false, RedirectStandardOutput = true
        };
        using (Process p = Process.Start(start))
        {
            string text = p.StandardOutput.ReadToEnd();
            p.WaitForExit();
            double cpp = 0, c = 0;
            foreach (string line in text.Split('\n'))
            {
                string[] words = line.Trim().Split(' ');
                if (words.Length != 2) continue;
                if (words[0] == "cpp_ns") cpp = double.Parse(words[1], CultureInfo.InvariantCulture);
                if (words[0] == "c_api_ns") c = double.Parse(words[1], CultureInfo.InvariantCulture);
            }
            return new[] { cpp, c };
        }
    }

    private static int Overhead(string program)
    {
        CultureInfo inv = CultureInfo.InvariantCulture;
        // The article's buffer size (trajectoryCapacity(3 s)), then a large one: the C API
        // prepares every point of the buffer on each call, so its cost grows with the capacity.
        int[] capacities = { Projectiles.TrajectoryCapacity(Fuse, GrenadeSettings(ProjectileMethod.Exact)), 4096 };
        Console.WriteLine("grenade (Exact, floor and wall, 3 s fuse), ns per call, best of 3 alternated rounds:");
        foreach (int capacity in capacities)
        {
            // Alternate C# and C++ and keep each one's best: the machine's load weighs on both alike.
            double csharp = double.MaxValue, cpp = double.MaxValue, capi = double.MaxValue;
            for (int round = 0; round < 3; ++round)
            {
                csharp = Math.Min(csharp, TimeGrenade(capacity));
                double[] native = TimeCpp(program, capacity);
                cpp = Math.Min(cpp, native[0]);
                capi = Math.Min(capi, native[1]);
            }
            Console.WriteLine("  buffer " + capacity + " points: C++ " + cpp.ToString("F0", inv) + ", C API " +
                              capi.ToString("F0", inv) + " (" + (capi / cpp).ToString("F2", inv) + "x), C# " +
                              csharp.ToString("F0", inv) + " (" + (csharp / cpp).ToString("F2", inv) + "x C++, " +
                              (csharp / capi).ToString("F2", inv) + "x C API)");
        }
        return 0;
    }

    private static int Main(string[] args)
    {
        if (args.Length >= 1 && args[0] == "--check-format") return CheckFormat();
        if (args.Length >= 2 && args[0] == "--overhead") return Overhead(args[1]);
        try
        {
            Library.EnsureCompatible();
            Character();
            Grenades();
            Car();
        }
        catch (ForesightException e)
        {
            Console.Error.WriteLine(e.Message);
            return 1;
        }
        // One write, "\n" line ends on every platform (the C++ program's output).
        Console.Out.Write(Out.ToString());
        Console.Out.Flush();
        return 0;
    }
}
