// unreal.h: Unreal Engine coordinates (Z up, X forward, Y right, centimetres) to foresight's.
//
// Stand-ins for FVector and FQuat (same member names, double like Unreal 5's) carry the data;
// every expectation is computed in Unreal's own axes and units by formulas written here (the
// rotation of a vector by Rodrigues' formula, a parabola, a circle), never by converting back.

#include <foresight/foresight.h>
#include <foresight/unreal.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using namespace foresight;

struct FVectorLike {
    double X = 0, Y = 0, Z = 0;
    FVectorLike() = default;
    FVectorLike(double x, double y, double z) : X(x), Y(y), Z(z) {}
};

struct FQuatLike {
    double X = 0, Y = 0, Z = 0, W = 1;
    FQuatLike() = default;
    FQuatLike(double x, double y, double z, double w) : X(x), Y(y), Z(z), W(w) {}
};

// Unreal 4's FVector was float: the templates take it too.
struct FVector3fLike {
    float X = 0, Y = 0, Z = 0;
    FVector3fLike() = default;
    FVector3fLike(float x, float y, float z) : X(x), Y(y), Z(z) {}
};

// Rotation of v by `angle` about the unit `axis`, in Unreal's own axes (Rodrigues' formula).
FVectorLike rotate(const FVectorLike& axis, double angle, const FVectorLike& v) {
    const double c = std::cos(angle), s = std::sin(angle);
    const double d = axis.X * v.X + axis.Y * v.Y + axis.Z * v.Z;
    const FVectorLike cross(axis.Y * v.Z - axis.Z * v.Y, axis.Z * v.X - axis.X * v.Z, axis.X * v.Y - axis.Y * v.X);
    return FVectorLike(v.X * c + cross.X * s + axis.X * d * (1 - c), v.Y * c + cross.Y * s + axis.Y * d * (1 - c),
                       v.Z * c + cross.Z * s + axis.Z * d * (1 - c));
}

// Tolerances: a float result (foresight's Vec3 and Quat) of a quantity of magnitude M is exact
// to about 6e-8 M; the expectations allow a few ulps of it.

TEST(Unreal, AxesAndUnits) {
    // Unreal (X forward, Y right, Z up) in cm -> foresight (x right, y up, z forward) in m.
    const RVec3 p = unreal::toPosition(FVectorLike(100, 200, 300));
    EXPECT_FLOAT_EQ(static_cast<float>(p.x), 2.0f);  // right
    EXPECT_FLOAT_EQ(static_cast<float>(p.y), 3.0f);  // up
    EXPECT_FLOAT_EQ(static_cast<float>(p.z), 1.0f);  // forward
    const Vec3 v = unreal::toVelocity(FVectorLike(0, 0, -500));
    EXPECT_EQ(v, Vec3(0, -5, 0));
    const Vec3 n = unreal::toDirection(FVectorLike(0, 0, 1));  // Unreal's up is foresight's up
    EXPECT_EQ(n, Vec3(0, 1, 0));
    EXPECT_EQ(unreal::toDirection(FVectorLike(1, 0, 0)), Vec3(0, 0, 1));  // forward is forward
    EXPECT_EQ(unreal::gravityFromZ(), Vec3(0, -9.8f, 0));                 // Unreal's default gravity
    EXPECT_EQ(unreal::toAcceleration(FVectorLike(0, 0, -980)), Vec3(0, -9.8f, 0));

    const FVectorLike back = unreal::fromPosition<FVectorLike>(RVec3(2, 3, 1));
    EXPECT_DOUBLE_EQ(back.X, 100.0);
    EXPECT_DOUBLE_EQ(back.Y, 200.0);
    EXPECT_DOUBLE_EQ(back.Z, 300.0);
    const FVector3fLike single = unreal::fromVelocity<FVector3fLike>(Vec3(0.25f, -1.5f, 4));
    EXPECT_EQ(single.X, 400.0f);
    EXPECT_EQ(single.Y, 25.0f);
    EXPECT_EQ(single.Z, -150.0f);
    EXPECT_EQ(unreal::toVelocity(single), Vec3(0.25f, -1.5f, 4));
}

