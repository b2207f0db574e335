#include "netsim.h"

#include "svg_writer.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace foresight_cli::netsim {

namespace {

using foresight::DeadReckoningAlgorithm;
using foresight::Status;

constexpr double kPi = glm::pi<double>();
/// Standard gravity (9.80665 m/s^2 by definition): the aircraft's coordinated-turn bank [m/s^2].
constexpr double kStandardGravity = 9.80665;
/// Positions of the heading-driven trajectories are integrated from their exact velocity with
/// 3-point Gauss-Legendre on steps of this length [s]: the velocity is C2 (smoothstep ramps of
/// the turn rate), so the error is below 1e-8 m over an hour.
constexpr double kQuadratureStep = 1.0 / 128.0;

/// 53 random bits as a double in [0, 1): the raw output of std::mt19937_64 is fixed by the
/// standard, its distributions are not.
double uniform01(std::mt19937_64& engine) { return static_cast<double>(engine() >> 11) * 0x1.0p-53; }

glm::dquat rotationAbout(const glm::dvec3& axis, double angle) { return glm::angleAxis(angle, axis); }

/// exp of a body angular velocity over `time`: the rotation by |w| t about w.
glm::dquat rotationExp(const glm::dvec3& w, double time) {
    const double speed = glm::length(w);
    if (!(speed * std::abs(time) > 0)) return glm::identity<glm::dquat>();
    return glm::angleAxis(speed * time, w / speed);
}

// --------------------------------------------------------------------------------------------
// Profiles: a value that moves between plateaus along smoothstep ramps (C1: its derivative is
// continuous), with its exact derivative, second derivative and integral from time 0.

class Profile {
public:
    explicit Profile(double initial = 0) : mInitial(initial) {}

    /// From `start`, ramp to `target` over `length` seconds. Ramps must come in time order and
    /// not overlap.
    void rampTo(double start, double length, double target) {
        Ramp ramp{start, length, target - finalValue(), finalValue(), 0};
        if (mRamps.empty()) {
            ramp.integralAtStart = mInitial * start;
        } else {
            const Ramp& last = mRamps.back();
            ramp.integralAtStart = last.integralAtStart + last.valueAtStart * (start - last.start) +
                                   last.delta * (0.5 * last.length + (start - last.start - last.length));
        }
        mRamps.push_back(ramp);
    }
    double finalValue() const { return mRamps.empty() ? mInitial : mRamps.back().valueAtStart + mRamps.back().delta; }

    double value(double t) const {
        const Ramp* ramp = find(t);
        if (ramp == nullptr) return mInitial;
        const double u = std::min((t - ramp->start) / ramp->length, 1.0);
        return ramp->valueAtStart + ramp->delta * u * u * (3 - 2 * u);
    }
    double derivative(double t) const {
        const Ramp* ramp = find(t);
        if (ramp == nullptr || t >= ramp->start + ramp->length) return 0;
        const double u = (t - ramp->start) / ramp->length;
        return ramp->delta * 6 * u * (1 - u) / ramp->length;
    }
    double secondDerivative(double t) const {
        const Ramp* ramp = find(t);
        if (ramp == nullptr || t >= ramp->start + ramp->length) return 0;
        const double u = (t - ramp->start) / ramp->length;
        return ramp->delta * (6 - 12 * u) / (ramp->length * ramp->length);
    }
    /// The integral over [0, t].
    double integral(double t) const {
        const Ramp* ramp = find(t);
        if (ramp == nullptr) return mInitial * t;
        const double since = t - ramp->start;
        double ramped;  // integral of the ramp's own smoothstep part, times delta
        if (since < ramp->length) {
            const double u = since / ramp->length;
            ramped = ramp->length * (u * u * u - 0.5 * u * u * u * u);
        } else {
            ramped = 0.5 * ramp->length + (since - ramp->length);
        }
        return ramp->integralAtStart + ramp->valueAtStart * since + ramp->delta * ramped;
    }

private:
    struct Ramp {
        double start, length, delta, valueAtStart, integralAtStart;
    };
    /// The last ramp that starts at or before t (nullptr: before every ramp).
    const Ramp* find(double t) const {
        const auto after = std::upper_bound(mRamps.begin(), mRamps.end(), t,
                                            [](double time, const Ramp& r) { return time < r.start; });
        return after == mRamps.begin() ? nullptr : &*(after - 1);
    }
    double mInitial;
    std::vector<Ramp> mRamps;
};

// --------------------------------------------------------------------------------------------
// Character: world velocity ramps between directions (exact position: the profile's integral),
// facing a direction that sweeps slowly (strafing and back-pedalling relative to it).

struct CharacterMotion {
    Profile vx, vz;
    double lookAmplitude = 0.8;  // rad
    double lookRate = 0.35;      // rad/s, angular frequency of the look sweep

    double facing(double t) const { return lookAmplitude * std::sin(lookRate * t); }
    double facingRate(double t) const { return lookAmplitude * lookRate * std::cos(lookRate * t); }

    TruthState sample(double t) const {
        TruthState s;
        s.position = glm::dvec3(vx.integral(t), 0, vz.integral(t));
        s.velocity = glm::dvec3(vx.value(t), 0, vz.value(t));
        s.acceleration = glm::dvec3(vx.derivative(t), 0, vz.derivative(t));
        s.orientation = rotationAbout(glm::dvec3(0, 1, 0), facing(t));
        s.angularVelocity = glm::dvec3(0, facingRate(t), 0);
        return s;
    }
};

std::shared_ptr<CharacterMotion> makeRunStrafe(double duration) {
    constexpr double kSpeed = 6.0;  // m/s
    constexpr double kRamp = 0.25;  // s: from one direction to the next
    // Directions relative to the facing: forward, the diagonals, the strafes, back.
    constexpr std::array<double, 8> kDirections = {0, 45, -45, 90, -90, 135, -135, 180};
    auto motion = std::make_shared<CharacterMotion>();
    std::mt19937_64 engine(6);  // the trajectory is fixed; --seed is the link's
    std::size_t current = 0;
    motion->vx = Profile(0);
    motion->vz = Profile(kSpeed);
    for (double t = 0.5 + uniform01(engine); t < duration; t += 0.5 + uniform01(engine)) {
        std::size_t next = current;
        while (next == current) next = static_cast<std::size_t>(engine() % kDirections.size());
        current = next;
        const double angle = motion->facing(t) + kDirections[current] * kPi / 180;
        motion->vx.rampTo(t, kRamp, kSpeed * std::sin(angle));
        motion->vz.rampTo(t, kRamp, kSpeed * std::cos(angle));
    }
    return motion;
}

// --------------------------------------------------------------------------------------------
// Vehicles: constant speed along a heading (yaw about +Y) and a climb angle; the aircraft banks
// for a coordinated turn. Orientation R_y(heading) R_x(-climb) R_z(bank); exact velocity,
// acceleration and angular velocity; the position integrated from the velocity.

struct HeadingMotion {
    double speed = 20;           // m/s
    Profile yawRate;             // rad/s
    double slalomAmplitude = 0;  // rad, heading += A sin(W t)
    double slalomFrequency = 0;  // rad/s (W)
    Profile climb;               // rad
    bool bank = false;
    glm::dvec3 origin{0};
    std::vector<glm::dvec3> positions;  // at k * kQuadratureStep

