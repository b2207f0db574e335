#pragma once
/// @file replication.h
/// Network replication with dead reckoning: the sender that decides when an entity must send a
/// state update, and the receiver that turns the updates it gets into a smooth rendered pose.
///
/// Time: every time here is a `double` [Units: s] on one clock shared by sender and receiver
/// (DIS absolute timestamps, or a game's synchronised network clock). Updates carry the
/// sender's timestamp and the receiver extrapolates from it, never from the time of receipt,
/// so latency does not add error to the extrapolation itself. Doubles keep a 1 ms resolution
/// for 285 years of session time; floats would lose it after 2.3 hours.
///
/// Both classes hold fixed-size state only: no call allocates, none throws, and the same calls
/// in the same order give bit-identical results.

#include <foresight/dead_reckoning.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

FORESIGHT_NAMESPACE_BEGIN

// ---------------------------------------------------------------------------------------------
// Sender
// ---------------------------------------------------------------------------------------------

/// When an entity must send an update. Defaults are the DIS defaults (IEEE 1278.1 thresholds:
/// 1 m, 3 degrees; heartbeat 5 s).
struct SenderSettings {
    /// [Units: m] [Limit: > 0, finite] send when the receivers' extrapolated position is this
    /// far from the true position.
    float positionThreshold = 1.0f;
    /// [Units: rad] [Limit: > 0, finite] send when the extrapolated orientation is this far
    /// from the true one, measured as the angle of the rotation between them (0 to pi).
    float orientationThreshold = 0.05235987755982988f;  // 3 degrees
    /// [Units: s] [Limit: > 0, finite] send at least this often, even when nothing changed.
    float heartbeat = 5.0f;
};

/// Checks every field of `settings` against its documented range.
/// @return Ok or InvalidSetting.
Status validateSenderSettings(const SenderSettings& settings);

/// Why an update was sent: a bit set (several reasons can hold at once).
enum SendReason : std::uint8_t {
    SendReasonNone = 0,         ///< no update is needed.
    SendReasonFirst = 1,        ///< the first update of the entity.
    SendReasonPosition = 2,     ///< the position error reached positionThreshold.
    SendReasonOrientation = 4,  ///< the orientation error reached orientationThreshold.
    SendReasonHeartbeat = 8,    ///< heartbeat seconds passed since the last update.
    SendReasonAlgorithm = 16,   ///< the entity's dead-reckoning algorithm changed.
};

/// What DeadReckoningSender::update decided.
struct SendDecision {
    std::uint8_t reasons = SendReasonNone;  ///< SendReason bits; non-zero means "send now".
    /// [Units: m] distance between the receivers' extrapolation and the truth, before sending
    /// (0 for the first update; the largest float when the extrapolation overflows).
    float positionError = 0.0f;
    /// [Units: rad] rotation angle between the extrapolated and the true orientation (0 to pi).
    float orientationError = 0.0f;
    /// True when an update must be sent now (`reasons != SendReasonNone`).
    bool send() const { return reasons != SendReasonNone; }
};

/// Decides, tick by tick, when one entity must send a state update: it extrapolates its last
/// sent update exactly as every receiver does and compares that with the entity's true state.
class DeadReckoningSender {
public:
    /// A sender with `settings` (checked by the first update).
    explicit DeadReckoningSender(const SenderSettings& settings = {});

    /// Compares the truth at `time` with what receivers extrapolate from the last sent update:
    /// predictDeadReckoning(lastSent(), float(time - lastSentTime())), as a receiver computes it
    /// (without its extrapolationLimit). A threshold is reached when the error is >= it; the
    /// heartbeat when time - lastSentTime() >= heartbeat. When `decision.send()` is true the
    /// caller sends `truth` stamped with `time`, and the sender records it as the last sent
    /// update.
    /// @param time   [Units: s] [Limit: finite, >= the previous call's time; equal is fine].
    /// @param truth  the entity's true state now, with the algorithm receivers should use.
    /// @return Ok, InvalidSetting, NonFiniteInput (also for a NaN or infinite time),
    ///         TimeWentBackwards, or validateDeadReckoningState's other refusals; on a refusal
    ///         nothing changes and `decision` is untouched.
    Status update(double time, const DeadReckoningState& truth, SendDecision& decision);

