// Throw planning (throw_planner.h). Every plan is checked by flying it again with the predictor
// and, where a closed form exists, against it: on a frictionless flat floor the horizontal
// velocity is constant, so the grenade covers |v_horizontal| * fuse; a bank shot off a vertical
// wall keeps the vertical motion and mirrors the horizontal one (the path of the mirrored
// target).
//
// The planner stops a prediction early once it surely ends too far from the target to matter
// (projectile_internal.h); its bound is checked on throws that bounce, slide down a steep slope
// and fly at a target straight ahead, against the same throws run to the end.
//
// Own binary: it replaces global operator new (counting_allocator.h) to check that planThrow
// does not allocate.

#include "counting_allocator.h"
#include "projectile_internal.h"  // src/: the planner's cutoff
#include "test_util.h"

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace {

using foresight::OrientedBox;
using foresight::Plane;
using foresight::ProjectileResult;
using foresight::Real;
using foresight::RVec3;
using foresight::StaticWorld;
using foresight::Status;
using foresight::ThrowPlan;
using foresight::ThrowPlanRequest;
using foresight::ThrowPlanResult;
using foresight::TrajectoryEvent;
using foresight::TrajectoryPoint;
using foresight::Vec3;
using ftest::DVec3;

using ftest::rv;

double horizontalLength(const DVec3& v) { return std::hypot(v.x, v.z); }

/// A request with the settings of these tests: fuse 3 s, step 0.02 s, restitution 0.5.
ThrowPlanRequest request(RVec3 start, RVec3 target) {
    ThrowPlanRequest r;
    r.start = start;
    r.target = target;
    r.acceptanceRadius = 0.5f;
    r.fuseTime = 3.0f;
    r.maxSpeed = 20.0f;
    r.settings.step = 0.02f;
    r.settings.restitution = 0.5f;
    return r;
}

/// Plans with room for `count` plans and the documented scratch.
struct Planning {
    std::vector<ThrowPlan> plans;
    std::vector<TrajectoryPoint> scratch;
    ThrowPlanResult result;
    Status status = Status::Ok;

    Planning(const ThrowPlanRequest& r, const foresight::CollisionWorld* world, std::size_t count = 3)
        : plans(count), scratch(foresight::throwPlanScratchSize(r)) {
        status = foresight::planThrow(r, world, plans, scratch, result);
    }
    std::span<const ThrowPlan> found() const { return {plans.data(), result.planCount}; }
};

/// Re-predicts a plan as a user would (predictProjectile with the request's settings).
ProjectileResult fly(const ThrowPlanRequest& r, const ThrowPlan& plan, const foresight::CollisionWorld* world,
                     std::vector<TrajectoryPoint>& trajectory) {
    trajectory.assign(foresight::trajectoryCapacity(r.fuseTime, r.settings, plan.bounces + 8), {});
    ProjectileResult out;
    EXPECT_EQ(
        foresight::predictProjectile(r.start, plan.launchVelocity, r.fuseTime, r.settings, world, trajectory, out),
        Status::Ok);
    return out;
}

/// The checks every plan must pass: within the radius and the speed cap when flown again, the
/// reported fields matching that flight, closest first, pairwise distinct.
void expectValidPlans(const ThrowPlanRequest& r, const Planning& p, const foresight::CollisionWorld* world) {
    std::vector<TrajectoryPoint> trajectory;
    float previous = 0;
    for (const ThrowPlan& plan : p.found()) {
        const ProjectileResult flown = fly(r, plan, world, trajectory);
        const double distance = glm::length(ftest::toD(flown.position) - ftest::toD(r.target));
        EXPECT_LE(distance, r.acceptanceRadius);
        // The same prediction run again: bit-identical (determinism).
        EXPECT_EQ(flown.position, plan.finalPosition);
        EXPECT_EQ(flown.bounces, plan.bounces);
        EXPECT_NEAR(plan.distance, distance, 1e-6);  // float of the same double
        EXPECT_LE(glm::length(ftest::toD(plan.launchVelocity)), r.maxSpeed * (1 + 1e-6));
        EXPECT_GE(plan.distance, previous);  // closest first
        previous = plan.distance;
    }
    for (std::size_t i = 0; i < p.result.planCount; ++i) {
        for (std::size_t j = i + 1; j < p.result.planCount; ++j) {
            const DVec3 a = glm::normalize(ftest::toD(p.plans[i].launchVelocity));
            const DVec3 b = glm::normalize(ftest::toD(p.plans[j].launchVelocity));
            const bool differentDirection = glm::dot(a, b) < std::cos(r.distinctAngle) + 1e-9;
            const bool differentSurface =
                glm::dot(ftest::toD(p.plans[i].firstImpactNormal), ftest::toD(p.plans[j].firstImpactNormal)) <
                std::cos(r.distinctAngle) + 1e-9;
            EXPECT_TRUE(differentDirection || differentSurface) << "plans " << i << " and " << j;
        }
    }
}

class ThrowPlanner : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_EQ(floor.add(Plane{Vec3(0.0f, 1.0f, 0.0f), Real(0)}), Status::Ok); }
    StaticWorld floor;  // y = 0
};

