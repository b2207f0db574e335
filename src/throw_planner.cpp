#include <foresight/throw_planner.h>

#include "internal.h"
#include "projectile_internal.h"

#include <algorithm>
#include <cmath>
#include <limits>

FORESIGHT_NAMESPACE_BEGIN

using detail::DVec3;
using detail::isFinite;
using detail::toD;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Grid elevations, from slightly down (throws at a floor or off a low wall) to a steep lob.
constexpr double kGridLowestElevation = -30.0 * kPi / 180.0;
constexpr double kGridHighestElevation = 75.0 * kPi / 180.0;

// Refinement stops when a throw is this fraction of the acceptance radius from the target: a
// margin inside the radius, so that plans survive small differences in the game's physics.
constexpr double kRefinementGoal = 0.5;

/// One evaluated throw.
struct Candidate {
    DVec3 velocity{0};
    double distance = kInfinity;  // at the fuse time, to the target [m]
    ProjectileResult result;
    bool hasImpact = false;  // a first impact was recorded
    double impactTime = -1;
    DVec3 impactNormal{0};
    DVec3 impactPosition{0};
    DVec3 residual{0};    // final position - target [m]
    bool coarse = false;  // predicted with the grid's coarse step: not verified
};

/// The planner's state for one call (all on the stack).
class Planner {
public:
    Planner(const ThrowPlanRequest& request, const CollisionWorld* world, std::span<ThrowPlan> plans,
            std::span<TrajectoryPoint> scratch)
        : mRequest(request), mWorld(world), mPlans(plans), mScratch(scratch),
          mWanted(std::min<std::size_t>(request.maxPlans, plans.size())), mStart(toD(request.start)),
          mTarget(toD(request.target)), mRadius(request.acceptanceRadius),
          mFuse(detail::decimalValue(request.fuseTime)), mMaxSpeed(request.maxSpeed), mMinSpeed(request.minSpeed),
          mCosDistinct(std::cos(std::clamp(static_cast<double>(request.distinctAngle), 0.0, kPi))) {
        const DVec3 gravity = toD(request.settings.gravity);
        mGravity = glm::length(gravity);
        mUp = mGravity > 0 ? -gravity / mGravity : DVec3(0, 1, 0);
        const DVec3 offset = mTarget - mStart;
        const DVec3 horizontal = offset - mUp * glm::dot(offset, mUp);
        mHorizontalDistance = glm::length(horizontal);
        if (mHorizontalDistance > 1e-9 * detail::coordinateMagnitude(offset)) {
            mForward = horizontal / mHorizontalDistance;
        } else {
            // Target straight above or below: any horizontal direction serves as the reference.
            const DVec3 axis = std::abs(mUp.x) < 0.9 ? DVec3(1, 0, 0) : DVec3(0, 0, 1);
            mForward = glm::normalize(axis - mUp * glm::dot(axis, mUp));
            mHorizontalDistance = 0;
        }
        mSide = glm::cross(mUp, mForward);
        mHeightAboveTarget = -glm::dot(offset, mUp);
    }

    void run() {
        seeds();
        if (done()) return;
        refineClosest(mSeeds, mSeedCount);
        if (done()) return;
        grid();
        if (done()) return;
        refineClosest(mCells, mCellCount);
    }

    void finish(ThrowPlanResult& out) {
        // Closest first; insertion sort: stable, in place, no allocation.
        for (std::size_t i = 1; i < mAccepted; ++i) {
            const ThrowPlan plan = mPlans[i];
            std::size_t j = i;
            for (; j > 0 && mPlans[j - 1].distance > plan.distance; --j) mPlans[j] = mPlans[j - 1];
            mPlans[j] = plan;
        }
        out.planCount = mAccepted;
        out.predictions = mPredictions;
        // No throw finished (none ran, or all failed), or it ended beyond a float's range (or
        // the double distance overflowed): the largest float says "nowhere near".
        const bool any = mClosest.distance <= static_cast<double>(std::numeric_limits<float>::max());
        out.closestDistance = any ? static_cast<float>(mClosest.distance) : std::numeric_limits<float>::max();
        out.closestVelocity = any ? Vec3(mClosest.velocity) : Vec3(0);
    }

private:
    bool done() const { return mAccepted >= mWanted || budgetSpent(); }
    bool budgetSpent() const { return mPredictions >= mRequest.budget.maxPredictions; }

