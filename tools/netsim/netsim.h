#pragma once
/// @file netsim.h
/// `foresight netsim`: trajectories sent through a simulated network link with dead reckoning
/// (include/foresight/replication.h), measured against the truth.
///
/// The pieces, each usable (and tested, tests/netsim_test.cpp) on its own:
/// - Trajectory: the true motion, sampled at any time: position, body-to-world orientation,
///   world velocity and acceleration, body angular velocity. Body axes are the library's:
///   +Z forward, +Y up, +X = Y x Z. Built-in ones (makeBuiltinTrajectory) are analytic; a CSV
///   file (parseTrajectoryCsv) is interpolated between its rows.
/// - Link: a seeded, deterministic packet link with latency, uniform jitter and loss.
/// - simulateTrajectory: for each dead-reckoning model a DeadReckoningSender ticking at the send
///   rate, its updates through the link, and one DeadReckoningReceiver per smoothing rendering at
///   the render rate; the per-frame errors summarised.
/// - Reports: textTable (the default output), markdownTable (the table of docs/results.md), svgChart
///   (position error over time). The command, its options and the JSON report are in
///   commands/netsim_command.h/.cpp.
/// Everything is deterministic: the same settings give the same bytes.

#include <foresight/replication.h>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace foresight_cli::netsim {

/// The longest simulated time [Units: s]: bounds the work and the memory of a run.
inline constexpr double kMaxDuration = 3600.0;
/// The most rows a CSV trajectory may have.
inline constexpr std::size_t kMaxCsvRows = 1000000;

/// The true state of the entity at one time.
struct TruthState {
    glm::dvec3 position{0};                                ///< [Units: m], world axes.
    glm::dquat orientation = glm::identity<glm::dquat>();  ///< body-to-world, unit.
    glm::dvec3 velocity{0};                                ///< [Units: m/s], world axes.
    glm::dvec3 acceleration{0};                            ///< [Units: m/s^2], world axes.
    glm::dvec3 angularVelocity{0};                         ///< [Units: rad/s], body axes.
};

/// A true motion over [start, end].
struct Trajectory {
    std::string name;                          ///< "slalom", or the CSV file's name.
    std::string description;                   ///< one line for people.
    double start = 0;                          ///< [Units: s] first time.
    double end = 0;                            ///< [Units: s] last time (> start).
    std::function<TruthState(double)> sample;  ///< the truth at a time in [start, end].
};

/// The built-in trajectories, in the order "all" runs them: run-strafe, slalom, circuit,
/// aircraft-turn.
const std::vector<std::string>& builtinTrajectoryNames();

/// The built-in trajectory `name` over [0, duration] (duration in (0, kMaxDuration]).
/// @return false (out untouched) for an unknown name.
bool makeBuiltinTrajectory(std::string_view name, double duration, Trajectory& out);

/// A trajectory from CSV text: a header naming the columns, then one row per sample.
/// Columns: `t,x,y,z` required; `qw,qx,qy,qz` (orientation, body-to-world, normalised),
/// `vx,vy,vz` (world velocity, m/s) and `wx,wy,wz` (body angular velocity, rad/s) optional,
/// each group complete or absent, in any order. Times strictly increasing; at least 2 rows, at
/// most kMaxCsvRows. Missing velocities come from differences (three-point, exact for a
/// parabola), a missing orientation is the identity, a missing angular velocity is the
/// constant rotation between rows. Between rows: cubic Hermite positions, slerp orientations.
/// @param fileName  used in messages: `FILE:LINE: ...`.
/// @return false and `error` (one line naming the line and column) on a bad file.
bool parseTrajectoryCsv(std::string_view text, const std::string& fileName, Trajectory& out, std::string& error);

/// A packet link. Each packet is lost with probability `loss`; otherwise it arrives after
/// `latency` plus a jitter uniform in [-jitter, +jitter] (never before it was sent).
/// Reordering follows from the jitter.
struct LinkSettings {
    double latency = 0.1;    ///< [Units: s] [Limit: 0 .. 10]
    double jitter = 0.02;    ///< [Units: s] [Limit: 0 .. 10]
    double loss = 0.02;      ///< [Limit: 0 .. 1] fraction of packets lost.
    std::uint64_t seed = 1;  ///< the generator's seed.
};

/// The link's random fates, in packet order. Uses the raw output of std::mt19937_64 (fixed by
/// the C++ standard), never <random>'s distributions (they differ between standard libraries).
class Link {
public:
    explicit Link(const LinkSettings& settings);
    /// The fate of the next packet: false when it is lost, otherwise true and its delay [s].
    bool transmit(double& delay);

private:
    double uniform();  // [0, 1), 53 bits
    LinkSettings mSettings;
    std::mt19937_64 mEngine;
};

/// The receiver variants compared: the four smoothings of Extrapolate mode, and Interpolate.
enum class Display : std::uint8_t { Snap, Linear, Projective, Decay, Interpolate };

/// Every Display, in report order.
const std::vector<Display>& allDisplays();
/// Its command-line name: "snap", "linear", "pvb", "decay", "interpolate".
const char* displayName(Display display);
/// Finds a Display by its command-line name. @return false when unknown.
bool findDisplay(std::string_view name, Display& out);