// ---------------------------------------------------------------------------------------------
// Flat floor

// Thrown from hand height at a point of the floor 8.06 m away: the seeds are solutions.
TEST_F(ThrowPlanner, FlatFloorReachableTargetGetsDistinctPlansWithinTheRadius) {
    const ThrowPlanRequest r = request(rv(0, 1.5, 0), rv(4, 0, 7));
    const Planning p(r, &floor);
    ASSERT_EQ(p.status, Status::Ok);
    ASSERT_EQ(p.result.planCount, 3u);
    expectValidPlans(r, p, &floor);
    for (const ThrowPlan& plan : p.found()) {
        // Closed form, frictionless floor: the horizontal velocity never changes, so the
        // grenade covers |v_h| * 3 s horizontally (0.5 m of radius, ~1e-6 m of rounding).
        const double covered = horizontalLength(ftest::toD(plan.launchVelocity)) * 3.0;
        EXPECT_NEAR(covered, std::hypot(4.0, 7.0), 0.5);
        EXPECT_EQ(plan.firstImpactNormal, Vec3(0.0f, 1.0f, 0.0f));  // the floor
        EXPECT_GT(plan.firstImpactTime, 0.0f);
        EXPECT_GE(plan.bounces, 1u);
    }
    EXPECT_LE(p.result.predictions, 10u);  // one prediction per seed on open ground
    EXPECT_LE(p.result.closestDistance, p.plans[0].distance);
}

// Friction 0.4: the flat-ground model of the seeds accounts for the impacts' and the sliding's
// losses; whatever the search needs, the plans must hold when flown again.
TEST_F(ThrowPlanner, FlatFloorWithFrictionStillGetsPlans) {
    ThrowPlanRequest r = request(rv(0, 1.5, 0), rv(-3, 0, 6));
    r.settings.friction = 0.4f;
    const Planning p(r, &floor);
    ASSERT_EQ(p.status, Status::Ok);
    ASSERT_GE(p.result.planCount, 1u);
    expectValidPlans(r, p, &floor);
}

// A target 1 m above the floor, 2 m up from the start: reached in flight at the fuse time
// (the no-bounce seed) or from a bounce; either way the flown plan must end near it.
TEST_F(ThrowPlanner, TargetInTheAirIsReachedInFlight) {
    ThrowPlanRequest r = request(rv(0, 1.5, 0), rv(2, 3.5, 5));
    r.fuseTime = 1.5f;
    r.acceptanceRadius = 0.3f;
    const Planning p(r, &floor, 2);
    ASSERT_EQ(p.status, Status::Ok);
    ASSERT_GE(p.result.planCount, 1u);
    expectValidPlans(r, p, &floor);
}