TEST(Unreal, RotationsRotateTheSameWay) {
    // A rotation given in Unreal's axes, applied in foresight's axes, must move a vector to where
    // Unreal's own rotation moves it.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 200; ++i) {
        FVectorLike axis(unit(rng), unit(rng), unit(rng));
        const double length = std::sqrt(axis.X * axis.X + axis.Y * axis.Y + axis.Z * axis.Z);
        if (length < 0.1) continue;
        axis = FVectorLike(axis.X / length, axis.Y / length, axis.Z / length);
        const double angle = 3.0 * unit(rng);
        const double s = std::sin(angle / 2);
        const FQuatLike q(axis.X * s, axis.Y * s, axis.Z * s, std::cos(angle / 2));  // FQuat(Axis, Angle)
        const FVectorLike v(100 * unit(rng), 100 * unit(rng), 100 * unit(rng));

        const FVectorLike expected = rotate(axis, angle, v);
        const Vec3 turned = unreal::toRotation(q) * unreal::toDirection(v);
        const FVectorLike actual = unreal::fromDirection<FVectorLike>(turned);
        // |v| <= 174: float rounding of the quaternion and the product, a few 1e-5 at most.
        EXPECT_NEAR(actual.X, expected.X, 1e-4) << i;
        EXPECT_NEAR(actual.Y, expected.Y, 1e-4) << i;
        EXPECT_NEAR(actual.Z, expected.Z, 1e-4) << i;

        const FQuatLike back = unreal::fromRotation<FQuatLike>(unreal::toRotation(q));
        EXPECT_NEAR(back.X, q.X, 1e-7);  // float rounding of a component <= 1
        EXPECT_NEAR(back.Y, q.Y, 1e-7);
        EXPECT_NEAR(back.Z, q.Z, 1e-7);
        EXPECT_NEAR(back.W, q.W, 1e-7);
    }
}

TEST(Unreal, ThrowInCentimetres) {
    // A ball thrown in an Unreal level: 2 m up, 10 m/s forward and 5 m/s up, default gravity.
    const FVectorLike hand(0, 0, 200), throwVelocity(1000, 0, 500);
    PointState start;
    start.position = unreal::toPosition(hand);
    start.velocity = unreal::toVelocity(throwVelocity);
    PointState later;
    ASSERT_EQ(predictAccelerated(start, unreal::gravityFromZ(), 0.8f, later), Status::Ok);
    const FVectorLike at = unreal::fromPosition<FVectorLike>(later.position);
    // In cm: p + v t + g t^2 / 2 with g = -980 cm/s^2 on Z.
    const double t = 0.8;
    EXPECT_NEAR(at.X, 1000 * t, 1e-3);  // float positions of metres: 1e-6 m = 1e-4 cm
    EXPECT_NEAR(at.Y, 0.0, 1e-3);
    EXPECT_NEAR(at.Z, 200 + 500 * t - 0.5 * 980 * t * t, 1e-3);
    const FVectorLike velocity = unreal::fromVelocity<FVectorLike>(later.velocity);
    EXPECT_NEAR(velocity.Z, 500 - 980 * t, 1e-3);
}

TEST(Unreal, VehicleTurningRightStaysOnItsCircle) {
    // A car facing Unreal's +X at 10 m/s, yawing at +0.5 rad/s about +Z (towards +Y: right).
    VehicleState car;
    car.position = unreal::toPosition(FVectorLike(0, 0, 0));
    car.velocity = unreal::toVelocity(FVectorLike(1000, 0, 0));
    car.orientation = unreal::toRotation(FQuatLike(0, 0, 0, 1));
    car.angularVelocity = unreal::toDirection(FVectorLike(0, 0, 0.5));
    VehicleSettings settings;
    settings.frame = AngularFrame::World;  // Unreal's physics reports world axes
    VehicleState later;
    ASSERT_EQ(predictVehicleExact(car, 2.0f, settings, later), Status::Ok);
    // In Unreal's axes: a circle of radius v / w = 2000 cm, heading theta = w t = 1 rad.
    const double radius = 2000, theta = 1.0;
    const FVectorLike at = unreal::fromPosition<FVectorLike>(later.position);
    EXPECT_NEAR(at.X, radius * std::sin(theta), 1e-2);  // float metres near 20 m: 2e-6 m = 2e-4 cm
    EXPECT_NEAR(at.Y, radius * (1 - std::cos(theta)), 1e-2);
    EXPECT_NEAR(at.Z, 0.0, 1e-2);
    const FVectorLike heading = unreal::fromVelocity<FVectorLike>(later.velocity);
    EXPECT_NEAR(heading.X, 1000 * std::cos(theta), 1e-2);
    EXPECT_NEAR(heading.Y, 1000 * std::sin(theta), 1e-2);
}

}  // namespace
