// The library's prediction calls with arbitrary floats (include/foresight/*.h): the input
// picks an entry point and is decoded into its settings and states (raw float bits, special
// values or small numbers). The contract checked: every call returns a Status (or count) and
// never crashes; when it is Ok, no output holds a NaN or an infinity (status.h: "foresight never
// produces NaN from bad data"). A broken contract aborts, so that libFuzzer keeps the input.
// Work caps (maxSteps, maxEvents, budgets, iterations) are drawn small so that one input runs
// in milliseconds; they are settings like any other.
#include "fuzz_common.h"

#include <foresight/foresight.h>

#include <fuzzer/FuzzedDataProvider.h>

#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <vector>

namespace {

using namespace foresight;

class Decoder {
public:
    Decoder(const std::uint8_t* data, std::size_t size) : mIn(data, size) {}

    std::uint8_t byte() { return mIn.ConsumeIntegral<std::uint8_t>(); }
    bool flag() { return mIn.ConsumeBool(); }
    std::uint32_t upTo(std::uint32_t high) { return mIn.ConsumeIntegralInRange<std::uint32_t>(0, high); }

    /// Any float: raw bits, a special value, or a small number (most inputs).
    float f() {
        const std::uint8_t mode = byte() % 8;
        if (mode == 0) return std::bit_cast<float>(mIn.ConsumeIntegral<std::uint32_t>());
        if (mode == 1) {
            static constexpr std::array<float, 14> kSpecial = {0.0f,
                                                               -0.0f,
                                                               std::numeric_limits<float>::infinity(),
                                                               -std::numeric_limits<float>::infinity(),
                                                               std::numeric_limits<float>::quiet_NaN(),
                                                               std::numeric_limits<float>::max(),
                                                               -std::numeric_limits<float>::max(),
                                                               std::numeric_limits<float>::min(),
                                                               std::numeric_limits<float>::denorm_min(),
                                                               1e-30f,
                                                               1e30f,
                                                               1e16f,
                                                               1e7f,
                                                               -1e7f};
            return kSpecial[byte() % kSpecial.size()];
        }
        return static_cast<float>(mIn.ConsumeIntegral<std::int16_t>()) / 64.0f;
    }
    /// Any double, as f().
    double d() {
        const std::uint8_t mode = byte() % 8;
        if (mode == 0) return std::bit_cast<double>(mIn.ConsumeIntegral<std::uint64_t>());
        if (mode == 1) return static_cast<double>(f());
        return static_cast<double>(mIn.ConsumeIntegral<std::int32_t>()) / 4096.0;
    }
    Vec3 v() { return Vec3(f(), f(), f()); }
    RVec3 p() {
        if constexpr (kDoublePrecision)
            return RVec3(d(), d(), d());
        else
            return RVec3(f(), f(), f());
    }
    Quat q() {
        if (byte() % 4 == 0) return glm::identity<Quat>();
        return Quat(f(), f(), f(), f());
    }

private:
    FuzzedDataProvider mIn;
};

bool finite(float x) { return std::isfinite(x); }
[[maybe_unused]] bool finite(double x) { return std::isfinite(x); }
template <int N, typename T, glm::qualifier Q>
bool finite(const glm::vec<N, T, Q>& x) {
    for (int i = 0; i < N; ++i)
        if (!std::isfinite(x[i])) return false;
    return true;
}
template <typename T, glm::qualifier Q>
bool finite(const glm::qua<T, Q>& x) {
    return std::isfinite(x.w) && std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z);
}
bool finite(const TrajectoryPoint& p) {
    return finite(p.time) && finite(p.position) && finite(p.velocity) && finite(p.normal);
}
bool finite(const DeadReckoningResult& r) { return finite(r.position) && finite(r.velocity) && finite(r.orientation); }

#define CHECK_OK_FINITE(status, ...)                                   \
    do {                                                               \
        if ((status) == Status::Ok) FORESIGHT_FUZZ_CHECK(__VA_ARGS__); \
    } while (false)

// ---------------------------------------------------------------------------------------------