    // ---- the forward model ----------------------------------------------------------------

    /// True when the grid predicts with a coarser step than the request's (gridStep).
    bool coarseGrid() const {
        return mRequest.settings.method == ProjectileMethod::Exact && mRequest.budget.gridStep > mRequest.settings.step;
    }

    /// Runs one prediction; false when the budget is spent (candidate untouched). `velocity` is
    /// taken by value: callers may pass the candidate's own velocity. A coarse
    /// prediction (the grid's step) is only a ranking: it is neither a plan nor the closest.
    /// `irrelevantBeyond`: the caller does nothing with a throw that ends farther than this from
    /// the target [m]; the prediction may then stop early (projectile_internal.h) and the
    /// candidate is left as a miss, its distance infinite. What evaluate itself does with a
    /// throw (a plan within the radius, the closest so far, a coarse cell verified within twice
    /// the radius) raises the bound, so that no outcome changes.
    bool evaluate(const DVec3 velocity, Candidate& c, bool coarse = false, double irrelevantBeyond = kInfinity) {
        if (budgetSpent()) return false;
        ++mPredictions;
        c = Candidate();
        c.velocity = velocity;
        c.coarse = coarse;
        ProjectileSettings settings = mRequest.settings;
        if (coarse) settings.step = mRequest.budget.gridStep;
        detail::DistanceCutoff cutoff;
        cutoff.target = mTarget;
        cutoff.keepBelow = coarse ? std::max(irrelevantBeyond, 2.0 * mRadius)
                                  : std::max({irrelevantBeyond, mRadius, mClosest.distance});
        ProjectileResult result;
        bool abandoned = false;
        const Status status = detail::predictProjectileWithCutoff(
            mRequest.start, Vec3(velocity), mRequest.fuseTime, settings, mWorld, mScratch, result,
            std::isfinite(cutoff.keepBelow) ? &cutoff : nullptr, abandoned);
        // A miss: work caps or overflow on this throw, or surely too far to matter.
        if (status != Status::Ok || abandoned) return true;
        c.result = result;
        c.residual = toD(result.position) - mTarget;
        c.distance = glm::length(c.residual);
        const std::size_t recorded = std::min(result.trajectorySize, mScratch.size());
        for (std::size_t i = 0; i < recorded; ++i) {
            const TrajectoryPoint& point = mScratch[i];
            if (point.event == TrajectoryEvent::Bounce || point.event == TrajectoryEvent::Hit) {
                c.hasImpact = true;
                c.impactTime = point.time;
                c.impactNormal = toD(point.normal);
                c.impactPosition = toD(point.position);
                break;
            }
        }
        if (coarse) return true;
        if (c.distance < mClosest.distance) mClosest = c;
        consider(c);
        return true;
    }

    bool withinSpeed(const DVec3& velocity) const {
        const double speed = glm::length(velocity);
        // The float velocity handed to the predictor may round a hair above the cap.
        return speed <= mMaxSpeed * (1 + 1e-6) && speed >= mMinSpeed * (1 - 1e-6);
    }

    DVec3 clampSpeed(const DVec3& velocity) const {
        const double speed = glm::length(velocity);
        if (speed > mMaxSpeed) return velocity * (mMaxSpeed / speed);
        if (speed < mMinSpeed) {
            if (speed > 0) return velocity * (mMinSpeed / speed);
            return mForward * mMinSpeed;
        }
        return velocity;
    }