// Without gravity the only seed is the straight line that arrives at the fuse time.
TEST_F(ThrowPlanner, ZeroGravityFlightIsAStraightLine) {
    ThrowPlanRequest r = request(rv(0, 1.5, 0), rv(3, 1.5, 6));
    r.settings.gravity = Vec3(0.0f);
    const Planning p(r, nullptr, 1);
    ASSERT_EQ(p.status, Status::Ok);
    ASSERT_EQ(p.result.planCount, 1u);
    EXPECT_NEAR(p.plans[0].launchVelocity.x, 1.0f, 1e-5f);  // 3 m / 3 s, float rounding
    EXPECT_NEAR(p.plans[0].launchVelocity.z, 2.0f, 1e-5f);
    EXPECT_EQ(p.plans[0].bounces, 0u);
    EXPECT_LT(p.plans[0].firstImpactTime, 0.0f);  // no impact
    expectValidPlans(r, p, nullptr);
}

// ---------------------------------------------------------------------------------------------
// Bank shot
//
// Top view (x right, z up), no floor: a wall from x = -30 to 2 at z = 4.75 .. 5.25 (60 m tall:
// nothing flies over or under it within the fuse), the plane x = 4 facing -x. The start is at
// the origin, the target at (0, 14) behind the wall. A straight throw is blocked; the way is
// off the plane x = 4 and through the gap 2 < x < 4.
//
//   z=14  T         |
//          \        |
//   z=5  =====gap\   |     the wall's normal speed halves at the bounce (restitution 0.5):
//                 \  |     v_x t1 = 4, 4 - v_x / 2 (T - t1) = 0, v_z T = 14 with T = 1.5 s:
//   z=4.67         \ |     v_x = 12 / T = 8, t1 = 0.5 s, bounce at z = 14 / 3 = 4.67 (just
//                  / |     short of the wall, which the grenade then passes in the gap)
//   z=0  S . . . .   x=4
class ThrowPlannerBank : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_EQ(world.add(OrientedBox{rv(-14, 0, 5), Vec3(16.0f, 30.0f, 0.25f)}), Status::Ok);
        ASSERT_EQ(world.add(Plane{Vec3(-1.0f, 0.0f, 0.0f), Real(-4)}), Status::Ok);
    }
    StaticWorld world;
};

TEST_F(ThrowPlannerBank, TargetBehindAWallIsReachedOffTheOtherWall) {
    ThrowPlanRequest r = request(rv(0, 1.5, 0), rv(0, 1.5, 14));
    r.fuseTime = 1.5f;
    r.acceptanceRadius = 0.3f;
    const Planning p(r, &world, 2);
    ASSERT_EQ(p.status, Status::Ok);
    ASSERT_GE(p.result.planCount, 1u) << "closest " << p.result.closestDistance << " m after " << p.result.predictions
                                      << " predictions";
    expectValidPlans(r, p, &world);
    std::vector<TrajectoryPoint> trajectory;
    int singleBounce = 0;
    for (const ThrowPlan& plan : p.found()) {
        const ProjectileResult flown = fly(r, plan, &world, trajectory);
        const TrajectoryPoint* first = nullptr;
        for (std::size_t i = 0; i < flown.trajectorySize && first == nullptr; ++i)
            if (trajectory[i].event == TrajectoryEvent::Bounce) first = &trajectory[i];
        ASSERT_NE(first, nullptr);
        EXPECT_EQ(first->normal, Vec3(-1.0f, 0.0f, 0.0f));  // the plane x = 4, exact in float
        EXPECT_NEAR(first->position.x, 4.0f, 1e-5f);        // on the plane, float rounding
        EXPECT_EQ(plan.firstImpactNormal, first->normal);
        EXPECT_EQ(plan.firstImpactTime, first->time);
        // Closed form for the plans with one bounce (others may bounce again off the blocking
        // wall): v_x = 8, v_z = 14 / 1.5, bounce at z = 4.67 (sketch above); the vertical motion
        // is free flight back to 1.5 m (v_y = g T / 2). Tolerances: the 0.3 m radius through
        // each closed form (x_final = 6 - 0.75 v_x, z_final = v_z T, y_final linear in v_y T).
        if (plan.bounces != 1) continue;
        ++singleBounce;
        const DVec3 v = ftest::toD(plan.launchVelocity);
        EXPECT_NEAR(v.x, 8.0, 0.3 / 0.75);
        EXPECT_NEAR(v.z, 14.0 / 1.5, 0.3 / 1.5);
        EXPECT_NEAR(v.y, 9.81 * 1.5 / 2, 0.3 / 1.5);
        EXPECT_NEAR(first->position.z, 14.0 / 3.0, 0.3);
    }
    EXPECT_GE(singleBounce, 1);
}