/// A world of up to 4 shapes (refused ones are not added).
void buildWorld(Decoder& in, StaticWorld& world) {
    const std::uint32_t count = in.upTo(4);
    for (std::uint32_t i = 0; i < count; ++i) {
        SurfaceMaterial material;
        const bool ownMaterial = in.flag();
        if (ownMaterial) {
            material.restitution = in.f();
            material.friction = in.f();
        }
        auto add = [&](const auto& shape) {
            const Status s = ownMaterial ? world.add(shape, material) : world.add(shape);
            (void)s;
        };
        switch (in.byte() % 4) {
            case 0: {
                Plane plane;
                plane.normal = in.v();
                plane.distance = in.f();
                add(plane);
                break;
            }
            case 1: {
                Sphere sphere;
                sphere.center = in.p();
                sphere.radius = in.f();
                add(sphere);
                break;
            }
            case 2: {
                OrientedBox box;
                box.center = in.p();
                box.halfExtents = in.v();
                box.orientation = in.q();
                add(box);
                break;
            }
            default: {
                Triangle triangle;
                triangle.a = in.p();
                triangle.b = in.p();
                triangle.c = in.p();
                add(triangle);
                break;
            }
        }
    }
}

void projectileSettings(Decoder& in, ProjectileSettings& s) {
    s.method = static_cast<ProjectileMethod>(in.byte() % 4);  // 3: out of range
    if (in.flag()) s.gravity = in.v();
    if (in.flag()) s.step = in.f();
    if (in.flag()) s.restitution = in.f();
    if (in.flag()) s.friction = in.f();
    if (in.flag()) s.radius = in.f();
    if (in.flag()) s.maxBounces = in.upTo(64);
    s.maxSteps = in.upTo(1u << 14);
    s.maxEvents = in.upTo(1u << 10);
    if (s.method == ProjectileMethod::Engine) {
        s.engine = engineProfile(static_cast<PhysicsEngine>(in.byte() % 8));
        EngineProfile& e = s.engine;
        const std::uint8_t mask = in.byte();
        if (mask & 1) e.timestep = in.f();
        if (mask & 2) e.substeps = in.upTo(16);
        if (mask & 4) {
            e.linearDamping = in.f();
            e.addedLinearDamping = in.f();
            e.angularDamping = in.f();
        }
        if (mask & 8) {
            e.restitutionThreshold = in.f();
            e.contactDistance = in.f();
            e.penetrationSlop = in.f();
            e.positionCorrection = in.f();
        }
        if (mask & 16) {
            e.maxLinearSpeed = in.f();
            e.maxStepDistance = in.f();
        }
        if (mask & 32) {
            e.order = static_cast<DampingOrder>(in.byte() % 4);
            e.damping = static_cast<DampingLaw>(in.byte() % 4);
            e.firstStep = static_cast<FirstStepRule>(in.byte() % 4);
            e.restitutionBase = static_cast<RestitutionBase>(in.byte() % 4);
            e.restitutionCombine = static_cast<CombineRule>(in.byte() % 8);
            e.frictionCombine = static_cast<CombineRule>(in.byte() % 8);
            e.contact = static_cast<ContactMethod>(in.byte() % 4);
        }
        if (mask & 64) {
            e.correctionIsVelocity = in.flag();
            e.planar = in.flag();
            e.rotates = in.flag();
            e.triangleMesh = in.flag();
        }
    }
}

bool finite(const ProjectileResult& r) {
    return finite(r.position) && finite(r.velocity) && finite(r.time) && finite(r.hitNormal);
}

void danger(Decoder& in, std::span<const TrajectoryPoint> trajectory) {
    ProjectileDanger danger;
    danger.trajectory = trajectory;
    danger.fuseTime = in.f();
    danger.blastRadius = in.f();
    danger.contactRadius = in.f();
    DangerZone zone;
    Status s = computeDangerZone(danger, zone);
    CHECK_OK_FINITE(s, finite(zone.center) && finite(zone.radius) && finite(zone.time));
    const RVec3 point = in.p();
    bool safe = false;
    s = isPointSafe(danger, point, in.f(), safe);
    DangerStart start;
    s = findDangerStart(danger, point, start);
    CHECK_OK_FINITE(s, finite(start.time));
    s = findPathApproach(trajectory, point, in.f(), in.f(), in.f(), start);
    CHECK_OK_FINITE(s, finite(start.time));
    ClosestApproach closest;
    s = findClosestPathApproach(trajectory, point, in.f(), in.f(), closest);
    CHECK_OK_FINITE(s, finite(closest.distance) && finite(closest.time));
    RVec3 position;
    s = positionOnTrajectory(trajectory, in.f(), position);
    CHECK_OK_FINITE(s, finite(position));
}