    /// True once an update has been sent.
    bool hasSent() const { return mHasSent; }
    /// The last update sent (meaningful once hasSent()).
    const DeadReckoningState& lastSent() const { return mLastSent; }
    /// [Units: s] the timestamp of the last update sent (meaningful once hasSent()).
    double lastSentTime() const { return mLastSentTime; }
    /// The settings in use.
    const SenderSettings& settings() const { return mSettings; }
    /// Forgets every update: the next update() sends with SendReasonFirst.
    void reset();

private:
    SenderSettings mSettings;
    Status mSettingsStatus = Status::Ok;  // validateSenderSettings(mSettings), checked once
    DeadReckoningState mLastSent{};
    double mLastSentTime = 0.0;
    double mLastTime = 0.0;  // the previous update()'s time (TimeWentBackwards)
    bool mHasSent = false;
    bool mHasTime = false;
};

// ---------------------------------------------------------------------------------------------
// Receiver
// ---------------------------------------------------------------------------------------------

/// How the receiver hides the jump when a new update disagrees with what it was showing.
enum class Smoothing : std::uint8_t {
    /// Show the new update's extrapolation at once (a visible jump at every correction).
    Snap,
    /// Blend from the old update's extrapolation to the new one's, linearly over blendTime
    /// (position and velocity lerp, orientation slerp). If the previous blend had not finished,
    /// the old extrapolation carries the shown-minus-old offset of the correction instant, so
    /// the shown pose never jumps (the offset is zero otherwise).
    LinearBlend,
    /// Projective velocity blending (C. Murphy, "Believable Dead Reckoning for Networked
    /// Games", Game Engine Gems 2, 2011): project from the shown position with a velocity
    /// blended from the shown one to the new one, then blend that projection towards the new
    /// update's extrapolation over blendTime. With P0, V0 the shown position and world velocity
    /// when the correction starts, V', A' the new update's world velocity and acceleration then,
    /// P'(t) its extrapolation, T = t - start, alpha = T / blendTime (0 to 1):
    /// Vb = V0 + (V' - V0) alpha, Pt = P0 + Vb T + A' T^2 / 2, shown = Pt + (P'(t) - Pt) alpha.
    /// Orientation: slerp, by alpha, from the shown orientation at the start carried along by
    /// the new update's rotation, to the new update's orientation.
    ProjectiveVelocityBlending,
    /// Keep the shown-minus-new offset at the moment of the update and let it decay
    /// exponentially with half-life decayHalfLife (position and rotation angle):
    /// shown = new(t) + offset 2^(-T / decayHalfLife). The velocity shown is the new update's.
    ExponentialDecay,
};

/// Extrapolate from the newest update, or interpolate between buffered updates in the past.
enum class ReceiverMode : std::uint8_t {
    /// Show the newest update extrapolated to now (dead reckoning), with smoothing.
    Extrapolate,
    /// Show the entity interpolationDelay seconds in the past, between the two buffered
    /// updates around that time (Source's entity interpolation, made model-aware): the older
    /// update's own prediction at that time plus the correction onto the newer update, growing
    /// linearly from 0 to 1 between their timestamps (position and velocity; orientation: that
    /// fraction of the correcting rotation). For updates that agree with each other's models
    /// (fixed-rate snapshots of straight motion, STATIC updates) this is exactly linear
    /// interpolation and slerp; for sparse updates of a turning vehicle it follows the model's
    /// arc instead of the chord (no Hermite curve: it would overshoot). When an update changes
    /// what the last render time showed (the buffer had run dry and the newest update was being
    /// extrapolated, or a late update lands in the pair being shown), the difference fades out
    /// linearly over blendTime, so the shown entity does not pop (unless it is a teleport).
    /// Before the oldest
    /// buffered update: that update as stamped; after the newest: extrapolate from it, up to
    /// extrapolationLimit, when the buffer runs dry. Two updates whose newer one is further
    /// than teleportDistance from the older one's own prediction (its model run, without
    /// extrapolationLimit, to the newer one's timestamp) are not interpolated (a teleport: no
    /// sweep through the level): the older one is extrapolated until the newer one is due.
    /// Comparing with the prediction, not the older position, keeps sparse updates of a fast
    /// entity (a threshold sender sends every few seconds) from counting as teleports.
    Interpolate,
};

