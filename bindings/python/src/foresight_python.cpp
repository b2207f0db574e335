/// @file foresight_python.cpp
/// The Python module `foresight` (pybind11): the core library's public API with NumPy arrays.
///
/// Conventions of the module: metres, seconds, radians; +Y up, +Z forward. Vectors are taken as
/// any sequence of 3 numbers (tuple, list, NumPy array) and returned as NumPy arrays (float32,
/// positions in the library's Real type). Quaternions are (x, y, z, w), scalar last, as
/// scipy.spatial.transform.Rotation takes them and as GLM stores them (so that batch results are
/// views of the library's own output, without a copy). Refused input raises foresight.Error, a
/// subclass of ValueError, whose message is the library's statusMessage; nothing here computes
/// on its own: every number comes from the library.

#include <foresight/foresight.h>
#include <pybind11/numpy.h>
#include <pybind11/operators.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace py = pybind11;
using namespace foresight;

namespace {

/// Raised for every refused input: foresight.Error (a ValueError).
struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

/// The name of a Status enumerator, e.g. "NegativeTime".
const char* statusName(Status status) {
    switch (status) {
        case Status::Ok:
            return "Ok";
        case Status::NonFiniteInput:
            return "NonFiniteInput";
        case Status::NegativeTime:
            return "NegativeTime";
        case Status::InvalidStep:
            return "InvalidStep";
        case Status::InvalidIterations:
            return "InvalidIterations";
        case Status::InvalidRestitution:
            return "InvalidRestitution";
        case Status::InvalidFriction:
            return "InvalidFriction";
        case Status::InvalidRadius:
            return "InvalidRadius";
        case Status::ZeroQuaternion:
            return "ZeroQuaternion";
        case Status::ZeroVector:
            return "ZeroVector";
        case Status::DegenerateShape:
            return "DegenerateShape";
        case Status::TooManySteps:
            return "TooManySteps";
        case Status::TooManyEvents:
            return "TooManyEvents";
        case Status::NonFiniteResult:
            return "NonFiniteResult";
        case Status::InvalidAlgorithm:
            return "InvalidAlgorithm";
        case Status::InvalidSpeed:
            return "InvalidSpeed";
        case Status::InvalidFuse:
            return "InvalidFuse";
        case Status::InvalidSetting:
            return "InvalidSetting";
        case Status::TimeWentBackwards:
            return "TimeWentBackwards";
        case Status::NoUpdate:
            return "NoUpdate";
        case Status::OutOfRange:
            return "OutOfRange";
    }
    return "?";
}

/// Throws Error("what: <statusMessage> (<StatusName>)") unless `status` is Ok.
void check(Status status, const std::string& what) {
    if (status != Status::Ok) throw Error(what + ": " + statusMessage(status) + " (" + statusName(status) + ")");
}

/// A ValueError naming the argument and the problem.
[[noreturn]] void badArgument(const std::string& name, const std::string& problem) {
    throw Error(name + ": " + problem);
}

/// The shape of an array as "(a, b)".
std::string shapeText(const py::array& a) {
    std::string text = "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i) text += (i ? ", " : "") + std::to_string(a.shape(i));
    return text + (a.ndim() == 1 ? ",)" : ")");
}

/// Any sequence of numbers as a contiguous float64 array (raises Error when it is not numbers).
py::array_t<double, py::array::c_style | py::array::forcecast> numbers(py::handle object, const std::string& name) {
    auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(object);
    if (!a) badArgument(name, "expected numbers");
    return a;
}

/// `value` as a T: a double beyond the float range becomes an infinity (which the library
/// refuses) instead of an undefined conversion.
template <typename T>
T narrow(double value) {
    if constexpr (std::is_same_v<T, float>) {
        if (value > static_cast<double>(std::numeric_limits<float>::max()))
            return std::numeric_limits<float>::infinity();
        if (value < -static_cast<double>(std::numeric_limits<float>::max()))
            return -std::numeric_limits<float>::infinity();
    }
    return static_cast<T>(value);
}

/// `N` numbers from a sequence (tuple, list, NumPy array).
template <int N>
std::array<double, N> fixedNumbers(py::handle object, const std::string& name) {
    auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(object);
    if (!a) badArgument(name, "expected a sequence of " + std::to_string(N) + " numbers");
    if (a.ndim() != 1 || a.shape(0) != N)
        badArgument(name, "expected " + std::to_string(N) + " numbers, got shape " + shapeText(a));
    std::array<double, N> r{};
    for (int i = 0; i < N; ++i) r[static_cast<std::size_t>(i)] = a.at(i);
    return r;
}

/// A float vector (velocity, direction) from 3 numbers; `name` names the argument in errors.
Vec3 toVec3(py::handle object, const std::string& name) {
    const auto v = fixedNumbers<3>(object, name);
    return Vec3(narrow<float>(v[0]), narrow<float>(v[1]), narrow<float>(v[2]));
}

/// A position (Real) from 3 numbers; `name` names the argument in errors.
RVec3 toRVec3(py::handle object, const std::string& name) {
    const auto v = fixedNumbers<3>(object, name);
    return RVec3(narrow<Real>(v[0]), narrow<Real>(v[1]), narrow<Real>(v[2]));
}

/// A quaternion from (x, y, z, w).
Quat toQuat(py::handle object, const std::string& name) {
    const auto v = fixedNumbers<4>(object, name);
    Quat q;
    q.x = narrow<float>(v[0]);
    q.y = narrow<float>(v[1]);
    q.z = narrow<float>(v[2]);
    q.w = narrow<float>(v[3]);
    return q;
}

template <typename T>
py::array_t<T> fromVec(const glm::vec<3, T, glm::defaultp>& v) {
    py::array_t<T> a(3);
    auto m = a.template mutable_unchecked<1>();
    m(0) = v.x;
    m(1) = v.y;
    m(2) = v.z;
    return a;
}

/// A quaternion as (x, y, z, w).
py::array_t<float> fromQuat(const Quat& q) {
    py::array_t<float> a(4);
    auto m = a.mutable_unchecked<1>();
    m(0) = q.x;
    m(1) = q.y;
    m(2) = q.z;
    m(3) = q.w;
    return a;
}

/// The shortest text that reads back as `value` (std::to_chars), in Python's style: "2.5", "0.0",
/// "1e-07", "inf". A float is shown as a float (0.05f is "0.05", not 0.05000000074505806).
template <typename T>
std::string floatText(T value) {
    std::array<char, 64> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    std::string text(buffer.data(), result.ptr);
    if (text.find_first_of(".ein") == std::string::npos) text += ".0";
    return text;
}

/// "(1.0, 2.0, 3.0)": the components of a glm vector.
template <typename V>
std::string vecText(const V& v) {
    std::string text = "(";
    for (int i = 0; i < V::length(); ++i) text += (i ? ", " : "") + floatText(v[i]);
    return text + ")";
}

/// "(x, y, z, w)".
std::string quatText(const Quat& q) { return vecText(glm::vec4(q.x, q.y, q.z, q.w)); }

/// A time or scalar argument as the library's float (the library checks its range).
float toFloat(double value) { return narrow<float>(value); }

// Properties that read and write glm vectors as NumPy arrays / sequences.
#define FS_VEC3(cls, Type, name, member, doc)                        \
    cls.def_property(                                                \
        name, [](const Type& self) { return fromVec(self.member); }, \
        [](Type& self, py::handle v) { self.member = toVec3(v, name); }, doc)
#define FS_RVEC3(cls, Type, name, member, doc)                       \
    cls.def_property(                                                \
        name, [](const Type& self) { return fromVec(self.member); }, \
        [](Type& self, py::handle v) { self.member = toRVec3(v, name); }, doc)
#define FS_QUAT(cls, Type, name, member, doc)                         \
    cls.def_property(                                                 \
        name, [](const Type& self) { return fromQuat(self.member); }, \
        [](Type& self, py::handle v) { self.member = toQuat(v, name); }, doc)

// ---------------------------------------------------------------------------------------------
// Projectiles

/// A predicted trajectory as NumPy arrays (copies, owned by this object).
struct Trajectory {
    py::array_t<float> times;             ///< (N,) [s]
    py::array_t<std::uint8_t> events;     ///< (N,) TrajectoryEvent values
    py::array_t<Real> positions;          ///< (N, 3) [m]
    py::array_t<float> velocities;        ///< (N, 3) [m/s]
    py::array_t<float> normals;           ///< (N, 3)
    std::vector<TrajectoryPoint> points;  ///< the library's own points (for danger queries)