/// The library's ReceiverSettings with extrapolationLimit infinite.
inline foresight::ReceiverSettings unlimitedReceiverSettings() {
    foresight::ReceiverSettings settings;
    settings.extrapolationLimit = std::numeric_limits<float>::infinity();
    return settings;
}

/// Everything a run needs.
struct SimulationSettings {
    double duration = 60.0;  ///< [Units: s] (0, kMaxDuration]; cut to a CSV's length.
    double sendRate = 30.0;  ///< [Units: Hz] sender ticks.
    /// false: DeadReckoningSender's thresholds decide which ticks send (dead reckoning);
    /// true: every tick sends a snapshot (Source's model: a fixed rate, usually with
    /// interpolation on the receiver).
    bool snapshots = false;
    double renderRate = 60.0;  ///< [Units: Hz] receiver frames.
    LinkSettings link;
    foresight::SenderSettings sender;  ///< thresholds and heartbeat.
    /// Mode and smoothing are set per Display. The library's defaults except
    /// extrapolationLimit: none (infinity), as the sender sends only when the receivers'
    /// extrapolation drifts, seconds apart on a smooth path.
    foresight::ReceiverSettings receiver = unlimitedReceiverSettings();
    /// [Units: m] a frame is a visible jump when the shown position moved by more than this
    /// beyond what the true position did: |shown_j - shown_j-1| > |true_j - true_j-1| + this.
    double jumpThreshold = 0.25;
    std::vector<foresight::DeadReckoningAlgorithm> models;  ///< in report order.
    std::vector<Display> displays;                          ///< in report order.
};

/// Mean, 95th percentile (nearest rank) and maximum of some values; all 0 when empty (the
/// reports print "-" or null for a display with no frames, never these zeros).
struct Summary {
    double mean = 0;
    double p95 = 0;
    double max = 0;
};
/// Summarises `values` (reordered).
Summary summarise(std::vector<double>& values);

/// The angle [Units: degrees] of the rotation between two unit quaternions (0 to 180).
double rotationAngleDegrees(const glm::dquat& a, const glm::dquat& b);

/// One receiver's result.
struct DisplayResult {
    Display display = Display::Snap;
    std::uint64_t frames = 0;        ///< frames rendered with a pose (after the first update).
    Summary position;                ///< [Units: m] |shown - true| at the render time.
    Summary orientation;             ///< [Units: degrees] the rotation between shown and true.
    std::uint64_t snaps = 0;         ///< updates the receiver applied with a snap (first included).
    std::uint64_t jumps = 0;         ///< frames that jumped (SimulationSettings::jumpThreshold).
    std::uint64_t dropped = 0;       ///< updates it dropped (out of order, duplicate, invalid).
    std::vector<float> seriesTime;   ///< [Units: s] frame times (with a pose), when kept.
    std::vector<float> seriesError;  ///< [Units: m] position error per frame, when kept.
};

/// One model's result.
struct ModelResult {
    foresight::DeadReckoningAlgorithm model = foresight::DeadReckoningAlgorithm::Fpw;
    std::uint64_t updates = 0;    ///< updates the sender sent.
    double updatesPerSecond = 0;  ///< updates / duration.
    std::uint64_t lost = 0;       ///< lost by the link.
    std::uint64_t late = 0;       ///< would arrive after the end of the run.
    std::uint64_t reordered = 0;  ///< arrived after a packet sent later.
    /// Updates sent for each reason (SendReason bits; one update may count under several).
    std::uint64_t sentFirst = 0, sentPosition = 0, sentOrientation = 0, sentHeartbeat = 0;
    std::uint64_t sentSnapshot = 0;  ///< updates sent as fixed-rate snapshots (SimulationSettings::snapshots).
    std::vector<DisplayResult> displays;
};

/// One trajectory's result.
struct TrajectoryResult {
    std::string name;
    std::string description;
    double duration = 0;  ///< [Units: s] simulated.
    double distance = 0;  ///< [Units: m] travelled (sum over render frames).
    std::vector<ModelResult> models;
};

/// Runs every model and display of `settings` on `trajectory` (from its start, for
/// min(duration, end - start) seconds). `keepSeries`: fill seriesTime/seriesError.
/// `progress(done, total)` is called after each model.
/// @return false and `error` when the library refuses a setting or a state.
bool simulateTrajectory(const Trajectory& trajectory, const SimulationSettings& settings, bool keepSeries,
                        TrajectoryResult& out, std::string& error,
                        const std::function<void(std::size_t, std::size_t)>& progress = {});

/// The settings line printed above the tables (latency, jitter, loss, seed, rates, thresholds).
std::string settingsLine(const SimulationSettings& settings);
/// The default output: one row per trajectory, model and display, aligned columns.
std::string textTable(const std::vector<TrajectoryResult>& results, const SimulationSettings& settings);
/// docs/results.md's table (Markdown): one row per trajectory and model, one column per display,
/// cells "p95 / max [m] / jumps", followed by the settings line.
std::string markdownTable(const std::vector<TrajectoryResult>& results, const SimulationSettings& settings);
/// An SVG chart of position error over time for one trajectory's model: one line per display,
/// axes in seconds and metres, a legend. The model's displays must have their series kept.
std::string svgChart(const TrajectoryResult& result, std::size_t modelIndex, const SimulationSettings& settings);

}  // namespace foresight_cli::netsim