    /// True when a and b count as the same plan (ThrowPlanRequest::distinctAngle).
    bool samePlan(const DVec3& velocityA, bool impactA, const DVec3& normalA, const DVec3& velocityB, bool impactB,
                  const DVec3& normalB) const {
        const double speedA = glm::length(velocityA), speedB = glm::length(velocityB);
        if (speedA == 0 || speedB == 0) {
            if (speedA != speedB) return false;
        } else if (glm::dot(velocityA, velocityB) / (speedA * speedB) < mCosDistinct) {
            return false;
        }
        if (impactA != impactB) return false;
        return !impactA || glm::dot(normalA, normalB) >= mCosDistinct;
    }

    /// Keeps `c` as a plan when it is within the radius: a new one if distinct, or in place of
    /// the same plan if closer.
    void consider(const Candidate& c) {
        if (!(c.distance <= mRadius) || !withinSpeed(c.velocity)) return;
        for (std::size_t i = 0; i < mAccepted; ++i) {
            ThrowPlan& plan = mPlans[i];
            if (samePlan(c.velocity, c.hasImpact, c.impactNormal, toD(plan.launchVelocity), plan.firstImpactTime >= 0,
                         toD(plan.firstImpactNormal))) {
                if (c.distance < plan.distance) plan = toPlan(c);
                return;
            }
        }
        if (mAccepted < mWanted) mPlans[mAccepted++] = toPlan(c);
    }

    ThrowPlan toPlan(const Candidate& c) const {
        ThrowPlan plan;
        plan.launchVelocity = Vec3(c.velocity);
        plan.finalPosition = c.result.position;
        plan.distance = static_cast<float>(c.distance);
        plan.bounces = c.result.bounces;
        plan.atRest = c.result.atRest;
        plan.firstImpactTime = c.hasImpact ? static_cast<float>(c.impactTime) : -1.0f;
        plan.firstImpactNormal = c.hasImpact ? Vec3(c.impactNormal) : Vec3(0);
        plan.firstImpactPosition = c.hasImpact ? detail::toR(c.impactPosition) : mRequest.start;
        return plan;
    }

    bool nearAcceptedPlan(const Candidate& c) const {
        for (std::size_t i = 0; i < mAccepted; ++i) {
            const ThrowPlan& plan = mPlans[i];
            if (samePlan(c.velocity, c.hasImpact, c.impactNormal, toD(plan.launchVelocity), plan.firstImpactTime >= 0,
                         toD(plan.firstImpactNormal)))
                return true;
        }
        return false;
    }

    // ---- 1. seeds: the flat-ground model ---------------------------------------------------

    /// Where a throw with horizontal speed `horizontal` and vertical speed `vertical` is at the
    /// fuse time in the flat-ground model (a plane through the target perpendicular to gravity,
    /// the request's restitution and friction): the horizontal distance covered.
    double flatGroundDistance(double horizontal, double vertical) const {
        const double e = mRequest.settings.restitution, mu = mRequest.settings.friction;
        const double g = mGravity;
        double t = 0, x = 0, height = mHeightAboveTarget, u = horizontal, w = vertical;
        for (int impact = 0; impact < 256; ++impact) {
            // The descending crossing of the plane: height + w s - g s^2 / 2 = 0.
            const double discriminant = w * w + 2 * g * height;
            if (discriminant < 0) return x + u * (mFuse - t);  // never comes down to the plane
            const double landing = (w + std::sqrt(discriminant)) / g;
            if (!(landing > 0) || t + landing >= mFuse) return x + u * (mFuse - t);
            t += landing;
            x += u * landing;
            const double normalSpeed = std::sqrt(discriminant);
            u = std::max(0.0, u - mu * (1 + e) * normalSpeed);
            w = e * normalSpeed;
            height = 0;
            // A hop under a micrometre: the grenade slides (the exact predictor's rule).
            if (w * w < 2e-6 * g) break;
        }
        const double left = mFuse - t;
        if (mu > 0 && mu * g * left >= u) return x + u * u / (2 * mu * g);
        return x + u * left - 0.5 * mu * g * left * left;
    }