    struct Angles {
        double heading, headingRate, climb, climbRate, bank, bankRate;
    };

    Angles angles(double t) const {
        Angles a{};
        const double w = slalomFrequency;
        a.heading = yawRate.integral(t) + slalomAmplitude * std::sin(w * t);
        a.headingRate = yawRate.value(t) + slalomAmplitude * w * std::cos(w * t);
        const double headingAcceleration = yawRate.derivative(t) - slalomAmplitude * w * w * std::sin(w * t);
        a.climb = climb.value(t);
        a.climbRate = climb.derivative(t);
        if (bank) {
            // tan(bank) = lateral acceleration / g; a left turn (heading rate > 0 turns +Z
            // towards +X) banks towards +X, which is a negative roll about +Z.
            const double u = speed * std::cos(a.climb) * a.headingRate / kStandardGravity;
            const double uRate =
                speed / kStandardGravity *
                (-std::sin(a.climb) * a.climbRate * a.headingRate + std::cos(a.climb) * headingAcceleration);
            a.bank = -std::atan(u);
            a.bankRate = -uRate / (1 + u * u);
        }
        return a;
    }

    glm::dvec3 velocity(double t) const {
        const Angles a = angles(t);
        return speed * glm::dvec3(std::sin(a.heading) * std::cos(a.climb), std::sin(a.climb),
                                  std::cos(a.heading) * std::cos(a.climb));
    }

    glm::dvec3 gauss(double a, double b) const {
        // 3-point Gauss-Legendre: exact for polynomials of degree 5.
        const double half = 0.5 * (b - a), middle = 0.5 * (a + b);
        const double offset = half * std::sqrt(0.6);
        return half * (5.0 / 9.0 * velocity(middle - offset) + 8.0 / 9.0 * velocity(middle) +
                       5.0 / 9.0 * velocity(middle + offset));
    }

    void integrate(double duration) {
        const std::size_t steps = static_cast<std::size_t>(std::ceil(duration / kQuadratureStep)) + 1;
        positions.resize(steps + 1);
        positions[0] = origin;
        for (std::size_t k = 0; k < steps; ++k)
            positions[k + 1] = positions[k] + gauss(static_cast<double>(k) * kQuadratureStep,
                                                    static_cast<double>(k + 1) * kQuadratureStep);
    }

    TruthState sample(double t) const {
        TruthState s;
        const std::size_t k =
            std::min(static_cast<std::size_t>(std::max(t, 0.0) / kQuadratureStep), positions.size() - 1);
        s.position = positions[k] + gauss(static_cast<double>(k) * kQuadratureStep, t);
        const Angles a = angles(t);
        const double sh = std::sin(a.heading), ch = std::cos(a.heading);
        const double sc = std::sin(a.climb), cc = std::cos(a.climb);
        s.velocity = speed * glm::dvec3(sh * cc, sc, ch * cc);
        s.acceleration = speed * (a.headingRate * glm::dvec3(ch * cc, 0, -sh * cc) +
                                  a.climbRate * glm::dvec3(-sh * sc, cc, -ch * sc));
        const glm::dquat yaw = rotationAbout(glm::dvec3(0, 1, 0), a.heading);
        const glm::dquat pitch = rotationAbout(glm::dvec3(1, 0, 0), -a.climb);
        const glm::dquat roll = rotationAbout(glm::dvec3(0, 0, 1), a.bank);
        s.orientation = glm::normalize(yaw * pitch * roll);
        // The body rate of q = A B C with each factor about a fixed axis:
        // w = C^-1 B^-1 (yaw rate) + C^-1 (pitch rate) + (roll rate).
        const glm::dquat rollInverse = glm::conjugate(roll);
        s.angularVelocity = rollInverse * (glm::conjugate(pitch) * glm::dvec3(0, a.headingRate, 0)) +
                            rollInverse * glm::dvec3(-a.climbRate, 0, 0) + glm::dvec3(0, 0, a.bankRate);
        return s;
    }
};

std::shared_ptr<HeadingMotion> makeSlalom(double duration) {
    auto motion = std::make_shared<HeadingMotion>();
    motion->speed = 20;
    motion->slalomAmplitude = 0.25;           // rad: about 14 degrees either side
    motion->slalomFrequency = 2 * kPi / 3.0;  // a left-right cycle every 3 s (cones 30 m apart)
    motion->integrate(duration);
    return motion;
}

std::shared_ptr<HeadingMotion> makeCircuit(double duration) {
    // A rounded rectangle: 160 m and 80 m straights, 40 m corners at 20 m/s (10 m/s^2 sideways),
    // the turn rate eased in and out over 0.5 s (the track stays closed: each corner turns
    // rate * (ramp-out start - ramp-in start) = 90 degrees).
    constexpr double kSpeed = 20, kRadius = 40, kEase = 0.5;
    auto motion = std::make_shared<HeadingMotion>();
    motion->speed = kSpeed;
    const double rate = kSpeed / kRadius;
    const double turn = 0.5 * kPi / rate;
    double t = 0;
    for (int corner = 0; t < duration; ++corner) {
        t += (corner % 2 == 0 ? 160.0 : 80.0) / kSpeed;
        motion->yawRate.rampTo(t, kEase, rate);
        t += turn;
        motion->yawRate.rampTo(t, kEase, 0);
        t += kEase;
    }
    motion->integrate(duration);
    return motion;
}

std::shared_ptr<HeadingMotion> makeAircraftTurn(double duration) {
    // Per minute: 6 s straight, a 120 degree turn at 5 degrees/s (banked 47 degrees), straight,
    // a climb at 10 degrees, level again.
    constexpr double kRate = 5 * kPi / 180, kClimb = 10 * kPi / 180;
    auto motion = std::make_shared<HeadingMotion>();
    motion->speed = 120;
    motion->bank = true;
    motion->origin = glm::dvec3(0, 1000, 0);
    for (double cycle = 0; cycle < duration; cycle += 60) {
        motion->yawRate.rampTo(cycle + 6, 2, kRate);
        motion->yawRate.rampTo(cycle + 30, 2, 0);
        motion->climb.rampTo(cycle + 36, 3, kClimb);
        motion->climb.rampTo(cycle + 48, 3, 0);
    }
    motion->integrate(duration);
    return motion;
}

// --------------------------------------------------------------------------------------------
// CSV

struct CsvRow {
    std::size_t line = 0;  // in the file, for messages
    double t = 0;          // [s] from the first row's time (after parsing)
    glm::dvec3 position{0};
    glm::dquat orientation = glm::identity<glm::dquat>();
    glm::dvec3 velocity{0};
    glm::dvec3 angularVelocity{0};
};

struct TableMotion {
    std::vector<CsvRow> rows;
    std::vector<glm::dvec3> segmentRotation;  // body angular velocity taking row i to row i + 1
    bool hasAngularVelocity = false;