/// How a receiver shows a remote entity.
struct ReceiverSettings {
    ReceiverMode mode = ReceiverMode::Extrapolate;                ///< extrapolate or interpolate.
    Smoothing smoothing = Smoothing::ProjectiveVelocityBlending;  ///< Extrapolate mode only.
    /// [Units: s] [Limit: > 0, finite] duration of LinearBlend and ProjectiveVelocityBlending,
    /// and of the fade of Interpolate mode's switch from extrapolating to interpolating.
    float blendTime = 0.2f;
    /// [Units: s] [Limit: > 0, finite] half-life of the ExponentialDecay offset.
    float decayHalfLife = 0.1f;
    /// [Units: m] [Limit: > 0; infinity disables] a correction longer than this snaps (a
    /// teleport, a respawn): blending across it would sweep the entity through the level.
    float teleportDistance = 10.0f;
    /// [Units: s] [Limit: >= 0; infinity disables] extrapolate at most this far past the
    /// newest update's timestamp, then hold there (Source's cl_extrapolate_amount, 0.25 s).
    /// The default suits senders that send every tick. With DeadReckoningSender's thresholds a
    /// well-predicted entity sends only every heartbeat (5 s): set this to at least the
    /// heartbeat plus the latency there, or every such entity freezes between heartbeats.
    float extrapolationLimit = 0.25f;
    /// [Units: s] [Limit: > 0, finite] how far in the past Interpolate mode renders (Source's
    /// cl_interp, 0.1 s).
    float interpolationDelay = 0.1f;
    /// [Units: s] [Limit: >= 0; infinity disables] an update stamped more than this after its
    /// receive time is dropped (UpdateOutcome::TooFarAhead): a corrupt timestamp or a clock
    /// far off. Accepted, it would make every real update after it look out of order.
    float maxFutureSkew = 1.0f;
    /// [Units: s] [Limit: > 0; infinity disables] Extrapolate mode: when no update has been
    /// accepted for this long (receive time), an update stamped earlier than the newest one is
    /// taken as the sender's clock starting again (a restart, a reconnect): the receiver
    /// forgets its updates and snaps to it (ReceiverCounters::clockRestarts). A late packet
    /// of a live sender arrives sooner; the default is two default heartbeats.
    float restartAfter = 10.0f;
};

/// Checks every field of `settings` against its documented range.
/// @return Ok or InvalidSetting.
Status validateReceiverSettings(const ReceiverSettings& settings);

/// What DeadReckoningReceiver::receive did with an update.
enum class UpdateOutcome : std::uint8_t {
    Accepted,     ///< applied, smoothed per the settings.
    Snapped,      ///< applied with a snap: the first update, Snap smoothing, a teleport, or
                  ///< a sender whose clock started again (ReceiverSettings::restartAfter).
    Buffered,     ///< Interpolate mode: every accepted update (stored in timestamp order, shown
                  ///< once the render time reaches it), late ones included.
    OutOfOrder,   ///< dropped: older than the newest update (Extrapolate mode, unless it
                  ///< comes after restartAfter of silence); older than the
                  ///< last sample()'s render time, or than every update of a full buffer
                  ///< (Interpolate mode).
    Duplicate,    ///< dropped: same timestamp as an update already received.
    Invalid,      ///< dropped: NaN or infinite fields, zero quaternion, unknown algorithm, a
                  ///< non-finite timestamp or receive time, or invalid receiver settings.
    TooFarAhead,  ///< dropped: stamped more than maxFutureSkew after its receive time (last, so
                  ///< that the earlier values keep their numbers).
};

/// Counts of what a receiver did, for statistics and tests.
struct ReceiverCounters {
    std::uint64_t accepted = 0;       ///< updates applied or buffered (Accepted, Snapped, Buffered).
    std::uint64_t snaps = 0;          ///< updates that snapped (first, Snap smoothing, teleports,
                                      ///< sender restarts).
    std::uint64_t teleports = 0;      ///< snaps caused by teleportDistance (Interpolate mode: updates
                                      ///< further than it from the previous buffered one's
                                      ///< prediction at their timestamp).
    std::uint64_t outOfOrder = 0;     ///< OutOfOrder updates dropped.
    std::uint64_t duplicates = 0;     ///< Duplicate updates dropped.
    std::uint64_t invalid = 0;        ///< Invalid updates dropped.
    std::uint64_t held = 0;           ///< sample() calls that returned a held pose (ReceivedPose::held).
    std::uint64_t futureUpdates = 0;  ///< updates stamped later than the receive time (treated
                                      ///< as age 0 until their timestamp: never extrapolated
                                      ///< backwards), within maxFutureSkew.
    std::uint64_t tooFarAhead = 0;    ///< TooFarAhead updates dropped.
    std::uint64_t clockRestarts = 0;  ///< older updates taken as a sender restart (restartAfter);
                                      ///< each also counts as a snap.
};