    void seeds() {
        if (mGravity == 0) {
            // Straight lines: the throw that arrives at the fuse time.
            const DVec3 velocity = (mTarget - mStart) / mFuse;
            if (glm::length(velocity) <= mMaxSpeed && glm::length(velocity) >= mMinSpeed) addSeed(velocity);
            return;
        }
        for (const float fraction : mRequest.budget.seedLandingFractions) {
            if (done()) return;
            if (!(fraction > 0.0f && fraction <= 1.0f)) continue;
            const double landing = detail::decimalValue(fraction) * mFuse;
            // First landing on the plane at `landing`: height + w t - g t^2 / 2 = 0.
            const double vertical = (0.5 * mGravity * landing * landing - mHeightAboveTarget) / landing;
            if (std::abs(vertical) > mMaxSpeed) continue;
            const double horizontalCap = std::sqrt(mMaxSpeed * mMaxSpeed - vertical * vertical);
            if (flatGroundDistance(horizontalCap, vertical) < mHorizontalDistance) continue;
            // The distance covered grows with the horizontal speed: bisection.
            double low = 0, high = horizontalCap;
            for (int i = 0; i < 60; ++i) {
                const double middle = 0.5 * (low + high);
                (flatGroundDistance(middle, vertical) < mHorizontalDistance ? low : high) = middle;
            }
            const double horizontal = 0.5 * (low + high);
            const DVec3 velocity = mForward * horizontal + mUp * vertical;
            if (glm::length(velocity) < mMinSpeed) continue;
            addSeed(velocity);
        }
    }

    void addSeed(const DVec3& velocity) {
        Candidate c;
        if (!evaluate(velocity, c)) return;
        if (mSeedCount < mSeeds.size()) mSeeds[mSeedCount++] = c;
    }

    // ---- 2. refinement ---------------------------------------------------------------------

    /// Refines the closest candidates of `list` that are not plans yet, closest first.
    template <std::size_t N>
    void refineClosest(std::array<Candidate, N>& list, std::size_t count) {
        std::sort(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(count),
                  [](const Candidate& a, const Candidate& b) { return a.distance < b.distance; });
        for (std::size_t i = 0; i < count && !done(); ++i) {
            if (mRefinements >= mRequest.budget.refinements) return;
            Candidate c = list[i];
            if (!std::isfinite(c.distance)) return;
            // A coarse grid cell: predicted again with the request's settings first (which may
            // accept it as it is). DVec3(...) copies: evaluate resets c.
            if (c.coarse && (!evaluate(DVec3(c.velocity), c) || done())) return;
            if (!std::isfinite(c.distance)) continue;
            if (c.distance <= mRadius * kRefinementGoal || nearAcceptedPlan(c)) continue;
            ++mRefinements;
            refine(c);
        }
    }

