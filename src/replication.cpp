#include <foresight/replication.h>

#include <foresight/orientation.h>

#include "internal.h"

FORESIGHT_NAMESPACE_BEGIN
using namespace detail;

namespace {

bool isPositiveFinite(float x) { return std::isfinite(x) && x > 0.0f; }

// The identity rotation in double, from named components.
DQuat identityD() { return glm::identity<DQuat>(); }

// The angle of the rotation between unit quaternions a and b (0 to pi): 2 atan2(|vec(r)|, |w|)
// with r = a^-1 b. atan2 keeps full precision at 0 and pi, where acos(|w|) loses half the digits
// (acos(1 - e) ~ sqrt(2e)); |w| makes q and -q the same rotation.
double rotationAngle(const DQuat& a, const DQuat& b) {
    const DQuat r = glm::conjugate(a) * b;
    const double vectorLength = std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z);
    return 2.0 * std::atan2(vectorLength, std::abs(r.w));
}

// The rotation `offset` (unit) scaled to `fraction` of its angle about the same axis, taking
// the short way (w >= 0). fraction 1 gives offset, 0 the identity.
DQuat scaleRotation(const DQuat& offset, double fraction) {
    const DQuat q = offset.w < 0.0 ? -offset : offset;
    const double vectorLength = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
    if (!(vectorLength > 0.0)) return identityD();
    const double halfAngle = std::atan2(vectorLength, q.w) * fraction;
    const double s = std::sin(halfAngle) / vectorLength;
    DQuat r;
    r.w = std::cos(halfAngle);
    r.x = q.x * s;
    r.y = q.y * s;
    r.z = q.z * s;
    return r;
}

// The world-axis velocity of an extrapolated result: body-axis models report it in the body
// axes of the result's orientation.
DVec3 worldVelocity(DeadReckoningAlgorithm algorithm, const DQuat& orientation, const DVec3& velocity) {
    return deadReckoningInBodyAxes(algorithm) ? orientation * velocity : velocity;
}

// The world-axis acceleration of an update's model at its extrapolated orientation and
// velocity: W models a (when used); B models R(q) (a + w x v_body), the derivative of R(q) v_body
// as the body turns at w (w applied by the R* models only).
DVec3 worldAcceleration(const DeadReckoningState& state, const DQuat& orientation, const DVec3& bodyOrWorldVelocity) {
    const DVec3 a = deadReckoningUsesAcceleration(state.algorithm) ? toD(state.acceleration) : DVec3(0.0);
    if (!deadReckoningInBodyAxes(state.algorithm)) return a;
    const DVec3 w = deadReckoningRotates(state.algorithm) ? toD(state.angularVelocity) : DVec3(0.0);
    return orientation * (a + glm::cross(w, bodyOrWorldVelocity));
}

// The age an extrapolation uses: >= 0 (a future-stamped update is shown as stamped, never
// extrapolated backwards), at most `limit` (then `held`).
double clampedAge(double time, double timestamp, float limit, bool& held) {
    double age = time - timestamp;
    held = false;
    if (!(age > 0.0)) return 0.0;
    if (age > static_cast<double>(limit)) {
        age = static_cast<double>(limit);
        held = true;
    }
    return age;
}

// The DIS validity of a state without normalising its quaternion: finite float components
// square to a finite double, and a non-zero one to a non-zero double (the smallest float
// denormal squared is 2e-90), so "length > 0 and finite" is "finite and not all zero".
bool quickValid(const DeadReckoningState& s) {
    const int algorithm = static_cast<int>(s.algorithm);
    if (algorithm < 1 || algorithm > kDeadReckoningAlgorithmCount) return false;
    if (!isFinite(s.position) || !isFinite(s.velocity) || !isFinite(s.acceleration) ||
        !isFinite(s.angularVelocity) || !isFinite(s.orientation))
        return false;
    const Quat& q = s.orientation;
    return q.w != 0.0f || q.x != 0.0f || q.y != 0.0f || q.z != 0.0f;
}