/// The pose a receiver shows at a time, in world axes.
struct ReceivedPose {
    RVec3 position{0};  ///< [Units: m], world axes.
    /// [Units: m/s], world axes (converted for `*B`): the model's velocity at the age shown
    /// (also when held); during a correction the blend of the old and new velocities, not the
    /// derivative of the blended position (which includes the correction's own speed).
    Vec3 velocity{0};
    Quat orientation = glm::identity<Quat>();  ///< body-to-world, unit.
    /// True when extrapolationLimit stopped the extrapolation of the newest update: the
    /// position stays at its extrapolation to timestamp + extrapolationLimit.
    bool held = false;
};

/// Shows one remote entity from the updates it receives.
class DeadReckoningReceiver {
public:
    /// Updates kept for Interpolate mode (the newest ones; older ones are forgotten).
    static constexpr std::size_t kBufferCapacity = 32;

    /// A receiver with `settings` (checked by the first call).
    explicit DeadReckoningReceiver(const ReceiverSettings& settings = {});

    /// Takes an update stamped `timestamp` (sender clock) that arrives at `receiveTime`.
    /// Bad or stale updates are dropped and counted, never applied (see UpdateOutcome).
    /// Extrapolate mode: the first update snaps; a later one starts a correction at
    /// receiveTime from what sample(receiveTime) showed, or snaps (Snap smoothing, or a
    /// correction longer than teleportDistance).
    /// @param timestamp   [Units: s] the sender's time of the state; finite.
    /// @param receiveTime [Units: s] the receiver's time now; the correction starts here.
    UpdateOutcome receive(double timestamp, const DeadReckoningState& state, double receiveTime);

    /// The pose to show at `time` [Units: s]. Times may go backwards (a replay); smoothing
    /// then clamps to its start. Extrapolation uses the age min(max(time - timestamp, 0),
    /// extrapolationLimit) (Interpolate mode: renders at time - interpolationDelay).
    /// @return Ok; InvalidSetting; NoUpdate before the first accepted update;
    ///         NonFiniteInput for a NaN or infinite time; NonFiniteResult only with an infinite
    ///         extrapolationLimit when the age or the extrapolation overflows; `out` untouched
    ///         unless Ok.
    Status sample(double time, ReceivedPose& out);

    /// The counters since construction or the last reset().
    const ReceiverCounters& counters() const { return mCounters; }
    /// The settings in use.
    const ReceiverSettings& settings() const { return mSettings; }
    /// Forgets every update and counter.
    void reset();

private:
    struct Snapshot {
        double timestamp = 0.0;
        DeadReckoningState state{};
    };
    // A pose in double, velocity in world axes (the blends are computed in double).
    struct Pose {
        glm::dvec3 position{0.0};
        glm::dvec3 velocity{0.0};
        glm::dquat orientation{glm::identity<glm::dquat>()};
    };
    Status extrapolate(const Snapshot& update, double time, DeadReckoningResult& result, Pose& pose, bool& held) const;
    Status showExtrapolated(double time, ReceivedPose& out, Pose& shown) const;
    Status showInterpolated(double renderTime, ReceivedPose& out) const;
    // Whether `to` is further than teleportDistance from `from`'s prediction at its timestamp
    // (true when that prediction overflows); `predicted` receives the prediction.
    bool isTeleport(const Snapshot& from, const Snapshot& to, DeadReckoningResult& predicted) const;
    UpdateOutcome receiveInterpolated(double timestamp, const DeadReckoningState& state);
    void applySwitchOffset(double renderTime, ReceivedPose& pose) const;
    const Snapshot& buffered(std::size_t i) const { return mBuffer[(mBufferStart + i) % kBufferCapacity]; }