    TruthState sample(double t) const {
        const auto after =
            std::upper_bound(rows.begin(), rows.end(), t, [](double time, const CsvRow& r) { return time < r.t; });
        std::size_t i = after == rows.begin() ? 0 : static_cast<std::size_t>(after - rows.begin()) - 1;
        i = std::min(i, rows.size() - 2);
        const CsvRow& a = rows[i];
        const CsvRow& b = rows[i + 1];
        const double h = b.t - a.t;
        const double s = std::clamp((t - a.t) / h, 0.0, 1.0);
        const double s2 = s * s, s3 = s2 * s;
        TruthState out;
        out.position = (2 * s3 - 3 * s2 + 1) * a.position + (s3 - 2 * s2 + s) * h * a.velocity +
                       (-2 * s3 + 3 * s2) * b.position + (s3 - s2) * h * b.velocity;
        out.velocity = ((6 * s2 - 6 * s) * a.position + (3 * s2 - 4 * s + 1) * h * a.velocity +
                        (-6 * s2 + 6 * s) * b.position + (3 * s2 - 2 * s) * h * b.velocity) /
                       h;
        out.acceleration = ((12 * s - 6) * a.position + (6 * s - 4) * h * a.velocity + (-12 * s + 6) * b.position +
                            (6 * s - 2) * h * b.velocity) /
                           (h * h);
        out.orientation = glm::normalize(a.orientation * rotationExp(segmentRotation[i], s * h));
        out.angularVelocity =
            hasAngularVelocity ? a.angularVelocity + s * (b.angularVelocity - a.angularVelocity) : segmentRotation[i];
        return out;
    }
};

std::string_view trim(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t' || text.back() == '\r')) text.remove_suffix(1);
    return text;
}

std::vector<std::string_view> splitFields(std::string_view line) {
    std::vector<std::string_view> fields;
    std::size_t begin = 0;
    for (;;) {
        const std::size_t comma = line.find(',', begin);
        fields.push_back(
            trim(line.substr(begin, comma == std::string_view::npos ? std::string_view::npos : comma - begin)));
        if (comma == std::string_view::npos) return fields;
        begin = comma + 1;
    }
}

std::string shortValue(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", value);
    return buffer;
}

constexpr std::array<const char*, 14> kCsvColumns = {"t",  "x",  "y",  "z",  "qw", "qx", "qy",
                                                     "qz", "vx", "vy", "vz", "wx", "wy", "wz"};

}  // namespace

// --------------------------------------------------------------------------------------------
// Trajectories

const std::vector<std::string>& builtinTrajectoryNames() {
    static const std::vector<std::string> names = {"run-strafe", "slalom", "circuit", "aircraft-turn"};
    return names;
}

bool makeBuiltinTrajectory(std::string_view name, double duration, Trajectory& out) {
    Trajectory t;
    t.name = std::string(name);
    t.start = 0;
    t.end = duration;
    if (name == "run-strafe") {
        auto motion = makeRunStrafe(duration);
        t.description =
            "a character at 6 m/s changing direction every 0.5 to 1.5 s (0.25 s "
            "ramps), strafing and back-pedalling while it looks around";
        t.sample = [motion](double time) { return motion->sample(time); };
    } else if (name == "slalom") {
        auto motion = makeSlalom(duration);
        t.description = "a car at 20 m/s weaving +/-14 degrees every 3 s, heading along its velocity";
        t.sample = [motion](double time) { return motion->sample(time); };
    } else if (name == "circuit") {
        auto motion = makeCircuit(duration);
        t.description =
            "a car at 20 m/s round a rectangle of 160 m and 80 m straights and 40 m "
            "corners (10 m/s^2 sideways)";
        t.sample = [motion](double time) { return motion->sample(time); };
    } else if (name == "aircraft-turn") {
        auto motion = makeAircraftTurn(duration);
        t.description =
            "an aircraft at 120 m/s: straight, a banked 120 degree turn at 5 "
            "degrees/s, straight, a 10 degree climb, every minute";
        t.sample = [motion](double time) { return motion->sample(time); };
    } else {
        return false;
    }
    out = std::move(t);
    return true;
}