// The grid's coarse step (budget.gridStep) only ranks cells: with the request's own step for the
// grid (gridStep 0) the bank shot is found as well, and every plan of either is verified with
// the request's settings (expectValidPlans flies each with them).
TEST_F(ThrowPlannerBank, CoarseAndFineGridsBothFindTheBankShot) {
    for (const float gridStep : {0.0f, 0.1f, 0.25f}) {
        ThrowPlanRequest r = request(rv(0, 1.5, 0), rv(0, 1.5, 14));
        r.fuseTime = 1.5f;
        r.acceptanceRadius = 0.3f;
        r.budget.gridStep = gridStep;
        const Planning p(r, &world, 2);
        ASSERT_EQ(p.status, Status::Ok);
        EXPECT_GE(p.result.planCount, 1u) << "grid step " << gridStep;
        expectValidPlans(r, p, &world);
    }
}

// The same target with the plane removed: nothing works, and that is an empty answer.
TEST_F(ThrowPlannerBank, WithoutTheBankWallNothingIsFound) {
    StaticWorld blocked;
    ASSERT_EQ(blocked.add(OrientedBox{rv(-14, 0, 5), Vec3(16.0f, 30.0f, 0.25f)}), Status::Ok);
    ASSERT_EQ(blocked.add(OrientedBox{rv(20, 0, 5), Vec3(17.0f, 30.0f, 0.25f)}), Status::Ok);
    ThrowPlanRequest r = request(rv(0, 1.5, 0), rv(0, 1.5, 14));
    r.fuseTime = 1.5f;
    const Planning p(r, &blocked);
    ASSERT_EQ(p.status, Status::Ok);
    EXPECT_EQ(p.result.planCount, 0u);
    EXPECT_GT(p.result.closestDistance, r.acceptanceRadius);
    EXPECT_LE(p.result.predictions, r.budget.maxPredictions);
}

// ---------------------------------------------------------------------------------------------
// Out of reach, budget, bad input

// 200 m away at 10 m/s for 3 s: at most 30 m of flight. An empty answer, not an error.
TEST_F(ThrowPlanner, OutOfReachIsAnEmptyAnswer) {
    ThrowPlanRequest r = request(rv(0, 1.5, 0), rv(0, 0, 200));
    r.maxSpeed = 10.0f;
    ThrowPlan untouched;
    untouched.distance = 123.0f;
    std::vector<ThrowPlan> plans(3, untouched);
    std::vector<TrajectoryPoint> scratch(foresight::throwPlanScratchSize(r));
    ThrowPlanResult result;
    ASSERT_EQ(foresight::planThrow(r, &floor, plans, scratch, result), Status::Ok);
    EXPECT_EQ(result.planCount, 0u);
    EXPECT_GE(result.closestDistance, 200.0f - 30.0f - 0.5f);  // |v| * t at most, and the radius
    EXPECT_LE(result.predictions, r.budget.maxPredictions);
    for (const ThrowPlan& plan : plans) EXPECT_EQ(plan.distance, 123.0f);  // untouched
}

// A target beyond a float's range of any throw (3e38 m on two axes: 4.2e38 m > FLT_MAX): no
// distance can be reported, so closestDistance is FLT_MAX ("nowhere near") and the velocity
// zero, not an infinity.
TEST_F(ThrowPlanner, NowhereNearIsTheLargestFloat) {
    const ThrowPlanRequest r = request(rv(0, 1.5, 0), rv(3e38, 0, 3e38));
    const Planning p(r, &floor);
    ASSERT_EQ(p.status, Status::Ok);
    EXPECT_EQ(p.result.planCount, 0u);
    EXPECT_GT(p.result.predictions, 0u);
    EXPECT_EQ(p.result.closestDistance, std::numeric_limits<float>::max());
    EXPECT_EQ(p.result.closestVelocity, Vec3(0.0f));
}