    /// Damped Gauss-Newton on the launch velocity, from `start`.
    void refine(Candidate current) {
        const std::uint32_t limit = mPredictions + mRequest.budget.refinementPredictions;
        const double h = std::max(1e-4, 5e-4 * mMaxSpeed);  // forward-difference step [m/s]
        double damping = 1e-3;
        while (mPredictions < limit && !budgetSpent()) {
            if (current.distance <= mRadius * kRefinementGoal) return;
            // Jacobian of the final position by the launch velocity, column by column.
            double jacobian[3][3] = {};
            for (int axis = 0; axis < 3; ++axis) {
                if (mPredictions >= limit) return;
                DVec3 step(0);
                step[axis] = h;
                // Backward differences where a forward step would leave the speed cap.
                if (glm::length(current.velocity + step) > mMaxSpeed) step[axis] = -h;
                Candidate probe;
                if (!evaluate(current.velocity + step, probe)) return;
                if (!std::isfinite(probe.distance)) return;
                for (int row = 0; row < 3; ++row)
                    jacobian[row][axis] = (probe.residual[row] - current.residual[row]) / step[axis];
            }
            // Normal equations (J^T J + damping diag) delta = -J^T r.
            double normal[3][3], rhs[3];
            for (int i = 0; i < 3; ++i) {
                rhs[i] = 0;
                for (int row = 0; row < 3; ++row) rhs[i] -= jacobian[row][i] * current.residual[row];
                for (int j = 0; j < 3; ++j) {
                    normal[i][j] = 0;
                    for (int row = 0; row < 3; ++row) normal[i][j] += jacobian[row][i] * jacobian[row][j];
                }
            }
            bool improved = false;
            while (!improved && mPredictions < limit && !budgetSpent()) {
                DVec3 delta;
                if (!solveDamped(normal, rhs, damping, delta)) return;
                // No step longer than half the speed cap: the model is local.
                const double length = glm::length(delta);
                if (length > 0.5 * mMaxSpeed) delta *= 0.5 * mMaxSpeed / length;
                if (length < 1e-9 * mMaxSpeed) return;  // converged as far as it can
                // Only a trial closer than the current throw is taken (or one within the radius,
                // evaluate's own bound).
                Candidate trial;
                if (!evaluate(clampSpeed(current.velocity + delta), trial, false, current.distance)) return;
                if (trial.distance < current.distance) {
                    current = trial;
                    damping = std::max(damping * 0.2, 1e-9);
                    improved = true;
                } else {
                    damping *= 8;
                    if (damping > 1e8) return;  // stuck at a discontinuity or a minimum
                }
            }
        }
    }