bool parseTrajectoryCsv(std::string_view text, const std::string& fileName, Trajectory& out, std::string& error) {
    auto motion = std::make_shared<TableMotion>();
    std::array<int, kCsvColumns.size()> columnOf;  // index in the row, or -1
    columnOf.fill(-1);
    std::size_t columnCount = 0;
    std::size_t lineNumber = 0;
    bool haveHeader = false;
    const auto fail = [&](const std::string& message) {
        error = fileName + ":" + std::to_string(lineNumber) + ": " + message;
        return false;
    };
    std::size_t begin = 0;
    // A UTF-8 byte order mark (spreadsheets write one) is not part of the header.
    if (text.substr(0, 3) == "\xEF\xBB\xBF") begin = 3;
    while (begin < text.size()) {
        std::size_t end = text.find('\n', begin);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view line = trim(text.substr(begin, end - begin));
        begin = end + 1;
        ++lineNumber;
        if (line.empty() || line.front() == '#') continue;
        const auto fields = splitFields(line);
        if (!haveHeader) {
            haveHeader = true;
            columnCount = fields.size();
            for (std::size_t i = 0; i < fields.size(); ++i) {
                const auto known = std::find_if(kCsvColumns.begin(), kCsvColumns.end(),
                                                [&](const char* name) { return fields[i] == name; });
                if (known == kCsvColumns.end())
                    return fail("column " + std::to_string(i + 1) + ": unknown column \"" + std::string(fields[i]) +
                                "\" (expected t, x, y, z and optionally qw, qx, qy, qz, vx, vy, vz, wx, wy, wz)");
                const std::size_t index = static_cast<std::size_t>(known - kCsvColumns.begin());
                if (columnOf[index] >= 0)
                    return fail("column " + std::to_string(i + 1) + ": \"" + std::string(fields[i]) +
                                "\" appears twice");
                columnOf[index] = static_cast<int>(i);
            }
            for (std::size_t c = 0; c < 4; ++c)
                if (columnOf[c] < 0)
                    return fail(std::string("missing required column \"") + kCsvColumns[c] +
                                "\" (the header needs t, x, y, z)");
            for (const std::size_t group : {std::size_t{4}, std::size_t{8}, std::size_t{11}}) {
                const std::size_t size = group == 4 ? 4 : 3;
                std::size_t present = 0;
                for (std::size_t c = group; c < group + size; ++c) present += columnOf[c] >= 0 ? 1 : 0;
                if (present != 0 && present != size) {
                    std::string names, missing;
                    for (std::size_t c = group; c < group + size; ++c) {
                        names += (names.empty() ? "" : ", ") + std::string(kCsvColumns[c]);
                        if (columnOf[c] < 0) missing += (missing.empty() ? "" : ", ") + std::string(kCsvColumns[c]);
                    }
                    return fail("columns " + names + " come together (missing " + missing + ")");
                }
            }
            continue;
        }
        if (motion->rows.size() == kMaxCsvRows)
            return fail("too many rows (the limit is " + std::to_string(kMaxCsvRows) + ")");
        if (fields.size() != columnCount)
            return fail("expected " + std::to_string(columnCount) + " fields (as the header), got " +
                        std::to_string(fields.size()));
        std::array<double, kCsvColumns.size()> values{};
        for (std::size_t c = 0; c < kCsvColumns.size(); ++c) {
            if (columnOf[c] < 0) continue;
            std::string_view field = fields[static_cast<std::size_t>(columnOf[c])];
            // from_chars takes no leading '+': "+1" is a number in CSV files.
            if (field.size() > 1 && field.front() == '+' && field[1] != '-' && field[1] != '+') field.remove_prefix(1);
            double value = 0;
            const auto result = std::from_chars(field.data(), field.data() + field.size(), value);
            if (field.empty() || result.ec != std::errc() || result.ptr != field.data() + field.size() ||
                !std::isfinite(value))
                return fail("column " + std::to_string(columnOf[c] + 1) + " (\"" + kCsvColumns[c] +
                            "\"): expected a finite number, got \"" + std::string(field) + "\"");
            values[c] = value;
        }
        CsvRow row;
        row.line = lineNumber;
        row.t = values[0];
        if (!motion->rows.empty() && !(row.t > motion->rows.back().t))
            return fail("column " + std::to_string(columnOf[0] + 1) + " (\"t\"): time " + shortValue(row.t) +
                        " is not after the previous row's " + shortValue(motion->rows.back().t) +
                        " (times must increase strictly)");
        row.position = glm::dvec3(values[1], values[2], values[3]);
        if (columnOf[4] >= 0) {
            glm::dquat q = glm::identity<glm::dquat>();
            q.w = values[4];
            q.x = values[5];
            q.y = values[6];
            q.z = values[7];
            const double length = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
            if (!(length > 1e-9) || !std::isfinite(length))
                return fail("column " + std::to_string(columnOf[4] + 1) +
                            " (\"qw\"): the quaternion qw, qx, qy, qz is zero");
            q = q / length;
            // The same hemisphere as the previous row: the interpolation takes the short way.
            if (!motion->rows.empty() && glm::dot(q, motion->rows.back().orientation) < 0) q = -q;
            row.orientation = q;
        }
        if (columnOf[8] >= 0) row.velocity = glm::dvec3(values[8], values[9], values[10]);
        if (columnOf[11] >= 0) row.angularVelocity = glm::dvec3(values[11], values[12], values[13]);
        motion->rows.push_back(row);
    }
    ++lineNumber;
    if (!haveHeader) {
        error = fileName + ": empty: expected a header line (t,x,y,z,...) and at least 2 rows";
        return false;
    }
    if (motion->rows.size() < 2) {
        error = fileName + ": expected at least 2 rows, got " + std::to_string(motion->rows.size());
        return false;
    }
    auto& rows = motion->rows;
    const std::size_t n = rows.size();
    // Times from the first row: absolute times (1e9 s of Unix time, or more) would leave the
    // simulation's tick and frame times k / rate with a coarse resolution.
    const double t0 = rows.front().t;
    for (std::size_t i = 0; i < n; ++i) {
        rows[i].t -= t0;
        if (i > 0 && !(rows[i].t > rows[i - 1].t)) {
            error = fileName + ":" + std::to_string(rows[i].line) + ": times " + shortValue(rows[i - 1].t + t0) +
                    " and " + shortValue(rows[i].t + t0) +
                    " are too close for their size (less than a double's "
                    "resolution apart once taken from the first row's time)";
            return false;
        }
    }
    if (columnOf[8] < 0) {
        // Three-point differences on uneven times (exact for a parabola); two points for 2 rows.
        if (n == 2) {
            rows[0].velocity = rows[1].velocity = (rows[1].position - rows[0].position) / (rows[1].t - rows[0].t);
        } else {
            for (std::size_t i = 0; i < n; ++i) {
                const std::size_t m = std::clamp<std::size_t>(i, 1, n - 2);  // the middle of the 3 rows used
                const double h1 = rows[m].t - rows[m - 1].t, h2 = rows[m + 1].t - rows[m].t;
                const glm::dvec3 &p0 = rows[m - 1].position, &p1 = rows[m].position, &p2 = rows[m + 1].position;
                const double x = rows[i].t - rows[m].t;  // -h1, 0 or h2
                // Derivative at x of the parabola through (-h1, p0), (0, p1), (h2, p2).
                const glm::dvec3 d01 = (p1 - p0) / h1, d12 = (p2 - p1) / h2;
                const glm::dvec3 curvature = (d12 - d01) / (h1 + h2);  // half the second derivative
                rows[i].velocity = d01 + curvature * (h1 + 2 * x);
            }
        }
    }
    // Everything the sender sends is float (velocities, angular velocities) and the float
    // positions of the library's default build: refuse what would overflow there, naming the
    // row, instead of a refusal from the sender with no place in the file.
    constexpr double kFloatRange = 1e30;  // well inside float (3.4e38): v t and a t^2 stay finite
    auto beyond = [](const glm::dvec3& v) {
        return !(std::abs(v.x) <= kFloatRange && std::abs(v.y) <= kFloatRange && std::abs(v.z) <= kFloatRange);
    };
    for (const CsvRow& row : rows) {
        if (beyond(row.position)) {
            error = fileName + ":" + std::to_string(row.line) + ": the position is beyond 1e30 m";
            return false;
        }
    }
    for (const CsvRow& row : rows) {
        if (beyond(row.velocity) || beyond(row.angularVelocity)) {
            error = fileName + ":" + std::to_string(row.line) + ": the " +
                    (beyond(row.velocity) ? std::string("velocity") : std::string("angular velocity")) +
                    (columnOf[8] < 0 && beyond(row.velocity) ? " (from the positions and times around this row)" : "") +
                    " is beyond 1e30: rows too close in time for their distance?";
            return false;
        }
    }
    motion->hasAngularVelocity = columnOf[11] >= 0;
    motion->segmentRotation.resize(n - 1);
    for (std::size_t i = 0; i + 1 < n; ++i) {
        glm::dquat r = glm::conjugate(rows[i].orientation) * rows[i + 1].orientation;
        if (r.w < 0) r = -r;
        const glm::dvec3 axis(r.x, r.y, r.z);
        const double sine = glm::length(axis);
        const double angle = 2 * std::atan2(sine, r.w);
        motion->segmentRotation[i] = sine > 0 ? axis / sine * (angle / (rows[i + 1].t - rows[i].t)) : glm::dvec3(0);
        if (beyond(motion->segmentRotation[i])) {
            error = fileName + ":" + std::to_string(rows[i + 1].line) +
                    ": the turn rate from the orientations of this row and the previous is beyond 1e30 rad/s";
            return false;
        }
    }
    Trajectory t;
    t.name = fileName;
    t.description = "the rows of " + fileName + " (" + std::to_string(n) + " rows" +
                    (t0 != 0 ? ", times from the first row's " + shortValue(t0) + " s" : std::string()) + ")";
    t.start = rows.front().t;
    t.end = rows.back().t;
    t.sample = [motion](double time) { return motion->sample(time); };
    out = std::move(t);
    return true;
}