void projectile(Decoder& in) {
    StaticWorld world;
    buildWorld(in, world);
    ProjectileSettings settings;
    projectileSettings(in, settings);
    const RVec3 position = in.p();
    const Vec3 velocity = in.v();
    const float time = in.f();
    std::vector<TrajectoryPoint> trajectory(in.upTo(256));
    ProjectileResult result;
    const Status s =
        predictProjectile(position, velocity, time, settings, in.flag() ? &world : nullptr, trajectory, result);
    if (s != Status::Ok) return;
    FORESIGHT_FUZZ_CHECK(finite(result));
    FORESIGHT_FUZZ_CHECK(result.trajectorySize <= trajectory.size());
    FORESIGHT_FUZZ_CHECK(result.trajectorySize <= result.trajectoryNeeded);
    for (std::size_t i = 0; i < result.trajectorySize; ++i) FORESIGHT_FUZZ_CHECK(finite(trajectory[i]));
    const std::span<const TrajectoryPoint> recorded(trajectory.data(), result.trajectorySize);
    if (settings.method != ProjectileMethod::Exact && in.flag()) {
        // Fixed-step trajectories as a game renders them.
        const RVec3 shown =
            renderedPosition(recorded, settingsStep(settings), in.f(), static_cast<RenderSmoothing>(in.byte() % 3));
        (void)shown;
    }
    danger(in, recorded);
}

void dangerOnRawTrajectory(Decoder& in) {
    std::vector<TrajectoryPoint> trajectory(in.upTo(8));
    for (auto& p : trajectory) {
        p.time = in.f();
        p.event = static_cast<TrajectoryEvent>(in.byte() % 7);
        p.position = in.p();
        p.velocity = in.v();
        p.normal = in.v();
    }
    danger(in, trajectory);
}

void character(Decoder& in) {
    PointState start;
    start.position = in.p();
    start.velocity = in.v();
    PointState out;
    Status s = predictLinear(start, in.f(), out);
    CHECK_OK_FINITE(s, finite(out.position) && finite(out.velocity));
    s = predictAccelerated(start, in.v(), in.f(), out);
    CHECK_OK_FINITE(s, finite(out.position) && finite(out.velocity));
    Quat orientation;
    s = predictOrientation(in.q(), in.v(), static_cast<AngularFrame>(in.byte() % 3), in.f(), orientation);
    CHECK_OK_FINITE(s, finite(orientation));
    s = normalizeQuaternion(in.q(), orientation);
    CHECK_OK_FINITE(s, finite(orientation));
}

void vehicle(Decoder& in) {
    VehicleState start;
    start.position = in.p();
    start.velocity = in.v();
    start.orientation = in.q();
    start.angularVelocity = in.v();
    VehicleSettings settings;
    settings.frame = static_cast<AngularFrame>(in.byte() % 3);
    if (in.flag()) settings.forward = in.v();
    const float time = in.f();
    VehicleState out;
    Status s = predictVehicleExact(start, time, settings, out);
    CHECK_OK_FINITE(
        s, finite(out.position) && finite(out.velocity) && finite(out.orientation) && finite(out.angularVelocity));
    const int iterations = static_cast<int>(in.upTo(1024)) - 2;
    s = predictVehicleIterative(start, time, iterations, settings, out);
    CHECK_OK_FINITE(
        s, finite(out.position) && finite(out.velocity) && finite(out.orientation) && finite(out.angularVelocity));
}

void vehicleDanger(Decoder& in) {
    VehicleBody vehicle;
    vehicle.state.position = in.p();
    vehicle.state.velocity = in.v();
    vehicle.state.orientation = in.q();
    vehicle.state.angularVelocity = in.v();
    vehicle.settings.frame = static_cast<AngularFrame>(in.byte() % 3);
    if (in.flag()) vehicle.settings.forward = in.v();
    if (in.flag()) vehicle.halfExtents = in.v();
    if (in.flag()) vehicle.boxCenter = in.v();
    CharacterBody character;
    character.position = in.p();
    character.velocity = in.v();
    if (in.flag()) character.acceleration = in.v();
    if (in.flag()) character.radius = in.f();
    if (in.flag()) character.halfAxis = in.v();
    ApproachSettings settings;
    if (in.flag()) settings.tolerance = in.f();
    settings.maxEvaluations = in.upTo(4096);
    float separation = 0;
    Status s = computeVehicleSeparation(vehicle, character, in.f(), separation);
    CHECK_OK_FINITE(s, finite(separation));
    const float horizon = in.f();
    VehicleContact contact;
    s = findVehicleContact(vehicle, character, horizon, settings, contact);
    CHECK_OK_FINITE(s, finite(contact.time) && finite(contact.separation));
    ClosestApproach closest;
    s = findClosestVehicleApproach(vehicle, character, horizon, settings, closest);
    CHECK_OK_FINITE(s, finite(closest.distance) && finite(closest.time));
}