    explicit Trajectory(std::vector<TrajectoryPoint> p) : points(std::move(p)) {
        const auto n = static_cast<py::ssize_t>(points.size());
        times = py::array_t<float>(n);
        events = py::array_t<std::uint8_t>(n);
        positions = py::array_t<Real>({n, py::ssize_t{3}});
        velocities = py::array_t<float>({n, py::ssize_t{3}});
        normals = py::array_t<float>({n, py::ssize_t{3}});
        auto t = times.mutable_unchecked<1>();
        auto e = events.mutable_unchecked<1>();
        auto pos = positions.mutable_unchecked<2>();
        auto vel = velocities.mutable_unchecked<2>();
        auto nor = normals.mutable_unchecked<2>();
        for (py::ssize_t i = 0; i < n; ++i) {
            const TrajectoryPoint& point = points[static_cast<std::size_t>(i)];
            t(i) = point.time;
            e(i) = static_cast<std::uint8_t>(point.event);
            for (int k = 0; k < 3; ++k) {
                pos(i, k) = point.position[k];
                vel(i, k) = point.velocity[k];
                nor(i, k) = point.normal[k];
            }
        }
        for (py::array* a :
             {static_cast<py::array*>(&times), static_cast<py::array*>(&events), static_cast<py::array*>(&positions),
              static_cast<py::array*>(&velocities), static_cast<py::array*>(&normals)})
            a->attr("setflags")(py::arg("write") = false);
    }
};

/// ProjectileResult plus its trajectory.
struct PyProjectileResult {
    ProjectileResult result;
    std::shared_ptr<Trajectory> trajectory;
};

PyProjectileResult predictProjectilePy(py::handle position, py::handle velocity, double time,
                                       const ProjectileSettings& settings, const CollisionWorld* world) {
    const RVec3 p = toRVec3(position, "position");
    const Vec3 v = toVec3(velocity, "velocity");
    const float t = toFloat(time);
    // Validate first so that the capacity below is computed from valid settings and time.
    check(validateProjectileSettings(settings), "predict_projectile");
    if (std::isnan(t) || std::isinf(t)) check(Status::NonFiniteInput, "predict_projectile");
    if (t < 0.0f) check(Status::NegativeTime, "predict_projectile");
    std::vector<TrajectoryPoint> points;
    PyProjectileResult r;
    Status status = Status::Ok;
    {
        // Without a world nothing shared is read: other Python threads may run meanwhile. A world
        // keeps the GIL, so that no thread adds shapes to it during the prediction.
        std::optional<py::gil_scoped_release> release;
        if (world == nullptr) release.emplace();
        // The first guess is capped (a long prediction the library will refuse with TooManySteps
        // allocates nothing big); a trajectory longer than it is predicted again at its full size.
        constexpr std::size_t kFirstCapacity = std::size_t{1} << 16;
        points.resize(std::clamp<std::size_t>(trajectoryCapacity(t, settings), 2, kFirstCapacity));
        status = predictProjectile(p, v, t, settings, world, points, r.result);
        if (status == Status::Ok && r.result.trajectoryNeeded > r.result.trajectorySize) {
            points.resize(r.result.trajectoryNeeded);
            status = predictProjectile(p, v, t, settings, world, points, r.result);
        }
    }
    check(status, "predict_projectile");
    points.resize(r.result.trajectorySize);
    r.trajectory = std::make_shared<Trajectory>(std::move(points));
    return r;
}

// ---------------------------------------------------------------------------------------------
// Dead reckoning

/// The median of `repeats` runs of `run` [Units: s], without the GIL.
template <typename Run>
double medianSeconds(int repeats, Run&& run) {
    std::vector<double> samples;
    py::gil_scoped_release release;
    for (int i = 0; i < std::max(repeats, 1); ++i) {
        const auto start = std::chrono::steady_clock::now();
        run();
        samples.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::nth_element(samples.begin(), samples.begin() + static_cast<std::ptrdiff_t>(samples.size() / 2), samples.end());
    return samples[samples.size() / 2];
}

/// Reads the batch arrays, checks their shapes, and fills DeadReckoningState values.
struct BatchInput {
    template <typename T>
    using Array = py::array_t<T, py::array::c_style | py::array::forcecast>;
    Array<std::int64_t> algorithms;
    Array<double> timestamps;
    /// The vector arrays, all float32 (`single`: read as they are, half the bytes of float64) or
    /// all converted to float64.
    bool single = false;
    Array<double> positions, velocities, accelerations, orientations, angularVelocities;
    Array<float> positionsF, velocitiesF, accelerationsF, orientationsF, angularVelocitiesF;
    std::size_t count = 0;

    BatchInput(py::handle alg, py::handle pos, py::handle vel, py::handle acc, py::handle ori, py::handle ang,
               py::handle stamps) {
        algorithms = Array<std::int64_t>::ensure(alg);
        if (!algorithms) badArgument("algorithms", "expected integers (DeadReckoningAlgorithm values)");
        if (algorithms.ndim() != 1) badArgument("algorithms", "expected shape (N,), got " + shapeText(algorithms));
        count = static_cast<std::size_t>(algorithms.shape(0));
        single = true;
        for (py::handle h : {pos, vel, acc, ori, ang}) single = single && py::isinstance<py::array_t<float>>(h);
        if (single) {
            positionsF = rows<float>(pos, "positions", 3);
            velocitiesF = rows<float>(vel, "velocities", 3);
            accelerationsF = rows<float>(acc, "accelerations", 3);
            orientationsF = rows<float>(ori, "orientations", 4);
            angularVelocitiesF = rows<float>(ang, "angular_velocities", 3);
        } else {
            positions = rows<double>(pos, "positions", 3);
            velocities = rows<double>(vel, "velocities", 3);
            accelerations = rows<double>(acc, "accelerations", 3);
            orientations = rows<double>(ori, "orientations", 4);
            angularVelocities = rows<double>(ang, "angular_velocities", 3);
        }
        timestamps = numbers(stamps, "timestamps");
        if (timestamps.ndim() != 1 || static_cast<std::size_t>(timestamps.shape(0)) != count)
            badArgument("timestamps", "expected shape (" + std::to_string(count) + ",), got " + shapeText(timestamps));
    }

    template <typename T>
    Array<T> rows(py::handle object, const char* name, py::ssize_t width) const {
        auto a = Array<T>::ensure(object);
        if (!a) badArgument(name, "expected numbers");
        if (a.ndim() != 2 || static_cast<std::size_t>(a.shape(0)) != count || a.shape(1) != width)
            badArgument(name, "expected shape (" + std::to_string(count) + ", " + std::to_string(width) + "), got " +
                                  shapeText(a));
        return a;
    }

    /// Entity i's state, read from the arrays' raw data (shapes checked by the constructor).
    DeadReckoningState state(std::size_t i) const {
        return single ? read(i, positionsF, velocitiesF, accelerationsF, orientationsF, angularVelocitiesF)
                      : read(i, positions, velocities, accelerations, orientations, angularVelocities);
    }

    template <typename T>
    DeadReckoningState read(std::size_t i, const Array<T>& pos, const Array<T>& vel, const Array<T>& acc,
                            const Array<T>& ori, const Array<T>& ang) const {
        DeadReckoningState s;
        const std::int64_t algorithm = algorithms.data()[i];
        // Out-of-range values become 0, which the library refuses as InvalidAlgorithm.
        s.algorithm = static_cast<DeadReckoningAlgorithm>(algorithm >= 1 && algorithm <= 9 ? algorithm : 0);
        const T* p = pos.data() + 3 * i;
        const T* v = vel.data() + 3 * i;
        const T* a = acc.data() + 3 * i;
        const T* q = ori.data() + 4 * i;
        const T* w = ang.data() + 3 * i;
        s.position = RVec3(narrow<Real>(p[0]), narrow<Real>(p[1]), narrow<Real>(p[2]));
        s.velocity = Vec3(narrow<float>(v[0]), narrow<float>(v[1]), narrow<float>(v[2]));
        s.acceleration = Vec3(narrow<float>(a[0]), narrow<float>(a[1]), narrow<float>(a[2]));
        s.orientation.x = narrow<float>(q[0]);
        s.orientation.y = narrow<float>(q[1]);
        s.orientation.z = narrow<float>(q[2]);
        s.orientation.w = narrow<float>(q[3]);
        s.angularVelocity = Vec3(narrow<float>(w[0]), narrow<float>(w[1]), narrow<float>(w[2]));
        return s;
    }
};

/// A capsule that keeps a std::vector<DeadReckoningResult> alive for the views on it.
py::capsule ownerOf(std::shared_ptr<std::vector<DeadReckoningResult>> results) {
    auto* holder = new std::shared_ptr<std::vector<DeadReckoningResult>>(std::move(results));
    return py::capsule(holder,
                       [](void* p) { delete static_cast<std::shared_ptr<std::vector<DeadReckoningResult>>*>(p); });
}

/// Views (no copy) of the results' positions (N, 3), velocities (N, 3), orientations (N, 4).
py::tuple resultViews(const std::shared_ptr<std::vector<DeadReckoningResult>>& results, bool writable) {
    static_assert(offsetof(Quat, x) == 0 && offsetof(Quat, w) == 3 * sizeof(float),
                  "quaternions are stored (x, y, z, w)");
    const auto n = static_cast<py::ssize_t>(results->size());
    const auto stride = static_cast<py::ssize_t>(sizeof(DeadReckoningResult));
    auto* base = reinterpret_cast<char*>(results->data());
    py::capsule owner = ownerOf(results);
    py::array_t<Real> positions({n, py::ssize_t{3}}, {stride, py::ssize_t{sizeof(Real)}},
                                reinterpret_cast<Real*>(base + offsetof(DeadReckoningResult, position)), owner);
    py::array_t<float> velocities({n, py::ssize_t{3}}, {stride, py::ssize_t{sizeof(float)}},
                                  reinterpret_cast<float*>(base + offsetof(DeadReckoningResult, velocity)), owner);
    py::array_t<float> orientations({n, py::ssize_t{4}}, {stride, py::ssize_t{sizeof(float)}},
                                    reinterpret_cast<float*>(base + offsetof(DeadReckoningResult, orientation)), owner);
    if (!writable) {
        for (py::array* a : {static_cast<py::array*>(&positions), static_cast<py::array*>(&velocities),
                             static_cast<py::array*>(&orientations)})
            a->attr("setflags")(py::arg("write") = false);
    }
    return py::make_tuple(positions, velocities, orientations);
}

/// The Python DeadReckoningBatch: the library's structure-of-arrays batch and its output buffer.
class PyDeadReckoningBatch {
public:
    explicit PyDeadReckoningBatch(std::size_t capacity)
        : mBatch(capacity), mResults(std::make_shared<std::vector<DeadReckoningResult>>(capacity)) {
        refreshViews();
    }

    /// The number of entities.
    std::size_t capacity() const { return mBatch.capacity(); }

    /// Prepares and sets every entity from the arrays (all or nothing).
    void setAll(py::handle alg, py::handle pos, py::handle vel, py::handle acc, py::handle ori, py::handle ang,
                py::handle stamps) {
        const BatchInput in(alg, pos, vel, acc, ori, ang, stamps);
        if (in.count != mBatch.capacity())
            badArgument("algorithms",
                        "expected " + std::to_string(mBatch.capacity()) + " entities, got " + std::to_string(in.count));
        // Prepare every entity first, so that a refused one leaves the batch unchanged.
        std::vector<PreparedDeadReckoning> prepared(in.count);
        for (std::size_t i = 0; i < in.count; ++i) {
            const Status status = prepareDeadReckoning(in.state(i), in.timestamps.data()[i], prepared[i]);
            check(status, "DeadReckoningBatch.set_all: entity " + std::to_string(i));
        }
        for (std::size_t i = 0; i < in.count; ++i) mBatch.set(i, prepared[i]);
    }

    /// Prepares and sets one entity.
    void set(std::size_t entity, const DeadReckoningState& state, double timestamp) {
        if (entity >= mBatch.capacity())
            badArgument("entity",
                        std::to_string(entity) + " is not below the capacity " + std::to_string(mBatch.capacity()));
        PreparedDeadReckoning prepared;
        check(prepareDeadReckoning(state, timestamp, prepared), "DeadReckoningBatch.set");
        check(mBatch.set(entity, prepared), "DeadReckoningBatch.set");
    }

    /// One frame: every entity to `time`; returns the refused count.
    std::size_t extrapolate(double time, double limit) {
        if (!std::isfinite(time)) check(Status::NonFiniteInput, "DeadReckoningBatch.extrapolate: time");
        if (std::isnan(limit) || limit < 0)
            badArgument("DeadReckoningBatch.extrapolate: extrapolation_limit", "must be >= 0 (inf disables it)");
        // The GIL stays held: no other thread can set() an entity during the frame.
        return mBatch.extrapolate(time, narrow<float>(limit), *mResults);
    }

    /// C++ reference timing: the median of `repeats` calls of DeadReckoningBatch::extrapolate
    /// made from C++ on this batch [Units: s].
    double timeExtrapolate(double time, double limit, int repeats) {
        return medianSeconds(repeats, [&] { mBatch.extrapolate(time, static_cast<float>(limit), *mResults); });
    }

    /// (positions, velocities, orientations): read-only views of the output buffer.
    const py::tuple& views() const { return mViews; }

private:
    void refreshViews() { mViews = resultViews(mResults, false); }

    DeadReckoningBatch mBatch;
    std::shared_ptr<std::vector<DeadReckoningResult>> mResults;
    py::tuple mViews;
};

py::tuple predictDeadReckoningBatchPy(py::handle alg, py::handle pos, py::handle vel, py::handle acc, py::handle ori,
                                      py::handle ang, py::handle stamps, double time) {
    const BatchInput in(alg, pos, vel, acc, ori, ang, stamps);
    if (std::isnan(time)) check(Status::NonFiniteInput, "predict_dead_reckoning_batch: time");
    auto results = std::make_shared<std::vector<DeadReckoningResult>>(in.count);
    std::size_t refused = 0;
    {
        py::gil_scoped_release release;
        // Converted and extrapolated in chunks small enough to stay in the cache: the library
        // reads each chunk's states right after they are written (entities are independent, so
        // the results are those of one call over all of them).
        constexpr std::size_t kChunk = 512;
        std::array<DeadReckoningState, kChunk> states;
        const std::span<const double> timestamps(in.timestamps.data(), in.count);
        for (std::size_t first = 0; first < in.count; first += kChunk) {
            const std::size_t size = std::min(kChunk, in.count - first);
            for (std::size_t i = 0; i < size; ++i) states[i] = in.state(first + i);
            refused += predictDeadReckoningBatch(std::span<const DeadReckoningState>(states.data(), size),
                                                 timestamps.subspan(first, size), time,
                                                 std::span<DeadReckoningResult>(*results).subspan(first, size));
        }
    }
    py::tuple views = resultViews(results, true);
    return py::make_tuple(views[0], views[1], views[2], refused);
}

/// Benchmark helper: predictDeadReckoningBatch timed from C++ on the states of the arrays
/// (converted once, not timed) [Units: s], the reference of predict_dead_reckoning_batch.
double timeCppPredictBatch(py::handle alg, py::handle pos, py::handle vel, py::handle acc, py::handle ori,
                           py::handle ang, py::handle stamps, double time, int repeats) {
    const BatchInput in(alg, pos, vel, acc, ori, ang, stamps);
    std::vector<DeadReckoningState> states(in.count);
    for (std::size_t i = 0; i < in.count; ++i) states[i] = in.state(i);
    std::vector<double> timestamps(in.timestamps.data(), in.timestamps.data() + in.count);
    std::vector<DeadReckoningResult> out(in.count);
    return medianSeconds(repeats, [&] { predictDeadReckoningBatch(states, timestamps, time, out); });
}

}  // namespace

PYBIND11_MODULE(foresight, m) {
    m.doc() =
        "foresight: predicts where moving things in games will be (characters, projectiles, vehicles,\n"
        "replicated entities).\n\n"
        "Units: metres, seconds, radians. Axes: +Y up, +Z forward. Vectors: any sequence of 3 numbers\n"
        "(tuple, list, NumPy array); results are NumPy arrays (float32; positions float32, or float64\n"
        "in a double-precision build). Quaternions are (x, y, z, w), scalar last (as scipy's\n"
        "Rotation.from_quat). Refused input raises foresight.Error (a ValueError) carrying the\n"
        "library's status message.";

    static py::exception<Error> error(m, "Error", PyExc_ValueError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const Error& e) {
            error(e.what());
        }
    });

    m.attr("__version__") = FORESIGHT_VERSION_STRING;
    m.def("version", &versionString, "The version of the compiled library, e.g. '0.1.0'.");
    m.attr("DOUBLE_PRECISION") = kDoublePrecision;
    m.attr("MAX_COORDINATE") = kMaxCoordinate;
    m.attr("MAX_SPEED") = kMaxSpeed;
    m.attr("DEFAULT_GRAVITY") = kDefaultGravity;

    // Status -------------------------------------------------------------------------------
    py::enum_<Status> status(m, "Status", "Why the library refused an input (foresight.Error names it).");
    for (int i = 0; i <= static_cast<int>(Status::OutOfRange); ++i) {
        const auto s = static_cast<Status>(i);
        status.value(statusName(s), s);
    }
    m.def("status_message", &statusMessage, py::arg("status"),
          "A short English description of a Status, e.g. 'time must be >= 0'.");

    // Characters ---------------------------------------------------------------------------
    py::class_<PointState> pointState(m, "PointState", "Position [m] and velocity [m/s] of a moving point.");
    pointState.def(py::init([](py::handle position, py::handle velocity) {
                       PointState s;
                       s.position = toRVec3(position, "position");
                       s.velocity = toVec3(velocity, "velocity");
                       return s;
                   }),
                   py::arg("position") = py::make_tuple(0, 0, 0), py::arg("velocity") = py::make_tuple(0, 0, 0));
    FS_RVEC3(pointState, PointState, "position", position, "Position [m], world axes.");
    FS_VEC3(pointState, PointState, "velocity", velocity, "Velocity [m/s], world axes.");
    pointState.def("__repr__", [](const PointState& s) {
        return "PointState(position=" + vecText(s.position) + ", velocity=" + vecText(s.velocity) + ")";
    });

    m.def(
        "predict_linear",
        [](py::handle position, py::handle velocity, double time) {
            PointState start, out;
            start.position = toRVec3(position, "position");
            start.velocity = toVec3(velocity, "velocity");
            check(predictLinear(start, toFloat(time), out), "predict_linear");
            return out;
        },
        py::arg("position"), py::arg("velocity"), py::arg("time"),
        "Constant-velocity prediction: position p + v t [m], velocity unchanged [m/s].\n"
        "position [m], velocity [m/s], time [s] (>= 0). Returns a PointState.");
    m.def(
        "predict_accelerated",
        [](py::handle position, py::handle velocity, py::handle acceleration, double time) {
            PointState start, out;
            start.position = toRVec3(position, "position");
            start.velocity = toVec3(velocity, "velocity");
            check(predictAccelerated(start, toVec3(acceleration, "acceleration"), toFloat(time), out),
                  "predict_accelerated");
            return out;
        },
        py::arg("position"), py::arg("velocity"), py::arg("acceleration"), py::arg("time"),
        "Constant-acceleration prediction: position p + v t + a t^2 / 2 [m], velocity v + a t [m/s].\n"
        "position [m], velocity [m/s], acceleration [m/s^2], time [s] (>= 0). Returns a PointState.");

    // Orientation --------------------------------------------------------------------------
    py::enum_<AngularFrame>(m, "AngularFrame", "The axes an angular velocity is expressed in.")
        .value("Body", AngularFrame::Body, "the object's own axes: q' = q * r (the article)")
        .value("World", AngularFrame::World, "world axes: q' = r * q");
    m.def(
        "rotation_from_angular_velocity",
        [](py::handle w, double time) {
            return fromQuat(rotationFromAngularVelocity(toVec3(w, "angular_velocity"), toFloat(time)));
        },
        py::arg("angular_velocity"), py::arg("time"),
        "The rotation (x, y, z, w) of turning at angular_velocity [rad/s] for time [s]: angle |w| t about w / |w|.");
    m.def(
        "compose_rotation",
        [](py::handle q, py::handle r, AngularFrame frame) {
            return fromQuat(composeRotation(toQuat(q, "orientation"), toQuat(r, "rotation"), frame));
        },
        py::arg("orientation"), py::arg("rotation"), py::arg("frame") = AngularFrame::Body,
        "orientation * rotation (Body) or rotation * orientation (World), renormalised; quaternions (x, y, z, w).");
    m.def(
        "predict_orientation",
        [](py::handle q, py::handle w, double time, AngularFrame frame) {
            Quat out;
            check(
                predictOrientation(toQuat(q, "orientation"), toVec3(w, "angular_velocity"), frame, toFloat(time), out),
                "predict_orientation");
            return fromQuat(out);
        },
        py::arg("orientation"), py::arg("angular_velocity"), py::arg("time"), py::arg("frame") = AngularFrame::Body,
        "Orientation (x, y, z, w) after time [s] (>= 0) of constant angular_velocity [rad/s] in `frame` axes.");
    m.def(
        "normalize_quaternion",
        [](py::handle q) {
            Quat out;
            check(normalizeQuaternion(toQuat(q, "quaternion"), out), "normalize_quaternion");
            return fromQuat(out);
        },
        py::arg("quaternion"), "The unit quaternion (x, y, z, w); refuses a zero or non-finite one.");

    // Vehicles -----------------------------------------------------------------------------
    py::class_<VehicleSettings> vehicleSettings(m, "VehicleSettings", "How to interpret a VehicleState.");
    vehicleSettings
        .def(py::init([](AngularFrame frame, py::handle forward) {
                 VehicleSettings s;
                 s.frame = frame;
                 s.forward = toVec3(forward, "forward");
                 return s;
             }),
             py::arg("frame") = AngularFrame::Body, py::arg("forward") = py::make_tuple(0, 0, 1))
        .def_readwrite("frame", &VehicleSettings::frame, "Axes of the angular velocity (Body: the article).");
    FS_VEC3(vehicleSettings, VehicleSettings, "forward", forward, "Local forward axis (non-zero; article: +Z).");
    vehicleSettings.def("__repr__", [](const VehicleSettings& s) {
        return std::string("VehicleSettings(frame=") + (s.frame == AngularFrame::Body ? "Body" : "World") +
               ", forward=" + vecText(s.forward) + ")";
    });

    py::class_<VehicleState> vehicleState(m, "VehicleState", "The kinematic state of a vehicle.");
    vehicleState.def(py::init([](py::handle position, py::handle velocity, py::handle orientation, py::handle w) {
                         VehicleState s;
                         s.position = toRVec3(position, "position");
                         s.velocity = toVec3(velocity, "velocity");
                         s.orientation = toQuat(orientation, "orientation");
                         s.angularVelocity = toVec3(w, "angular_velocity");
                         return s;
                     }),
                     py::arg("position") = py::make_tuple(0, 0, 0), py::arg("velocity") = py::make_tuple(0, 0, 0),
                     py::arg("orientation") = py::make_tuple(0, 0, 0, 1),
                     py::arg("angular_velocity") = py::make_tuple(0, 0, 0));
    FS_RVEC3(vehicleState, VehicleState, "position", position, "Position [m], world axes.");
    FS_VEC3(vehicleState, VehicleState, "velocity", velocity, "Velocity [m/s], world axes.");
    FS_QUAT(vehicleState, VehicleState, "orientation", orientation, "Local-to-world rotation (x, y, z, w).");
    FS_VEC3(vehicleState, VehicleState, "angular_velocity", angularVelocity,
            "Angular velocity [rad/s], in the axes of VehicleSettings.frame.");
    vehicleState.def("__repr__", [](const VehicleState& s) {
        return "VehicleState(position=" + vecText(s.position) + ", velocity=" + vecText(s.velocity) +
               ", orientation=" + quatText(s.orientation) + ", angular_velocity=" + vecText(s.angularVelocity) + ")";
    });
    m.attr("MAX_VEHICLE_ITERATIONS") = kMaxVehicleIterations;
    m.def(
        "signed_vehicle_speed",
        [](py::handle v, py::handle f) {
            return signedVehicleSpeed(toVec3(v, "velocity"), toVec3(f, "forward_world"));
        },
        py::arg("velocity"), py::arg("forward_world"),
        "|velocity| [m/s], negative when the vehicle moves backwards relative to forward_world.");
    m.def(
        "predict_vehicle_iterative",
        [](const VehicleState& start, double time, int iterations, const VehicleSettings& settings) {
            VehicleState out;
            check(predictVehicleIterative(start, toFloat(time), iterations, settings, out),
                  "predict_vehicle_iterative");
            return out;
        },
        py::arg("start"), py::arg("time"), py::arg("iterations") = 4, py::arg("settings") = VehicleSettings(),
        "The article's loop: `iterations` equal steps (1 .. MAX_VEHICLE_ITERATIONS; the article uses 4)\n"
        "over time [s] (>= 0), each moving then turning. Returns a VehicleState.");
    m.def(
        "predict_vehicle_exact",
        [](const VehicleState& start, double time, const VehicleSettings& settings) {
            VehicleState out;
            check(predictVehicleExact(start, toFloat(time), settings, out), "predict_vehicle_exact");
            return out;
        },
        py::arg("start"), py::arg("time"), py::arg("settings") = VehicleSettings(),
        "The exact arc of constant angular velocity and constant signed speed on the forward axis,\n"
        "time [s] (>= 0) ahead. Returns a VehicleState.");

    // World --------------------------------------------------------------------------------
    py::class_<SurfaceMaterial> surfaceMaterial(
        m, "SurfaceMaterial", "A surface's own material, used by ProjectileMethod.Engine (negative: none).");
    surfaceMaterial
        .def(py::init([](float restitution, float friction) {
                 SurfaceMaterial s;
                 s.restitution = restitution;
                 s.friction = friction;
                 return s;
             }),
             py::arg("restitution") = -1.0f, py::arg("friction") = -1.0f)
        .def_readwrite("restitution", &SurfaceMaterial::restitution, "0 .. 1, or negative: none.")
        .def_readwrite("friction", &SurfaceMaterial::friction, ">= 0, or negative: none.")
        .def("__repr__", [](const SurfaceMaterial& s) {
            return "SurfaceMaterial(restitution=" + floatText(s.restitution) + ", friction=" + floatText(s.friction) +
                   ")";
        });

    py::class_<CastHit> castHit(m, "CastHit", "The first hit of a segment (or swept sphere) cast.");
    castHit.def_readonly("fraction", &CastHit::fraction, "Where along the segment, 0 .. 1.")
        .def_readonly("restitution", &CastHit::restitution, "The surface's own restitution (negative: none).")
        .def_readonly("friction", &CastHit::friction, "The surface's own friction (negative: none).");
    castHit.def_property_readonly(
        "position", [](const CastHit& h) { return fromVec(h.position); },
        "The cast's origin point (sphere centre) at the hit [m].");
    castHit.def_property_readonly(
        "normal", [](const CastHit& h) { return fromVec(h.normal); },
        "Unit surface normal, facing against the motion.");
    castHit.def("__repr__", [](const CastHit& h) {
        return "CastHit(fraction=" + floatText(h.fraction) + ", position=" + vecText(h.position) +
               ", normal=" + vecText(h.normal) + ")";
    });

    py::class_<CollisionWorld>(m, "CollisionWorld", "A world projectiles bounce off (see StaticWorld).");
    py::class_<StaticWorld, CollisionWorld>(
        m, "StaticWorld",
        "The built-in static world: one-sided planes, spheres, oriented boxes, two-sided triangles.\n"
        "Shapes are validated when added (foresight.Error when refused).")
        .def(py::init([](float surfaceTolerance) {
                 StaticWorldSettings s;
                 s.surfaceTolerance = surfaceTolerance;
                 return std::make_unique<StaticWorld>(s);
             }),
             py::arg("surface_tolerance") = 1e-5f,
             "surface_tolerance [m]: how far behind a one-sided surface a cast moving into it still hits it.")
        .def(
            "add_plane",
            [](StaticWorld& w, py::handle normal, double distance, std::optional<SurfaceMaterial> material) {
                Plane p;
                p.normal = toVec3(normal, "normal");
                p.distance = narrow<Real>(distance);
                check(material ? w.add(p, *material) : w.add(p), "add_plane");
            },
            py::arg("normal"), py::arg("distance") = 0.0, py::arg("material") = py::none(),
            "Adds the one-sided plane dot(normal, x) = distance [m] (solid behind, normal non-zero).")
        .def(
            "add_sphere",
            [](StaticWorld& w, py::handle center, float radius, std::optional<SurfaceMaterial> material) {
                Sphere s;
                s.center = toRVec3(center, "center");
                s.radius = radius;
                check(material ? w.add(s, *material) : w.add(s), "add_sphere");
            },
            py::arg("center"), py::arg("radius"), py::arg("material") = py::none(),
            "Adds a solid sphere: center [m], radius [m] (> 0).")
        .def(
            "add_box",
            [](StaticWorld& w, py::handle center, py::handle halfExtents, py::handle orientation, float rounding,
               std::optional<SurfaceMaterial> material) {
                OrientedBox b;
                b.center = toRVec3(center, "center");
                b.halfExtents = toVec3(halfExtents, "half_extents");
                b.orientation = toQuat(orientation, "orientation");
                b.rounding = rounding;
                check(material ? w.add(b, *material) : w.add(b), "add_box");
            },
            py::arg("center"), py::arg("half_extents"), py::arg("orientation") = py::make_tuple(0, 0, 0, 1),
            py::arg("rounding") = 0.0f, py::arg("material") = py::none(),
            "Adds a solid box: center [m], half_extents [m] (> 0), orientation (x, y, z, w),\n"
            "rounding [m] of its edges (0 .. smallest half extent).")
        .def(
            "add_triangle",
            [](StaticWorld& w, py::handle a, py::handle b, py::handle c, std::optional<SurfaceMaterial> material) {
                Triangle t;
                t.a = toRVec3(a, "a");
                t.b = toRVec3(b, "b");
                t.c = toRVec3(c, "c");
                check(material ? w.add(t, *material) : w.add(t), "add_triangle");
            },
            py::arg("a"), py::arg("b"), py::arg("c"), py::arg("material") = py::none(),
            "Adds a two-sided triangle with vertices a, b, c [m] (non-zero area).")
        .def("clear", &StaticWorld::clear, "Removes every shape.")
        .def_property_readonly("shape_count", &StaticWorld::shapeCount, "Number of shapes of every kind.")
        .def(
            "cast_segment",
            [](const StaticWorld& w, py::handle origin, py::handle displacement, float radius) -> py::object {
                SegmentCast cast;
                cast.origin = toRVec3(origin, "origin");
                cast.displacement = toVec3(displacement, "displacement");
                cast.radius = radius;
                if (!(radius >= 0.0f)) badArgument("cast_segment: radius", "must be >= 0");
                CastHit hit;
                if (!w.castSegment(cast, hit)) return py::none();
                return py::cast(hit);
            },
            py::arg("origin"), py::arg("displacement"), py::arg("radius") = 0.0f,
            "The first hit of the segment origin .. origin + displacement [m] swept by a sphere of\n"
            "radius [m] (0: a point), or None.")
        .def("__len__", &StaticWorld::shapeCount)
        .def("__repr__", [](const StaticWorld& w) {
            return "StaticWorld(planes=" + std::to_string(w.planes().size()) +
                   ", spheres=" + std::to_string(w.spheres().size()) + ", boxes=" + std::to_string(w.boxes().size()) +
                   ", triangles=" + std::to_string(w.triangles().size()) + ")";
        });

    // Engine profiles ----------------------------------------------------------------------
    py::enum_<PhysicsEngine>(m, "PhysicsEngine", "Engines with a named profile (engine_profile()).")
        .value("Custom", PhysicsEngine::Custom)
        .value("Jolt", PhysicsEngine::Jolt)
        .value("PhysX", PhysicsEngine::PhysX)
        .value("Rapier", PhysicsEngine::Rapier)
        .value("Bullet", PhysicsEngine::Bullet)
        .value("Godot3", PhysicsEngine::Godot3)
        .value("Godot3Bullet", PhysicsEngine::Godot3Bullet)
        .value("Box2D", PhysicsEngine::Box2D);
    py::enum_<DampingOrder>(m, "DampingOrder", "Where the damping factor goes in a step.")
        .value("GravityThenDamping", DampingOrder::GravityThenDamping)
        .value("DampingThenGravity", DampingOrder::DampingThenGravity);
    py::enum_<DampingLaw>(m, "DampingLaw", "The damping factor's law.")
        .value("None_", DampingLaw::None)
        .value("LinearClamped", DampingLaw::LinearClamped)
        .value("Rational", DampingLaw::Rational)
        .value("Power", DampingLaw::Power);
    py::enum_<CombineRule>(m, "CombineRule", "How two materials' coefficients combine.")
        .value("Average", CombineRule::Average)
        .value("Min", CombineRule::Min)
        .value("Max", CombineRule::Max)
        .value("Multiply", CombineRule::Multiply)
        .value("GeometricMean", CombineRule::GeometricMean)
        .value("SumClamped", CombineRule::SumClamped);
    py::enum_<RestitutionBase>(m, "RestitutionBase", "Which velocity a bounce reflects.")
        .value("StepStart", RestitutionBase::StepStart)
        .value("AfterGravity", RestitutionBase::AfterGravity);
    py::enum_<FirstStepRule>(m, "FirstStepRule", "What a body's first step does.")
        .value("Normal", FirstStepRule::Normal)
        .value("NoGravity", FirstStepRule::NoGravity)
        .value("DampingOnly", FirstStepRule::DampingOnly);
    py::enum_<ContactMethod>(m, "ContactMethod", "When a contact starts to act.")
        .value("Speculative", ContactMethod::Speculative)
        .value("Penetration", ContactMethod::Penetration);

    py::class_<EngineProfile> profile(
        m, "EngineProfile",
        "How an engine steps a sphere and answers its contacts; every field can be overridden\n"
        "(see engine_profile.h for each field's meaning). Get a named one with engine_profile().");
    profile.def(py::init<>())
        .def_readwrite("engine", &EngineProfile::engine)
        .def_readwrite("timestep", &EngineProfile::timestep, "[s] 1e-5 .. 1")
        .def_readwrite("substeps", &EngineProfile::substeps, "1 .. 64")
        .def_readwrite("order", &EngineProfile::order)
        .def_readwrite("damping", &EngineProfile::damping)
        .def_readwrite("linear_damping", &EngineProfile::linearDamping, "[1/s] >= 0")
        .def_readwrite("added_linear_damping", &EngineProfile::addedLinearDamping, "[1/s] >= 0")
        .def_readwrite("angular_damping", &EngineProfile::angularDamping, "[1/s] >= 0")
        .def_readwrite("first_step", &EngineProfile::firstStep)
        .def_readwrite("restitution_threshold", &EngineProfile::restitutionThreshold, "[m/s] >= 0")
        .def_readwrite("restitution_base", &EngineProfile::restitutionBase)
        .def_readwrite("restitution_combine", &EngineProfile::restitutionCombine)
        .def_readwrite("friction_combine", &EngineProfile::frictionCombine)
        .def_readwrite("contact", &EngineProfile::contact)
        .def_readwrite("contact_distance", &EngineProfile::contactDistance, "[m] >= 0")
        .def_readwrite("penetration_slop", &EngineProfile::penetrationSlop, "[m] >= 0")
        .def_readwrite("position_correction", &EngineProfile::positionCorrection, "0 .. 1")
        .def_readwrite("correction_is_velocity", &EngineProfile::correctionIsVelocity)
        .def_readwrite("split_impulse_correction", &EngineProfile::splitImpulseCorrection, "0 .. 1")
        .def_readwrite("friction_warm_start", &EngineProfile::frictionWarmStart, "0 .. 1")
        .def_readwrite("max_linear_speed", &EngineProfile::maxLinearSpeed, "[m/s] > 0")
        .def_readwrite("max_step_distance", &EngineProfile::maxStepDistance, "[m] > 0")
        .def_readwrite("planar", &EngineProfile::planar)
        .def_readwrite("rotates", &EngineProfile::rotates)
        .def_readwrite("triangle_mesh", &EngineProfile::triangleMesh)
        .def(
            "validate", [](const EngineProfile& p) { check(validateEngineProfile(p), "EngineProfile"); },
            "Raises foresight.Error when a field is out of its range.")
        .def("__repr__", [](const EngineProfile& p) {
            return std::string("EngineProfile(engine=") + engineName(p.engine) + ", timestep=" + floatText(p.timestep) +
                   ", substeps=" + std::to_string(p.substeps) + ", linear_damping=" + floatText(p.linearDamping) + ")";
        });
    m.def("engine_profile", &engineProfile, py::arg("engine"),
          "The named profile of `engine` with the engine's own defaults (timestep 1/60 s).");
    m.def("ammo_js_profile", &ammoJsProfile,
          "Bullet as ammo.js 0.0.10 carries it (Bullet 2.83): Bullet's profile with no restitution "
          "threshold, friction_warm_start 0.85 and split_impulse_correction 0.8.");
    m.def("engine_name", &engineName, py::arg("engine"), "The profile's name, e.g. 'jolt'.");
    m.def("combine_material", &combineMaterial, py::arg("rule"), py::arg("a"), py::arg("b"),
          "The coefficient a contact uses for two materials under `rule`.");

    // Projectiles --------------------------------------------------------------------------
    py::enum_<ProjectileMethod>(m, "ProjectileMethod", "Which projectile integrator to run.")
        .value("Exact", ProjectileMethod::Exact, "event-driven, exact impact times (default)")
        .value("Stepped", ProjectileMethod::Stepped, "the reference article's fixed-step loop")
        .value("Engine", ProjectileMethod::Engine, "step for step as a physics engine (settings.engine)");
    // An enum.IntEnum (not a pybind11 enum): Trajectory.events is a uint8 array, and NumPy compares
    // it with an IntEnum member (events == TrajectoryEvent.Bounce) as with the int it is.
    {
        py::list members;
        for (const auto& [name, value] :
             {std::pair{"Start", TrajectoryEvent::Start}, std::pair{"Step", TrajectoryEvent::Step},
              std::pair{"Bounce", TrajectoryEvent::Bounce}, std::pair{"Rest", TrajectoryEvent::Rest},
              std::pair{"Hit", TrajectoryEvent::Hit}, std::pair{"End", TrajectoryEvent::End}})
            members.append(py::make_tuple(name, static_cast<int>(value)));
        py::object trajectoryEvent = py::module_::import("enum").attr("IntEnum")("TrajectoryEvent", members);
        trajectoryEvent.attr("__module__") = "foresight";
        trajectoryEvent.attr("__doc__") =
            "What a trajectory point marks (the values of Trajectory.events): Start (t = 0), Step, Bounce\n"
            "(an impact; has a normal), Rest (came to rest, Exact), Hit (stopped at an impact), End.";
        m.attr("TrajectoryEvent") = trajectoryEvent;
    }
    m.attr("UNLIMITED_BOUNCES") = kUnlimitedBounces;

    py::class_<ProjectileSettings> projectileSettings(m, "ProjectileSettings",
                                                      "How to predict a projectile; defaults follow the article.");
    projectileSettings
        .def(py::init([](ProjectileMethod method, py::handle gravity, float step, float restitution, float friction,
                         float radius, std::uint32_t maxBounces, std::optional<EngineProfile> engine) {
                 ProjectileSettings s;
                 s.method = method;
                 s.gravity = toVec3(gravity, "gravity");
                 s.step = step;
                 s.restitution = restitution;
                 s.friction = friction;
                 s.radius = radius;
                 s.maxBounces = maxBounces;
                 if (engine) s.engine = *engine;
                 return s;
             }),
             py::arg("method") = ProjectileMethod::Exact,
             py::arg("gravity") = py::make_tuple(0.0f, -kDefaultGravity, 0.0f), py::arg("step") = 0.02f,
             py::arg("restitution") = 0.5f, py::arg("friction") = 0.0f, py::arg("radius") = 0.0f,
             py::arg("max_bounces") = kUnlimitedBounces, py::arg("engine") = py::none())
        .def_readwrite("method", &ProjectileSettings::method)
        .def_readwrite("step", &ProjectileSettings::step, "Time step [s] (> 0); Exact records a point per step.")
        .def_readwrite("restitution", &ProjectileSettings::restitution, "Coefficient of restitution, 0 .. 1.")
        .def_readwrite("friction", &ProjectileSettings::friction, "Coulomb friction coefficient (>= 0).")
        .def_readwrite("radius", &ProjectileSettings::radius, "[m] 0: a point; > 0: a sphere.")
        .def_readwrite("max_bounces", &ProjectileSettings::maxBounces, "Bounces allowed; the next impact ends it.")
        .def_readwrite("max_steps", &ProjectileSettings::maxSteps, "Work cap on steps (TooManySteps).")
        .def_readwrite("max_events", &ProjectileSettings::maxEvents, "Work cap on events, Exact (TooManyEvents).")
        .def_readwrite("engine", &ProjectileSettings::engine,
                       "The EngineProfile (method Engine). Note: settings.engine returns a copy; assign a\n"
                       "modified profile back (p = s.engine; p.linear_damping = 0.1; s.engine = p).");
    FS_VEC3(projectileSettings, ProjectileSettings, "gravity", gravity, "[m/s^2], world axes (default (0, -9.81, 0)).");
    projectileSettings.def("__repr__", [](const ProjectileSettings& s) {
        const char* method = s.method == ProjectileMethod::Exact     ? "Exact"
                             : s.method == ProjectileMethod::Stepped ? "Stepped"
                                                                     : "Engine";
        return std::string("ProjectileSettings(method=") + method + ", gravity=" + vecText(s.gravity) +
               ", step=" + floatText(s.step) + ", restitution=" + floatText(s.restitution) +
               ", friction=" + floatText(s.friction) + ", radius=" + floatText(s.radius) +
               ", engine=" + engineName(s.engine.engine) + ")";
    });

    py::class_<Trajectory, std::shared_ptr<Trajectory>>(m, "Trajectory",
                                                        "A predicted trajectory as read-only NumPy arrays of N points.")
        .def_readonly("times", &Trajectory::times, "(N,) float32 [s] since the start.")
        .def_readonly("events", &Trajectory::events, "(N,) uint8 TrajectoryEvent values.")
        .def_readonly("positions", &Trajectory::positions, "(N, 3) [m].")
        .def_readonly("velocities", &Trajectory::velocities, "(N, 3) [m/s] (after the bounce at Bounce points).")
        .def_readonly("normals", &Trajectory::normals, "(N, 3) surface normals at Bounce and Hit points, else 0.")
        .def("__len__", [](const Trajectory& t) { return t.points.size(); })
        .def("__repr__",
             [](const Trajectory& t) { return "Trajectory(" + std::to_string(t.points.size()) + " points)"; });

    py::class_<PyProjectileResult>(m, "ProjectileResult", "The outcome of predict_projectile.")
        .def_property_readonly(
            "position", [](const PyProjectileResult& r) { return fromVec(r.result.position); }, "Final position [m].")
        .def_property_readonly(
            "velocity", [](const PyProjectileResult& r) { return fromVec(r.result.velocity); }, "Final velocity [m/s].")
        .def_property_readonly(
            "time", [](const PyProjectileResult& r) { return r.result.time; },
            "Time reached [s] (the impact time when stopped_at_hit).")
        .def_property_readonly("bounces", [](const PyProjectileResult& r) { return r.result.bounces; })
        .def_property_readonly("at_rest", [](const PyProjectileResult& r) { return r.result.atRest; })
        .def_property_readonly("stopped_at_hit", [](const PyProjectileResult& r) { return r.result.stoppedAtHit; })
        .def_property_readonly(
            "hit_normal", [](const PyProjectileResult& r) { return fromVec(r.result.hitNormal); },
            "Normal of the last impact (zero if none).")
        .def_readonly("trajectory", &PyProjectileResult::trajectory, "The whole trajectory (Trajectory).")
        .def("__repr__", [](const PyProjectileResult& r) {
            return "ProjectileResult(position=" + vecText(r.result.position) +
                   ", velocity=" + vecText(r.result.velocity) + ", time=" + floatText(r.result.time) +
                   ", bounces=" + std::to_string(r.result.bounces) +
                   ", at_rest=" + (r.result.atRest ? "True" : "False") +
                   ", points=" + std::to_string(r.trajectory->points.size()) + ")";
        });

    m.def("predict_projectile", &predictProjectilePy, py::arg("position"), py::arg("velocity"), py::arg("time"),
          py::arg("settings") = ProjectileSettings(), py::arg("world") = nullptr,
          "Predicts a projectile from position [m] (the sphere's centre when radius > 0) with velocity\n"
          "[m/s] for time [s] (>= 0, e.g. a fuse) bouncing off `world` (None: free flight).\n"
          "Returns a ProjectileResult with the whole trajectory as NumPy arrays.");
    m.def("trajectory_capacity", &trajectoryCapacity, py::arg("time"), py::arg("settings"),
          py::arg("expected_events") = 64, "Points always enough for Stepped, and for Exact with that many events.");
    m.def("stepped_step_count", &steppedStepCount, py::arg("time"), py::arg("step"),
          "ceil(time / step) on the decimal values: the Stepped method's step count.");

    py::enum_<RenderSmoothing>(m, "RenderSmoothing", "How a game shows a body between its fixed physics steps.")
        .value("None_", RenderSmoothing::None, "the last completed step")
        .value("Interpolate", RenderSmoothing::Interpolate, "between the last two steps, one step behind")
        .value("Extrapolate", RenderSmoothing::Extrapolate, "the last step moved on with its velocity");
    m.def(
        "rendered_position",
        [](const Trajectory& trajectory, float step, float renderTime, RenderSmoothing smoothing) {
            if (!(step > 0.0f) || !std::isfinite(step)) check(Status::InvalidStep, "rendered_position");
            return fromVec(renderedPosition(trajectory.points, step, renderTime, smoothing));
        },
        py::arg("trajectory"), py::arg("step"), py::arg("render_time"), py::arg("smoothing") = RenderSmoothing::None,
        "The position [m] a game draws at render_time [s] for a fixed-step trajectory (Engine or\n"
        "Stepped) of `step` [s] (> 0), with the given smoothing.");
    m.def(
        "engine_free_flight",
        [](const EngineProfile& engine, py::handle position, py::handle velocity, py::handle gravity,
           std::uint64_t steps) {
            check(validateEngineProfile(engine), "engine_free_flight");
            const EngineFlightState out = engineFreeFlight(
                engine, toRVec3(position, "position"), toVec3(velocity, "velocity"), toVec3(gravity, "gravity"), steps);
            return py::make_tuple(fromVec(out.position), fromVec(out.velocity));
        },
        py::arg("profile"), py::arg("position"), py::arg("velocity"),
        py::arg("gravity") = py::make_tuple(0.0f, -kDefaultGravity, 0.0f), py::arg("steps") = 1,
        "The state after `steps` engine steps of free flight, in closed form: (position [m], velocity\n"
        "[m/s]). position [m], velocity [m/s], gravity [m/s^2]. Speed limits are not applied.");

    // Aim ----------------------------------------------------------------------------------
    py::enum_<AimConstraint>(m, "AimConstraint", "What fixes the launch velocity besides meeting the target.")
        .value("Speed", AimConstraint::Speed, "|velocity| = speed")
        .value("HorizontalSpeed", AimConstraint::HorizontalSpeed, "the part across gravity has length speed")
        .value("ApexAboveStart", AimConstraint::ApexAboveStart, "apex apex_height above the launch point")
        .value("ApexAboveTarget", AimConstraint::ApexAboveTarget, "apex apex_height above the hit point");
    py::class_<FiringSolution>(m, "FiringSolution", "One way to hit the target.")
        .def_property_readonly(
            "velocity", [](const FiringSolution& s) { return fromVec(s.velocity); }, "Launch velocity [m/s].")
        .def_readonly("time", &FiringSolution::time, "Flight time to the hit [s].")
        .def_property_readonly(
            "hit", [](const FiringSolution& s) { return fromVec(s.hit); }, "Where projectile and target meet [m].")
        .def_readonly("elevation", &FiringSolution::elevation, "Launch angle above the plane across gravity [rad].")
        .def("__repr__", [](const FiringSolution& s) {
            return "FiringSolution(velocity=" + vecText(s.velocity) + ", time=" + floatText(s.time) +
                   ", hit=" + vecText(s.hit) + ", elevation=" + floatText(s.elevation) + ")";
        });
    m.def(
        "aim_projectile",
        [](py::handle from, py::handle targetPosition, float speed, py::handle targetVelocity,
           py::handle targetAcceleration, AimConstraint constraint, float apexHeight, py::handle gravity,
           float maxTime) {
            AimShot shot;
            shot.from = toRVec3(from, "from_");
            shot.constraint = constraint;
            shot.speed = speed;
            shot.apexHeight = apexHeight;
            shot.gravity = toVec3(gravity, "gravity");
            shot.maxTime = maxTime;
            AimTarget target;
            target.position = toRVec3(targetPosition, "target");
            target.velocity = toVec3(targetVelocity, "target_velocity");
            target.acceleration = toVec3(targetAcceleration, "target_acceleration");
            std::array<FiringSolution, kMaxFiringSolutions> solutions{};
            std::size_t count = 0;
            check(aimProjectile(shot, target, solutions, count), "aim_projectile");
            return std::vector<FiringSolution>(solutions.begin(),
                                               solutions.begin() + static_cast<std::ptrdiff_t>(count));
        },
        py::arg("from_"), py::arg("target"), py::arg("speed") = 0.0f,
        py::arg("target_velocity") = py::make_tuple(0, 0, 0), py::arg("target_acceleration") = py::make_tuple(0, 0, 0),
        py::arg("constraint") = AimConstraint::Speed, py::arg("apex_height") = 0.0f,
        py::arg("gravity") = py::make_tuple(0.0f, -kDefaultGravity, 0.0f), py::arg("max_time") = 60.0f,
        "Every firing solution from from_ [m] to a target at `target` [m] moving with target_velocity\n"
        "[m/s] and target_acceleration [m/s^2], sorted by flight time (low arc first); [] when\n"
        "unreachable. speed [m/s] for Speed/HorizontalSpeed, apex_height [m] for the apex constraints,\n"
        "gravity [m/s^2], max_time [s].");

    // Danger -------------------------------------------------------------------------------
    // A projectile danger is a Trajectory (from predict_projectile) with a fuse and a blast.
    auto danger = [](const Trajectory& trajectory, float fuseTime, float blastRadius, float contactRadius) {
        ProjectileDanger d;
        d.trajectory = trajectory.points;
        d.fuseTime = fuseTime;
        d.blastRadius = blastRadius;
        d.contactRadius = contactRadius;
        return d;
    };
    py::class_<DangerZone> dangerZone(m, "DangerZone", "Where and when a projectile explodes.");
    dangerZone
        .def_property_readonly(
            "center", [](const DangerZone& z) { return fromVec(z.center); },
            "The projectile's position at the fuse time [m].")
        .def_readonly("radius", &DangerZone::radius, "The blast radius [m].")
        .def_readonly("time", &DangerZone::time, "The fuse time [s]; dangerous from then on.")
        .def("__repr__", [](const DangerZone& z) {
            return "DangerZone(center=" + vecText(z.center) + ", radius=" + floatText(z.radius) +
                   ", time=" + floatText(z.time) + ")";
        });
    m.def(
        "position_on_trajectory",
        [](const Trajectory& trajectory, float time) {
            RVec3 out;
            check(positionOnTrajectory(trajectory.points, time, out), "position_on_trajectory");
            return fromVec(out);
        },
        py::arg("trajectory"), py::arg("time"),
        "The projectile's position [m] at time [s] on the trajectory (parabolic segments between points).");
    m.def(
        "danger_zone",
        [danger](const Trajectory& trajectory, float fuseTime, float blastRadius) {
            DangerZone out;
            check(computeDangerZone(danger(trajectory, fuseTime, blastRadius, 0.0f), out), "danger_zone");
            return out;
        },
        py::arg("trajectory"), py::arg("fuse_time"), py::arg("blast_radius"),
        "The blast sphere: the position at fuse_time [s], blast_radius [m], dangerous from fuse_time on.");
    m.def(
        "is_point_safe",
        [danger](const Trajectory& trajectory, py::handle point, float time, float fuseTime, float blastRadius,
                 float contactRadius) {
            bool safe = false;
            check(isPointSafe(danger(trajectory, fuseTime, blastRadius, contactRadius), toRVec3(point, "point"), time,
                              safe),
                  "is_point_safe");
            return safe;
        },
        py::arg("trajectory"), py::arg("point"), py::arg("time"), py::arg("fuse_time"), py::arg("blast_radius"),
        py::arg("contact_radius") = 0.0f,
        "Whether point [m] is safe at time [s]: outside the blast from fuse_time on; before it, farther\n"
        "than contact_radius [m] from the projectile (0: always safe before the fuse).");
    m.def(
        "find_danger_start",
        [danger](const Trajectory& trajectory, py::handle point, float fuseTime, float blastRadius,
                 float contactRadius) -> std::optional<float> {
            DangerStart out;
            check(
                findDangerStart(danger(trajectory, fuseTime, blastRadius, contactRadius), toRVec3(point, "point"), out),
                "find_danger_start");
            if (!out.ever) return std::nullopt;
            return out.time;
        },
        py::arg("trajectory"), py::arg("point"), py::arg("fuse_time"), py::arg("blast_radius"),
        py::arg("contact_radius") = 0.0f,
        "The earliest time [s] point [m] is unsafe (see is_point_safe), or None: never.");
    m.def(
        "find_path_approach",
        [](const Trajectory& trajectory, py::handle point, float distance, float fromTime,
           float untilTime) -> std::optional<float> {
            DangerStart out;
            check(findPathApproach(trajectory.points, toRVec3(point, "point"), distance, fromTime, untilTime, out),
                  "find_path_approach");
            if (!out.ever) return std::nullopt;
            return out.time;
        },
        py::arg("trajectory"), py::arg("point"), py::arg("distance"), py::arg("from_time"), py::arg("until_time"),
        "The earliest time [s] in [from_time, until_time] the projectile comes within distance [m] of\n"
        "point [m] (exact per segment), or None.");
    m.def(
        "find_closest_path_approach",
        [](const Trajectory& trajectory, py::handle point, float fromTime, float untilTime) {
            ClosestApproach out;
            check(findClosestPathApproach(trajectory.points, toRVec3(point, "point"), fromTime, untilTime, out),
                  "find_closest_path_approach");
            return py::make_tuple(out.distance, out.time);
        },
        py::arg("trajectory"), py::arg("point"), py::arg("from_time"), py::arg("until_time"),
        "The closest approach of the projectile to point [m] in [from_time, until_time] [s]:\n"
        "(distance [m], time [s]).");

    py::class_<VehicleBody> vehicleBody(m, "VehicleBody",
                                        "A vehicle as an oriented box on predict_vehicle_exact's path.");
    vehicleBody
        .def(py::init([](const VehicleState& state, const VehicleSettings& settings, py::handle halfExtents,
                         py::handle boxCenter) {
                 VehicleBody b;
                 b.state = state;
                 b.settings = settings;
                 b.halfExtents = toVec3(halfExtents, "half_extents");
                 b.boxCenter = toVec3(boxCenter, "box_center");
                 return b;
             }),
             py::arg("state"), py::arg("settings") = VehicleSettings(),
             py::arg("half_extents") = py::make_tuple(0.9f, 0.7f, 2.2f),
             py::arg("box_center") = py::make_tuple(0, 0, 0))
        .def_readwrite("state", &VehicleBody::state)
        .def_readwrite("settings", &VehicleBody::settings);
    FS_VEC3(vehicleBody, VehicleBody, "half_extents", halfExtents, "The box's half sizes [m], local axes.");
    FS_VEC3(vehicleBody, VehicleBody, "box_center", boxCenter, "The box's centre in local axes from the position [m].");
    py::class_<CharacterBody> characterBody(m, "CharacterBody",
                                            "A character: a sphere or a capsule moving with constant acceleration.");
    characterBody
        .def(py::init([](py::handle position, py::handle velocity, py::handle acceleration, float radius,
                         py::handle halfAxis) {
                 CharacterBody c;
                 c.position = toRVec3(position, "position");
                 c.velocity = toVec3(velocity, "velocity");
                 c.acceleration = toVec3(acceleration, "acceleration");
                 c.radius = radius;
                 c.halfAxis = toVec3(halfAxis, "half_axis");
                 return c;
             }),
             py::arg("position") = py::make_tuple(0, 0, 0), py::arg("velocity") = py::make_tuple(0, 0, 0),
             py::arg("acceleration") = py::make_tuple(0, 0, 0), py::arg("radius") = 0.4f,
             py::arg("half_axis") = py::make_tuple(0, 0, 0))
        .def_readwrite("radius", &CharacterBody::radius, "[m] >= 0");
    FS_RVEC3(characterBody, CharacterBody, "position", position, "The centre at t = 0 [m].");
    FS_VEC3(characterBody, CharacterBody, "velocity", velocity, "[m/s], world axes.");
    FS_VEC3(characterBody, CharacterBody, "acceleration", acceleration, "[m/s^2], world axes.");
    FS_VEC3(characterBody, CharacterBody, "half_axis", halfAxis, "Half the capsule's segment [m]; 0: a sphere.");
    py::class_<VehicleContact>(m, "VehicleContact", "The first contact of a vehicle and a character.")
        .def_readonly("contact", &VehicleContact::contact, "Whether they come within the tolerance.")
        .def_readonly("time", &VehicleContact::time, "Time of first contact [s] (valid when contact).")
        .def_readonly("separation", &VehicleContact::separation, "Separation at time [m].")
        .def_readonly("evaluations", &VehicleContact::evaluations)
        .def("__repr__", [](const VehicleContact& c) {
            return std::string("VehicleContact(contact=") + (c.contact ? "True" : "False") +
                   ", time=" + floatText(c.time) + ", separation=" + floatText(c.separation) + ")";
        });
    auto approach = [](float tolerance, std::uint32_t maxEvaluations) {
        ApproachSettings a;
        a.tolerance = tolerance;
        a.maxEvaluations = maxEvaluations;
        return a;
    };
    m.def(
        "vehicle_separation",
        [](const VehicleBody& vehicle, const CharacterBody& character, float time) {
            float separation = 0;
            check(computeVehicleSeparation(vehicle, character, time, separation), "vehicle_separation");
            return separation;
        },
        py::arg("vehicle"), py::arg("character"), py::arg("time"),
        "The separation [m] of the vehicle's box and the character at time [s] (<= 0: overlapping).");
    m.def(
        "find_vehicle_contact",
        [approach](const VehicleBody& vehicle, const CharacterBody& character, float horizon, float tolerance,
                   std::uint32_t maxEvaluations) {
            VehicleContact out;
            check(findVehicleContact(vehicle, character, horizon, approach(tolerance, maxEvaluations), out),
                  "find_vehicle_contact");
            return out;
        },
        py::arg("vehicle"), py::arg("character"), py::arg("horizon"), py::arg("tolerance") = 1e-3f,
        py::arg("max_evaluations") = 1u << 16,
        "The first time in [0, horizon] [s] the vehicle and the character come within tolerance [m].");
    m.def(
        "find_closest_vehicle_approach",
        [approach](const VehicleBody& vehicle, const CharacterBody& character, float horizon, float tolerance,
                   std::uint32_t maxEvaluations) {
            ClosestApproach out;
            check(findClosestVehicleApproach(vehicle, character, horizon, approach(tolerance, maxEvaluations), out),
                  "find_closest_vehicle_approach");
            return py::make_tuple(out.distance, out.time);
        },
        py::arg("vehicle"), py::arg("character"), py::arg("horizon"), py::arg("tolerance") = 1e-3f,
        py::arg("max_evaluations") = 1u << 16,
        "The closest approach in [0, horizon] [s]: (separation [m], time [s]), within tolerance [m].");

    // Throw planning -----------------------------------------------------------------------
    py::class_<ThrowPlan>(m, "ThrowPlan", "A launch velocity that brings the grenade near the target at the fuse.")
        .def_property_readonly(
            "launch_velocity", [](const ThrowPlan& p) { return fromVec(p.launchVelocity); }, "[m/s], world axes.")
        .def_property_readonly(
            "final_position", [](const ThrowPlan& p) { return fromVec(p.finalPosition); },
            "Where the grenade is at the fuse time [m].")
        .def_readonly("distance", &ThrowPlan::distance, "|final_position - target| [m].")
        .def_readonly("bounces", &ThrowPlan::bounces)
        .def_readonly("at_rest", &ThrowPlan::atRest)
        .def_readonly("first_impact_time", &ThrowPlan::firstImpactTime, "[s]; < 0 when none.")
        .def_property_readonly("first_impact_normal", [](const ThrowPlan& p) { return fromVec(p.firstImpactNormal); })
        .def_property_readonly("first_impact_position",
                               [](const ThrowPlan& p) { return fromVec(p.firstImpactPosition); })
        .def("__repr__", [](const ThrowPlan& p) {
            return "ThrowPlan(launch_velocity=" + vecText(p.launchVelocity) +
                   ", final_position=" + vecText(p.finalPosition) + ", distance=" + floatText(p.distance) +
                   ", bounces=" + std::to_string(p.bounces) + ")";
        });
    m.def(
        "plan_throw",
        [](py::handle start, py::handle target, const CollisionWorld* world, float acceptanceRadius, float fuseTime,
           float maxSpeed, float minSpeed, const ProjectileSettings& settings, std::uint32_t maxPlans,
           float distinctAngle, std::uint32_t maxPredictions) {
            ThrowPlanRequest request;
            request.start = toRVec3(start, "start");
            request.target = toRVec3(target, "target");
            request.acceptanceRadius = acceptanceRadius;
            request.fuseTime = fuseTime;
            request.maxSpeed = maxSpeed;
            request.minSpeed = minSpeed;
            request.settings = settings;
            request.maxPlans = maxPlans;
            request.distinctAngle = distinctAngle;
            request.budget.maxPredictions = maxPredictions;
            check(validateThrowPlanRequest(request), "plan_throw");
            std::vector<ThrowPlan> plans(maxPlans);
            std::vector<TrajectoryPoint> scratch(throwPlanScratchSize(request));
            ThrowPlanResult result;
            Status planned = Status::Ok;
            {
                std::optional<py::gil_scoped_release> release;  // as predict_projectile: kept with a world
                if (world == nullptr) release.emplace();
                planned = planThrow(request, world, plans, scratch, result);
            }
            check(planned, "plan_throw");
            plans.resize(result.planCount);
            py::dict info;
            info["predictions"] = result.predictions;
            info["closest_distance"] = result.closestDistance;
            info["closest_velocity"] = fromVec(result.closestVelocity);
            return py::make_tuple(plans, info);
        },
        py::arg("start"), py::arg("target"), py::arg("world") = nullptr, py::arg("acceptance_radius") = 0.5f,
        py::arg("fuse_time") = 3.0f, py::arg("max_speed") = 20.0f, py::arg("min_speed") = 0.0f,
        py::arg("settings") = ProjectileSettings(), py::arg("max_plans") = 3, py::arg("distinct_angle") = 0.1f,
        py::arg("max_predictions") = 400,
        "Searches launch velocities (speed <= max_speed [m/s]) from start [m] that bring a grenade within\n"
        "acceptance_radius [m] of target [m] at fuse_time [s], bouncing off world with `settings`.\n"
        "Returns (plans, info): plans best first (ThrowPlan), info = {predictions, closest_distance [m],\n"
        "closest_velocity [m/s]}.");

    // Dead reckoning -----------------------------------------------------------------------
    py::enum_<DeadReckoningAlgorithm>(m, "DeadReckoningAlgorithm",
                                      "The DIS dead-reckoning models; values are the DIS enumeration (1 to 9).")
        .value("Static", DeadReckoningAlgorithm::Static)
        .value("FPW", DeadReckoningAlgorithm::Fpw)
        .value("RPW", DeadReckoningAlgorithm::Rpw)
        .value("RVW", DeadReckoningAlgorithm::Rvw)
        .value("FVW", DeadReckoningAlgorithm::Fvw)
        .value("FPB", DeadReckoningAlgorithm::Fpb)
        .value("RPB", DeadReckoningAlgorithm::Rpb)
        .value("RVB", DeadReckoningAlgorithm::Rvb)
        .value("FVB", DeadReckoningAlgorithm::Fvb);

    py::class_<DeadReckoningState> drState(m, "DeadReckoningState", "The state an entity last reported.");
    drState
        .def(py::init([](DeadReckoningAlgorithm algorithm, py::handle position, py::handle velocity,
                         py::handle acceleration, py::handle orientation, py::handle w) {
                 DeadReckoningState s;
                 s.algorithm = algorithm;
                 s.position = toRVec3(position, "position");
                 s.velocity = toVec3(velocity, "velocity");
                 s.acceleration = toVec3(acceleration, "acceleration");
                 s.orientation = toQuat(orientation, "orientation");
                 s.angularVelocity = toVec3(w, "angular_velocity");
                 return s;
             }),
             py::arg("algorithm") = DeadReckoningAlgorithm::Fpw, py::arg("position") = py::make_tuple(0, 0, 0),
             py::arg("velocity") = py::make_tuple(0, 0, 0), py::arg("acceleration") = py::make_tuple(0, 0, 0),
             py::arg("orientation") = py::make_tuple(0, 0, 0, 1), py::arg("angular_velocity") = py::make_tuple(0, 0, 0))
        .def_readwrite("algorithm", &DeadReckoningState::algorithm);
    FS_RVEC3(drState, DeadReckoningState, "position", position, "[m], world axes.");
    FS_VEC3(drState, DeadReckoningState, "velocity", velocity, "[m/s]; world axes (*W) or body axes (*B).");
    FS_VEC3(drState, DeadReckoningState, "acceleration", acceleration, "[m/s^2]; axes as velocity.");
    FS_QUAT(drState, DeadReckoningState, "orientation", orientation, "Body-to-world (x, y, z, w).");
    FS_VEC3(drState, DeadReckoningState, "angular_velocity", angularVelocity, "[rad/s], body axes.");
    drState.def("__repr__", [](const DeadReckoningState& s) {
        return std::string("DeadReckoningState(algorithm=") + deadReckoningAlgorithmName(s.algorithm) +
               ", position=" + vecText(s.position) + ", velocity=" + vecText(s.velocity) +
               ", acceleration=" + vecText(s.acceleration) + ", orientation=" + quatText(s.orientation) +
               ", angular_velocity=" + vecText(s.angularVelocity) + ")";
    });

    py::class_<DeadReckoningResult> drResult(m, "DeadReckoningResult", "An extrapolated state.");
    drResult.def_property_readonly(
        "position", [](const DeadReckoningResult& r) { return fromVec(r.position); }, "[m], world axes.");
    drResult.def_property_readonly(
        "velocity", [](const DeadReckoningResult& r) { return fromVec(r.velocity); },
        "[m/s], in the input velocity's axes.");
    drResult.def_property_readonly(
        "orientation", [](const DeadReckoningResult& r) { return fromQuat(r.orientation); },
        "Body-to-world (x, y, z, w), unit.");
    drResult.def("__repr__", [](const DeadReckoningResult& r) {
        return "DeadReckoningResult(position=" + vecText(r.position) + ", velocity=" + vecText(r.velocity) +
               ", orientation=" + quatText(r.orientation) + ")";
    });

    m.def("dead_reckoning_algorithm_name", &deadReckoningAlgorithmName, py::arg("algorithm"),
          "The DIS name, e.g. 'FPW'.");
    m.def(
        "predict_dead_reckoning",
        [](const DeadReckoningState& state, double time) {
            DeadReckoningResult out;
            check(predictDeadReckoning(state, toFloat(time), out), "predict_dead_reckoning");
            return out;
        },
        py::arg("state"), py::arg("time"), "Extrapolates `state` by time [s] (>= 0) with its DIS model.");
    m.def("predict_dead_reckoning_batch", &predictDeadReckoningBatchPy, py::arg("algorithms"), py::arg("positions"),
          py::arg("velocities"), py::arg("accelerations"), py::arg("orientations"), py::arg("angular_velocities"),
          py::arg("timestamps"), py::arg("time"),
          "Extrapolates N entities to `time` [s] in one call (predictDeadReckoningBatch): algorithms (N,)\n"
          "ints 1..9, positions (N, 3) [m], velocities (N, 3) [m/s], accelerations (N, 3) [m/s^2],\n"
          "orientations (N, 4) (x, y, z, w), angular_velocities (N, 3) [rad/s], timestamps (N,) [s].\n"
          "Entity i is extrapolated by max(time - timestamps[i], 0). Returns (positions (N, 3),\n"
          "velocities (N, 3), orientations (N, 4), refused): refused entities (invalid state) keep\n"
          "their update as given and are counted.");
    m.def("_time_cpp_predict_dead_reckoning_batch", &timeCppPredictBatch, py::arg("algorithms"), py::arg("positions"),
          py::arg("velocities"), py::arg("accelerations"), py::arg("orientations"), py::arg("angular_velocities"),
          py::arg("timestamps"), py::arg("time"), py::arg("repeats"),
          "Benchmark helper: the median time [s] of `repeats` predictDeadReckoningBatch calls made from C++\n"
          "on these entities (the reference of predict_dead_reckoning_batch; bench/dead_reckoning_overhead.py).");

    py::class_<PyDeadReckoningBatch>(
        m, "DeadReckoningBatch",
        "Many entities' updates held in the library's structure-of-arrays form, extrapolated every\n"
        "frame at SIMD speed. Set the updates when they arrive (set_all or set), then call\n"
        "extrapolate(time) each frame and read positions, velocities and orientations: read-only\n"
        "views (no copy) of the batch's output, overwritten by the next extrapolate (copy to keep).")
        .def(py::init<std::size_t>(), py::arg("capacity"), "A batch of `capacity` entities, each STATIC at the origin.")
        .def_property_readonly("capacity", &PyDeadReckoningBatch::capacity)
        .def("__len__", &PyDeadReckoningBatch::capacity)
        .def("set_all", &PyDeadReckoningBatch::setAll, py::arg("algorithms"), py::arg("positions"),
             py::arg("velocities"), py::arg("accelerations"), py::arg("orientations"), py::arg("angular_velocities"),
             py::arg("timestamps"),
             "Replaces every entity's update; arrays as predict_dead_reckoning_batch's, N = capacity.\n"
             "Raises foresight.Error naming the first refused entity (then nothing changes).")
        .def("set", &PyDeadReckoningBatch::set, py::arg("entity"), py::arg("state"), py::arg("timestamp"),
             "Replaces one entity's update (a DeadReckoningState stamped timestamp [s]).")
        .def("extrapolate", &PyDeadReckoningBatch::extrapolate, py::arg("time"),
             py::arg("extrapolation_limit") = std::numeric_limits<double>::infinity(),
             "Extrapolates every entity to time [s], each by min(max(time - timestamp, 0), limit) [s].\n"
             "Returns the number of refused (overflowing) entities; results in positions, velocities,\n"
             "orientations.")
        .def_property_readonly(
            "positions", [](const PyDeadReckoningBatch& b) { return b.views()[0]; }, "(N, 3) [m], world axes.")
        .def_property_readonly(
            "velocities", [](const PyDeadReckoningBatch& b) { return b.views()[1]; }, "(N, 3) [m/s].")
        .def_property_readonly(
            "orientations", [](const PyDeadReckoningBatch& b) { return b.views()[2]; }, "(N, 4) (x, y, z, w).")
        .def("_time_cpp_extrapolate", &PyDeadReckoningBatch::timeExtrapolate, py::arg("time"),
             py::arg("extrapolation_limit"), py::arg("repeats"),
             "Benchmark helper: the median time [s] of `repeats` extrapolate calls made from C++.")
        .def("__repr__", [](const PyDeadReckoningBatch& b) {
            return "DeadReckoningBatch(capacity=" + std::to_string(b.capacity()) + ")";
        });
}
