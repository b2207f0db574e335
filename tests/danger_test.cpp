// Danger for AI (danger.h): grenade danger zones and corridors, vehicles against characters.
//
// Reference values come from closed forms (a straight drive, a crossing, a turning car on its
// circle, the closest point of a parabola) or from an independent fine-sampling brute force:
// poses from predictVehicleExact, box-to-segment distances by golden-section search on the
// segment (the distance to a convex box is convex along a segment), projectile positions from
// the free-flight parabola with the prediction's own gravity. Never from the code under test.
//
// Own binary: it counts heap allocations (counting_allocator.h replaces operator new here).

#include "counting_allocator.h"
#include "test_util.h"

#include <foresight/danger.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <vector>

namespace {

using foresight::ApproachSettings;
using foresight::CharacterBody;
using foresight::ClosestApproach;
using foresight::DangerStart;
using foresight::DangerZone;
using foresight::ProjectileDanger;
using foresight::ProjectileResult;
using foresight::ProjectileSettings;
using foresight::RVec3;
using foresight::Status;
using foresight::TrajectoryEvent;
using foresight::TrajectoryPoint;
using foresight::Vec3;
using foresight::VehicleBody;
using foresight::VehicleContact;
using ftest::DVec3;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

using ftest::rv;

// The cases were drawn with Knuth's MMIX LCG (ftest::Random, test_util.h); keep the step.
constexpr ftest::Random::Step kRandomStep = ftest::Random::Step::Lcg64;

// ---------------------------------------------------------------------------------------------
// Independent references

/// Distance from a point to the box [-h, h] (local axes), by clamping.
double pointBoxDistance(const DVec3& p, const DVec3& h) {
    const DVec3 outside = p - glm::clamp(p, -h, h);
    return glm::length(outside);
}

/// Separation of the vehicle box and the character at `t`: pose from predictVehicleExact, the
/// segment's distance by golden-section search (convex along the segment), minus the radius.
double referenceSeparation(const VehicleBody& vehicle, const CharacterBody& character, double t) {
    foresight::VehicleState pose;
    EXPECT_EQ(foresight::predictVehicleExact(vehicle.state, static_cast<float>(t), vehicle.settings, pose), Status::Ok);
    const ftest::DQuat q = ftest::toD(pose.orientation);
    const ftest::DQuat inverse = ftest::dquatWXYZ(q.w, -q.x, -q.y, -q.z);
    const DVec3 center = ftest::toD(pose.position) + ftest::dRotate(q, ftest::toD(vehicle.boxCenter));
    const DVec3 c = ftest::toD(character.position) + ftest::toD(character.velocity) * t +
                    ftest::toD(character.acceleration) * (0.5 * t * t);
    const DVec3 axis = ftest::toD(character.halfAxis);
    const DVec3 h = ftest::toD(vehicle.halfExtents);
    auto at = [&](double u) { return pointBoxDistance(ftest::dRotate(inverse, c + axis * u - center), h); };
    double low = -1.0, high = 1.0;
    if (axis != DVec3(0.0)) {
        const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
        for (int i = 0; i < 40; ++i) {  // the bracket shrinks to 8e-9 (distance error below that)
            const double u1 = high - ratio * (high - low), u2 = low + ratio * (high - low);
            if (at(u1) <= at(u2))
                high = u2;
            else
                low = u1;
        }
    }
    const double best = std::min({at(-1.0), at(1.0), at(0.5 * (low + high))});
    return best - static_cast<double>(character.radius);
}

VehicleBody car(DVec3 position, double speed, double yawRate) {
    VehicleBody vehicle;
    vehicle.state.position = ftest::toR(position);
    vehicle.state.velocity = Vec3(0.0f, 0.0f, static_cast<float>(speed));
    vehicle.state.angularVelocity = Vec3(0.0f, static_cast<float>(yawRate), 0.0f);
    vehicle.halfExtents = Vec3(0.9f, 0.7f, 2.2f);
    return vehicle;
}

CharacterBody sphere(DVec3 position, double radius, DVec3 velocity = DVec3(0.0)) {
    CharacterBody character;
    character.position = ftest::toR(position);
    character.velocity = ftest::toF(velocity);
    character.radius = static_cast<float>(radius);
    return character;
}

// ---------------------------------------------------------------------------------------------
// Vehicles: closed forms

// A car at 10 m/s straight at a standing sphere 30 m ahead: the front face (2.2 m ahead of the
// centre) touches the sphere (radius 0.5) at (30 - 2.2 - 0.5) / 10 = 2.73 s.
TEST(DangerVehicle, StraightAtAStandingSphere) {
    const VehicleBody vehicle = car(DVec3(0.0), 10.0, 0.0);
    const CharacterBody target = sphere(DVec3(0.0, 0.0, 30.0), 0.5);
    ApproachSettings settings;
    VehicleContact contact;
    ASSERT_EQ(foresight::findVehicleContact(vehicle, target, 5.0f, settings, contact), Status::Ok);
    ASSERT_TRUE(contact.contact);
    const double expected = (30.0 - 2.2 - 0.5) / 10.0;
    // Never later; within the tolerance's travel (1e-3 m at 10 m/s) plus float rounding of times.
    EXPECT_LE(contact.time, expected + 1e-6);
    EXPECT_GE(contact.time, expected - 1e-4 - 1e-6);
    EXPECT_LE(contact.separation, settings.tolerance);
    EXPECT_GE(contact.separation, -1e-6f);  // conservative advancement never steps inside
    // The closest approach is an overlap: the separation reaches -radius (segment inside).
    ClosestApproach closest;
    ASSERT_EQ(foresight::findClosestVehicleApproach(vehicle, target, 5.0f, settings, closest), Status::Ok);
    // The plateau's value -0.5, up to the tolerance (the earliest time within it is reported).
    EXPECT_GE(closest.distance, -0.5f - 1e-5f);  // float rounding
    EXPECT_LE(closest.distance, -0.5f + settings.tolerance + 1e-5f);
    // ... at the earliest time: no later than where the sphere's centre reaches the front face
    // ((30 - 2.2) / 10 s: D = -0.5 from then on), no earlier than where D = -0.5 + tol.
    EXPECT_LE(closest.time, (30.0 - 2.2) / 10.0 + 1e-6);
    EXPECT_GE(closest.time, (30.0 - 2.2 - settings.tolerance) / 10.0 - 1e-6);
    // Short of the sphere: no contact, closest at the horizon.
    ASSERT_EQ(foresight::findVehicleContact(vehicle, target, 2.5f, settings, contact), Status::Ok);
    EXPECT_FALSE(contact.contact);
    ASSERT_EQ(foresight::findClosestVehicleApproach(vehicle, target, 2.5f, settings, closest), Status::Ok);
    // 2.3 m at the horizon, up to the tolerance: reported at the first time within it, which
    // is at most tol / 10 m/s before the horizon (float rounding 1e-6).
    EXPECT_GE(closest.distance, 30.0 - 2.2 - 0.5 - 25.0 - 1e-5);
    EXPECT_LE(closest.distance, 30.0 - 2.2 - 0.5 - 25.0 + 1e-3 + 1e-5);
    EXPECT_LE(closest.time, 2.5f);
    EXPECT_GE(closest.time, 2.5 - 1e-3 / 10.0 - 1e-6);
    EXPECT_NEAR(closest.distance, 30.0 - 2.2 - 0.5 - 10.0 * closest.time, 1e-5);  // D at its time
}

// A capsule (half axis 0.5 m up, radius 0.3) walking at 5 m/s across the car's path from x = 8,
// at z = 15, while the car drives at 10 m/s: it reaches the car's side (x = 0.9) when
// 8 - 0.3 - 5 t = 0.9, t = 1.36 s, when the car spans z in [11.4, 15.8] (the side, not a corner).
TEST(DangerVehicle, CrossingCapsuleHitsTheSide) {
    const VehicleBody vehicle = car(DVec3(0.0), 10.0, 0.0);
    CharacterBody walker = sphere(DVec3(8.0, 0.0, 15.0), 0.3, DVec3(-5.0, 0.0, 0.0));
    walker.halfAxis = Vec3(0.0f, 0.5f, 0.0f);
    VehicleContact contact;
    ASSERT_EQ(foresight::findVehicleContact(vehicle, walker, 3.0f, {}, contact), Status::Ok);
    ASSERT_TRUE(contact.contact);
    // It closes on the side at 5 m/s: 1e-3 m of tolerance is 2e-4 s (plus float rounding).
    EXPECT_LE(contact.time, 1.36 + 1e-6);
    EXPECT_GE(contact.time, 1.36 - 2e-4 - 1e-6);
    // Lifted 2 m (the segment's bottom at 1.5 m, the capsule's at 1.2 m, above the roof at
    // 0.7 m): it never touches; the closest approach is the gap above the roof, 0.5 m.
    walker.position = rv(8.0, 2.0, 15.0);
    ASSERT_EQ(foresight::findVehicleContact(vehicle, walker, 3.0f, {}, contact), Status::Ok);
    EXPECT_FALSE(contact.contact);
    ClosestApproach closest;
    ASSERT_EQ(foresight::findClosestVehicleApproach(vehicle, walker, 3.0f, {}, closest), Status::Ok);
    EXPECT_NEAR(closest.distance, 0.5f, 1e-3f + 1e-6f);  // the tolerance
    EXPECT_GE(closest.distance, 0.5f - 1e-6f);           // a real value: never below the minimum
    const double over = referenceSeparation(vehicle, walker, static_cast<double>(closest.time));
    EXPECT_NEAR(over, 0.5, 1e-3 + 1e-5);
}

// A car at 10 m/s turning at 0.5 rad/s drives a circle of radius 20 m: x = 20 (1 - cos wt),
// z = 20 sin wt. A sphere of radius 0.3 on the circle at 1 rad: in the car's axes it is at
// (20 (1 - cos d), 0, 20 sin d) for the angle d still ahead, inside the front face's x range, so
// it touches the front face (z = 2.2) when 20 sin d = 2.5: t = (1 - asin(0.125)) / 0.5.
TEST(DangerVehicle, TurningCarMeetsAPointOnItsCircle) {
    const VehicleBody vehicle = car(DVec3(0.0), 10.0, 0.5);
    const double radius = 20.0;
    const CharacterBody target = sphere(DVec3(radius * (1.0 - std::cos(1.0)), 0.0, radius * std::sin(1.0)), 0.3);
    VehicleContact contact;
    ASSERT_EQ(foresight::findVehicleContact(vehicle, target, 4.0f, {}, contact), Status::Ok);
    ASSERT_TRUE(contact.contact);
    const double expected = (1.0 - std::asin(2.5 / radius)) / 0.5;
    EXPECT_LE(contact.time, expected + 1e-6);
    EXPECT_GE(contact.time, expected - 2e-4);  // 1e-3 m at >= 10 m/s, float rounding
    // The circle's centre: the box turns about it with its inner side 20 - 0.9 m away, always.
    const CharacterBody centre = sphere(DVec3(radius, 0.0, 0.0), 0.3);
    ClosestApproach closest;
    ASSERT_EQ(foresight::findClosestVehicleApproach(vehicle, centre, 4.0f, {}, closest), Status::Ok);
    EXPECT_NEAR(closest.distance, radius - 0.9 - 0.3, 2e-5);  // float positions of ~20 m
    // A point 30 m from the centre: the box's outer corners sweep a circle of radius
    // sqrt(20.9^2 + 2.2^2); the closest approach is 30 minus that minus 0.3 (one turn is 12.6 s).
    const CharacterBody outside = sphere(DVec3(radius - 30.0, 0.0, 0.0), 0.3);
    ASSERT_EQ(foresight::findClosestVehicleApproach(vehicle, outside, 13.0f, {}, closest), Status::Ok);
    const double sweep = std::sqrt(20.9 * 20.9 + 2.2 * 2.2);
    EXPECT_LE(closest.distance, 30.0 - sweep - 0.3 + 1e-3 + 2e-5);  // within the tolerance
    EXPECT_GE(closest.distance, 30.0 - sweep - 0.3 - 2e-5);         // a real value
}

// Equal minima: a car at 10 m/s turning at 0.5 rad/s drives a 20 m circle every 4 pi = 12.57 s;
// a sphere at (50, 0, 30), outside the circle, is closest once per turn, always at the same
// distance mu. The reported time is in the first turn's band [first time D <= mu + tol, first
// time D = mu], whatever the horizon (it was 4.92 s up to 20 s, then 17.49 s at 30 s and
// 92.89 s at 100 s: whichever turn's samples happened to be lowest).
TEST(DangerVehicle, ClosestApproachIsTheEarliestOfEqualMinima) {
    const VehicleBody vehicle = car(DVec3(0.0), 10.0, 0.5);
    const CharacterBody character = sphere(DVec3(50.0, 0.0, 30.0), 0.4);
    const ApproachSettings settings;  // tolerance 1e-3 m
    const double tolerance = static_cast<double>(settings.tolerance);
    const double period = 4.0 * 3.14159265358979323846;
    // The reference minimum over one turn: 1 ms samples, then golden section around the best.
    double bestTime = 0, mu = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= 12600; ++k) {
        const double t = 1e-3 * k;
        const double d = referenceSeparation(vehicle, character, t);
        if (d < mu) mu = d, bestTime = t;
    }
    double low = std::max(0.0, bestTime - 1e-3), high = bestTime + 1e-3;
    for (int i = 0; i < 60; ++i) {
        const double a = low + 0.381966 * (high - low), b = high - 0.381966 * (high - low);
        if (referenceSeparation(vehicle, character, a) < referenceSeparation(vehicle, character, b))
            high = b;
        else
            low = a;
    }
    mu = std::min(mu, referenceSeparation(vehicle, character, 0.5 * (low + high)));
    // The reference's float poses of predictVehicleExact are good to ~1e-6 m at 60 m; 2e-5 m as
    // in the other vehicle tests.
    const double poseError = 2e-5;
    std::vector<float> times;
    for (const float horizon : {6.0f, 10.0f, 20.0f, 30.0f, 100.0f, 300.0f}) {
        ClosestApproach closest;
        ASSERT_EQ(foresight::findClosestVehicleApproach(vehicle, character, horizon, settings, closest), Status::Ok)
            << "horizon " << horizon;
        const double t = static_cast<double>(closest.time);
        EXPECT_LT(t, period) << "horizon " << horizon;  // the first turn
        EXPECT_GE(static_cast<double>(closest.distance), mu - poseError) << "horizon " << horizon;
        EXPECT_LE(static_cast<double>(closest.distance), mu + tolerance + poseError) << "horizon " << horizon;
        EXPECT_NEAR(referenceSeparation(vehicle, character, t), static_cast<double>(closest.distance), poseError);
        times.push_back(closest.time);
    }
    // The band on the way into the first minimum, sampled at 0.1 ms (one sample of slack on
    // the early side; the late side ends where D is within the pose error of mu).
    double bandLow = -1, bandHigh = -1;
    for (double s = 0.0; s < period && bandHigh < 0.0; s += 1e-4) {
        const double d = referenceSeparation(vehicle, character, s);
        if (bandLow < 0.0 && d <= mu + tolerance + poseError) bandLow = s - 1e-4;
        if (d <= mu + poseError) bandHigh = s;
    }
    ASSERT_GE(bandLow, 0.0);
    ASSERT_GE(bandHigh, bandLow);
    std::printf("closest approach of a circling car: mu %.6f m at %.4f s; reported times", mu, bestTime);
    for (const float t : times) std::printf(" %.5f", static_cast<double>(t));
    std::printf(" s; band [%.5f, %.5f] s\n", bandLow, bandHigh);
    for (const float t : times) {
        EXPECT_GE(static_cast<double>(t), bandLow);
        EXPECT_LE(static_cast<double>(t), bandHigh);
    }
}