void aim(Decoder& in) {
    AimShot shot;
    shot.from = in.p();
    shot.constraint = static_cast<AimConstraint>(in.byte() % 5);  // 4: out of range
    shot.speed = in.f();
    shot.apexHeight = in.f();
    if (in.flag()) shot.gravity = in.v();
    if (in.flag()) shot.maxTime = in.f();
    AimTarget target;
    target.position = in.p();
    target.velocity = in.v();
    target.acceleration = in.v();
    std::array<FiringSolution, kMaxFiringSolutions> solutions{};
    std::size_t count = 0;
    const Status s = aimProjectile(shot, target, std::span(solutions).first(in.upTo(kMaxFiringSolutions)), count);
    if (s != Status::Ok) return;
    FORESIGHT_FUZZ_CHECK(count <= kMaxFiringSolutions);
    for (std::size_t i = 0; i < count; ++i) {
        const FiringSolution& f = solutions[i];
        FORESIGHT_FUZZ_CHECK(finite(f.velocity) && finite(f.time) && finite(f.hit) && finite(f.elevation));
    }
}

DeadReckoningState deadReckoningState(Decoder& in) {
    DeadReckoningState state;
    state.algorithm = static_cast<DeadReckoningAlgorithm>(in.byte() % 11);  // 0 and 10: invalid
    state.position = in.p();
    state.velocity = in.v();
    state.acceleration = in.v();
    state.orientation = in.q();
    state.angularVelocity = in.v();
    return state;
}

void deadReckoning(Decoder& in) {
    const std::size_t count = 1 + in.upTo(7);
    std::vector<DeadReckoningState> states;
    std::vector<double> timestamps;
    for (std::size_t i = 0; i < count; ++i) {
        states.push_back(deadReckoningState(in));
        timestamps.push_back(in.d());
    }
    DeadReckoningResult result;
    const Status s = predictDeadReckoning(states[0], in.f(), result);
    CHECK_OK_FINITE(s, finite(result));

    const double time = in.d();
    std::vector<DeadReckoningResult> out(count);
    const std::size_t refused = predictDeadReckoningBatch(states, timestamps, time, out);
    FORESIGHT_FUZZ_CHECK(refused <= count);

    std::vector<PreparedDeadReckoning> prepared;
    DeadReckoningBatch batch(count);
    for (std::size_t i = 0; i < count; ++i) {
        PreparedDeadReckoning p;
        if (prepareDeadReckoning(states[i], timestamps[i], p) == Status::Ok) {
            prepared.push_back(p);
            FORESIGHT_FUZZ_CHECK(batch.set(prepared.size() - 1, p) == Status::Ok);
        }
    }
    const float limit = in.f();
    std::vector<DeadReckoningResult> extrapolated(prepared.size());
    const std::size_t refusedPrepared = extrapolateDeadReckoning(prepared, time, limit, extrapolated);
    FORESIGHT_FUZZ_CHECK(refusedPrepared <= prepared.size());
    // Every entity was validated: each result is extrapolated or its update as given, finite.
    if (refusedPrepared < prepared.size() || prepared.empty())
        for (const auto& r : extrapolated) FORESIGHT_FUZZ_CHECK(finite(r));
    std::vector<DeadReckoningResult> fast(count);
    const std::size_t refusedFast = batch.extrapolate(time, limit, std::span(fast).first(prepared.size()));
    FORESIGHT_FUZZ_CHECK(refusedFast <= count);
    if (refusedFast < prepared.size())
        for (std::size_t i = 0; i < prepared.size(); ++i) FORESIGHT_FUZZ_CHECK(finite(fast[i]));
}