// --------------------------------------------------------------------------------------------
// Link

Link::Link(const LinkSettings& settings) : mSettings(settings), mEngine(settings.seed) {}

double Link::uniform() { return uniform01(mEngine); }

bool Link::transmit(double& delay) {
    // Both draws happen for every packet, so a packet's jitter does not depend on the fates of
    // the packets before it.
    const bool lost = uniform() < mSettings.loss;
    const double jitter = mSettings.jitter * (2 * uniform() - 1);
    if (lost) return false;
    delay = std::max(0.0, mSettings.latency + jitter);
    return true;
}

// --------------------------------------------------------------------------------------------
// Displays

const std::vector<Display>& allDisplays() {
    static const std::vector<Display> displays = {Display::Snap, Display::Linear, Display::Projective, Display::Decay,
                                                  Display::Interpolate};
    return displays;
}

const char* displayName(Display display) {
    switch (display) {
        case Display::Snap:
            return "snap";
        case Display::Linear:
            return "linear";
        case Display::Projective:
            return "pvb";
        case Display::Decay:
            return "decay";
        case Display::Interpolate:
            return "interpolate";
    }
    return "?";
}

bool findDisplay(std::string_view name, Display& out) {
    for (const Display display : allDisplays()) {
        if (name == displayName(display)) {
            out = display;
            return true;
        }
    }
    return false;
}

// --------------------------------------------------------------------------------------------
// Statistics

Summary summarise(std::vector<double>& values) {
    Summary summary;
    if (values.empty()) return summary;
    double sum = 0;
    for (const double v : values) sum += v;
    summary.mean = sum / static_cast<double>(values.size());
    // Nearest rank: the smallest value with at least 95% of the values at or below it.
    const std::size_t rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(values.size())));
    const auto nth = values.begin() + static_cast<std::ptrdiff_t>(std::max<std::size_t>(rank, 1) - 1);
    std::nth_element(values.begin(), nth, values.end());
    summary.p95 = *nth;
    summary.max = *std::max_element(values.begin(), values.end());
    return summary;
}

double rotationAngleDegrees(const glm::dquat& a, const glm::dquat& b) {
    const glm::dquat r = glm::conjugate(a) * b;
    const double sine = std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z);
    return 2 * std::atan2(sine, std::abs(r.w)) * 180 / kPi;
}

// --------------------------------------------------------------------------------------------
// Simulation