    /// Solves (A + damping (diag(A) + tiny)) x = b by Gaussian elimination with pivoting.
    static bool solveDamped(const double (&a)[3][3], const double (&b)[3], double damping, DVec3& x) {
        double m[3][4];
        double scale = 0;
        for (int i = 0; i < 3; ++i) scale = std::max(scale, a[i][i]);
        const double floor = 1e-12 * std::max(scale, 1e-300);
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) m[i][j] = a[i][j];
            m[i][i] += damping * (a[i][i] + floor) + floor;
            m[i][3] = b[i];
        }
        for (int column = 0; column < 3; ++column) {
            int pivot = column;
            for (int row = column + 1; row < 3; ++row)
                if (std::abs(m[row][column]) > std::abs(m[pivot][column])) pivot = row;
            if (!(std::abs(m[pivot][column]) > 0)) return false;
            if (pivot != column)
                for (int j = 0; j < 4; ++j) std::swap(m[pivot][j], m[column][j]);
            for (int row = column + 1; row < 3; ++row) {
                const double factor = m[row][column] / m[column][column];
                for (int j = column; j < 4; ++j) m[row][j] -= factor * m[column][j];
            }
        }
        for (int row = 2; row >= 0; --row) {
            double sum = m[row][3];
            for (int j = row + 1; j < 3; ++j) sum -= m[row][j] * x[j];
            x[row] = sum / m[row][row];
        }
        return isFinite(x);
    }

    // ---- 3. the grid -----------------------------------------------------------------------

    void grid() {
        const ThrowPlanBudget& budget = mRequest.budget;
        const double azimuthSpacing = 2 * kPi / budget.azimuthSamples;
        const double elevationSpacing =
            budget.elevationSamples > 1 ? (kGridHighestElevation - kGridLowestElevation) / (budget.elevationSamples - 1)
                                        : 0.0;
        // Cells closer than this in direction fall into the same basin: keep the closer one.
        const double cosNeighbour = std::cos(1.5 * std::max(azimuthSpacing, elevationSpacing));
        for (std::uint32_t s = 0; s < budget.speedSamples; ++s) {
            const double speed =
                mMinSpeed + (mMaxSpeed - mMinSpeed) * (s + 1.0) / static_cast<double>(budget.speedSamples);
            for (std::uint32_t e = 0; e < budget.elevationSamples; ++e) {
                const double elevation = budget.elevationSamples > 1
                                             ? kGridLowestElevation + e * elevationSpacing
                                             : 0.5 * (kGridLowestElevation + kGridHighestElevation);
                for (std::uint32_t a = 0; a < budget.azimuthSamples; ++a) {
                    if (done()) return;
                    // Azimuth 0 is towards the target, then alternately left and right of it.
                    const double k = std::ceil(a / 2.0);
                    const double azimuth = (a % 2 == 1 ? 1.0 : -1.0) * k * azimuthSpacing;
                    const DVec3 direction =
                        std::cos(elevation) * (std::cos(azimuth) * mForward + std::sin(azimuth) * mSide) +
                        std::sin(elevation) * mUp;
                    Candidate c;
                    if (!evaluate(direction * speed, c, coarseGrid(), irrelevantCell())) return;
                    // A coarse cell that ends near the target is verified at once: it may be a
                    // plan as it is, and the grid can stop early as with fine cells.
                    if (c.coarse && c.distance <= 2 * mRadius && !evaluate(DVec3(c.velocity), c)) return;
                    keepCell(c, cosNeighbour, speed);
                }
            }
        }
    }

    /// The distance beyond which a new cell changes nothing in keepCell: once the list is full,
    /// a cell is kept only in place of a neighbour or of the farthest one, and only if closer.
    double irrelevantCell() const {
        const std::size_t capacity = std::min<std::size_t>(mRequest.budget.refinements, mCells.size());
        if (mCellCount < capacity) return kInfinity;
        double farthest = 0;
        for (std::size_t i = 0; i < mCellCount; ++i) farthest = std::max(farthest, mCells[i].distance);
        return farthest;
    }

    /// Keeps the closest cells, one per neighbourhood (direction and speed).
    void keepCell(const Candidate& c, double cosNeighbour, double speed) {
        if (!std::isfinite(c.distance)) return;
        const std::size_t capacity = std::min<std::size_t>(mRequest.budget.refinements, mCells.size());
        const double speedTolerance = 0.6 * (mMaxSpeed - mMinSpeed) / mRequest.budget.speedSamples + 1e-9;
        for (std::size_t i = 0; i < mCellCount; ++i) {
            Candidate& kept = mCells[i];
            const double keptSpeed = glm::length(kept.velocity);
            const bool neighbour = std::abs(keptSpeed - speed) <= speedTolerance &&
                                   glm::dot(kept.velocity, c.velocity) >= cosNeighbour * keptSpeed * speed &&
                                   kept.hasImpact == c.hasImpact &&
                                   (!c.hasImpact || glm::dot(kept.impactNormal, c.impactNormal) >= mCosDistinct);
            if (neighbour) {
                if (c.distance < kept.distance) kept = c;
                return;
            }
        }
        if (mCellCount < capacity) {
            mCells[mCellCount++] = c;
            return;
        }
        std::size_t worst = 0;
        for (std::size_t i = 1; i < mCellCount; ++i)
            if (mCells[i].distance > mCells[worst].distance) worst = i;
        if (c.distance < mCells[worst].distance) mCells[worst] = c;
    }

    const ThrowPlanRequest& mRequest;
    const CollisionWorld* mWorld;
    std::span<ThrowPlan> mPlans;
    std::span<TrajectoryPoint> mScratch;
    std::size_t mWanted;
    DVec3 mStart, mTarget;
    double mRadius, mFuse, mMaxSpeed, mMinSpeed, mCosDistinct;
    double mGravity = 0;
    DVec3 mUp{0, 1, 0}, mForward{0, 0, 1}, mSide{1, 0, 0};
    double mHorizontalDistance = 0, mHeightAboveTarget = 0;

    std::size_t mAccepted = 0;
    std::uint32_t mPredictions = 0;
    std::uint32_t mRefinements = 0;
    Candidate mClosest;
    std::array<Candidate, 5> mSeeds{};
    std::size_t mSeedCount = 0;
    std::array<Candidate, kMaxThrowPlanRefinements> mCells{};
    std::size_t mCellCount = 0;
};

}  // namespace