// The total work, maxPredictions x fuse / step, is capped (maxTotalSteps, 2^24 by default): a
// 20000 s fuse at 0.02 s (10^6 steps per prediction, under settings.maxSteps) with 400
// predictions is refused; 838 s (41 900 steps, 16 760 000 in all) is not; 20000 s with one
// prediction is not.
TEST_F(ThrowPlanner, TotalWorkIsCapped) {
    ThrowPlanRequest r = request(rv(0, 1.5, 0), rv(0, 0, 1e6));
    r.settings.method = foresight::ProjectileMethod::Stepped;
    r.fuseTime = 20000.0f;
    EXPECT_EQ(foresight::throwPlanWork(r), 400u * 1000000u);
    EXPECT_EQ(foresight::validateThrowPlanRequest(r), Status::TooManySteps);
    EXPECT_EQ(foresight::throwPlanScratchSize(r), 0u);
    ThrowPlanResult result;
    result.predictions = 99;
    std::array<ThrowPlan, 1> plans{};
    EXPECT_EQ(foresight::planThrow(r, &floor, plans, {}, result), Status::TooManySteps);
    EXPECT_EQ(result.predictions, 99u);  // untouched
    r.budget.maxPredictions = 1;
    EXPECT_EQ(foresight::throwPlanWork(r), 1000000u);
    EXPECT_EQ(foresight::validateThrowPlanRequest(r), Status::Ok);
    r.budget.maxPredictions = 400;
    r.fuseTime = 838.0f;
    EXPECT_EQ(foresight::throwPlanWork(r), 400u * 41900u);
    EXPECT_EQ(foresight::validateThrowPlanRequest(r), Status::Ok);
    r.budget.maxTotalSteps = 400u * 41900u - 1u;  // one step under: refused
    EXPECT_EQ(foresight::validateThrowPlanRequest(r), Status::TooManySteps);
    // A bad fuse or step: no work to count.
    r.fuseTime = 0.0f;
    EXPECT_EQ(foresight::throwPlanWork(r), 0u);
}

TEST_F(ThrowPlanner, BudgetCapsThePredictions) {
    ThrowPlanRequest r = request(rv(0, 1.5, 0), rv(0, 0, 200));
    r.budget.maxPredictions = 7;
    const Planning p(r, &floor);
    ASSERT_EQ(p.status, Status::Ok);
    EXPECT_EQ(p.result.predictions, 7u);
}

// No scratch: the plans are found all the same; their first impacts are not known.
TEST_F(ThrowPlanner, EmptyScratchStillPlans) {
    const ThrowPlanRequest r = request(rv(0, 1.5, 0), rv(4, 0, 7));
    std::array<ThrowPlan, 2> plans{};
    ThrowPlanResult result;
    ASSERT_EQ(foresight::planThrow(r, &floor, plans, {}, result), Status::Ok);
    ASSERT_EQ(result.planCount, 2u);
    EXPECT_LT(plans[0].firstImpactTime, 0.0f);
    EXPECT_LE(plans[0].distance, r.acceptanceRadius);
}