    ReceiverSettings mSettings;
    Status mSettingsStatus = Status::Ok;  // validateReceiverSettings(mSettings), checked once
    ReceiverCounters mCounters;
    // Interpolate mode: the newest updates, a ring ordered by timestamp.
    std::array<Snapshot, kBufferCapacity> mBuffer{};
    std::size_t mBufferStart = 0;
    std::size_t mBufferCount = 0;
    double mLastRenderTime = 0.0;  // the last sample()'s render time (OutOfOrder)
    bool mHasRendered = false;
    // Interpolate mode: what the switch from extrapolating the newest update to interpolating
    // towards a newer one moved the shown pose by, fading out over blendTime from mSwitchStart.
    glm::dvec3 mSwitchOffset{0.0};
    glm::dquat mSwitchRotationOffset{glm::identity<glm::dquat>()};
    double mSwitchStart = 0.0;
    bool mHasSwitchOffset = false;
    // Extrapolate mode: the update being shown and the correction in progress.
    Snapshot mCurrent{};
    Snapshot mPrevious{};             // the update shown before mCurrent (LinearBlend)
    Pose mShownAtCorrection{};        // what was shown when the correction started
    glm::dvec3 mPreviousOffset{0.0};  // LinearBlend: shown minus mPrevious's extrapolation at start
    glm::dquat mPreviousRotationOffset{glm::identity<glm::dquat>()};  // the same, world-frame rotation
    glm::dvec3 mCurrentOffset{0.0};  // shown minus mCurrent's extrapolation at start (decay)
    glm::dquat mCurrentRotationOffset{glm::identity<glm::dquat>()};  // the same, world-frame rotation
    glm::dvec3 mCurrentVelocity{0.0};                                // PVB: V', mCurrent's world velocity at start
    glm::dvec3 mCurrentAcceleration{0.0};                            // PVB: A', mCurrent's world acceleration at start
    double mCorrectionStart = 0.0;
    double mLastAcceptedAt = 0.0;  // receive time of the last accepted update (restartAfter)
    bool mHasCurrent = false;
    bool mCorrecting = false;
};

/// Extrapolates many entities to one time, as a receiver does every frame (the batch form of
/// predictDeadReckoning, no smoothing, no extrapolation limit). Entity i's result is
/// bit-identical to predictDeadReckoning(states[i], float(max(time - timestamps[i], 0))).
/// Entities that predictDeadReckoning refuses (or a NaN timestamp) keep their state and are
/// counted. When the spans' lengths differ, the entities up to the shortest are processed
/// and the states beyond it are counted as refused.
/// @param states      updates, one per entity.
/// @param timestamps  [Units: s] each update's timestamp, same length as `states`.
/// @param time        [Units: s] the time to extrapolate to; an entity stamped later is shown
///                    at its update (age 0).
/// @param out         receives one result per entity; same length as `states`.
/// @return the number of entities refused (their `out` is their update as given).
std::size_t predictDeadReckoningBatch(std::span<const DeadReckoningState> states, std::span<const double> timestamps,
                                      double time, std::span<DeadReckoningResult> out);

// ---------------------------------------------------------------------------------------------
// Prepared extrapolation (many entities per frame)
// ---------------------------------------------------------------------------------------------

namespace detail {
struct PreparedAccess;
struct BatchAccess;
}  // namespace detail

/// An update made ready for fast extrapolation: validated once by prepareDeadReckoning when it
/// arrives (quaternion normalised, unused fields zeroed, |w|, its axis and the rotation's terms
/// precomputed), so that extrapolateDeadReckoning does no validation and no square root per
/// frame. A plain value (104 bytes, 112 in the double build): store one per entity in your
/// own array. The default is a valid STATIC update at the origin stamped 0.
class PreparedDeadReckoning {
public:
    /// The model the update asked for.
    DeadReckoningAlgorithm algorithm() const { return mAlgorithm; }
    /// [Units: s] the update's timestamp (sender clock, see the file comment).
    double timestamp() const { return mTimestamp; }

private:
    friend Status prepareDeadReckoning(const DeadReckoningState& state, double timestamp, PreparedDeadReckoning& out);
    friend std::size_t extrapolateDeadReckoning(std::span<const PreparedDeadReckoning> entities, double time,
                                                float extrapolationLimit, std::span<DeadReckoningResult> out);
    friend class DeadReckoningBatch;
    friend struct detail::BatchAccess;
    friend struct detail::PreparedAccess;