namespace {

foresight::DeadReckoningState stateFor(DeadReckoningAlgorithm model, const TruthState& truth) {
    foresight::DeadReckoningState state;
    state.algorithm = model;
    state.position = foresight::RVec3(truth.position);
    state.orientation = foresight::Quat(truth.orientation);
    state.angularVelocity = foresight::Vec3(truth.angularVelocity);
    if (foresight::deadReckoningInBodyAxes(model)) {
        // Body axes: the velocity in the body's axes, and as acceleration the rate of change of
        // that body-axis velocity (q^-1 a - w x v_body), which is what RVB and FVB integrate
        // (the world acceleration in body axes would count a steady turn twice).
        const glm::dquat inverse = glm::conjugate(truth.orientation);
        const glm::dvec3 bodyVelocity = inverse * truth.velocity;
        state.velocity = foresight::Vec3(bodyVelocity);
        state.acceleration =
            foresight::Vec3(inverse * truth.acceleration - glm::cross(truth.angularVelocity, bodyVelocity));
    } else {
        state.velocity = foresight::Vec3(truth.velocity);
        state.acceleration = foresight::Vec3(truth.acceleration);
    }
    return state;
}

struct Packet {
    std::size_t sendIndex = 0;
    double timestamp = 0;
    double arrival = 0;
    foresight::DeadReckoningState state;
};

foresight::ReceiverSettings receiverSettingsFor(const foresight::ReceiverSettings& base, Display display) {
    foresight::ReceiverSettings settings = base;
    settings.mode = foresight::ReceiverMode::Extrapolate;
    switch (display) {
        case Display::Snap:
            settings.smoothing = foresight::Smoothing::Snap;
            break;
        case Display::Linear:
            settings.smoothing = foresight::Smoothing::LinearBlend;
            break;
        case Display::Projective:
            settings.smoothing = foresight::Smoothing::ProjectiveVelocityBlending;
            break;
        case Display::Decay:
            settings.smoothing = foresight::Smoothing::ExponentialDecay;
            break;
        case Display::Interpolate:
            settings.mode = foresight::ReceiverMode::Interpolate;
            break;
    }
    return settings;
}

/// The number of evenly spaced instants k / rate in [0, duration] (k = 0, 1, ...).
std::size_t instantCount(double duration, double rate) {
    // The epsilon keeps a last instant that lands on the end despite rounding (60 s at 60 Hz).
    return static_cast<std::size_t>(std::floor(duration * rate + 1e-9)) + 1;
}

}  // namespace

bool simulateTrajectory(const Trajectory& trajectory, const SimulationSettings& settings, bool keepSeries,
                        TrajectoryResult& out, std::string& error,
                        const std::function<void(std::size_t, std::size_t)>& progress) {
    TrajectoryResult result;
    result.name = trajectory.name;
    result.description = trajectory.description;
    result.duration = std::min(settings.duration, trajectory.end - trajectory.start);
    const double start = trajectory.start;
    const double end = start + result.duration;

    const std::size_t frameCount = instantCount(result.duration, settings.renderRate);
    std::vector<double> frameTimes(frameCount);
    std::vector<TruthState> frameTruth(frameCount);
    for (std::size_t j = 0; j < frameCount; ++j) {
        frameTimes[j] = start + static_cast<double>(j) / settings.renderRate;
        frameTruth[j] = trajectory.sample(frameTimes[j]);
        if (j > 0) result.distance += glm::length(frameTruth[j].position - frameTruth[j - 1].position);
    }
    const std::size_t tickCount = instantCount(result.duration, settings.sendRate);

    for (std::size_t m = 0; m < settings.models.size(); ++m) {
        const DeadReckoningAlgorithm model = settings.models[m];
        ModelResult modelResult;
        modelResult.model = model;

        // The sender, tick by tick; its updates through the link.
        foresight::DeadReckoningSender sender(settings.sender);
        Link link(settings.link);
        std::vector<Packet> packets;
        for (std::size_t k = 0; k < tickCount; ++k) {
            const double time = start + static_cast<double>(k) / settings.sendRate;
            const foresight::DeadReckoningState state = stateFor(model, trajectory.sample(time));
            foresight::SendDecision decision;
            const Status status = sender.update(time, state, decision);
            if (status != Status::Ok) {
                error = std::string("the sender refused an update at t = ") + shortValue(time) +
                        " s: " + foresight::statusMessage(status);
                return false;
            }
            if (settings.snapshots) {
                // Every tick: the thresholds' decision is ignored (the sender still runs, so a
                // bad state is refused the same way).
                ++modelResult.sentSnapshot;
            } else {
                if (!decision.send()) continue;
                const auto counts = [&](std::uint8_t reason) { return (decision.reasons & reason) != 0 ? 1u : 0u; };
                modelResult.sentFirst += counts(foresight::SendReasonFirst);
                modelResult.sentPosition += counts(foresight::SendReasonPosition);
                modelResult.sentOrientation += counts(foresight::SendReasonOrientation);
                modelResult.sentHeartbeat += counts(foresight::SendReasonHeartbeat);
            }
            ++modelResult.updates;
            double delay = 0;
            if (!link.transmit(delay)) {
                ++modelResult.lost;
                continue;
            }
            if (time + delay > end) {
                ++modelResult.late;
                continue;
            }
            packets.push_back({k, time, time + delay, state});
        }
        modelResult.updatesPerSecond = static_cast<double>(modelResult.updates) / result.duration;
        std::stable_sort(packets.begin(), packets.end(),
                         [](const Packet& a, const Packet& b) { return a.arrival < b.arrival; });
        std::size_t newestSent = 0;
        for (std::size_t p = 0; p < packets.size(); ++p) {
            if (p > 0 && packets[p].sendIndex < newestSent) ++modelResult.reordered;
            newestSent = std::max(newestSent, packets[p].sendIndex);
        }

        // One receiver per display, all fed the same arrivals, rendering every frame.
        struct Track {
            foresight::DeadReckoningReceiver receiver;
            std::vector<double> positionErrors, orientationErrors;
            glm::dvec3 previousShown{0};
            bool hasPrevious = false;
            DisplayResult result;
        };
        std::vector<Track> tracks;
        tracks.reserve(settings.displays.size());
        for (const Display display : settings.displays) {
            tracks.push_back(Track{foresight::DeadReckoningReceiver(receiverSettingsFor(settings.receiver, display)),
                                   {},
                                   {},
                                   glm::dvec3(0),
                                   false,
                                   DisplayResult{}});
            tracks.back().result.display = display;
            tracks.back().positionErrors.reserve(frameCount);
            tracks.back().orientationErrors.reserve(frameCount);
        }
        std::size_t next = 0;
        for (std::size_t j = 0; j < frameCount; ++j) {
            const double time = frameTimes[j];
            for (; next < packets.size() && packets[next].arrival <= time; ++next)
                for (Track& track : tracks)
                    track.receiver.receive(packets[next].timestamp, packets[next].state, packets[next].arrival);
            const TruthState& truth = frameTruth[j];
            for (Track& track : tracks) {
                foresight::ReceivedPose pose;
                const Status status = track.receiver.sample(time, pose);
                if (status == Status::NoUpdate) continue;
                if (status != Status::Ok) {
                    error = std::string("the receiver refused a frame at t = ") + shortValue(time) +
                            " s: " + foresight::statusMessage(status);
                    return false;
                }
                const glm::dvec3 shown(pose.position);
                const double positionError = glm::length(shown - truth.position);
                track.positionErrors.push_back(positionError);
                track.orientationErrors.push_back(
                    rotationAngleDegrees(glm::dquat(pose.orientation), truth.orientation));
                if (track.hasPrevious) {
                    // A pop, not a stall: the shown entity moved further than the true one did.
                    const double shownStep = glm::length(shown - track.previousShown);
                    const double trueStep = glm::length(truth.position - frameTruth[j - 1].position);
                    if (shownStep > trueStep + settings.jumpThreshold) ++track.result.jumps;
                }
                track.previousShown = shown;
                track.hasPrevious = true;
                if (keepSeries) {
                    track.result.seriesTime.push_back(static_cast<float>(time - start));
                    track.result.seriesError.push_back(static_cast<float>(positionError));
                }
            }
        }
        for (Track& track : tracks) {
            DisplayResult& r = track.result;
            r.frames = track.positionErrors.size();
            r.position = summarise(track.positionErrors);
            r.orientation = summarise(track.orientationErrors);
            const foresight::ReceiverCounters& counters = track.receiver.counters();
            r.snaps = counters.snaps;
            r.dropped = counters.outOfOrder + counters.duplicates + counters.invalid;
            modelResult.displays.push_back(std::move(r));
        }
        result.models.push_back(std::move(modelResult));
        if (progress) progress(m + 1, settings.models.size());
    }
    out = std::move(result);
    return true;
}