TEST_F(ThrowPlanner, BadInputIsRefusedWithAStatusAndNothingWritten) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const ThrowPlanRequest good = request(rv(0, 1.5, 0), rv(4, 0, 7));
    struct Case {
        const char* what;
        void (*edit)(ThrowPlanRequest&, float);
        Status expected;
    };
    const Case cases[] = {
        {"NaN start", [](ThrowPlanRequest& r, float n) { r.start.x = static_cast<Real>(n); }, Status::NonFiniteInput},
        {"NaN target", [](ThrowPlanRequest& r, float n) { r.target.y = static_cast<Real>(n); }, Status::NonFiniteInput},
        {"NaN fuse", [](ThrowPlanRequest& r, float n) { r.fuseTime = n; }, Status::NonFiniteInput},
        {"infinite speed", [](ThrowPlanRequest& r, float) { r.maxSpeed = INFINITY; }, Status::NonFiniteInput},
        {"NaN gravity", [](ThrowPlanRequest& r, float n) { r.settings.gravity.y = n; }, Status::NonFiniteInput},
        {"zero fuse", [](ThrowPlanRequest& r, float) { r.fuseTime = 0.0f; }, Status::InvalidFuse},
        {"negative fuse", [](ThrowPlanRequest& r, float) { r.fuseTime = -1.0f; }, Status::InvalidFuse},
        {"zero radius", [](ThrowPlanRequest& r, float) { r.acceptanceRadius = 0.0f; }, Status::InvalidRadius},
        {"negative radius", [](ThrowPlanRequest& r, float) { r.acceptanceRadius = -1.0f; }, Status::InvalidRadius},
        {"zero max speed", [](ThrowPlanRequest& r, float) { r.maxSpeed = 0.0f; }, Status::InvalidSpeed},
        {"negative max speed", [](ThrowPlanRequest& r, float) { r.maxSpeed = -5.0f; }, Status::InvalidSpeed},
        {"min speed over max", [](ThrowPlanRequest& r, float) { r.minSpeed = 30.0f; }, Status::InvalidSpeed},
        {"negative min speed", [](ThrowPlanRequest& r, float) { r.minSpeed = -1.0f; }, Status::InvalidSpeed},
        {"no plans wanted", [](ThrowPlanRequest& r, float) { r.maxPlans = 0; }, Status::InvalidIterations},
        {"no grid", [](ThrowPlanRequest& r, float) { r.budget.azimuthSamples = 0; }, Status::InvalidIterations},
        {"no predictions", [](ThrowPlanRequest& r, float) { r.budget.maxPredictions = 0; }, Status::InvalidIterations},
        {"no work allowed", [](ThrowPlanRequest& r, float) { r.budget.maxTotalSteps = 0; }, Status::InvalidIterations},
        {"total work over the cap", [](ThrowPlanRequest& r, float) { r.fuseTime = 20000.0f; }, Status::TooManySteps},
        {"too many refinements",
         [](ThrowPlanRequest& r, float) { r.budget.refinements = foresight::kMaxThrowPlanRefinements + 1; },
         Status::InvalidIterations},
        {"restitution 2", [](ThrowPlanRequest& r, float) { r.settings.restitution = 2.0f; },
         Status::InvalidRestitution},
        {"zero step", [](ThrowPlanRequest& r, float) { r.settings.step = 0.0f; }, Status::InvalidStep},
        {"negative grid step", [](ThrowPlanRequest& r, float) { r.budget.gridStep = -0.1f; }, Status::InvalidStep},
        {"NaN grid step", [](ThrowPlanRequest& r, float n) { r.budget.gridStep = n; }, Status::InvalidStep},
        {"fuse over the step cap", [](ThrowPlanRequest& r, float) { r.fuseTime = 1e6f; }, Status::TooManySteps},
    };
    for (const Case& c : cases) {
        ThrowPlanRequest r = good;
        c.edit(r, nan);
        EXPECT_EQ(foresight::validateThrowPlanRequest(r), c.expected) << c.what;
        EXPECT_EQ(foresight::throwPlanScratchSize(r), 0u) << c.what;
        std::array<ThrowPlan, 1> plans{};
        plans[0].distance = 42.0f;
        ThrowPlanResult result;
        result.predictions = 99;
        EXPECT_EQ(foresight::planThrow(r, &floor, plans, {}, result), c.expected) << c.what;
        EXPECT_EQ(result.predictions, 99u) << c.what;  // untouched
        EXPECT_EQ(plans[0].distance, 42.0f) << c.what;
    }
    EXPECT_EQ(foresight::validateThrowPlanRequest(good), Status::Ok);
}

// ---------------------------------------------------------------------------------------------
// Determinism, allocation