    RVec3 mPosition{0};                         // p
    double mTimestamp = 0.0;                    // [s]
    double mHalfRate = 0.0;                     // |w| / 2 [rad/s]; 0 unless the model rotates
    Vec3 mVelocity{0};                          // v, the model's axes
    Vec3 mAcceleration{0};                      // a; 0 unless the model uses it
    Quat mOrientation = glm::identity<Quat>();  // A = q normalised
    Quat mAxisTerm = zeroQuat();                // B = q (0, u): q exp(w t) = A cos h + B sin h
    Vec3 mAxis{0};                              // u = w / |w|, body axes; 0 unless rotating
    std::uint8_t mKernel = 0;                   // 0 STATIC, 1 world axes, 2 body axes
    DeadReckoningAlgorithm mAlgorithm = DeadReckoningAlgorithm::Static;

    static Quat zeroQuat() {
        Quat q;
        q.w = 0.0f;
        q.x = 0.0f;
        q.y = 0.0f;
        q.z = 0.0f;
        return q;
    }
};

/// Validates `state` (as predictDeadReckoning does) and prepares it for
/// extrapolateDeadReckoning. Call it once per update received, not per frame.
/// @param state      the update.
/// @param timestamp  [Units: s] [Limit: finite] the update's timestamp.
/// @param out        receives the prepared update; untouched unless Ok.
/// @return Ok, InvalidAlgorithm, NonFiniteInput (a field or the timestamp), ZeroQuaternion.
Status prepareDeadReckoning(const DeadReckoningState& state, double timestamp, PreparedDeadReckoning& out);

/// Extrapolates many prepared updates to one time: the per-frame call of a receiver showing
/// many entities (no smoothing). Entity i uses the age
/// `min(max(time - timestamp, 0), extrapolationLimit)` rounded to float once (the age
/// DeadReckoningReceiver uses), and its result agrees with predictDeadReckoning at that age
/// within this contract (measured on 100 000 random states in tests/replication_test.cpp):
/// - world-axis models and STATIC: position and velocity bit-identical here (the same double
///   operations; DeadReckoningBatch computes them in Real and float: within the bounds below);
/// - every model: position within 1e-6 (|v| t + |a| t^2 / 2) plus 2 ulps of Real at the
///   position (body-axis integrals use a float sine and cosine); velocity within 4 float ulps
///   plus 1e-6 (|v| + |a| t);
/// - orientation (all models): within 4e-7 rad of predictDeadReckoning's (sin/cos are a
///   Cephes-style float polynomial after an exact double range reduction, pure arithmetic, so
///   the same on every compiler; angles |w| t / 2 beyond 8.2e5 rad use the C library's double
///   sin/cos as predictDeadReckoning does); its length is 1 within 3e-7.
/// Never allocates, never validates per entity. Entities whose result overflows (finite but
/// absurd velocities or ages; never with a finite limit and sane inputs) are refused and
/// counted, and get their update as given (age 0). When `out` is shorter than `entities`,
/// the first out.size() are processed and the rest are counted as refused.
/// @param entities            prepared updates (prepareDeadReckoning), one per entity.
/// @param time                [Units: s] [Limit: finite] the time to show.
/// @param extrapolationLimit  [Units: s] [Limit: >= 0; infinity disables] the largest age.
/// @param out                 receives one result per entity.
/// @return the number of entities refused; entities.size() (nothing written) for a
///         non-finite `time` or a NaN or negative `extrapolationLimit`.
std::size_t extrapolateDeadReckoning(std::span<const PreparedDeadReckoning> entities, double time,
                                     float extrapolationLimit, std::span<DeadReckoningResult> out);

/// Many entities' prepared updates in structure-of-arrays form, for extrapolating them all
/// every frame at SIMD speed (the fast form of extrapolateDeadReckoning, same contract).
/// Entities are numbered 0 to capacity() - 1; each starts as a default PreparedDeadReckoning
/// (STATIC at the origin). The constructor allocates everything (about 340 bytes per entity,
/// 380 in the double build, in one block offered for huge pages); no other call allocates. One
/// frame: a vectorised pass over every entity (the world-axis translation), one that copies the
/// orientation of the entities that do not turn, one over the turning world-axis entities only
/// (their orientation: a non-turning entity pays no sine or cosine), then one over the
/// body-axis entities (their positions and orientations). On x86 processors with AVX2 (GCC or
/// clang builds) the passes run twice as wide; the results are the same bytes either way.
class DeadReckoningBatch {
public:
    /// A batch of `capacity` entities [Limit: < 2^32]. Allocates (std::bad_alloc when out of
    /// memory, as a std::vector would).
    explicit DeadReckoningBatch(std::size_t capacity);
    /// A copy of every entity's update. Allocates.
    DeadReckoningBatch(const DeadReckoningBatch& other);
    /// Replaces this batch by a copy of `other` (its capacity too). Allocates.
    DeadReckoningBatch& operator=(const DeadReckoningBatch& other);
    /// Takes `other`'s entities; `other` is left empty (capacity 0).
    DeadReckoningBatch(DeadReckoningBatch&& other) noexcept;
    /// Takes `other`'s entities; `other` is left empty (capacity 0).
    DeadReckoningBatch& operator=(DeadReckoningBatch&& other) noexcept;
    ~DeadReckoningBatch() = default;