void replication(Decoder& in) {
    SenderSettings senderSettings;
    if (in.flag()) {
        senderSettings.positionThreshold = in.f();
        senderSettings.orientationThreshold = in.f();
        senderSettings.heartbeat = in.f();
    }
    ReceiverSettings receiverSettings;
    receiverSettings.mode = static_cast<ReceiverMode>(in.byte() % 3);
    receiverSettings.smoothing = static_cast<Smoothing>(in.byte() % 5);
    if (in.flag()) {
        receiverSettings.blendTime = in.f();
        receiverSettings.decayHalfLife = in.f();
        receiverSettings.teleportDistance = in.f();
    }
    if (in.flag()) {
        receiverSettings.extrapolationLimit = in.f();
        receiverSettings.interpolationDelay = in.f();
        receiverSettings.maxFutureSkew = in.f();
        receiverSettings.restartAfter = in.f();
    }
    DeadReckoningSender sender(senderSettings);
    DeadReckoningReceiver receiver(receiverSettings);
    const std::uint32_t events = in.upTo(48);
    for (std::uint32_t i = 0; i < events; ++i) {
        switch (in.byte() % 3) {
            case 0: {
                SendDecision decision;
                const Status s = sender.update(in.d(), deadReckoningState(in), decision);
                CHECK_OK_FINITE(s, !std::isnan(decision.positionError) && finite(decision.orientationError));
                break;
            }
            case 1: {
                const DeadReckoningState state = deadReckoningState(in);
                const double stamp = in.d();
                receiver.receive(stamp, state, in.d());
                break;
            }
            default: {
                ReceivedPose pose;
                const Status s = receiver.sample(in.d(), pose);
                CHECK_OK_FINITE(s, finite(pose.position) && finite(pose.velocity) && finite(pose.orientation));
                break;
            }
        }
    }
}

void throwPlanner(Decoder& in) {
    StaticWorld world;
    buildWorld(in, world);
    ThrowPlanRequest request;
    request.start = in.p();
    request.target = in.p();
    if (in.flag()) request.acceptanceRadius = in.f();
    if (in.flag()) request.fuseTime = in.f();
    if (in.flag()) request.maxSpeed = in.f();
    if (in.flag()) request.minSpeed = in.f();
    projectileSettings(in, request.settings);
    request.maxPlans = in.upTo(4);
    if (in.flag()) request.distinctAngle = in.f();
    ThrowPlanBudget& b = request.budget;
    b.azimuthSamples = in.upTo(6);
    b.elevationSamples = in.upTo(4);
    b.speedSamples = in.upTo(3);
    b.refinements = in.upTo(40);
    b.refinementPredictions = in.upTo(8);
    b.maxPredictions = in.upTo(24);
    b.maxTotalSteps = in.upTo(1u << 16);
    if (in.flag()) b.gridStep = in.f();
    if (in.flag())
        for (float& fraction : b.seedLandingFractions) fraction = in.f();
    std::array<ThrowPlan, 4> plans{};
    std::vector<TrajectoryPoint> scratch(std::min<std::size_t>(throwPlanScratchSize(request), 512));
    ThrowPlanResult result;
    const Status s = planThrow(request, in.flag() ? &world : nullptr, plans, scratch, result);
    if (s != Status::Ok) return;
    FORESIGHT_FUZZ_CHECK(result.planCount <= plans.size());
    FORESIGHT_FUZZ_CHECK(finite(result.closestDistance) && finite(result.closestVelocity));
    for (std::size_t i = 0; i < result.planCount; ++i) {
        const ThrowPlan& p = plans[i];
        FORESIGHT_FUZZ_CHECK(finite(p.launchVelocity) && finite(p.finalPosition) && finite(p.distance) &&
                             finite(p.firstImpactTime) && finite(p.firstImpactNormal) && finite(p.firstImpactPosition));
        FORESIGHT_FUZZ_CHECK(p.distance <= request.acceptanceRadius);
    }
    if (result.planCount > 0) {
        std::vector<TrajectoryPoint> trajectory(64);
        ProjectileResult out;
        const Status ps = predictThrowPlan(request, plans[0], &world, trajectory, out);
        CHECK_OK_FINITE(ps, finite(out));
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    Decoder in(data + 1, size - 1);
    switch (data[0] % 9) {
        case 0:
            character(in);
            break;
        case 1:
            projectile(in);
            break;
        case 2:
            dangerOnRawTrajectory(in);
            break;
        case 3:
            vehicle(in);
            break;
        case 4:
            vehicleDanger(in);
            break;
        case 5:
            aim(in);
            break;
        case 6:
            deadReckoning(in);
            break;
        case 7:
            replication(in);
            break;
        default:
            throwPlanner(in);
            break;
    }
    return 0;
}