TEST_F(ThrowPlannerBank, SameRequestGivesBitIdenticalPlans) {
    ThrowPlanRequest r = request(rv(0, 1.5, 0), rv(0, 1.5, 14));
    r.fuseTime = 1.5f;
    const Planning a(r, &world), b(r, &world);
    ASSERT_EQ(a.result.planCount, b.result.planCount);
    EXPECT_EQ(a.result.predictions, b.result.predictions);
    EXPECT_EQ(a.result.closestDistance, b.result.closestDistance);
    for (std::size_t i = 0; i < a.result.planCount; ++i) {
        EXPECT_EQ(a.plans[i].launchVelocity, b.plans[i].launchVelocity);
        EXPECT_EQ(a.plans[i].finalPosition, b.plans[i].finalPosition);
        EXPECT_EQ(a.plans[i].distance, b.plans[i].distance);
    }
}

TEST_F(ThrowPlannerBank, PlanningDoesNotAllocate) {
    ThrowPlanRequest r = request(rv(0, 1.5, 0), rv(0, 1.5, 14));
    r.fuseTime = 1.5f;
    std::vector<ThrowPlan> plans(3);
    std::vector<TrajectoryPoint> scratch(foresight::throwPlanScratchSize(r));
    std::vector<TrajectoryPoint> trajectory(foresight::trajectoryCapacity(r.fuseTime, r.settings, 16));
    ThrowPlanResult result;
    ProjectileResult flown;
    Status planned = Status::Ok, replayed = Status::Ok;
    const long before = ftest::gAllocations.load();
    planned = foresight::planThrow(r, &world, plans, scratch, result);
    if (planned == Status::Ok && result.planCount > 0)
        replayed = foresight::predictThrowPlan(r, plans[0], &world, trajectory, flown);
    const long allocations = ftest::gAllocations.load() - before;
    ASSERT_EQ(planned, Status::Ok);
    ASSERT_EQ(replayed, Status::Ok);
    EXPECT_GT(result.predictions, 10u);  // the grid ran: the search did real work
    EXPECT_EQ(allocations, 0);
}

// ---------------------------------------------------------------------------------------------
// The planner's cutoff