    /// The number of entities.
    std::size_t capacity() const { return mPrepared.size(); }

    /// Replaces entity `entity`'s update (made by prepareDeadReckoning). O(1).
    /// @return Ok, or InvalidSetting when entity >= capacity() (nothing changes).
    Status set(std::size_t entity, const PreparedDeadReckoning& update);

    /// Entity `entity`'s update [Limit: < capacity()].
    const PreparedDeadReckoning& prepared(std::size_t entity) const { return mPrepared[entity]; }

    /// Extrapolates every entity to `time`: out[i] is entity i's result, within the contract
    /// of extrapolateDeadReckoning (same refusals: overflowing entities get their update as
    /// given). When `out` is shorter than capacity(), nothing is written.
    /// @param time                [Units: s] [Limit: finite].
    /// @param extrapolationLimit  [Units: s] [Limit: >= 0; infinity disables] the largest age.
    /// @param out                 one result per entity, at least capacity() long.
    /// @return the number of entities refused; capacity() (nothing written) for a non-finite
    ///         `time`, a NaN or negative limit or a short `out`.
    std::size_t extrapolate(double time, float extrapolationLimit, std::span<DeadReckoningResult> out) const;

private:
    friend struct detail::BatchAccess;  // the frame's passes, one per instruction set (src/)
    // The columns live in one allocation (the arena), laid out by bindColumns from capacity().
    template <class T>
    struct Vec3Columns {
        T *x = nullptr, *y = nullptr, *z = nullptr;
    };
    struct QuatColumns {
        float *w = nullptr, *x = nullptr, *y = nullptr, *z = nullptr;
    };
    // A subset of the entities kept dense (swap-remove): its members' numbers and, per entity,
    // its index among them (or kNoSlot).
    struct Group {
        std::uint32_t* entity = nullptr;
        std::uint32_t* slot = nullptr;
        std::size_t count = 0;
    };
    struct ArenaFree {
        void operator()(std::byte* memory) const noexcept;
    };
    // Points every column into `base` (null: nowhere) for capacity() entities; the arena's size.
    std::size_t bindColumns(std::byte* base);
    // Allocates the arena for capacity() entities and binds the columns into it.
    void allocateArena();

    std::vector<PreparedDeadReckoning> mPrepared;
    std::unique_ptr<std::byte[], ArenaFree> mArena;
    std::size_t mArenaBytes = 0;
    // Every entity: the translation (world-axis formula; body-axis positions are redone from
    // the body group).
    Vec3Columns<Real> mPosition;
    Vec3Columns<float> mVelocity, mAcceleration;
    double* mTimestamp = nullptr;  // +infinity for STATIC: frameAge gives it the age 0
    // The entities that neither turn nor are body-axis: their fixed orientation (A normalised
    // as the turning formula does at h = 0), copied into their results.
    Group mFixed;
    QuatColumns mFixedOrientation;
    // Turning world-axis entities (|w| > 0): the orientation A cos h + B sin h.
    Group mTurning;
    QuatColumns mTurnOrientation, mTurnAxisTerm;
    double *mTurnTimestamp = nullptr, *mTurnHalfRate = nullptr;
    // Body-axis entities: the columns the integrals and their orientation read.
    Group mBody;
    Vec3Columns<float> mBodyVelocity, mBodyAcceleration, mBodyAxis;
    QuatColumns mBodyOrientation, mBodyAxisTerm;
    double *mBodyTimestamp = nullptr, *mBodyHalfRate = nullptr;
    Vec3Columns<Real> mBodyPosition;
};

FORESIGHT_NAMESPACE_END