Status validateThrowPlanRequest(const ThrowPlanRequest& request) {
    if (!isFinite(request.start) || !isFinite(request.target) || !std::isfinite(request.acceptanceRadius) ||
        !std::isfinite(request.fuseTime) || !std::isfinite(request.maxSpeed) || !std::isfinite(request.minSpeed) ||
        !std::isfinite(request.distinctAngle))
        return Status::NonFiniteInput;
    if (Status s = validateProjectileSettings(request.settings); s != Status::Ok) return s;
    if (!(request.fuseTime > 0.0f)) return Status::InvalidFuse;
    if (!(request.acceptanceRadius > 0.0f)) return Status::InvalidRadius;
    if (!(request.maxSpeed > 0.0f) || !(request.minSpeed >= 0.0f) || !(request.minSpeed <= request.maxSpeed))
        return Status::InvalidSpeed;
    const ThrowPlanBudget& b = request.budget;
    if (request.maxPlans == 0 || b.azimuthSamples == 0 || b.elevationSamples == 0 || b.speedSamples == 0 ||
        b.refinements == 0 || b.refinements > kMaxThrowPlanRefinements || b.refinementPredictions == 0 ||
        b.maxPredictions == 0)
        return Status::InvalidIterations;
    if (!std::isfinite(request.budget.gridStep) || request.budget.gridStep < 0.0f) return Status::InvalidStep;
    if (b.maxTotalSteps == 0) return Status::InvalidIterations;
    if (steppedStepCount(request.fuseTime, request.settings.step) > request.settings.maxSteps)
        return Status::TooManySteps;
    if (throwPlanWork(request) > b.maxTotalSteps) return Status::TooManySteps;
    return Status::Ok;
}

std::uint64_t throwPlanWork(const ThrowPlanRequest& request) {
    // steppedStepCount is 0 for a bad fuse or step and saturates at 2^64 - 1: no overflow below
    // (a count over settings.maxSteps, a uint32, is refused before the product is used).
    const std::uint64_t steps = steppedStepCount(request.fuseTime, request.settings.step);
    const std::uint64_t predictions = request.budget.maxPredictions;
    if (steps != 0 && predictions > std::numeric_limits<std::uint64_t>::max() / steps)
        return std::numeric_limits<std::uint64_t>::max();
    return steps * predictions;
}

std::size_t throwPlanScratchSize(const ThrowPlanRequest& request) {
    if (validateThrowPlanRequest(request) != Status::Ok) return 0;
    return trajectoryCapacity(request.fuseTime, request.settings, 1);
}

Status planThrow(const ThrowPlanRequest& request, const CollisionWorld* world, std::span<ThrowPlan> plans,
                 std::span<TrajectoryPoint> scratch, ThrowPlanResult& out) {
    if (Status s = validateThrowPlanRequest(request); s != Status::Ok) return s;
    Planner planner(request, world, plans, scratch);
    if (!plans.empty()) planner.run();
    planner.finish(out);
    return Status::Ok;
}

Status predictThrowPlan(const ThrowPlanRequest& request, const ThrowPlan& plan, const CollisionWorld* world,
                        std::span<TrajectoryPoint> trajectory, ProjectileResult& out) {
    return predictProjectile(request.start, plan.launchVelocity, request.fuseTime, request.settings, world, trajectory,
                             out);
}

FORESIGHT_NAMESPACE_END
