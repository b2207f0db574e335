#include <foresight/replication.h>

#include <foresight/orientation.h>

#include "internal.h"
#include "replication_batch.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>
#include <type_traits>

#if defined(__linux__)
#include <sys/mman.h>
#endif

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
    if (!isFinite(s.position) || !isFinite(s.velocity) || !isFinite(s.acceleration) || !isFinite(s.angularVelocity) ||
        !isFinite(s.orientation))
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
    // Infinity disables these; NaN compares false and is refused.
    if (!(settings.teleportDistance > 0.0f) || !(settings.extrapolationLimit >= 0.0f) ||
        !(settings.maxFutureSkew >= 0.0f) || !(settings.restartAfter > 0.0f))
        return Status::InvalidSetting;
    return Status::Ok;
}

DeadReckoningReceiver::DeadReckoningReceiver(const ReceiverSettings& settings)
    : mSettings(settings), mSettingsStatus(validateReceiverSettings(settings)) {}

void DeadReckoningReceiver::reset() {
    const ReceiverSettings settings = mSettings;
    *this = DeadReckoningReceiver(settings);
}

Status DeadReckoningReceiver::extrapolate(const Snapshot& update, double time, DeadReckoningResult& result, Pose& pose,
                                          bool& held) const {
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
                shown.orientation =
                    glm::normalize(scaleRotation(mCurrentRotationOffset, remaining) * target.orientation);
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

bool DeadReckoningReceiver::isTeleport(const Snapshot& from, const Snapshot& to, DeadReckoningResult& predicted) const {
    // The older update's own prediction at the newer one's timestamp, without the
    // extrapolation limit (the sender's view of what receivers show): a threshold sender's
    // updates land within its threshold of it, a teleport far from it.
    const auto age = static_cast<float>(to.timestamp - from.timestamp);
    if (!std::isfinite(age) || predictDeadReckoning(from.state, age, predicted) != Status::Ok) return true;
    return glm::length(toD(to.state.position) - toD(predicted.position)) >
           static_cast<double>(mSettings.teleportDistance);
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
        DeadReckoningResult atTo;  // from's prediction at to's timestamp
        if (isTeleport(from, to, atTo)) {
            // A teleport between the two: no sweep through the level; `from` moves on its own
            // model until `to` is due.
            if (Status s = extrapolate(from, renderTime, result, a, held); s != Status::Ok) return s;
            pose.position = result.position;
            pose.orientation = result.orientation;
            pose.velocity = toF(a.velocity);
            pose.held = held;
        } else {
            // The older update's own prediction at the render time, plus the correction that
            // takes its prediction at the newer update's timestamp onto the newer update,
            // growing linearly (no extrapolation limit here: the newer update says where the
            // entity went). For updates that agree with each other's models (fixed-rate
            // snapshots of straight motion, STATIC updates) this is linear interpolation, as
            // Source does; for sparse updates of a turning vehicle it follows the model's arc
            // instead of the chord. No Hermite curve through the velocities: it would
            // overshoot on noisy updates.
            Pose b;
            DeadReckoningResult resultB;
            if (Status s = extrapolate(to, to.timestamp, resultB, b, held); s != Status::Ok) return s;
            const double alpha = (renderTime - from.timestamp) / (to.timestamp - from.timestamp);
            DeadReckoningResult now;
            if (Status s = predictDeadReckoning(from.state, static_cast<float>(renderTime - from.timestamp), now);
                s != Status::Ok)
                return s;
            const DQuat nowOrientation = toD(now.orientation);
            const DQuat atToOrientation = toD(atTo.orientation);
            const DVec3 nowVelocity = worldVelocity(from.state.algorithm, nowOrientation, toD(now.velocity));
            const DVec3 atToVelocity = worldVelocity(from.state.algorithm, atToOrientation, toD(atTo.velocity));
            pose.position = toR(toD(now.position) + (b.position - toD(atTo.position)) * alpha);
            pose.velocity = toF(nowVelocity + (b.velocity - atToVelocity) * alpha);
            // The rotation from the prediction to the newer update (world frame), a fraction
            // alpha of it applied to the prediction now.
            DQuat correction = glm::normalize(b.orientation * glm::conjugate(atToOrientation));
            if (correction.w < 0.0) correction = -correction;  // the short way
            pose.orientation = toF(glm::normalize(glm::slerp(identityD(), correction, alpha) * nowOrientation));
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
        applySwitchOffset(renderTime, pose);
    } else {
        if (!mHasCurrent) return Status::NoUpdate;
        Pose shown;
        if (Status s = showExtrapolated(time, pose, shown); s != Status::Ok) return s;
    }
    if (pose.held) ++mCounters.held;
    out = pose;
    return Status::Ok;
}

void DeadReckoningReceiver::applySwitchOffset(double renderTime, ReceivedPose& pose) const {
    if (!mHasSwitchOffset) return;
    const double progress = (renderTime - mSwitchStart) / static_cast<double>(mSettings.blendTime);
    const double remaining = 1.0 - std::clamp(progress, 0.0, 1.0);
    if (remaining <= 0.0) return;
    pose.position = toR(toD(pose.position) + mSwitchOffset * remaining);
    const DQuat turn = glm::slerp(identityD(), mSwitchRotationOffset, remaining);
    pose.orientation = toF(glm::normalize(turn * toD(pose.orientation)));
}

UpdateOutcome DeadReckoningReceiver::receiveInterpolated(double timestamp, const DeadReckoningState& state) {
    if (mHasRendered && timestamp < mLastRenderTime) {
        ++mCounters.outOfOrder;
        return UpdateOutcome::OutOfOrder;
    }
    // An update can change what the last render time shows: when the buffer had run dry (the
    // newest update was being extrapolated) and this one is newer, the frames from now on
    // interpolate towards it instead; a late update can land in the pair being shown. The
    // difference at the last render time fades out linearly over blendTime instead of popping
    // (a teleport still snaps).
    ReceivedPose beforeRaw;
    const bool rendered =
        mHasRendered && mBufferCount > 0 && showInterpolated(mLastRenderTime, beforeRaw) == Status::Ok;
    ReceivedPose before = beforeRaw;
    if (rendered) applySwitchOffset(mLastRenderTime, before);
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
    DeadReckoningResult predicted;
    const bool teleport = index > 0 && isTeleport(buffered(index - 1), buffered(index), predicted);
    if (teleport) {
        ++mCounters.teleports;
        ++mCounters.snaps;
    }
    ReceivedPose after;
    if (rendered && !teleport && showInterpolated(mLastRenderTime, after) == Status::Ok &&
        (after.position != beforeRaw.position || after.orientation != beforeRaw.orientation)) {
        const DVec3 offset = toD(before.position) - toD(after.position);
        if (glm::length(offset) <= static_cast<double>(mSettings.teleportDistance)) {
            mSwitchOffset = offset;
            DQuat rotation = glm::normalize(toD(before.orientation) * glm::conjugate(toD(after.orientation)));
            if (rotation.w < 0.0) rotation = -rotation;  // the short way
            mSwitchRotationOffset = rotation;
            mSwitchStart = mLastRenderTime;
            mHasSwitchOffset = true;
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
    if (timestamp - receiveTime > static_cast<double>(mSettings.maxFutureSkew)) {
        ++mCounters.tooFarAhead;
        return UpdateOutcome::TooFarAhead;
    }
    if (mSettings.mode == ReceiverMode::Interpolate) {
        const UpdateOutcome outcome = receiveInterpolated(timestamp, state);
        if (outcome == UpdateOutcome::Buffered && timestamp > receiveTime) ++mCounters.futureUpdates;
        return outcome;
    }

    bool restart = false;
    if (mHasCurrent && timestamp <= mCurrent.timestamp) {
        if (timestamp == mCurrent.timestamp) {
            ++mCounters.duplicates;
            return UpdateOutcome::Duplicate;
        }
        if (!(receiveTime - mLastAcceptedAt > static_cast<double>(mSettings.restartAfter))) {
            ++mCounters.outOfOrder;
            return UpdateOutcome::OutOfOrder;
        }
        // Silence for restartAfter, then an older timestamp: the sender's clock started again.
        restart = true;
        ++mCounters.clockRestarts;
    }
    mLastAcceptedAt = receiveTime;
    if (timestamp > receiveTime) ++mCounters.futureUpdates;
    ++mCounters.accepted;

    const Snapshot update{timestamp, state};
    // What is shown now, and where the new update puts the entity now.
    ReceivedPose shownPose;
    Pose shown;
    Pose target;
    DeadReckoningResult targetResult;
    bool targetHeld = false;
    bool snap = !mHasCurrent || restart || mSettings.smoothing == Smoothing::Snap;
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

// ---------------------------------------------------------------------------------------------
// Prepared extrapolation

namespace {

enum : std::uint8_t { kKernelStatic = 0, kKernelWorld = 1, kKernelBody = 2 };

// sin, cos and sin(h)/h of h >= 0 (the half angle |w| t / 2), in float after a double range
// reduction; pure arithmetic (no libm below kReductionLimit), so the same everywhere.
struct SinCos {
    float sine;
    float cosine;
    float sinc;  // sin(h) / h, 1 at h = 0
};

// Cody-Waite reduction by pi/2 (fdlibm's split: kPiOver2Head has 33 significant bits, so
// k * kPiOver2Head is exact for k < 2^20 and h - k * kPiOver2Head is exact; the tail adds the
// next 53 bits): |r| <= pi/4 within ~1e-17 absolute.
constexpr double kTwoOverPi = 6.36619772367581382433e-01;
constexpr double kPiOver2Head = 1.57079632673412561417e+00;
constexpr double kPiOver2Tail = 6.07710050650619224932e-11;
constexpr double kReductionLimit = 823549.6;  // 2^19 pi/2: k stays below 2^20

// Cephes sinf/cosf minimax polynomials of r in [-pi/4, pi/4] (about 1 ulp in float):
// sin r = r + r sinPoly, cos r = c.
inline void sinCosPolynomials(float r, float& sinPoly, float& sine, float& cosine) {
    const float z = r * r;
    sinPoly = ((-1.9515295891e-4f * z + 8.3321608736e-3f) * z - 1.6666654611e-1f) * z;
    sine = r + r * sinPoly;
    cosine =
        ((2.443315711809948e-5f * z - 1.388731625493765e-3f) * z + 4.166664568298827e-2f) * z * z - 0.5f * z + 1.0f;
}

// sin, cos and sin(h)/h of 0 <= h < kReductionLimit: the Cody-Waite reduction, then the
// quadrant by arithmetic, not a switch, so that loops over it vectorise.
inline void sinCosReduced(double h, float& sine, float& cosine, float& sinc) {
    const auto k = static_cast<std::int32_t>(h * kTwoOverPi + 0.5);
    const double kd = static_cast<double>(k);
    const auto r = static_cast<float>((h - kd * kPiOver2Head) - kd * kPiOver2Tail);
    float sinPoly, s, c;
    sinCosPolynomials(r, sinPoly, s, c);
    const bool odd = (k & 1) != 0;
    const float sineSign = (k & 2) != 0 ? -1.0f : 1.0f;
    const float cosineSign = ((k + 1) & 2) != 0 ? -1.0f : 1.0f;
    sine = (odd ? c : s) * sineSign;
    cosine = (odd ? s : c) * cosineSign;
    // k = 0: h = r and sin(r)/r = 1 + the polynomial, exact at 0; otherwise h >= pi/4.
    const float hf = k == 0 ? 1.0f : static_cast<float>(h);
    sinc = k == 0 ? 1.0f + sinPoly : sine / hf;
}

// The same for h * kTwoOverPi + 0.5 < 1 (k = 0, h < pi/4 about): then the reduction is
// exact (r = h rounded to float) and the results are sinCosReduced's bit for bit, without
// its double arithmetic and quadrant selection.
inline void sinCosFirstQuadrant(double h, float& sine, float& cosine, float& sinc) {
    float sinPoly;
    sinCosPolynomials(static_cast<float>(h), sinPoly, sine, cosine);
    sinc = 1.0f + sinPoly;
}

SinCos sinCosHalfAngle(double h) {
    SinCos out;
    if (!(h < kReductionLimit)) {
        // Beyond any sensible age (|w| t > 1.6e6 rad): libm's double sin/cos, as
        // predictDeadReckoning uses.
        out.sine = static_cast<float>(std::sin(h));
        out.cosine = static_cast<float>(std::cos(h));
        out.sinc = static_cast<float>(std::sin(h) / h);
        return out;
    }
    // sinCosReduced's results, with a switch and a branch: cheaper where nothing vectorises.
    const auto k = static_cast<std::int32_t>(h * kTwoOverPi + 0.5);
    const double kd = static_cast<double>(k);
    const auto r = static_cast<float>((h - kd * kPiOver2Head) - kd * kPiOver2Tail);
    float sinPoly, s, c;
    sinCosPolynomials(r, sinPoly, s, c);
    switch (k & 3) {
        case 0:
            out.sine = s;
            out.cosine = c;
            break;
        case 1:
            out.sine = c;
            out.cosine = -s;
            break;
        case 2:
            out.sine = -s;
            out.cosine = -c;
            break;
        default:
            out.sine = -c;
            out.cosine = s;
            break;
    }
    out.sinc = k == 0 ? 1.0f + sinPoly : out.sine / static_cast<float>(h);
    return out;
}

// The receiver's age of an update stamped `timestamp` (>= 0, at most `limit`), clamped in
// double and rounded to float once; branch-free.
inline float frameAge(double time, double timestamp, double limit) {
    double age = time - timestamp;
    age = age > 0.0 ? age : 0.0;
    age = age < limit ? age : limit;
    return static_cast<float>(age);
}

// The orientation q exp(w t) = A cos h + B sin h (A = q, B = q (0, u)), then one Newton step
// towards unit length (1/sqrt(n2) ~ (3 - n2) / 2 for n2 = 1 + O(1e-7): error O(1e-14), no
// sqrt). Plain float arithmetic on values, so that loops over it vectorise.
inline Quat turnedOrientation(const Quat& a, const Quat& b, float cosine, float sine) {
    const float w = a.w * cosine + b.w * sine;
    const float x = a.x * cosine + b.x * sine;
    const float y = a.y * cosine + b.y * sine;
    const float z = a.z * cosine + b.z * sine;
    const float f = 1.5f - 0.5f * (w * w + x * x + y * y + z * z);
    Quat o;
    o.w = w * f;
    o.x = x * f;
    o.y = y * f;
    o.z = z * f;
    return o;
}

// The Taylor series of (x - sin x) / x^3 in z = x^2 (the first omitted term, x^12 / 15!, is
// below 3e-9 at x = 2).
inline float xMinusSinSeriesF(float z) {
    return 1.0f / 6.0f -
           z * (1.0f / 120.0f -
                z * (1.0f / 5040.0f - z * (1.0f / 362880.0f - z * (1.0f / 39916800.0f - z / 6227020800.0f))));
}

// (x - sin x) / x^3 for x >= 0 in float, with sin x given: Taylor series below 2 (the direct
// form cancels there; the first omitted term, x^12 / 15!, is below 3e-9 at 2), direct above.
float xMinusSinOverCubeF(float x, float sinX) {
    const float z = x * x;
    if (x < 2.0f) return xMinusSinSeriesF(z);
    return (x - sinX) / (z * x);
}

DVec3 rotateD(const DQuat& q, const DVec3& v) {
    // v + 2 w (u x v) + 2 u x (u x v), u = vec(q): q v q^-1 for a unit q.
    const DVec3 u(q.x, q.y, q.z);
    const DVec3 c = 2.0 * glm::cross(u, v);
    return v + q.w * c + glm::cross(u, c);
}

}  // namespace

namespace detail {
// The implementation's access to PreparedDeadReckoning's members.
struct PreparedAccess {
    static bool extrapolateOne(const PreparedDeadReckoning& e, double time, double limit, DeadReckoningResult& result);
};
}  // namespace detail

Status prepareDeadReckoning(const DeadReckoningState& state, double timestamp, PreparedDeadReckoning& out) {
    if (Status s = validateDeadReckoningState(state); s != Status::Ok) return s;
    if (!isFinite(timestamp)) return Status::NonFiniteInput;
    const DeadReckoningAlgorithm algorithm = state.algorithm;
    const DQuat q = glm::normalize(toD(state.orientation));
    const DVec3 w = deadReckoningRotates(algorithm) ? toD(state.angularVelocity) : DVec3(0.0);
    const double rate = glm::length(w);
    const DVec3 axis = rate > 0.0 ? w / rate : DVec3(0.0);

    PreparedDeadReckoning p;
    p.mPosition = state.position;
    p.mTimestamp = timestamp;
    // The half angle is h = (0.5 rate) t, the product predictDeadReckoning computes.
    p.mHalfRate = 0.5 * rate;
    p.mVelocity = state.velocity;
    p.mAcceleration = deadReckoningUsesAcceleration(algorithm) ? state.acceleration : Vec3(0.0f);
    p.mOrientation = toF(q);
    // q exp(w t) = q (cos h, u sin h) = A cos h + B sin h with B = q (0, u).
    const DVec3 qv(q.x, q.y, q.z);
    DQuat b;
    b.w = -glm::dot(qv, axis);
    const DVec3 bv = q.w * axis + glm::cross(qv, axis);
    b.x = bv.x;
    b.y = bv.y;
    b.z = bv.z;
    p.mAxisTerm = toF(b);
    p.mAxis = toF(axis);
    p.mKernel = algorithm == DeadReckoningAlgorithm::Static ? kKernelStatic
                : deadReckoningInBodyAxes(algorithm)        ? kKernelBody
                                                            : kKernelWorld;
    p.mAlgorithm = algorithm;
    out = p;
    return Status::Ok;
}

// One prepared entity (the scalar form; DeadReckoningBatch's fallback). False when the result
// overflows: `result` is then the update as given.
bool detail::PreparedAccess::extrapolateOne(const PreparedDeadReckoning& e, double time, double limit,
                                            DeadReckoningResult& result) {
    if (e.mKernel == kKernelStatic) {
        result.position = e.mPosition;
        result.velocity = e.mVelocity;
        result.orientation = e.mOrientation;
        return true;
    }
    const double t = frameAge(time, e.mTimestamp, limit);

    const DVec3 p = toD(e.mPosition);
    const DVec3 v = toD(e.mVelocity);
    const DVec3 a = toD(e.mAcceleration);
    const SinCos sc = sinCosHalfAngle(e.mHalfRate * t);

    // turnedOrientation's operations, written out: through the helper this scalar path measured
    // 12% slower (bench_replication's Prepared), the vectorised passes the same.
    Quat o;
    o.w = e.mOrientation.w * sc.cosine + e.mAxisTerm.w * sc.sine;
    o.x = e.mOrientation.x * sc.cosine + e.mAxisTerm.x * sc.sine;
    o.y = e.mOrientation.y * sc.cosine + e.mAxisTerm.y * sc.sine;
    o.z = e.mOrientation.z * sc.cosine + e.mAxisTerm.z * sc.sine;
    const float n2 = o.w * o.w + o.x * o.x + o.y * o.y + o.z * o.z;
    const float f = 1.5f - 0.5f * n2;
    o.w *= f;
    o.x *= f;
    o.y *= f;
    o.z *= f;

    DVec3 position;
    if (e.mKernel == kKernelWorld) {
        // predictDeadReckoning's operations, in its order: bit-identical.
        position = p + (v * t + a * (0.5 * t * t));
    } else {
        // The body-axis integrals (see predictDeadReckoning) with unit axis u, x = |w| t:
        //   R1 v = t sinc(x) v + t x c1 (u x v) + t x^2 e (u.v) u,
        //   R2 a = t^2 (sinc x - c1) a + t^2 x (c1 - e) (u x a) + t^2 (1/2 - sinc x + c1) (u.a) u,
        // c1 = (1 - cos x)/x^2 = sinc(x/2)^2 / 2, e = (x - sin x)/x^3. Each coefficient is
        // a bounded function of x times t or t^2, so float errors of a few ulps in the
        // functions are errors relative to |v| t and |a| t^2 (the contract).
        const float sincHalf = sc.sinc;
        const float sincX = sincHalf * sc.cosine;  // sin(2h) / 2h
        const auto x = static_cast<float>(2.0 * e.mHalfRate * t);
        const float c1 = 0.5f * sincHalf * sincHalf;
        const float ex = xMinusSinOverCubeF(x, 2.0f * sc.sine * sc.cosine);
        const double xd = x;
        const DVec3 u = toD(e.mAxis);
        const double t2 = t * t;
        const DVec3 body = (t * sincX) * v + (t * xd * c1) * glm::cross(u, v) +
                           (t * xd * xd * ex * glm::dot(u, v)) * u + (t2 * (sincX - c1)) * a +
                           (t2 * xd * (c1 - ex)) * glm::cross(u, a) + (t2 * (0.5 - sincX + c1) * glm::dot(u, a)) * u;
        position = p + rotateD(toD(e.mOrientation), body);
    }
    const RVec3 positionR = toR(position);
    const Vec3 velocity = toF(v + a * t);
    if (!isFinite(positionR) || !isFinite(velocity)) {
        result.position = e.mPosition;
        result.velocity = e.mVelocity;
        result.orientation = e.mOrientation;
        return false;
    }
    result.position = positionR;
    result.velocity = velocity;
    result.orientation = o;
    return true;
}

std::size_t extrapolateDeadReckoning(std::span<const PreparedDeadReckoning> entities, double time,
                                     float extrapolationLimit, std::span<DeadReckoningResult> out) {
    if (!isFinite(time) || !(extrapolationLimit >= 0.0f)) return entities.size();
    const std::size_t count = std::min(entities.size(), out.size());
    std::size_t refused = entities.size() - count;
    const double limit = static_cast<double>(extrapolationLimit);
    for (std::size_t i = 0; i < count; ++i)
        if (!PreparedAccess::extrapolateOne(entities[i], time, limit, out[i])) ++refused;
    return refused;
}

// ---------------------------------------------------------------------------------------------
// DeadReckoningBatch

namespace {

constexpr std::uint32_t kNoSlot = 0xffffffffu;
constexpr std::size_t kChunk = 256;  // entities per vectorised pass

inline bool finiteF(float x) { return x - x == 0.0f; }
inline bool finiteR(Real x) { return x - x == Real(0); }

// Asks for the cache lines of `bytes` bytes from `address`, to be written (a hint; nothing
// where the compiler has no prefetch). On x86-64 without PREFETCHW in the target (the baseline,
// and the AVX2 copy) the compilers emit a plain prefetch: the line then comes in exclusive when
// no other core holds it, and the store finds it ready. That is what was measured; PREFETCHW
// itself (target "prfchw" for the AVX2 copy) measured within the noise of it.
inline void prefetchForWrite(const void* address, std::size_t bytes) {
#if defined(__GNUC__) || defined(__clang__)
    const char* p = static_cast<const char*>(address);
    for (std::size_t offset = 0; offset < bytes; offset += 64) __builtin_prefetch(p + offset, 1);
#else
    (void)address;
    (void)bytes;
#endif
}

// Pass 1 asks for the result lines this many entities ahead of the ones it stores, a group of
// kStoreGroup at a time (measured: 64 ahead as good as 256 or 1024).
constexpr std::size_t kStoreAhead = 64;
constexpr std::size_t kStoreGroup = 8;

// Entity i's quaternion from a batch's w, x, y, z columns.
template <class Columns>
inline Quat quatAt(const Columns& c, std::size_t i) {
    Quat q;
    q.w = c.w[i];
    q.x = c.x[i];
    q.y = c.y[i];
    q.z = c.z[i];
    return q;
}

// Puts `entity` in or out of `group`; `fill(slot, update)` writes a member's columns at `slot`
// (also for the member moved into a freed slot, from `all`).
template <class Group, class Fill>
void assignToGroup(Group& group, std::span<const PreparedDeadReckoning> all, std::size_t entity, bool member,
                   Fill fill) {
    std::uint32_t slot = group.slot[entity];
    if (member) {
        if (slot == kNoSlot) {
            slot = static_cast<std::uint32_t>(group.count++);
            group.slot[entity] = slot;
            group.entity[slot] = static_cast<std::uint32_t>(entity);
        }
        fill(slot, all[entity]);
    } else if (slot != kNoSlot) {
        // Swap-remove: the last member takes the freed slot.
        const std::size_t last = --group.count;
        const std::uint32_t moved = group.entity[last];
        if (last != slot) {
            group.entity[slot] = moved;
            group.slot[moved] = slot;
            fill(slot, all[moved]);
        }
        group.slot[entity] = kNoSlot;
    }
}

// The columns one frame reads (DeadReckoningBatch's, as pointers), for the passes.
template <class T>
struct Vec3View {
    const T *x, *y, *z;
};
struct QuatView {
    const float *w, *x, *y, *z;
};
struct GroupView {
    const std::uint32_t* entity;
    std::size_t count;
};
struct BatchView {
    Vec3View<Real> position;
    Vec3View<float> velocity, acceleration;
    const double* timestamp;
    GroupView fixed;
    QuatView fixedOrientation;
    GroupView turning;
    QuatView turnOrientation, turnAxisTerm;
    const double *turnTimestamp, *turnHalfRate;
    GroupView body;
    Vec3View<float> bodyVelocity, bodyAcceleration, bodyAxis;
    QuatView bodyOrientation, bodyAxisTerm;
    const double *bodyTimestamp, *bodyHalfRate;
    Vec3View<Real> bodyPosition;
};

// The passes for every processor of the target (SSE2 on x86-64).
namespace baseline {
#include "replication_passes.inc"
}  // namespace baseline

#if FORESIGHT_BATCH_AVX2
// The same source compiled for AVX2 (without FMA: the same operations, twice as wide).
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif
namespace avx2 {
#include "replication_passes.inc"
}  // namespace avx2
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif
#endif

}  // namespace

// The batch's arena: columns aligned to cache lines; an arena of 2 MiB or more aligned to 2 MiB
// and, on Linux, offered to the kernel for transparent huge pages (madvise). A frame streams
// through some 20 columns: with 4 KiB pages each of them crosses a page every 1 024 floats, a
// TLB miss each time and a new start for the hardware prefetcher. Measured, alternating with
// the columns in separate vectors: a frame of 100 000 entities from memory 0.87 to 0.92 ->
// 0.82 to 0.83 ms (docs/results.md).
constexpr std::size_t kColumnAlignment = 64;
constexpr std::size_t kHugePage = std::size_t(2) << 20;

void DeadReckoningBatch::ArenaFree::operator()(std::byte* memory) const noexcept { std::free(memory); }

std::size_t DeadReckoningBatch::bindColumns(std::byte* base) {
    const std::size_t n = mPrepared.size();
    std::size_t offset = 0;
    bool overflow = false;  // a size beyond std::size_t (never for a capacity mPrepared could hold)
    const auto take = [&](auto*& column) {
        using T = std::remove_reference_t<decltype(*column)>;
        const std::size_t limit = std::numeric_limits<std::size_t>::max() - kColumnAlignment;
        overflow = overflow || offset > limit || (n != 0 && sizeof(T) > (limit - offset) / n);
        offset = overflow ? 0 : (offset + kColumnAlignment - 1) / kColumnAlignment * kColumnAlignment;
        column = base != nullptr && !overflow ? reinterpret_cast<T*>(base + offset) : nullptr;
        offset += overflow ? 0 : n * sizeof(T);
    };
    const auto vec3 = [&](auto& c) {
        take(c.x);
        take(c.y);
        take(c.z);
    };
    const auto quat = [&](QuatColumns& c) {
        take(c.w);
        take(c.x);
        take(c.y);
        take(c.z);
    };
    const auto group = [&](Group& g) {
        take(g.entity);
        take(g.slot);
    };
    // In the order the passes read them.
    vec3(mPosition);
    vec3(mVelocity);
    vec3(mAcceleration);
    take(mTimestamp);
    group(mFixed);
    quat(mFixedOrientation);
    group(mTurning);
    quat(mTurnOrientation);
    quat(mTurnAxisTerm);
    take(mTurnTimestamp);
    take(mTurnHalfRate);
    group(mBody);
    vec3(mBodyVelocity);
    vec3(mBodyAcceleration);
    vec3(mBodyAxis);
    quat(mBodyOrientation);
    quat(mBodyAxisTerm);
    take(mBodyTimestamp);
    take(mBodyHalfRate);
    vec3(mBodyPosition);
    return overflow ? std::numeric_limits<std::size_t>::max() : offset;
}

void DeadReckoningBatch::allocateArena() {
    const std::size_t bytes = bindColumns(nullptr);
    mArena.reset();
    mArenaBytes = 0;
    if (bytes == 0) return;
    if (bytes > std::numeric_limits<std::size_t>::max() / 2) throw std::bad_alloc();
    const std::size_t alignment = bytes >= kHugePage ? kHugePage : kColumnAlignment;
    const std::size_t rounded = (bytes + alignment - 1) / alignment * alignment;
    void* memory = std::aligned_alloc(alignment, rounded);
    if (memory == nullptr) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (alignment == kHugePage) (void)madvise(memory, rounded, MADV_HUGEPAGE);  // a hint: failure is harmless
#endif
    // Written at once: the kernel backs a huge page when a write first touches its range (a
    // first read would map the zero page, and the write after it small pages).
    std::memset(memory, 0, rounded);
    mArena.reset(static_cast<std::byte*>(memory));
    mArenaBytes = rounded;
    bindColumns(mArena.get());
}

DeadReckoningBatch::DeadReckoningBatch(std::size_t capacity) : mPrepared(capacity) {
    allocateArena();
    for (Group* g : {&mFixed, &mTurning, &mBody}) {
        std::fill_n(g->slot, capacity, kNoSlot);
        g->count = 0;
    }
    for (std::size_t i = 0; i < capacity; ++i) (void)set(i, PreparedDeadReckoning{});
}

DeadReckoningBatch::DeadReckoningBatch(const DeadReckoningBatch& other) : mPrepared(other.mPrepared) {
    allocateArena();
    if (mArenaBytes != 0) std::memcpy(mArena.get(), other.mArena.get(), mArenaBytes);
    mFixed.count = other.mFixed.count;
    mTurning.count = other.mTurning.count;
    mBody.count = other.mBody.count;
}

DeadReckoningBatch& DeadReckoningBatch::operator=(const DeadReckoningBatch& other) {
    if (this != &other) *this = DeadReckoningBatch(other);
    return *this;
}

DeadReckoningBatch::DeadReckoningBatch(DeadReckoningBatch&& other) noexcept { *this = std::move(other); }

DeadReckoningBatch& DeadReckoningBatch::operator=(DeadReckoningBatch&& other) noexcept {
    if (this == &other) return *this;
    mPrepared = std::move(other.mPrepared);
    mArena = std::move(other.mArena);
    mArenaBytes = other.mArenaBytes;
    mFixed.count = other.mFixed.count;
    mTurning.count = other.mTurning.count;
    mBody.count = other.mBody.count;
    bindColumns(mArena.get());
    // `other` empty: no entities, no arena, no columns.
    other.mPrepared.clear();
    other.mArenaBytes = 0;
    other.mFixed.count = other.mTurning.count = other.mBody.count = 0;
    other.bindColumns(nullptr);
    return *this;
}

Status DeadReckoningBatch::set(std::size_t entity, const PreparedDeadReckoning& update) {
    if (entity >= mPrepared.size()) return Status::InvalidSetting;
    const PreparedDeadReckoning& u = update;
    mPrepared[entity] = u;
    auto put = [](auto& c, std::size_t i, const auto& v) {
        c.x[i] = v.x;
        c.y[i] = v.y;
        c.z[i] = v.z;
    };
    auto putQuat = [](QuatColumns& c, std::size_t i, const Quat& q) {
        c.w[i] = q.w;
        c.x[i] = q.x;
        c.y[i] = q.y;
        c.z[i] = q.z;
    };
    put(mPosition, entity, u.mPosition);
    put(mVelocity, entity, u.mVelocity);
    put(mAcceleration, entity, u.mAcceleration);
    // A STATIC entity keeps its state: the age 0 (a timestamp in the future is shown as stamped),
    // without a column of its own to read every frame.
    mTimestamp[entity] = u.mKernel == kKernelStatic ? std::numeric_limits<double>::infinity() : u.mTimestamp;

    const std::span<const PreparedDeadReckoning> all(mPrepared);
    // Body-axis entities get their orientation from the body pass (the same formula, with the
    // sine and cosine it computes anyway).
    const bool turning = u.mHalfRate > 0.0 && u.mKernel != kKernelBody, body = u.mKernel == kKernelBody;
    // What the turning formula gives at h = 0: the orientation of an entity that does not turn.
    assignToGroup(mFixed, all, entity, !turning && !body, [&](std::uint32_t slot, const PreparedDeadReckoning& m) {
        putQuat(mFixedOrientation, slot, turnedOrientation(m.mOrientation, m.mAxisTerm, 1.0f, 0.0f));
    });
    assignToGroup(mTurning, all, entity, turning, [&](std::uint32_t slot, const PreparedDeadReckoning& m) {
        putQuat(mTurnOrientation, slot, m.mOrientation);
        putQuat(mTurnAxisTerm, slot, m.mAxisTerm);
        mTurnTimestamp[slot] = m.mTimestamp;
        mTurnHalfRate[slot] = m.mHalfRate;
    });
    assignToGroup(mBody, all, entity, body, [&](std::uint32_t slot, const PreparedDeadReckoning& m) {
        put(mBodyPosition, slot, m.mPosition);
        put(mBodyVelocity, slot, m.mVelocity);
        put(mBodyAcceleration, slot, m.mAcceleration);
        put(mBodyAxis, slot, m.mAxis);
        putQuat(mBodyOrientation, slot, m.mOrientation);
        putQuat(mBodyAxisTerm, slot, m.mAxisTerm);
        mBodyTimestamp[slot] = m.mTimestamp;
        mBodyHalfRate[slot] = m.mHalfRate;
    });
    return Status::Ok;
}

bool detail::BatchAccess::available(BatchSimd simd) {
    switch (simd) {
        case BatchSimd::Baseline:
            return true;
        case BatchSimd::Avx2: {
#if FORESIGHT_BATCH_AVX2
            // Asked once (extrapolate checks it every frame).
            static const bool kAvx2 = [] {
                __builtin_cpu_init();
                return __builtin_cpu_supports("avx2") != 0;
            }();
            return kAvx2;
#else
            return false;
#endif
        }
    }
    return false;
}

detail::BatchSimd detail::BatchAccess::best() {
    return available(BatchSimd::Avx2) ? BatchSimd::Avx2 : BatchSimd::Baseline;
}

std::size_t DeadReckoningBatch::extrapolate(double time, float extrapolationLimit,
                                            std::span<DeadReckoningResult> out) const {
    return detail::BatchAccess::extrapolate(*this, detail::BatchAccess::best(), time, extrapolationLimit, out);
}

std::size_t detail::BatchAccess::extrapolate(const DeadReckoningBatch& batch, BatchSimd simd, double time,
                                             float extrapolationLimit, std::span<DeadReckoningResult> out) {
    const std::size_t n = batch.mPrepared.size();
    if (!isFinite(time) || !(extrapolationLimit >= 0.0f) || out.size() < n) return n;
    const double limit = static_cast<double>(extrapolationLimit);
    const auto vec3 = [](const auto& c) { return Vec3View<std::remove_cvref_t<decltype(c.x[0])>>{c.x, c.y, c.z}; };
    const auto quat = [](const DeadReckoningBatch::QuatColumns& c) { return QuatView{c.w, c.x, c.y, c.z}; };
    const auto group = [](const DeadReckoningBatch::Group& g) { return GroupView{g.entity, g.count}; };
    const BatchView view{vec3(batch.mPosition),     vec3(batch.mVelocity),
                         vec3(batch.mAcceleration), batch.mTimestamp,
                         group(batch.mFixed),       quat(batch.mFixedOrientation),
                         group(batch.mTurning),     quat(batch.mTurnOrientation),
                         quat(batch.mTurnAxisTerm), batch.mTurnTimestamp,
                         batch.mTurnHalfRate,       group(batch.mBody),
                         vec3(batch.mBodyVelocity), vec3(batch.mBodyAcceleration),
                         vec3(batch.mBodyAxis),     quat(batch.mBodyOrientation),
                         quat(batch.mBodyAxisTerm), batch.mBodyTimestamp,
                         batch.mBodyHalfRate,       vec3(batch.mBodyPosition)};
    // When a pass meets an unusual entity (an angle beyond the reduction, or an overflow),
    // a last scan redoes every such entity by extrapolateOne, which writes its whole result
    // (or refuses it). Never in a sane frame.
#if FORESIGHT_BATCH_AVX2
    const std::int32_t unusual = simd == BatchSimd::Avx2 && available(BatchSimd::Avx2)
                                     ? avx2::passes(view, n, time, limit, out)
                                     : baseline::passes(view, n, time, limit, out);
#else
    (void)simd;
    const std::int32_t unusual = baseline::passes(view, n, time, limit, out);
#endif
    std::size_t refused = 0;
    if (unusual != 0) {
        for (std::size_t i = 0; i < n; ++i) {
            const PreparedDeadReckoning& e = batch.mPrepared[i];
            const DeadReckoningResult& r = out[i];
            const double h = e.mHalfRate * static_cast<double>(frameAge(time, e.mTimestamp, limit));
            const bool beyondReduction = e.mHalfRate > 0.0 && !(h < kReductionLimit);
            if (beyondReduction || !isFinite(r.position) || !isFinite(r.velocity))
                if (!PreparedAccess::extrapolateOne(e, time, limit, out[i])) ++refused;
        }
    }
    return refused;
}

FORESIGHT_NAMESPACE_END