// predictDeadReckoning for the world-axis models and STATIC, for a state that quickValid
// accepted and a finite time >= 0: the same operations in the same order (so bit-identical),
// without the second normalisation of the validation, and with the identity written out for
// the fixed-orientation models (rotationFromAngularVelocityD(0, t) is exactly (1, +0, +0, +0)
// for every t >= 0: cos 0 = 1, +0 * (0.5 t) = +0).
bool predictWorldModel(const DeadReckoningState& state, float time, DeadReckoningResult& out) {
    const double t = time;
    const DVec3 p = toD(state.position);
    const DVec3 v = toD(state.velocity);
    const bool accelerates = deadReckoningUsesAcceleration(state.algorithm);
    const DVec3 a = accelerates ? toD(state.acceleration) : DVec3(0.0);
    const DQuat q = glm::normalize(toD(state.orientation));

    DVec3 position = p;
    DVec3 velocity = v;
    DQuat orientation = q;
    if (state.algorithm != DeadReckoningAlgorithm::Static) {
        position = p + (v * t + a * (0.5 * t * t));
        velocity = v + a * t;
        const DQuat rotation = deadReckoningRotates(state.algorithm)
                                   ? rotationFromAngularVelocityD(toD(state.angularVelocity), t)
                                   : identityD();
        orientation = glm::normalize(q * rotation);
    }
    DeadReckoningResult result;
    result.position = toR(position);
    result.velocity = toF(velocity);
    result.orientation = toF(orientation);
    if (!isFinite(result.position) || !isFinite(result.velocity) || !isFinite(result.orientation)) return false;
    out = result;
    return true;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Sender

Status validateSenderSettings(const SenderSettings& settings) {
    if (!isPositiveFinite(settings.positionThreshold) || !isPositiveFinite(settings.orientationThreshold) ||
        !isPositiveFinite(settings.heartbeat))
        return Status::InvalidSetting;
    return Status::Ok;
}

DeadReckoningSender::DeadReckoningSender(const SenderSettings& settings)
    : mSettings(settings), mSettingsStatus(validateSenderSettings(settings)) {}

void DeadReckoningSender::reset() {
    mLastSent = DeadReckoningState{};
    mLastSentTime = 0.0;
    mLastTime = 0.0;
    mHasSent = false;
    mHasTime = false;
}

Status DeadReckoningSender::update(double time, const DeadReckoningState& truth, SendDecision& decision) {
    if (mSettingsStatus != Status::Ok) return mSettingsStatus;
    if (!isFinite(time)) return Status::NonFiniteInput;
    if (Status s = validateDeadReckoningState(truth); s != Status::Ok) return s;
    if (mHasTime && time < mLastTime) return Status::TimeWentBackwards;

    SendDecision result;
    if (!mHasSent) {
        result.reasons = SendReasonFirst;
    } else {
        // What every receiver extrapolates: the same float age as the receiver's (time minus the
        // timestamp, in double, then rounded to float).
        const float age = static_cast<float>(time - mLastSentTime);
        DeadReckoningResult predicted;
        const DQuat trueOrientation = glm::normalize(toD(truth.orientation));
        double positionError;
        DQuat predictedOrientation;
        if (predictDeadReckoning(mLastSent, age, predicted) == Status::Ok) {
            positionError = glm::length(toD(predicted.position) - toD(truth.position));
            predictedOrientation = toD(predicted.orientation);
        } else {
            // The extrapolation overflows (an age beyond float range, or absurd velocities):
            // receivers are lost, send. The orientation alone never overflows.
            positionError = std::numeric_limits<double>::infinity();
            Quat q = mLastSent.orientation;
            if (deadReckoningRotates(mLastSent.algorithm) && std::isfinite(age))
                predictOrientation(mLastSent.orientation, mLastSent.angularVelocity, AngularFrame::Body, age, q);
            predictedOrientation = glm::normalize(toD(q));
        }
        const double orientationError = rotationAngle(predictedOrientation, trueOrientation);
        // Saturate at the largest float: the decision is reported, never infinity.
        result.positionError = static_cast<float>(std::min(positionError, double(std::numeric_limits<float>::max())));
        result.orientationError = static_cast<float>(orientationError);
        if (positionError >= static_cast<double>(mSettings.positionThreshold)) result.reasons |= SendReasonPosition;
        if (orientationError >= static_cast<double>(mSettings.orientationThreshold))
            result.reasons |= SendReasonOrientation;
        if (time - mLastSentTime >= static_cast<double>(mSettings.heartbeat)) result.reasons |= SendReasonHeartbeat;
        if (truth.algorithm != mLastSent.algorithm) result.reasons |= SendReasonAlgorithm;
    }
    if (result.send()) {
        mLastSent = truth;
        mLastSentTime = time;
        mHasSent = true;
    }
    mLastTime = time;
    mHasTime = true;
    decision = result;
    return Status::Ok;
}

// ---------------------------------------------------------------------------------------------
// Receiver

Status validateReceiverSettings(const ReceiverSettings& settings) {
    const int mode = static_cast<int>(settings.mode);
    const int smoothing = static_cast<int>(settings.smoothing);
    if (mode < 0 || mode > static_cast<int>(ReceiverMode::Interpolate)) return Status::InvalidSetting;
    if (smoothing < 0 || smoothing > static_cast<int>(Smoothing::ExponentialDecay)) return Status::InvalidSetting;
    if (!isPositiveFinite(settings.blendTime) || !isPositiveFinite(settings.decayHalfLife) ||
        !isPositiveFinite(settings.interpolationDelay))
        return Status::InvalidSetting;
    // Infinity disables these two; NaN compares false and is refused.
    if (!(settings.teleportDistance > 0.0f) || !(settings.extrapolationLimit >= 0.0f)) return Status::InvalidSetting;
    return Status::Ok;
}

DeadReckoningReceiver::DeadReckoningReceiver(const ReceiverSettings& settings)
    : mSettings(settings), mSettingsStatus(validateReceiverSettings(settings)) {}

void DeadReckoningReceiver::reset() {
    const ReceiverSettings settings = mSettings;
    *this = DeadReckoningReceiver(settings);
}

Status DeadReckoningReceiver::extrapolate(const Snapshot& update, double time, DeadReckoningResult& result,
                                          Pose& pose, bool& held) const {
    const double age = clampedAge(time, update.timestamp, mSettings.extrapolationLimit, held);
    const float ageF = static_cast<float>(age);
    // Only with an infinite extrapolationLimit: an age beyond float range.
    if (!std::isfinite(ageF)) return Status::NonFiniteResult;
    if (Status s = predictDeadReckoning(update.state, ageF, result); s != Status::Ok) return s;
    pose.position = toD(result.position);
    pose.orientation = toD(result.orientation);
    pose.velocity = worldVelocity(update.state.algorithm, pose.orientation, toD(result.velocity));
    return Status::Ok;
}

Status DeadReckoningReceiver::showExtrapolated(double time, ReceivedPose& out, Pose& shown) const {
    DeadReckoningResult result;
    Pose target;
    bool held = false;
    if (Status s = extrapolate(mCurrent, time, result, target, held); s != Status::Ok) return s;

    ReceivedPose pose;
    pose.held = held;
    // The smoothing's own elapsed time: a time before the correction started (a replay) shows
    // its start.
    const double elapsed = std::max(0.0, time - mCorrectionStart);
    const Smoothing smoothing = mSettings.smoothing;
    bool blended = false;
    if (mCorrecting && smoothing != Smoothing::Snap) {
        if (smoothing == Smoothing::ExponentialDecay) {
            // 2^-elapsed/halfLife: finite for any elapsed, 0 after ~1075 half-lives.
            const double remaining = std::exp2(-elapsed / static_cast<double>(mSettings.decayHalfLife));
            if (remaining > 0.0) {
                shown.position = target.position + mCurrentOffset * remaining;
                shown.velocity = target.velocity;
                shown.orientation = glm::normalize(scaleRotation(mCurrentRotationOffset, remaining) * target.orientation);
                blended = true;
            }
        } else {
            const double alpha = elapsed / static_cast<double>(mSettings.blendTime);
            // alpha >= 1: the blend is over and the target is shown as is (exactly).
            if (alpha < 1.0) {
                if (smoothing == Smoothing::LinearBlend) {
                    DeadReckoningResult previousResult;
                    Pose previous;
                    bool previousHeld = false;
                    // Fails only with an infinite extrapolationLimit and an overflowing age:
                    // then the target is shown as is.
                    if (extrapolate(mPrevious, time, previousResult, previous, previousHeld) == Status::Ok) {
                        const DVec3 from = previous.position + mPreviousOffset;
                        const DQuat fromOrientation = glm::normalize(mPreviousRotationOffset * previous.orientation);
                        shown.position = from + (target.position - from) * alpha;
                        shown.velocity = previous.velocity + (target.velocity - previous.velocity) * alpha;
                        shown.orientation = glm::normalize(glm::slerp(fromOrientation, target.orientation, alpha));
                        blended = true;
                    }
                } else {  // ProjectiveVelocityBlending (Murphy)
                    const DVec3& p0 = mShownAtCorrection.position;
                    const DVec3& v0 = mShownAtCorrection.velocity;
                    const DVec3 blendedVelocity = v0 + (mCurrentVelocity - v0) * alpha;
                    const DVec3 projected =
                        p0 + blendedVelocity * elapsed + mCurrentAcceleration * (0.5 * elapsed * elapsed);
                    shown.position = projected + (target.position - projected) * alpha;
                    const DVec3 projectedVelocity = blendedVelocity + mCurrentAcceleration * elapsed;
                    shown.velocity = projectedVelocity + (target.velocity - projectedVelocity) * alpha;
                    // From the shown orientation carried along by the new update's rotation, to
                    // the new update's orientation.
                    const DQuat fromOrientation = glm::normalize(mCurrentRotationOffset * target.orientation);
                    shown.orientation = glm::normalize(glm::slerp(fromOrientation, target.orientation, alpha));
                    blended = true;
                }
            }
        }
    }
    if (blended) {
        pose.position = toR(shown.position);
        pose.velocity = toF(shown.velocity);
        pose.orientation = toF(shown.orientation);
        if (!isFinite(pose.position) || !isFinite(pose.velocity) || !isFinite(pose.orientation))
            return Status::NonFiniteResult;
    } else {
        shown = target;
        pose.position = result.position;  // the extrapolation exactly, bit for bit
        pose.orientation = result.orientation;
        pose.velocity = deadReckoningInBodyAxes(mCurrent.state.algorithm) ? toF(target.velocity) : result.velocity;
        if (!isFinite(pose.velocity)) return Status::NonFiniteResult;
    }
    out = pose;
    return Status::Ok;
}

Status DeadReckoningReceiver::showInterpolated(double renderTime, ReceivedPose& out) const {
    const Snapshot& oldest = buffered(0);
    const Snapshot& newest = buffered(mBufferCount - 1);
    DeadReckoningResult result;
    Pose a;
    bool held = false;
    ReceivedPose pose;
    if (renderTime <= oldest.timestamp || renderTime >= newest.timestamp) {
        // Before the oldest: hold it (age 0). After the newest: extrapolate it, up to the limit.
        const Snapshot& update = renderTime <= oldest.timestamp ? oldest : newest;
        if (Status s = extrapolate(update, renderTime, result, a, held); s != Status::Ok) return s;
        pose.position = result.position;
        pose.orientation = result.orientation;
        pose.velocity = toF(a.velocity);
        pose.held = held;
    } else {
        // The bracketing pair: from = the newest at or before renderTime, to = the next one.
        std::size_t next = mBufferCount - 1;
        while (next > 1 && buffered(next - 1).timestamp > renderTime) --next;
        const Snapshot& from = buffered(next - 1);
        const Snapshot& to = buffered(next);
        Pose b;
        DeadReckoningResult resultB;
        if (Status s = extrapolate(from, from.timestamp, result, a, held); s != Status::Ok) return s;
        if (Status s = extrapolate(to, to.timestamp, resultB, b, held); s != Status::Ok) return s;
        if (glm::length(b.position - a.position) > static_cast<double>(mSettings.teleportDistance)) {
            // A teleport between the two: no sweep through the level; `from` moves on its own
            // model until `to` is due.
            if (Status s = extrapolate(from, renderTime, result, a, held); s != Status::Ok) return s;
            pose.position = result.position;
            pose.orientation = result.orientation;
            pose.velocity = toF(a.velocity);
            pose.held = held;
        } else {
            // Linear in position and velocity, slerp in orientation (Source's default; a
            // Hermite curve through the velocities would overshoot on noisy updates).
            const double alpha = (renderTime - from.timestamp) / (to.timestamp - from.timestamp);
            pose.position = toR(a.position + (b.position - a.position) * alpha);
            pose.velocity = toF(a.velocity + (b.velocity - a.velocity) * alpha);
            pose.orientation = toF(glm::normalize(glm::slerp(a.orientation, b.orientation, alpha)));
        }
    }
    if (!isFinite(pose.position) || !isFinite(pose.velocity) || !isFinite(pose.orientation))
        return Status::NonFiniteResult;
    out = pose;
    return Status::Ok;
}

Status DeadReckoningReceiver::sample(double time, ReceivedPose& out) {
    if (mSettingsStatus != Status::Ok) return mSettingsStatus;
    if (!isFinite(time)) return Status::NonFiniteInput;
    ReceivedPose pose;
    if (mSettings.mode == ReceiverMode::Interpolate) {
        const double renderTime = time - static_cast<double>(mSettings.interpolationDelay);
        mLastRenderTime = renderTime;
        mHasRendered = true;
        if (mBufferCount == 0) return Status::NoUpdate;
        if (Status s = showInterpolated(renderTime, pose); s != Status::Ok) return s;
    } else {
        if (!mHasCurrent) return Status::NoUpdate;
        Pose shown;
        if (Status s = showExtrapolated(time, pose, shown); s != Status::Ok) return s;
    }
    if (pose.held) ++mCounters.held;
    out = pose;
    return Status::Ok;
}

UpdateOutcome DeadReckoningReceiver::receiveInterpolated(double timestamp, const DeadReckoningState& state) {
    if (mHasRendered && timestamp < mLastRenderTime) {
        ++mCounters.outOfOrder;
        return UpdateOutcome::OutOfOrder;
    }
    // Where it goes: after every buffered update stamped earlier (usually at the end).
    std::size_t index = mBufferCount;
    while (index > 0 && buffered(index - 1).timestamp >= timestamp) {
        if (buffered(index - 1).timestamp == timestamp) {
            ++mCounters.duplicates;
            return UpdateOutcome::Duplicate;
        }
        --index;
    }
    if (mBufferCount == kBufferCapacity) {
        if (index == 0) {  // older than every one of a full buffer: it would be forgotten at once
            ++mCounters.outOfOrder;
            return UpdateOutcome::OutOfOrder;
        }
        mBufferStart = (mBufferStart + 1) % kBufferCapacity;  // forget the oldest
        --mBufferCount;
        --index;
    }
    for (std::size_t i = mBufferCount; i > index; --i)
        mBuffer[(mBufferStart + i) % kBufferCapacity] = mBuffer[(mBufferStart + i - 1) % kBufferCapacity];
    mBuffer[(mBufferStart + index) % kBufferCapacity] = Snapshot{timestamp, state};
    ++mBufferCount;
    if (index > 0) {
        const DVec3 jump = toD(state.position) - toD(buffered(index - 1).state.position);
        if (glm::length(jump) > static_cast<double>(mSettings.teleportDistance)) {
            ++mCounters.teleports;
            ++mCounters.snaps;
        }
    }
    ++mCounters.accepted;
    return UpdateOutcome::Buffered;
}

UpdateOutcome DeadReckoningReceiver::receive(double timestamp, const DeadReckoningState& state, double receiveTime) {
    if (mSettingsStatus != Status::Ok || !isFinite(timestamp) || !isFinite(receiveTime) ||
        validateDeadReckoningState(state) != Status::Ok) {
        ++mCounters.invalid;
        return UpdateOutcome::Invalid;
    }
    if (mSettings.mode == ReceiverMode::Interpolate) {
        const UpdateOutcome outcome = receiveInterpolated(timestamp, state);
        if (outcome == UpdateOutcome::Buffered && timestamp > receiveTime) ++mCounters.futureUpdates;
        return outcome;
    }

    if (mHasCurrent && timestamp <= mCurrent.timestamp) {
        if (timestamp == mCurrent.timestamp) {
            ++mCounters.duplicates;
            return UpdateOutcome::Duplicate;
        }
        ++mCounters.outOfOrder;
        return UpdateOutcome::OutOfOrder;
    }
    if (timestamp > receiveTime) ++mCounters.futureUpdates;
    ++mCounters.accepted;

    const Snapshot update{timestamp, state};
    // What is shown now, and where the new update puts the entity now.
    ReceivedPose shownPose;
    Pose shown;
    Pose target;
    DeadReckoningResult targetResult;
    bool targetHeld = false;
    bool snap = !mHasCurrent || mSettings.smoothing == Smoothing::Snap;
    if (!snap) {
        // Either fails only with an infinite extrapolationLimit and an overflowing age: snap.
        snap = showExtrapolated(receiveTime, shownPose, shown) != Status::Ok ||
               extrapolate(update, receiveTime, targetResult, target, targetHeld) != Status::Ok;
        if (!snap && glm::length(shown.position - target.position) > static_cast<double>(mSettings.teleportDistance)) {
            snap = true;
            ++mCounters.teleports;
        }
    }
    if (snap) {
        mCurrent = update;
        mHasCurrent = true;
        mCorrecting = false;
        ++mCounters.snaps;
        return UpdateOutcome::Snapped;
    }

    mPrevious = mCurrent;
    mCurrent = update;
    mCorrecting = true;
    mCorrectionStart = receiveTime;
    mShownAtCorrection = shown;
    mCurrentOffset = shown.position - target.position;
    mCurrentRotationOffset = glm::normalize(shown.orientation * glm::conjugate(target.orientation));
    mCurrentVelocity = target.velocity;
    mCurrentAcceleration =
        targetHeld ? DVec3(0.0) : worldAcceleration(state, target.orientation, toD(targetResult.velocity));
    // LinearBlend blends from the previous update's extrapolation; if a blend was still running
    // the shown pose is off that extrapolation, and the offset between them at this instant
    // rides along so that the shown pose does not jump (it is zero after a finished blend).
    DeadReckoningResult previousResult;
    Pose previous;
    bool previousHeld = false;
    if (extrapolate(mPrevious, receiveTime, previousResult, previous, previousHeld) == Status::Ok) {
        mPreviousOffset = shown.position - previous.position;
        mPreviousRotationOffset = glm::normalize(shown.orientation * glm::conjugate(previous.orientation));
    } else {
        mPreviousOffset = DVec3(0.0);
        mPreviousRotationOffset = identityD();
    }
    return UpdateOutcome::Accepted;
}

// ---------------------------------------------------------------------------------------------
// Batch

std::size_t predictDeadReckoningBatch(std::span<const DeadReckoningState> states, std::span<const double> timestamps,
                                      double time, std::span<DeadReckoningResult> out) {
    const std::size_t count = std::min({states.size(), timestamps.size(), out.size()});
    std::size_t refused = states.size() - count;
    for (std::size_t i = 0; i < count; ++i) {
        const DeadReckoningState& state = states[i];
        const double age = time - timestamps[i];
        // NaN age (NaN time or timestamp) is refused by predictDeadReckoning's time check.
        // An entity stamped later than `time` is shown at age 0; a NaN age (NaN time or
        // timestamp) stays NaN and is refused by predictDeadReckoning's time check.
        const float ageF = age <= 0.0 ? 0.0f : static_cast<float>(age);
        bool ok;
        if (quickValid(state) && std::isfinite(ageF) && !deadReckoningInBodyAxes(state.algorithm)) {
            ok = predictWorldModel(state, ageF, out[i]);
        } else {
            ok = predictDeadReckoning(state, ageF, out[i]) == Status::Ok;
        }
        if (!ok) {
            out[i].position = state.position;
            out[i].velocity = state.velocity;
            out[i].orientation = state.orientation;
            ++refused;
        }
    }
    return refused;
}

FORESIGHT_NAMESPACE_END