// Throws in two worlds: the random scene (floor, box walls, a sphere, a slanted roof) and a steep
// frictionless slope (70 degrees, nothing below it), on which a body slides down at 0.94 g: the
// bound's |g| T^2 / 2 is nearly reached there. Targets: anywhere around, or beyond the throw's
// end along its course from the start (the body runs at them, where the bound is tightest).
// Each throw is run to the end, then again with the cutoff's distance half its end's distance,
// 5 mm below it (half the margin) or 5 mm above it. An abandoned run must end farther than that
// distance; one that went on must give the full run's result bit for bit (the cutoff only
// watches). Without the bound's gravity term, 134 of these throws stopped though they end within
// the distance.
TEST(PlannerCutoff, StopsOnlyThrowsThatEndBeyondItsDistance) {
    using foresight::ProjectileMethod;
    using foresight::ProjectileSettings;
    ftest::Random random(20261129);
    const StaticWorld scene = ftest::randomScene(random);
    StaticWorld slope;
    const double tilt = 70.0 * M_PI / 180.0;
    ASSERT_EQ(slope.add(Plane{Vec3(static_cast<float>(std::sin(tilt)), static_cast<float>(std::cos(tilt)), 0.0f), 0}),
              Status::Ok);
    int abandoned = 0, kept = 0;
    std::vector<TrajectoryPoint> full(4096), cut(4096);
    for (int i = 0; i < 1200; ++i) {
        const bool onSlope = i % 3 == 2;
        const StaticWorld& world = onSlope ? slope : scene;
        ProjectileSettings settings;
        settings.method = ProjectileMethod::Exact;
        settings.step = i % 4 == 0 ? 0.1f : 0.02f;
        settings.radius = i % 2 == 0 ? 0.0f : static_cast<float>(random.uniform(0.05, 0.3));
        settings.restitution = static_cast<float>(random.uniform(0.2, 1.0));
        settings.friction = onSlope ? 0.0f : static_cast<float>(random.uniform(0.0, 0.6));
        const RVec3 start = onSlope ? rv(random.uniform(0, 2), random.uniform(1, 4), random.uniform(-2, 2))
                                    : rv(random.uniform(-2, 2), random.uniform(0.5, 3), random.uniform(-2, 2));
        const Vec3 velocity(ftest::toD(random.direction()) * random.uniform(1, 20));
        const float fuse = static_cast<float>(random.uniform(1, 4));
        ProjectileResult whole;
        ASSERT_EQ(foresight::predictProjectile(start, velocity, fuse, settings, &world, full, whole), Status::Ok);
        const DVec3 end = ftest::toD(whole.position);
        DVec3 target = ftest::toD(random.inBox(DVec3(-15, -5, -15), DVec3(15, 10, 15)));
        if (i % 2 == 1) {  // beyond the end, along the throw's course (start to end)
            const DVec3 motion = end - ftest::toD(start);
            if (glm::length(motion) > 1e-3) target = end + glm::normalize(motion) * random.uniform(0.5, 8);
        }
        const double distance = glm::length(end - target);
        foresight::detail::DistanceCutoff cutoff;
        cutoff.target = target;
        // Half the end's distance or 5 mm below it (a stop is right), or 5 mm above it (wrong).
        cutoff.keepBelow = i % 5 == 0 ? 0.5 * distance : i % 5 < 3 ? distance - 0.005 : distance + 0.005;
        ProjectileResult part;
        bool gaveUp = false;
        ASSERT_EQ(foresight::detail::predictProjectileWithCutoff(start, velocity, fuse, settings, &world, cut, part,
                                                                 &cutoff, gaveUp),
                  Status::Ok);
        if (gaveUp) {
            ++abandoned;
            EXPECT_GT(distance, cutoff.keepBelow) << "throw " << i;
            continue;
        }
        ++kept;
        EXPECT_EQ(part.position, whole.position) << "throw " << i;
        EXPECT_EQ(part.velocity, whole.velocity) << "throw " << i;
        EXPECT_EQ(part.bounces, whole.bounces) << "throw " << i;
        ASSERT_EQ(part.trajectorySize, whole.trajectorySize) << "throw " << i;
        EXPECT_EQ(std::memcmp(full.data(), cut.data(), whole.trajectorySize * sizeof(TrajectoryPoint)), 0) << i;
    }
    // Both outcomes occur often: the check sees real stops.
    EXPECT_GT(abandoned, 200);
    EXPECT_GT(kept, 200);
}

// The other methods ignore the cutoff; so does a null one.
TEST(PlannerCutoff, OnlyTheExactMethodStops) {
    StaticWorld floor;
    ASSERT_EQ(floor.add(Plane{Vec3(0.0f, 1.0f, 0.0f), Real(0)}), Status::Ok);
    foresight::detail::DistanceCutoff cutoff;
    cutoff.target = DVec3(1000, 0, 0);
    cutoff.keepBelow = 1;  // far beyond any throw below
    std::vector<TrajectoryPoint> trajectory(512);
    for (const auto method : {foresight::ProjectileMethod::Exact, foresight::ProjectileMethod::Stepped,
                              foresight::ProjectileMethod::Engine}) {
        foresight::ProjectileSettings settings;
        settings.method = method;
        settings.restitution = 0.5f;
        ProjectileResult out;
        bool gaveUp = true;
        ASSERT_EQ(foresight::detail::predictProjectileWithCutoff(rv(0, 1, 0), Vec3(3, 4, 0), 3.0f, settings, &floor,
                                                                 trajectory, out, &cutoff, gaveUp),
                  Status::Ok);
        EXPECT_EQ(gaveUp, method == foresight::ProjectileMethod::Exact) << static_cast<int>(method);
        gaveUp = true;
        ASSERT_EQ(foresight::detail::predictProjectileWithCutoff(rv(0, 1, 0), Vec3(3, 4, 0), 3.0f, settings, &floor,
                                                                 trajectory, out, nullptr, gaveUp),
                  Status::Ok);
        EXPECT_FALSE(gaveUp);
    }
}

}  // namespace