// The pose the queries use is predictVehicleExact's, also in the world frame and with an offset
// box: the separation agrees with the independent reference.
TEST(DangerVehicle, SeparationMatchesThePredictedPose) {
    VehicleBody vehicle = car(DVec3(3.0, 0.5, -2.0), -6.0, 0.0);
    vehicle.state.orientation = glm::angleAxis(0.7f, glm::normalize(Vec3(0.2f, 1.0f, 0.1f)));
    vehicle.state.velocity = vehicle.state.orientation * Vec3(0.0f, 0.0f, -6.0f);  // reversing
    vehicle.state.angularVelocity = Vec3(0.1f, 0.8f, -0.3f);
    vehicle.boxCenter = Vec3(0.0f, 0.3f, 1.1f);
    for (const auto frame : {foresight::AngularFrame::Body, foresight::AngularFrame::World}) {
        vehicle.settings.frame = frame;
        CharacterBody walker = sphere(DVec3(1.0, 0.0, -6.0), 0.4, DVec3(0.5, 0.0, 1.0));
        walker.acceleration = Vec3(0.2f, 0.0f, -0.4f);
        walker.halfAxis = Vec3(0.1f, 0.6f, 0.0f);
        for (double t = 0.0; t <= 3.0; t += 0.25) {
            float separation = 0;
            ASSERT_EQ(foresight::computeVehicleSeparation(vehicle, walker, static_cast<float>(t), separation),
                      Status::Ok);
            // Float poses of predictVehicleExact (~1e-6 m at these magnitudes).
            EXPECT_NEAR(separation, referenceSeparation(vehicle, walker, t), 2e-5) << "t = " << t;
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Vehicles: agreement with fine sampling on random cases

struct Agreement {
    int cases = 0, contacts = 0, sampledContacts = 0;
    double earliestBySampling = 0;  // max (sampled first overlap - reported time), >= 0
    double latestBySampling = 0;    // max (reported time - sampled first overlap): must be ~0
    double worstConfirmation = 0;   // max reference separation at a reported contact time
    double closestGap = 0;          // max (reported closest - sampled minimum)
    double closestUndershoot = 0;   // max (sampled minimum - reported closest): must be <= 0 + eps
    std::uint64_t evaluations = 0;
};

TEST(DangerVehicle, AgreesWithFineSamplingOnRandomCases) {
    ftest::Random random(12345, kRandomStep);
    ApproachSettings settings;  // tolerance 1e-3 m
    const double tolerance = static_cast<double>(settings.tolerance);
    const double horizon = 3.0;
    const int samples = 600;  // every 5 ms
    Agreement a;
#ifdef NDEBUG
    const int cases = 2000;
#else
    const int cases = 1000;  // the sanitizer build: the same checks on half the cases (time)
#endif
    for (int i = 0; i < cases; ++i) {
        VehicleBody vehicle;
        vehicle.state.position = rv(random.uniform(-10, 10), random.uniform(-1, 1), random.uniform(-10, 10));
        const Vec3 axis = glm::normalize(
            Vec3(static_cast<float>(random.uniform(-1, 1)), 1.0f, static_cast<float>(random.uniform(-1, 1))));
        vehicle.state.orientation = glm::angleAxis(static_cast<float>(random.uniform(-3.1, 3.1)), axis);
        const float speed = static_cast<float>(random.uniform(-15, 15));
        vehicle.state.velocity = vehicle.state.orientation * Vec3(0.0f, 0.0f, speed);
        vehicle.state.angularVelocity = random.uniform() < 0.2 ? Vec3(0.0f)
                                                               : Vec3(static_cast<float>(random.uniform(-0.2, 0.2)),
                                                                      static_cast<float>(random.uniform(-1.5, 1.5)),
                                                                      static_cast<float>(random.uniform(-0.2, 0.2)));
        vehicle.settings.frame =
            random.uniform() < 0.5 ? foresight::AngularFrame::Body : foresight::AngularFrame::World;
        vehicle.halfExtents =
            Vec3(static_cast<float>(random.uniform(0.3, 1.5)), static_cast<float>(random.uniform(0.3, 1.0)),
                 static_cast<float>(random.uniform(0.5, 3.0)));
        vehicle.boxCenter = Vec3(0.0f, 0.0f, static_cast<float>(random.uniform(-0.5, 0.5)));
        // The character starts near where the vehicle will be at some time in the horizon, so
        // that about half of the cases touch.
        foresight::VehicleState ahead;
        ASSERT_EQ(foresight::predictVehicleExact(vehicle.state, static_cast<float>(random.uniform(0.5, 2.5)),
                                                 vehicle.settings, ahead),
                  Status::Ok);
        CharacterBody character;
        character.position = ahead.position + rv(random.uniform(-4, 4), random.uniform(-1, 1), random.uniform(-4, 4));
        character.velocity =
            Vec3(static_cast<float>(random.uniform(-5, 5)), 0.0f, static_cast<float>(random.uniform(-5, 5)));
        if (random.uniform() < 0.5)
            character.acceleration =
                Vec3(static_cast<float>(random.uniform(-3, 3)), 0.0f, static_cast<float>(random.uniform(-3, 3)));
        character.radius = static_cast<float>(random.uniform(0.1, 0.6));
        if (random.uniform() < 0.5) character.halfAxis = Vec3(0.0f, static_cast<float>(random.uniform(0.2, 0.8)), 0.0f);

        VehicleContact contact;
        ClosestApproach closest;
        ASSERT_EQ(foresight::findVehicleContact(vehicle, character, static_cast<float>(horizon), settings, contact),
                  Status::Ok);
        ASSERT_EQ(
            foresight::findClosestVehicleApproach(vehicle, character, static_cast<float>(horizon), settings, closest),
            Status::Ok);
        a.evaluations += contact.evaluations;
        double sampledFirst = -1, sampledMin = std::numeric_limits<double>::infinity();
        for (int k = 0; k <= samples; ++k) {
            const double t = horizon * k / samples;
            const double separation = referenceSeparation(vehicle, character, t);
            if (separation <= 0.0 && sampledFirst < 0.0) sampledFirst = t;
            sampledMin = std::min(sampledMin, separation);
        }
        ++a.cases;
        if (sampledFirst >= 0.0) {
            ++a.sampledContacts;
            // Any sampled overlap must have been found, and never later.
            ASSERT_TRUE(contact.contact) << "case " << i << ": sampling overlaps at " << sampledFirst;
            a.latestBySampling = std::max(a.latestBySampling, static_cast<double>(contact.time) - sampledFirst);
            a.earliestBySampling = std::max(a.earliestBySampling, sampledFirst - static_cast<double>(contact.time));
        }
        if (contact.contact) {
            ++a.contacts;
            const double confirmation = referenceSeparation(vehicle, character, static_cast<double>(contact.time));
            a.worstConfirmation = std::max(a.worstConfirmation, confirmation);
            EXPECT_LE(confirmation, tolerance + 1e-4) << "case " << i;  // float poses of ~30 m
            // No sampled overlap before the reported time (the contact is the first).
            if (sampledFirst >= 0.0) {
                EXPECT_GE(sampledFirst, static_cast<double>(contact.time) - 1e-6) << "case " << i;
            }
        }
        // The closest approach: a real value at its time, and no sample below it by more than the
        // tolerance.
        EXPECT_NEAR(referenceSeparation(vehicle, character, static_cast<double>(closest.time)),
                    static_cast<double>(closest.distance), 1e-4)
            << "case " << i;
        a.closestGap = std::max(a.closestGap, static_cast<double>(closest.distance) - sampledMin);
        a.closestUndershoot = std::max(a.closestUndershoot, sampledMin - static_cast<double>(closest.distance));
        EXPECT_LE(static_cast<double>(closest.distance), sampledMin + tolerance + 1e-4) << "case " << i;
    }
    std::printf(
        "vehicle vs sampling (5 ms): %d cases, %d sampled overlaps, %d reported contacts;\n"
        "  reported first contact later than sampled by at most %.3g s, earlier by at most %.3g s;\n"
        "  separation at reported contacts at most %.3g m; closest approach above the sampled minimum by at "
        "most %.3g m, below it by at most %.3g m; %.1f evaluations per contact query\n",
        a.cases, a.sampledContacts, a.contacts, a.latestBySampling, a.earliestBySampling, a.worstConfirmation,
        a.closestGap, a.closestUndershoot, static_cast<double>(a.evaluations) / a.cases);
    EXPECT_LE(a.latestBySampling, 1e-6);           // never later (float rounding of the time only)
    EXPECT_GT(a.sampledContacts, cases / 10);      // the cases do exercise contacts
    EXPECT_LT(a.sampledContacts, cases * 9 / 10);  // and misses
}

// ---------------------------------------------------------------------------------------------
// Vehicles: edge cases and refusals

TEST(DangerVehicle, EdgeCases) {
    ApproachSettings settings;
    VehicleContact contact;
    ClosestApproach closest;
    // Nothing moves: the separation stays 10 - 2.2 - 0.5 m.
    const VehicleBody parked = car(DVec3(0.0), 0.0, 0.0);
    const CharacterBody standing = sphere(DVec3(0.0, 0.0, 10.0), 0.5);
    ASSERT_EQ(foresight::findVehicleContact(parked, standing, 10.0f, settings, contact), Status::Ok);
    EXPECT_FALSE(contact.contact);
    EXPECT_NEAR(contact.separation, 7.3f, 1e-6f);
    EXPECT_LE(contact.evaluations, 2u);
    ASSERT_EQ(foresight::findClosestVehicleApproach(parked, standing, 10.0f, settings, closest), Status::Ok);
    EXPECT_NEAR(closest.distance, 7.3f, 1e-6f);
    EXPECT_EQ(closest.time, 0.0f);  // the earliest of equal values
    // Already overlapping: time 0.
    const CharacterBody inside = sphere(DVec3(0.5, 0.0, 1.0), 0.5, DVec3(3.0, 0.0, 0.0));
    ASSERT_EQ(foresight::findVehicleContact(car(DVec3(0.0), 10.0, 0.3), inside, 2.0f, settings, contact), Status::Ok);
    EXPECT_TRUE(contact.contact);
    EXPECT_EQ(contact.time, 0.0f);
    // Horizon 0: t = 0 only.
    const VehicleBody moving = car(DVec3(0.0), 10.0, 0.0);
    ASSERT_EQ(foresight::findVehicleContact(moving, standing, 0.0f, settings, contact), Status::Ok);
    EXPECT_FALSE(contact.contact);
    EXPECT_EQ(contact.evaluations, 1u);
    ASSERT_EQ(foresight::findClosestVehicleApproach(moving, standing, 0.0f, settings, closest), Status::Ok);
    EXPECT_NEAR(closest.distance, 7.3f, 1e-6f);
    EXPECT_EQ(closest.time, 0.0f);
    // Just touching at the horizon (0.73 s): found at the horizon.
    ASSERT_EQ(foresight::findVehicleContact(moving, standing, 0.73f, settings, contact), Status::Ok);
    EXPECT_TRUE(contact.contact);
    EXPECT_NEAR(contact.time, 0.73f, 1e-4f);
    // A radius of 0 (a point) and a capsule lying along the path.
    CharacterBody point = sphere(DVec3(0.0, 0.0, 10.0), 0.0);
    ASSERT_EQ(foresight::findVehicleContact(moving, point, 2.0f, settings, contact), Status::Ok);
    EXPECT_NEAR(contact.time, (10.0 - 2.2) / 10.0, 1e-4);
    point.halfAxis = Vec3(0.0f, 0.0f, 2.0f);  // its near end is at z = 8
    ASSERT_EQ(foresight::findVehicleContact(moving, point, 2.0f, settings, contact), Status::Ok);
    EXPECT_NEAR(contact.time, (8.0 - 2.2) / 10.0, 1e-4);
    // The work cap.
    ApproachSettings tight;
    tight.maxEvaluations = 1;
    EXPECT_EQ(foresight::findVehicleContact(moving, standing, 2.0f, tight, contact), Status::TooManySteps);
    EXPECT_EQ(foresight::findClosestVehicleApproach(moving, standing, 2.0f, tight, closest), Status::TooManySteps);
}

TEST(DangerVehicle, RefusesBadInputAndLeavesTheOutputUntouched) {
    const VehicleBody good = car(DVec3(0.0), 10.0, 0.5);
    const CharacterBody target = sphere(DVec3(0.0, 0.0, 10.0), 0.5);
    struct Case {
        VehicleBody vehicle;
        CharacterBody character;
        float horizon;
        ApproachSettings settings;
        Status expected;
    };
    std::vector<Case> cases;
    auto add = [&](auto edit, Status expected) {
        Case c{good, target, 2.0f, {}, expected};
        edit(c);
        cases.push_back(c);
    };
    add([](Case& c) { c.vehicle.state.position.x = static_cast<foresight::Real>(kNaN); }, Status::NonFiniteInput);
    add([](Case& c) { c.vehicle.state.velocity.z = kNaN; }, Status::NonFiniteInput);
    add([](Case& c) { c.vehicle.state.angularVelocity.y = INFINITY; }, Status::NonFiniteInput);
    add([](Case& c) { c.vehicle.halfExtents.x = kNaN; }, Status::NonFiniteInput);
    add([](Case& c) { c.vehicle.boxCenter.x = kNaN; }, Status::NonFiniteInput);
    add([](Case& c) { c.character.position.z = static_cast<foresight::Real>(kNaN); }, Status::NonFiniteInput);
    add([](Case& c) { c.character.velocity.x = kNaN; }, Status::NonFiniteInput);
    add([](Case& c) { c.character.acceleration.x = kNaN; }, Status::NonFiniteInput);
    add([](Case& c) { c.character.radius = kNaN; }, Status::NonFiniteInput);
    add([](Case& c) { c.character.halfAxis.y = kNaN; }, Status::NonFiniteInput);
    add([](Case& c) { c.horizon = kNaN; }, Status::NonFiniteInput);
    add([](Case& c) { c.vehicle.state.orientation = ftest::quatWXYZ(0, 0, 0, 0); }, Status::ZeroQuaternion);
    add([](Case& c) { c.vehicle.settings.forward = Vec3(0.0f); }, Status::ZeroVector);
    add([](Case& c) { c.vehicle.halfExtents.y = 0.0f; }, Status::DegenerateShape);
    add([](Case& c) { c.character.radius = -0.1f; }, Status::InvalidRadius);
    add([](Case& c) { c.horizon = -1.0f; }, Status::NegativeTime);
    add([](Case& c) { c.settings.tolerance = 0.0f; }, Status::InvalidStep);
    add([](Case& c) { c.settings.tolerance = kNaN; }, Status::InvalidStep);
    add([](Case& c) { c.settings.maxEvaluations = 0; }, Status::InvalidStep);
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const Case& c = cases[i];
        VehicleContact contact;
        contact.time = 42.0f;
        ClosestApproach closest;
        closest.time = 42.0f;
        EXPECT_EQ(foresight::findVehicleContact(c.vehicle, c.character, c.horizon, c.settings, contact), c.expected)
            << "case " << i;
        EXPECT_EQ(foresight::findClosestVehicleApproach(c.vehicle, c.character, c.horizon, c.settings, closest),
                  c.expected)
            << "case " << i;
        EXPECT_EQ(contact.time, 42.0f);
        EXPECT_EQ(closest.time, 42.0f);
    }
    float separation = 7.0f;
    EXPECT_EQ(foresight::computeVehicleSeparation(good, target, -1.0f, separation), Status::NegativeTime);
    EXPECT_EQ(foresight::computeVehicleSeparation(good, target, kNaN, separation), Status::NonFiniteInput);
    EXPECT_EQ(separation, 7.0f);
    // Finite but absurd: overflow is refused, never NaN.
    VehicleBody fast = good;
    fast.state.velocity = Vec3(0.0f, 0.0f, 3e38f);
    VehicleContact contact;
    const Status status = foresight::findVehicleContact(fast, target, 3e38f, {}, contact);
    EXPECT_TRUE(status == Status::NonFiniteResult || status == Status::Ok) << foresight::statusMessage(status);
}

// ---------------------------------------------------------------------------------------------
// Projectiles

/// A throw predicted with the library (Exact), its trajectory kept.
struct Throw {
    std::vector<TrajectoryPoint> points;
    ProjectileResult result;
};

Throw predictThrow(DVec3 position, DVec3 velocity, float time, const foresight::CollisionWorld* world,
                   const ProjectileSettings& settings = {}) {
    Throw t;
    t.points.resize(foresight::trajectoryCapacity(time, settings, 256));
    EXPECT_EQ(foresight::predictProjectile(ftest::toR(position), ftest::toF(velocity), time, settings, world, t.points,
                                           t.result),
              Status::Ok);
    t.points.resize(t.result.trajectorySize);
    return t;
}

// A free throw from (0, 1, 0) at (4, 6, 0) m/s under 9.81: apex at t = 6 / 9.81, x = 4 t_a,
// y = 1 + 36 / (2 g). The parabola is y = y_a - k (x - x_a)^2, k = g / (2 * 16). A point h below
// the apex with h > 1 / (2k) (below the centre of curvature) is closest to the two points
// u = +-sqrt((2 k h - 1) / (2 k^2)) from the apex, at distance sqrt(u^2 + (h - k u^2)^2); a
// point above the apex (or below it, above the centre of curvature) is closest to the apex.
TEST(DangerProjectile, ClosestApproachOfTheParabola) {
    const double g = ftest::decimal(foresight::kDefaultGravity);
    const Throw t = predictThrow(DVec3(0, 1, 0), DVec3(4, 6, 0), 2.0f, nullptr);
    const double apexTime = 6.0 / g, apexX = 4.0 * apexTime, apexY = 1.0 + 36.0 / (2.0 * g);
    const double k = g / (2.0 * 16.0);
    ClosestApproach closest;
    // Above the apex, 0.5 m: the apex.
    ASSERT_EQ(foresight::findClosestPathApproach(t.points, rv(apexX, apexY + 0.5, 0), 0.0f, 2.0f, closest), Status::Ok);
    EXPECT_NEAR(closest.distance, 0.5, 1e-6);   // float positions of ~3 m
    EXPECT_NEAR(closest.time, apexTime, 1e-4);  // flat minimum: time to sqrt(1e-7 / k) / 4 m/s
    // 0.5 m below (1 / (2k) = 1.63 m): still the apex.
    ASSERT_EQ(foresight::findClosestPathApproach(t.points, rv(apexX, apexY - 0.5, 0), 0.0f, 2.0f, closest), Status::Ok);
    EXPECT_NEAR(closest.distance, 0.5, 1e-6);
    // 3 m below: the two side points, at the same distance (rounding picks one).
    const double h = 3.0;
    const double u = std::sqrt((2.0 * k * h - 1.0) / (2.0 * k * k));
    const double expected = std::sqrt(u * u + (h - k * u * u) * (h - k * u * u));
    ASSERT_EQ(foresight::findClosestPathApproach(t.points, rv(apexX, apexY - h, 0), 0.0f, 2.0f, closest), Status::Ok);
    EXPECT_NEAR(closest.distance, expected, 1e-6);
    const double side =
        std::min(std::abs(closest.time - (apexTime - u / 4.0)), std::abs(closest.time - (apexTime + u / 4.0)));
    EXPECT_LT(side, 1e-3);  // a flat minimum (see above)
    // Restricted to after the apex: the later side point.
    ASSERT_EQ(foresight::findClosestPathApproach(t.points, rv(apexX, apexY - h, 0), static_cast<float>(apexTime), 2.0f,
                                                 closest),
              Status::Ok);
    EXPECT_NEAR(closest.time, apexTime + u / 4.0, 1e-3);
    // Out of the plane by 2 m: the apex at sqrt(0.5^2 + 2^2)? No: the point above the apex by 0.5
    // and 2 m out is closest to the apex at sqrt(4.25).
    ASSERT_EQ(foresight::findClosestPathApproach(t.points, rv(apexX, apexY + 0.5, 2.0), 0.0f, 2.0f, closest),
              Status::Ok);
    EXPECT_NEAR(closest.distance, std::sqrt(4.25), 1e-6);
}

// Without gravity the path is a line p0 + v t; a point at distance d from it (foot at time t*)
// is first within r at t* - sqrt(r^2 - d^2) / |v|.
TEST(DangerProjectile, CorridorOfAStraightPath) {
    ProjectileSettings settings;
    settings.gravity = Vec3(0.0f);
    const Throw t = predictThrow(DVec3(0, 1, 0), DVec3(10, 0, 0), 2.0f, nullptr, settings);
    DangerStart start;
    // The foot at x = 12 (t* = 1.2), d = 0.6, r = 1: t = 1.2 - 0.8 / 10.
    ASSERT_EQ(foresight::findPathApproach(t.points, rv(12, 1.6, 0), 1.0f, 0.0f, 2.0f, start), Status::Ok);
    ASSERT_TRUE(start.ever);
    EXPECT_NEAR(start.time, 1.2 - 0.08, 1e-6);
    EXPECT_LE(start.time, 1.12f + 1e-7f);  // rounded down, never later
    // r = d exactly: the foot (a tangency); r < d: never.
    ASSERT_EQ(foresight::findPathApproach(t.points, rv(12, 1.5, 0), 0.5f, 0.0f, 2.0f, start), Status::Ok);
    EXPECT_TRUE(start.ever);
    EXPECT_NEAR(start.time, 1.2, 1e-3);  // tangency: the time is sqrt of the rounding
    ASSERT_EQ(foresight::findPathApproach(t.points, rv(12, 1.6, 0), 0.5f, 0.0f, 2.0f, start), Status::Ok);
    EXPECT_FALSE(start.ever);
    // A window starting inside the corridor: its start; a window before it: never; an empty one.
    ASSERT_EQ(foresight::findPathApproach(t.points, rv(12, 1.6, 0), 1.0f, 1.15f, 2.0f, start), Status::Ok);
    EXPECT_EQ(start.time, 1.15f);
    ASSERT_EQ(foresight::findPathApproach(t.points, rv(12, 1.6, 0), 1.0f, 0.0f, 1.0f, start), Status::Ok);
    EXPECT_FALSE(start.ever);
    ASSERT_EQ(foresight::findPathApproach(t.points, rv(12, 1.6, 0), 1.0f, 1.5f, 1.0f, start), Status::Ok);
    EXPECT_FALSE(start.ever);
    // After the last point the projectile stays there (x = 20 at t = 2).
    ASSERT_EQ(foresight::findPathApproach(t.points, rv(20, 1, 0), 0.1f, 2.5f, 3.0f, start), Status::Ok);
    EXPECT_EQ(start.time, 2.5f);
}

// A grenade thrown onto a floor: the zone is the predicted end position, dangerous from the fuse.
TEST(DangerProjectile, DangerZoneSafetyAndDangerStart) {
    foresight::StaticWorld world;
    ASSERT_EQ(world.add(foresight::Plane{Vec3(0.0f, 1.0f, 0.0f), 0}), Status::Ok);
    ProjectileSettings settings;
    settings.friction = 0.4f;
    const Throw t = predictThrow(DVec3(0, 1.5, 0), DVec3(0, 4, 8), 3.0f, &world, settings);
    ASSERT_GT(t.result.bounces, 0u);
    ProjectileDanger danger;
    danger.trajectory = t.points;
    danger.fuseTime = 3.0f;
    danger.blastRadius = 4.0f;
    DangerZone zone;
    ASSERT_EQ(foresight::computeDangerZone(danger, zone), Status::Ok);
    EXPECT_TRUE(ftest::vecNear(zone.center, t.result.position, 1e-6));  // the End point itself
    EXPECT_EQ(zone.radius, 4.0f);
    EXPECT_EQ(zone.time, 3.0f);
    const DVec3 c = ftest::toD(zone.center);
    bool safe = false;
    // Inside the blast: safe before the fuse, not from it on; exactly on the radius: unsafe.
    ASSERT_EQ(foresight::isPointSafe(danger, ftest::toR(c + DVec3(1, 0, 0)), 2.9f, safe), Status::Ok);
    EXPECT_TRUE(safe);
    ASSERT_EQ(foresight::isPointSafe(danger, ftest::toR(c + DVec3(1, 0, 0)), 3.0f, safe), Status::Ok);
    EXPECT_FALSE(safe);
    ASSERT_EQ(foresight::isPointSafe(danger, ftest::toR(c + DVec3(1, 0, 0)), 10.0f, safe), Status::Ok);
    EXPECT_FALSE(safe);
    ASSERT_EQ(foresight::isPointSafe(danger, ftest::toR(c + DVec3(0, 0, 4.01)), 3.0f, safe), Status::Ok);
    EXPECT_TRUE(safe);
    DangerStart start;
    ASSERT_EQ(foresight::findDangerStart(danger, ftest::toR(c + DVec3(2, 0, 0)), start), Status::Ok);
    EXPECT_TRUE(start.ever);
    EXPECT_EQ(start.time, 3.0f);
    ASSERT_EQ(foresight::findDangerStart(danger, ftest::toR(c + DVec3(5, 0, 0)), start), Status::Ok);
    EXPECT_FALSE(start.ever);
    // The projectile itself: a point on its path at t = 0.5 (before the first bounce).
    RVec3 onPath;
    ASSERT_EQ(foresight::positionOnTrajectory(t.points, 0.5f, onPath), Status::Ok);
    const double g = ftest::decimal(foresight::kDefaultGravity);
    EXPECT_TRUE(ftest::vecNear(onPath, DVec3(0, 1.5 + 4 * 0.5 - 0.5 * g * 0.25, 4), 1e-5));  // float steps
    ASSERT_EQ(foresight::isPointSafe(danger, onPath, 0.5f, safe), Status::Ok);
    EXPECT_TRUE(safe);  // contactRadius 0: nothing before the fuse
    danger.contactRadius = 0.3f;
    ASSERT_EQ(foresight::isPointSafe(danger, onPath, 0.5f, safe), Status::Ok);
    EXPECT_FALSE(safe);
    // At the throw point: unsafe from the first point's time (0) on, and safe before it (the
    // projectile is not there yet), as findDangerStart says (0, not earlier).
    const RVec3 thrower = t.points[0].position;
    ASSERT_EQ(t.points[0].time, 0.0f);
    ASSERT_EQ(foresight::isPointSafe(danger, thrower, -1.0f, safe), Status::Ok);
    EXPECT_TRUE(safe);
    ASSERT_EQ(foresight::isPointSafe(danger, thrower, -1e-6f, safe), Status::Ok);
    EXPECT_TRUE(safe);
    ASSERT_EQ(foresight::isPointSafe(danger, thrower, 0.0f, safe), Status::Ok);
    EXPECT_FALSE(safe);
    ASSERT_EQ(foresight::findDangerStart(danger, thrower, start), Status::Ok);
    EXPECT_TRUE(start.ever);
    EXPECT_EQ(start.time, 0.0f);
    ASSERT_EQ(foresight::isPointSafe(danger, onPath, 0.9f, safe), Status::Ok);
    EXPECT_TRUE(safe);  // it has flown on
    ASSERT_EQ(foresight::findDangerStart(danger, onPath, start), Status::Ok);
    EXPECT_TRUE(start.ever);
    // Within 0.3 m of the path: 0.3 m before the point at about |v| = |(8, -0.9)| m/s.
    EXPECT_NEAR(start.time, 0.5 - 0.3 / std::sqrt(64.0 + 0.905 * 0.905), 2e-3);
    EXPECT_LT(start.time, 0.5f);
    // The zone of an earlier fuse: the position on the segment model at that time.
    danger.fuseTime = 0.5f;
    ASSERT_EQ(foresight::computeDangerZone(danger, zone), Status::Ok);
    EXPECT_TRUE(ftest::vecNear(zone.center, onPath, 1e-6));
}

// Random throws bouncing off a floor and a wall, against fine sampling of the independent model
// (free flight p + v s + g s^2 / 2 from each point with the prediction's gravity, clamped at the
// next point's time; at rest after a Rest point).
TEST(DangerProjectile, AgreesWithFineSamplingOnRandomThrows) {
    foresight::StaticWorld world;
    ASSERT_EQ(world.add(foresight::Plane{Vec3(0.0f, 1.0f, 0.0f), 0}), Status::Ok);
    ASSERT_EQ(world.add(foresight::Plane{Vec3(0.0f, 0.0f, -1.0f), -8}), Status::Ok);  // z = 8
    ftest::Random random(777, kRandomStep);
    const double g = ftest::decimal(foresight::kDefaultGravity);
    double worstClosest = 0, worstEarliest = 0, worstLate = 0;
    int cases = 0, corridorHits = 0;
    for (int i = 0; i < 1000; ++i) {
        const DVec3 velocity(random.uniform(-4, 4), random.uniform(0, 8), random.uniform(2, 14));
        const Throw t = predictThrow(DVec3(random.uniform(-2, 2), random.uniform(0.5, 2), 0), velocity, 3.0f, &world);
        const DVec3 point(random.uniform(-6, 6), random.uniform(0, 4), random.uniform(-1, 9));
        const double radius = random.uniform(0.2, 2.5);
        auto reference = [&](double time) {
            std::size_t k = 0;
            while (k + 1 < t.points.size() && static_cast<double>(t.points[k + 1].time) <= time) ++k;
            const TrajectoryPoint& p = t.points[k];
            if (p.event == TrajectoryEvent::Rest || k + 1 == t.points.size()) return ftest::toD(p.position);
            const double s = time - static_cast<double>(p.time);
            // Sliding on the floor (frictionless): no vertical motion; otherwise free flight.
            const bool sliding = std::abs(static_cast<double>(p.position.y)) < 1e-5 && std::abs(p.velocity.y) < 1e-5f;
            return ftest::toD(p.position) + ftest::toD(p.velocity) * s +
                   DVec3(0, sliding ? 0.0 : -g, 0) * (0.5 * s * s);
        };
        double sampledMin = std::numeric_limits<double>::infinity(), sampledFirst = -1;
        for (int k = 0; k <= 6000; ++k) {  // every 0.5 ms
            const double time = 3.0 * k / 6000;
            const double d = glm::length(reference(time) - point);
            sampledMin = std::min(sampledMin, d);
            if (d <= radius && sampledFirst < 0) sampledFirst = time;
        }
        ClosestApproach closest;
        ASSERT_EQ(foresight::findClosestPathApproach(t.points, ftest::toR(point), 0.0f, 3.0f, closest), Status::Ok);
        DangerStart start;
        ASSERT_EQ(
            foresight::findPathApproach(t.points, ftest::toR(point), static_cast<float>(radius), 0.0f, 3.0f, start),
            Status::Ok);
        ++cases;
        // The exact minimum is never above the sampled one (float positions: 1e-5 m), and is a
        // real distance of the model at its time.
        worstClosest = std::max(worstClosest, static_cast<double>(closest.distance) - sampledMin);
        EXPECT_LE(static_cast<double>(closest.distance), sampledMin + 1e-5) << "case " << i;
        EXPECT_NEAR(glm::length(reference(static_cast<double>(closest.time)) - point),
                    static_cast<double>(closest.distance), 1e-4)
            << "case " << i;
        if (sampledFirst >= 0.0) {
            ++corridorHits;
            ASSERT_TRUE(start.ever) << "case " << i;
            worstLate = std::max(worstLate, static_cast<double>(start.time) - sampledFirst);
            worstEarliest = std::max(worstEarliest, sampledFirst - static_cast<double>(start.time));
            EXPECT_LE(static_cast<double>(start.time), sampledFirst + 1e-6) << "case " << i;
        }
        if (start.ever) {
            EXPECT_LE(glm::length(reference(static_cast<double>(start.time)) - point), radius + 1e-4) << "case " << i;
        }
    }
    std::printf(
        "projectile vs sampling (0.5 ms): %d throws, %d corridor entries; exact minimum above the sampled "
        "one by at most %.3g m; corridor entry later than sampled by at most %.3g s, earlier by at most "
        "%.3g s\n",
        cases, corridorHits, worstClosest, worstLate, worstEarliest);
    EXPECT_GT(corridorHits, 100);
}

TEST(DangerProjectile, RefusesBadInput) {
    const Throw t = predictThrow(DVec3(0, 1, 0), DVec3(1, 2, 3), 1.0f, nullptr);
    ProjectileDanger danger;
    danger.trajectory = t.points;
    danger.fuseTime = 1.0f;
    danger.blastRadius = 2.0f;
    DangerZone zone;
    zone.time = 42.0f;
    auto zoneStatus = [&](auto edit) {
        ProjectileDanger copy = danger;
        edit(copy);
        return foresight::computeDangerZone(copy, zone);
    };
    EXPECT_EQ(zoneStatus([](ProjectileDanger& d) { d.fuseTime = kNaN; }), Status::NonFiniteInput);
    EXPECT_EQ(zoneStatus([](ProjectileDanger& d) { d.blastRadius = INFINITY; }), Status::NonFiniteInput);
    EXPECT_EQ(zoneStatus([](ProjectileDanger& d) { d.contactRadius = kNaN; }), Status::NonFiniteInput);
    EXPECT_EQ(zoneStatus([](ProjectileDanger& d) { d.fuseTime = -1.0f; }), Status::InvalidFuse);
    EXPECT_EQ(zoneStatus([](ProjectileDanger& d) { d.blastRadius = -1.0f; }), Status::InvalidRadius);
    EXPECT_EQ(zoneStatus([](ProjectileDanger& d) { d.contactRadius = -1.0f; }), Status::InvalidRadius);
    EXPECT_EQ(zoneStatus([](ProjectileDanger& d) { d.trajectory = {}; }), Status::InvalidStep);
    std::vector<TrajectoryPoint> broken = t.points;
    std::swap(broken[1], broken[2]);  // times decrease
    EXPECT_EQ(zoneStatus([&](ProjectileDanger& d) { d.trajectory = broken; }), Status::InvalidStep);
    broken = t.points;
    broken[3].position.y = static_cast<foresight::Real>(kNaN);
    EXPECT_EQ(zoneStatus([&](ProjectileDanger& d) { d.trajectory = broken; }), Status::NonFiniteInput);
    broken = t.points;
    broken[3].velocity.x = kNaN;
    EXPECT_EQ(zoneStatus([&](ProjectileDanger& d) { d.trajectory = broken; }), Status::NonFiniteInput);
    broken = t.points;
    broken[3].time = kNaN;
    EXPECT_EQ(zoneStatus([&](ProjectileDanger& d) { d.trajectory = broken; }), Status::NonFiniteInput);
    EXPECT_EQ(zone.time, 42.0f);  // untouched

    const RVec3 nanPoint = rv(0, std::nan(""), 0);
    bool safe = false;
    DangerStart start;
    ClosestApproach closest;
    RVec3 position;
    EXPECT_EQ(foresight::isPointSafe(danger, nanPoint, 0.5f, safe), Status::NonFiniteInput);
    EXPECT_EQ(foresight::isPointSafe(danger, rv(0, 0, 0), kNaN, safe), Status::NonFiniteInput);
    EXPECT_EQ(foresight::findDangerStart(danger, nanPoint, start), Status::NonFiniteInput);
    EXPECT_EQ(foresight::findPathApproach(t.points, nanPoint, 1.0f, 0.0f, 1.0f, start), Status::NonFiniteInput);
    EXPECT_EQ(foresight::findPathApproach(t.points, rv(0, 0, 0), kNaN, 0.0f, 1.0f, start), Status::NonFiniteInput);
    EXPECT_EQ(foresight::findPathApproach(t.points, rv(0, 0, 0), 1.0f, kNaN, 1.0f, start), Status::NonFiniteInput);
    EXPECT_EQ(foresight::findPathApproach(t.points, rv(0, 0, 0), -1.0f, 0.0f, 1.0f, start), Status::InvalidRadius);
    EXPECT_EQ(foresight::findClosestPathApproach(t.points, nanPoint, 0.0f, 1.0f, closest), Status::NonFiniteInput);
    EXPECT_EQ(foresight::findClosestPathApproach({}, rv(0, 0, 0), 0.0f, 1.0f, closest), Status::InvalidStep);
    EXPECT_EQ(foresight::positionOnTrajectory(t.points, kNaN, position), Status::NonFiniteInput);
    EXPECT_EQ(foresight::positionOnTrajectory({}, 0.0f, position), Status::InvalidStep);
    EXPECT_EQ(foresight::validateTrajectory(t.points), Status::Ok);
    EXPECT_EQ(foresight::validateProjectileDanger(danger), Status::Ok);
}

// A single point (time 0 predictions) and repeated times (jumps) are valid trajectories.
TEST(DangerProjectile, SinglePointAndJumps) {
    TrajectoryPoint only;
    only.position = rv(1, 2, 3);
    const std::array<TrajectoryPoint, 1> single{only};
    ClosestApproach closest;
    ASSERT_EQ(foresight::findClosestPathApproach(single, rv(1, 2, 5), 0.0f, 4.0f, closest), Status::Ok);
    EXPECT_FLOAT_EQ(closest.distance, 2.0f);
    EXPECT_EQ(closest.time, 0.0f);
    ProjectileDanger danger;
    danger.trajectory = single;
    danger.blastRadius = 3.0f;
    danger.fuseTime = 0.0f;
    DangerStart start;
    ASSERT_EQ(foresight::findDangerStart(danger, rv(1, 2, 5), start), Status::Ok);
    EXPECT_TRUE(start.ever);
    EXPECT_EQ(start.time, 0.0f);
    // Two points at the same time: a jump; the later one holds from then on.
    TrajectoryPoint later = only;
    later.position = rv(4, 2, 3);
    const std::array<TrajectoryPoint, 2> jump{only, later};
    RVec3 position;
    ASSERT_EQ(foresight::positionOnTrajectory(jump, 0.0f, position), Status::Ok);
    EXPECT_TRUE(ftest::vecNear(position, DVec3(4, 2, 3), 0.0));
}

// ---------------------------------------------------------------------------------------------
// No allocation in any query.

TEST(DangerAllocation, QueriesDoNotAllocate) {
    const Throw t = predictThrow(DVec3(0, 1, 0), DVec3(1, 5, 6), 2.0f, nullptr);
    ProjectileDanger danger;
    danger.trajectory = t.points;
    danger.fuseTime = 2.0f;
    danger.blastRadius = 3.0f;
    danger.contactRadius = 0.5f;
    const VehicleBody vehicle = car(DVec3(0.0), 10.0, 0.5);
    CharacterBody walker = sphere(DVec3(6.0, 0.0, 15.0), 0.3, DVec3(-5.0, 0.0, 0.0));
    walker.halfAxis = Vec3(0.0f, 0.5f, 0.0f);
    DangerZone zone;
    DangerStart start;
    ClosestApproach closest;
    VehicleContact contact;
    RVec3 position;
    bool safe = false;
    float separation = 0;
    const long before = ftest::gAllocations.load();
    Status statuses[] = {
        foresight::computeDangerZone(danger, zone),
        foresight::isPointSafe(danger, rv(1, 1, 1), 1.0f, safe),
        foresight::findDangerStart(danger, rv(1, 1, 1), start),
        foresight::findPathApproach(t.points, rv(1, 1, 1), 1.0f, 0.0f, 2.0f, start),
        foresight::findClosestPathApproach(t.points, rv(1, 1, 1), 0.0f, 2.0f, closest),
        foresight::positionOnTrajectory(t.points, 0.3f, position),
        foresight::computeVehicleSeparation(vehicle, walker, 1.0f, separation),
        foresight::findVehicleContact(vehicle, walker, 3.0f, {}, contact),
        foresight::findClosestVehicleApproach(vehicle, walker, 3.0f, {}, closest),
    };
    const long allocations = ftest::gAllocations.load() - before;
    EXPECT_EQ(allocations, 0);
    for (const Status status : statuses) EXPECT_EQ(status, Status::Ok);
}

}  // namespace