// --------------------------------------------------------------------------------------------
// Reports

namespace {

std::string format(const char* pattern, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, pattern, value);
    return buffer;
}

std::string milliseconds(double seconds) { return format("%g", std::round(seconds * 1e6) / 1e3); }

}  // namespace

std::string settingsLine(const SimulationSettings& settings) {
    std::string line =
        "latency " + milliseconds(settings.link.latency) + " ms, jitter +/-" + milliseconds(settings.link.jitter) +
        " ms (uniform), loss " + format("%g", settings.link.loss * 100) + "%, seed " +
        std::to_string(settings.link.seed) + "; send " + format("%g", settings.sendRate) + " Hz, render " +
        format("%g", settings.renderRate) +
        (settings.snapshots
             ? std::string(" Hz; sender: a snapshot every tick")
             : " Hz; sender thresholds " + format("%g", static_cast<double>(settings.sender.positionThreshold)) +
                   " m, " +
                   format(
                       "%g",
                       std::round(static_cast<double>(settings.sender.orientationThreshold) * 180 / kPi * 1e4) / 1e4) +
                   " deg, heartbeat " + format("%g", static_cast<double>(settings.sender.heartbeat)) + " s") +
        "; blend " + milliseconds(static_cast<double>(settings.receiver.blendTime)) + " ms, decay half-life " +
        milliseconds(static_cast<double>(settings.receiver.decayHalfLife)) + " ms, interpolation delay " +
        milliseconds(static_cast<double>(settings.receiver.interpolationDelay)) + " ms, extrapolation limit " +
        (std::isinf(settings.receiver.extrapolationLimit)
             ? std::string("none")
             : milliseconds(static_cast<double>(settings.receiver.extrapolationLimit)) + " ms") +
        "; jump > " + format("%g", settings.jumpThreshold) + " m";
    return line;
}

std::string textTable(const std::vector<TrajectoryResult>& results, const SimulationSettings& settings) {
    std::string text = settingsLine(settings) + "\n\n";
    char buffer[400];
    std::snprintf(buffer, sizeof buffer, "%-16s %-6s %-11s %9s %9s %9s %9s %9s %9s %6s %6s %5s %5s %5s\n", "trajectory",
                  "model", "display", "updates/s", "mean [m]", "p95 [m]", "max [m]", "mean [d]", "max [d]", "snaps",
                  "jumps", "lost", "reord", "drop");
    text += buffer;
    for (const auto& trajectory : results) {
        for (const auto& model : trajectory.models) {
            for (const auto& d : model.displays) {
                // No frame shown (every update lost): no error to report, not a zero one.
                char errors[64];
                if (d.frames == 0)
                    std::snprintf(errors, sizeof errors, "%9s %9s %9s %9s %9s", "-", "-", "-", "-", "-");
                else
                    std::snprintf(errors, sizeof errors, "%9.3f %9.3f %9.3f %9.2f %9.2f", d.position.mean,
                                  d.position.p95, d.position.max, d.orientation.mean, d.orientation.max);
                std::snprintf(
                    buffer, sizeof buffer, "%-16s %-6s %-11s %9.2f %s %6llu %6llu %5llu %5llu %5llu\n",
                    trajectory.name.c_str(), foresight::deadReckoningAlgorithmName(model.model), displayName(d.display),
                    model.updatesPerSecond, errors, static_cast<unsigned long long>(d.snaps),
                    static_cast<unsigned long long>(d.jumps), static_cast<unsigned long long>(model.lost),
                    static_cast<unsigned long long>(model.reordered), static_cast<unsigned long long>(d.dropped));
                text += buffer;
            }
        }
    }
    text +=
        "\nPosition error: |shown - true| at each rendered frame (interpolate: against the truth at the\n"
        "render time, so its delay is part of its error). [d]: orientation error in degrees. lost, reord:\n"
        "updates the link lost or delivered after a later one; drop: updates the receiver dropped.\n";
    for (const auto& trajectory : results) text += "- " + trajectory.name + ": " + trajectory.description + "\n";
    return text;
}

std::string markdownTable(const std::vector<TrajectoryResult>& results, const SimulationSettings& settings) {
    std::string text = "| Trajectory | Model | Updates/s |";
    std::string rule = "|---|---|---:|";
    for (const Display display : settings.displays) {
        text += std::string(" ") + displayName(display) + " |";
        rule += "---:|";
    }
    text += "\n" + rule + "\n";
    char buffer[128];
    for (const auto& trajectory : results) {
        for (const auto& model : trajectory.models) {
            std::snprintf(buffer, sizeof buffer, "| %s | %s | %.1f |", trajectory.name.c_str(),
                          foresight::deadReckoningAlgorithmName(model.model), model.updatesPerSecond);
            text += buffer;
            for (const auto& d : model.displays) {
                if (d.frames == 0)
                    std::snprintf(buffer, sizeof buffer, " - / - / %llu |", static_cast<unsigned long long>(d.jumps));
                else
                    std::snprintf(buffer, sizeof buffer, " %.2f / %.2f / %llu |", d.position.p95, d.position.max,
                                  static_cast<unsigned long long>(d.jumps));
                text += buffer;
            }
            text += "\n";
        }
    }
    text += "\nEach cell: 95th percentile / maximum position error [m] / visible jumps, over " +
            format("%g", results.empty() ? settings.duration : results.front().duration) + " s. " +
            settingsLine(settings) + ".\n";
    return text;
}

std::string svgChart(const TrajectoryResult& result, std::size_t modelIndex, const SimulationSettings& settings) {
    constexpr double kWidth = 900, kHeight = 470;
    constexpr double kLeft = 70, kRight = 20, kTop = 64, kBottom = 50;
    constexpr double kPlotWidth = kWidth - kLeft - kRight, kPlotHeight = kHeight - kTop - kBottom;
    const char* const colours[] = {"#c0392b", "#e67e22", "#1f6fd1", "#16a085", "#6c3483"};
    const ModelResult& model = result.models.at(modelIndex);
    double maxError = 0;
    for (const auto& d : model.displays)
        for (const float e : d.seriesError) maxError = std::max(maxError, static_cast<double>(e));
    const double yStep = maxError > 0 ? gridStep(maxError) : 0.1;
    const double yMax = std::max(yStep, std::ceil(maxError / yStep) * yStep);
    const double xMax = result.duration > 0 ? result.duration : 1;
    const double xStep = gridStep(xMax);
    const auto px = [&](double t) { return kLeft + t / xMax * kPlotWidth; };
    const auto py = [&](double e) { return kTop + (1 - e / yMax) * kPlotHeight; };
    const SvgWriter svg(1, false);

    std::string out = svg.begin(kWidth, kHeight);
    const std::string title =
        "Position error over time: " + result.name + ", " + foresight::deadReckoningAlgorithmName(model.model);
    out += svg.text(kLeft, "22", "font-size=\"15\" font-weight=\"bold\"", escapeXml(title, false));
    // The settings, wrapped at "; " to fit the width (10 px text, about 5.5 px a character).
    const std::string line = settingsLine(settings);
    std::vector<std::string> rows(1);
    for (std::size_t at = 0; at < line.size();) {
        const std::size_t semicolon = std::min(line.find("; ", at), line.size());
        const std::string part = line.substr(at, semicolon - at);
        if (!rows.back().empty() && rows.back().size() + part.size() + 2 > 150) rows.emplace_back();
        rows.back() += (rows.back().empty() ? "" : "; ") + part;
        at = semicolon + 2;
    }
    for (std::size_t r = 0; r < rows.size(); ++r)
        out += svg.text(kLeft, 34 + 11 * static_cast<double>(r), "font-size=\"10\" fill=\"#555\"", rows[r]);
    out += svg.rect(kLeft, kTop, kPlotWidth, kPlotHeight, "fill=\"#fbfbfb\" stroke=\"#555\"");
    for (double t = 0; t <= xMax + 1e-9 * xStep; t += xStep) {
        out += svg.line(px(t), kTop, px(t), kTop + kPlotHeight, "stroke=\"#e3e3e3\"");
        out += svg.text(px(t), kTop + kPlotHeight + 16, "font-size=\"11\" text-anchor=\"middle\"", format("%g", t));
    }
    for (double e = 0; e <= yMax + 1e-9 * yStep; e += yStep) {
        out += svg.line(kLeft, py(e), kLeft + kPlotWidth, py(e), "stroke=\"#e3e3e3\"");
        out += svg.text(kLeft - 6, py(e) + 4, "font-size=\"11\" text-anchor=\"end\"", format("%g", e));
    }
    out += svg.text(kLeft + kPlotWidth / 2, kHeight - 12, "font-size=\"12\" text-anchor=\"middle\"", "time [s]");
    out += svg.text("18", kTop + kPlotHeight / 2,
                    "font-size=\"12\" text-anchor=\"middle\" transform=\"rotate(-90 18 " +
                        svg.number(kTop + kPlotHeight / 2) + ")\"",
                    "position error [m]");
    const double legendLeft = kLeft + kPlotWidth - 200;
    const auto legendY = [&](std::size_t i) { return kTop + 22 + 16 * static_cast<double>(i); };
    std::string legend;
    for (std::size_t i = 0; i < model.displays.size(); ++i) {
        const DisplayResult& d = model.displays[i];
        const std::string colour = colours[i % 5];
        // At most two points per pixel column (its smallest and largest error, in time order), so
        // an hour at 240 Hz stays a small file and keeps its peaks.
        std::string points;
        const std::size_t count = d.seriesError.size();
        std::size_t k = 0;
        while (k < count) {
            const double column = std::floor(px(d.seriesTime[k]));
            std::size_t low = k, high = k, last = k;
            while (last + 1 < count && std::floor(px(d.seriesTime[last + 1])) == column) {
                ++last;
                if (d.seriesError[last] < d.seriesError[low]) low = last;
                if (d.seriesError[last] > d.seriesError[high]) high = last;
            }
            for (const std::size_t p : {std::min(low, high), std::max(low, high)}) {
                points += svg.point(px(d.seriesTime[p]), py(d.seriesError[p])) + " ";
                if (low == high) break;
            }
            k = last + 1;
        }
        out += svg.polyline("fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"1.2\"", points);
        legend += svg.line(legendLeft + 8, legendY(i) - 4, legendLeft + 30, legendY(i) - 4,
                           "stroke=\"" + colour + "\" stroke-width=\"2\"");
        legend += svg.text(legendLeft + 36, legendY(i), "font-size=\"11\"",
                           displayName(d.display) + format(" (p95 %.2f m)", d.position.p95));
    }
    // The legend last, on a white box above the lines.
    out += svg.rect(legendLeft, kTop + 6, "190", 16 * static_cast<double>(model.displays.size()) + 8,
                    "fill=\"white\" fill-opacity=\"0.9\" stroke=\"#bbb\"");
    out += legend;
    out += SvgWriter::end();
    return out;
}

}  // namespace foresight_cli::netsim
