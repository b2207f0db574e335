// `foresight netsim`'s pieces (tools/netsim/netsim.h): the built-in trajectories against finite
// differences and their closed-form properties, the link's statistics, the CSV reader's rules and
// messages, the statistics, and whole simulations with known answers.
//
// Reference values come from closed forms (p + v t, binomial bounds, a closed circuit, the
// coordinated-turn condition) or from finite differences of the positions, never from the code
// under test.

#include "netsim.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace {

using namespace foresight_cli::netsim;
using foresight::DeadReckoningAlgorithm;

Trajectory builtin(const std::string& name, double duration = 60) {
    Trajectory t;
    EXPECT_TRUE(makeBuiltinTrajectory(name, duration, t)) << name;
    return t;
}

std::string csvError(const std::string& text) {
    Trajectory t;
    std::string error;
    EXPECT_FALSE(parseTrajectoryCsv(text, "f.csv", t, error)) << text;
    return error;
}

// ---------------------------------------------------------------------------------------------
// Trajectories

TEST(NetsimTrajectory, BuiltinDerivativesMatchFiniteDifferences) {
    // Central differences with h = 1e-5 s: truncation error h^2/6 times the third derivative
    // (below 1e-6 here), except within h of a ramp's end where the jerk jumps (then at most
    // h/2 times the jump, 0.03 m/s^2 for the character's 0.25 s ramps of 12 m/s).
    constexpr double h = 1e-5;
    for (const auto& name : builtinTrajectoryNames()) {
        const Trajectory t = builtin(name);
        for (double time = 0.37; time < 59; time += 1.013) {
            const TruthState s = t.sample(time);
            const TruthState before = t.sample(time - h), after = t.sample(time + h);
            const glm::dvec3 velocity = (after.position - before.position) / (2 * h);
            const glm::dvec3 acceleration = (after.velocity - before.velocity) / (2 * h);
            EXPECT_LT(glm::length(velocity - s.velocity), 1e-4) << name << " t = " << time;
            EXPECT_LT(glm::length(acceleration - s.acceleration), 0.05) << name << " t = " << time;
            // q(t + h) = q(t) exp(w h) to first order: the body rate from the orientations.
            const glm::dquat step = glm::conjugate(before.orientation) * after.orientation;
            const glm::dvec3 rate = glm::dvec3(step.x, step.y, step.z) * (step.w < 0 ? -1.0 : 1.0) * (2 / (2 * h));
            EXPECT_LT(glm::length(rate - s.angularVelocity), 1e-4) << name << " t = " << time;
            EXPECT_NEAR(glm::length(s.orientation), 1, 1e-12);
        }
    }
}

TEST(NetsimTrajectory, SpeedsAreTheDocumentedOnes) {
    for (const auto& [name, speed] :
         std::vector<std::pair<std::string, double>>{{"slalom", 20}, {"circuit", 20}, {"aircraft-turn", 120}}) {
        const Trajectory t = builtin(name);
        for (double time = 0; time <= 60; time += 0.7)
            EXPECT_NEAR(glm::length(t.sample(time).velocity), speed, 1e-9) << name;
    }
    // The character runs at 6 m/s between its 0.25 s direction changes.
    const Trajectory run = builtin("run-strafe");
    EXPECT_NEAR(glm::length(run.sample(0.2).velocity), 6, 1e-12);
}

TEST(NetsimTrajectory, VehiclesFaceTheirVelocity) {
    // Body +Z forward: the orientation turns +Z onto the velocity's direction.
    for (const char* name : {"slalom", "circuit", "aircraft-turn"}) {
        const Trajectory t = builtin(name);
        for (double time = 0.1; time < 60; time += 1.3) {
            const TruthState s = t.sample(time);
            const glm::dvec3 forward = s.orientation * glm::dvec3(0, 0, 1);
            EXPECT_LT(glm::length(forward - glm::normalize(s.velocity)), 1e-9) << name << " t = " << time;
        }
    }
}

TEST(NetsimTrajectory, CircuitClosesAfterOneLap) {
    // A lap: 2 x (160 + 80) m of straights at 20 m/s, and 4 corners of 90 degrees at 0.5 rad/s,
    // each (pi/2) / 0.5 s plus its 0.5 s ease.
    const double lap = 2 * (160.0 + 80.0) / 20 + 4 * (0.5 * M_PI / 0.5 + 0.5);
    const Trajectory t = builtin("circuit");
    const TruthState start = t.sample(0), end = t.sample(lap);
    EXPECT_LT(glm::length(end.position - start.position), 1e-6);  // quadrature: < 1e-8 m a step
    EXPECT_LT(glm::length(end.velocity - start.velocity), 1e-9);
}

TEST(NetsimTrajectory, AircraftTurnIsCoordinated) {
    // In a coordinated turn the body's up axis carries the specific force a - g.
    const Trajectory t = builtin("aircraft-turn");
    for (const double time : {10.0, 20.0, 29.0, 70.0}) {
        const TruthState s = t.sample(time);
        const glm::dvec3 lift = glm::normalize(s.acceleration + glm::dvec3(0, 9.80665, 0));
        const glm::dvec3 up = s.orientation * glm::dvec3(0, 1, 0);
        EXPECT_LT(glm::length(up - lift), 1e-9) << "t = " << time;
    }
    EXPECT_GT(std::abs(t.sample(20).angularVelocity.y), 0.05);  // turning at 5 degrees/s
}

TEST(NetsimTrajectory, UnknownBuiltinIsRefused) {
    Trajectory t;
    EXPECT_FALSE(makeBuiltinTrajectory("helicopter", 10, t));
}

// ---------------------------------------------------------------------------------------------
// CSV

TEST(NetsimCsv, VelocitiesFromDifferencesAreExactForAParabola) {
    // p = (t^2, 1, 3 t) on uneven times: v = (2 t, 0, 3), a = (2, 0, 0).
    std::string text = "t,x,y,z\n";
    for (const double t : {0.0, 0.1, 0.35, 0.5, 0.9, 1.0})
        text += std::to_string(t) + "," + std::to_string(t * t) + ",1," + std::to_string(3 * t) + "\n";
    Trajectory t;
    std::string error;
    ASSERT_TRUE(parseTrajectoryCsv(text, "p.csv", t, error)) << error;
    EXPECT_EQ(t.start, 0);
    EXPECT_EQ(t.end, 1);
    for (const double time : {0.0, 0.2, 0.35, 0.77, 1.0}) {
        const TruthState s = t.sample(time);
        // The Hermite cubic through exact parabola values and slopes is the parabola.
        EXPECT_NEAR(s.position.x, time * time, 1e-12);
        EXPECT_NEAR(s.velocity.x, 2 * time, 1e-12);
        EXPECT_NEAR(s.velocity.z, 3, 1e-12);
        EXPECT_NEAR(s.acceleration.x, 2, 1e-10);
        EXPECT_EQ(s.orientation, glm::identity<glm::dquat>());
    }
}

TEST(NetsimCsv, OrientationAndAngularVelocityColumns) {
    // A quarter turn about +Y over 1 s, columns in any order, spaces and a comment allowed.
    const double c = std::cos(M_PI / 8), s = std::sin(M_PI / 8);
    const std::string text =
        "# yaw\nqw, qx, qy, qz, t, x, y, z, vx, vy, vz\n"
        "1,0,0,0, 0, 0,0,0, 1,0,0\n" +
        std::to_string(c) + ",0," + std::to_string(s) + ",0, 0.5, 0.5,0,0, 1,0,0\n" +
        "0.70710678118654752,0,0.70710678118654752,0, 1, 1,0,0, 1,0,0\n";
    Trajectory t;
    std::string error;
    ASSERT_TRUE(parseTrajectoryCsv(text, "yaw.csv", t, error)) << error;
    const TruthState mid = t.sample(0.75);
    EXPECT_NEAR(mid.angularVelocity.y, M_PI / 2, 1e-5);  // the rows' 7 digits
    EXPECT_NEAR(mid.position.x, 0.75, 1e-12);
    EXPECT_NEAR(rotationAngleDegrees(mid.orientation, glm::angleAxis(0.375 * M_PI, glm::dvec3(0, 1, 0))), 0, 1e-3);
}

TEST(NetsimCsv, ErrorsNameTheLineAndColumn) {
    struct Case {
        std::string text;
        std::string message;
    };
    const std::vector<Case> cases = {
        {"", "f.csv: empty: expected a header line"},
        {"t,x,y\n0,0,0\n1,1,1\n", "f.csv:1: missing required column \"z\""},
        {"t,x,y,z,speed\n", "f.csv:1: column 5: unknown column \"speed\""},
        {"t,x,y,z,x\n", "f.csv:1: column 5: \"x\" appears twice"},
        {"t,x,y,z,qw,qx\n", "f.csv:1: columns qw, qx, qy, qz come together (missing qy, qz)"},
        {"t,x,y,z\n0,0,0,0\n1,abc,0,0\n", "f.csv:3: column 2 (\"x\"): expected a finite number, got \"abc\""},
        {"t,x,y,z\n0,0,0,0\n1,1e999,0,0\n", "f.csv:3: column 2 (\"x\"): expected a finite number"},
        {"t,x,y,z\n0,0,0,0\n1,,0,0\n", "f.csv:3: column 2 (\"x\"): expected a finite number, got \"\""},
        {"t,x,y,z\n0,0,0,0\n1,0,0\n", "f.csv:3: expected 4 fields (as the header), got 3"},
        {"t,x,y,z\n0,0,0,0\n\n0,1,0,0\n", "f.csv:4: column 1 (\"t\"): time 0 is not after the previous row's 0"},
        {"t,x,y,z\n1,0,0,0\n0.5,1,0,0\n", "time 0.5 is not after the previous row's 1"},
        {"t,x,y,z\n0,0,0,0\n", "f.csv: expected at least 2 rows, got 1"},
        {"t,x,y,z,qw,qx,qy,qz\n0,0,0,0,0,0,0,0\n", "f.csv:2: column 5 (\"qw\"): the quaternion qw, qx, qy, qz is zero"},
        // Finite, but beyond what the sender's float fields hold: the row is named.
        {"t,x,y,z\n0,0,0,0\n1,1e300,0,0\n2,0,0,0\n", "f.csv:3: the position is beyond 1e30 m"},
        {"t,x,y,z\n0,0,0,0\n1e-300,1,0,0\n1,2,0,0\n",
         "f.csv:2: the velocity (from the positions and times around this row) is beyond 1e30"},
        {"t,x,y,z,wx,wy,wz\n0,0,0,0,0,1e39,0\n1,1,0,0,0,0,0\n", "f.csv:2: the angular velocity is beyond 1e30"},
        // Distinct times that the first row's time swallows: not silently merged.
        // (1e17 and the next double, 1e17 + 16, both become 2e17 once -1e17 is taken away.)
        {"t,x,y,z\n-1e17,0,0,0\n1e17,0,0,0\n1.0000000000000002e17,1,0,0\n",
         "f.csv:4: times 1e+17 and 1e+17 are too close"},
    };
    for (const auto& c : cases) {
        const std::string error = csvError(c.text);
        EXPECT_NE(error.find(c.message), std::string::npos) << "got: " << error << "\nexpected: " << c.message;
    }
}

// Spreadsheet habits: a UTF-8 byte order mark before the header, "+1" for 1.
TEST(NetsimCsv, ByteOrderMarkAndPlusSignsAreAccepted) {
    Trajectory t;
    std::string error;
    ASSERT_TRUE(parseTrajectoryCsv("\xEF\xBB\xBFt,x,y,z\n0,+1,0,0\n1,+2.5,0,-1\n", "bom.csv", t, error)) << error;
    EXPECT_EQ(t.sample(0.0).position, glm::dvec3(1, 0, 0));
    EXPECT_EQ(t.sample(1.0).position, glm::dvec3(2.5, 0, -1));
    EXPECT_NE(csvError("t,x,y,z\n0,+-1,0,0\n1,1,0,0\n").find("got \"+-1\""), std::string::npos);
}

// Absolute times (Unix time, or larger) are taken from the first row: the simulation's
// instants k / rate keep their resolution. Rows 64 s apart at 1e17 s (a double's step there is
// 16 s): 10 m/s along x, sampled exactly at the rows and half-way.
TEST(NetsimCsv, TimesAreTakenFromTheFirstRow) {
    std::string text = "t,x,y,z\n";
    for (int i = 0; i < 4; ++i) text += std::to_string(1e17 + 64.0 * i) + "," + std::to_string(640 * i) + ",0,0\n";
    Trajectory t;
    std::string error;
    ASSERT_TRUE(parseTrajectoryCsv(text, "unix.csv", t, error)) << error;
    EXPECT_EQ(t.start, 0.0);
    EXPECT_EQ(t.end, 192.0);
    EXPECT_NEAR(t.sample(96.0).position.x, 960.0, 1e-9);  // linear rows: exact up to rounding
    EXPECT_NEAR(t.sample(100.0).velocity.x, 10.0, 1e-12);
    EXPECT_NE(t.description.find("times from the first row's"), std::string::npos) << t.description;
}

TEST(NetsimCsv, RowCountIsCapped) {
    std::string text = "t,x,y,z\n";
    text.reserve(kMaxCsvRows * 12);
    for (std::size_t i = 0; i <= kMaxCsvRows; ++i) text += std::to_string(i) + ",0,0,0\n";
    const std::string error = csvError(text);
    EXPECT_NE(error.find("too many rows (the limit is 1000000)"), std::string::npos) << error;
}

// ---------------------------------------------------------------------------------------------
// Link and statistics

TEST(NetsimLink, LossIsWithinBinomialBoundsAndDelaysWithinTheJitter) {
    LinkSettings settings;
    settings.latency = 0.1;
    settings.jitter = 0.02;
    settings.loss = 0.1;
    settings.seed = 7;
    Link link(settings);
    constexpr int n = 100000;
    int lost = 0;
    double low = 1, high = 0, sum = 0;
    for (int i = 0; i < n; ++i) {
        double delay = -1;
        if (!link.transmit(delay)) {
            ++lost;
            continue;
        }
        low = std::min(low, delay);
        high = std::max(high, delay);
        sum += delay;
    }
    // Binomial(100000, 0.1): mean 10000, standard deviation 94.9; 5 deviations either side.
    EXPECT_NEAR(lost, 10000, 475);
    EXPECT_GE(low, 0.08);
    EXPECT_LE(high, 0.12);
    EXPECT_LT(low, 0.0801);  // 90000 uniform draws reach within 1e-4 of the ends
    EXPECT_GT(high, 0.1199);
    EXPECT_NEAR(sum / (n - lost), 0.1, 1e-3);  // uniform: mean = latency (sd 3.8e-5 of the mean)
}

TEST(NetsimLink, SameSeedSameFatesAndNoNegativeDelay) {
    LinkSettings settings;
    settings.latency = 0.005;
    settings.jitter = 0.02;  // more jitter than latency: delays clamp at 0
    settings.loss = 0.3;
    Link a(settings), b(settings);
    settings.seed = 2;
    Link c(settings);
    int differences = 0;
    for (int i = 0; i < 1000; ++i) {
        double da = -1, db = -1, dc = -1;
        const bool ka = a.transmit(da), kb = b.transmit(db), kc = c.transmit(dc);
        EXPECT_EQ(ka, kb);
        EXPECT_EQ(da, db);
        if (ka) {
            EXPECT_GE(da, 0);
        }
        differences += (ka != kc || da != dc) ? 1 : 0;
    }
    EXPECT_GT(differences, 500);
    // No jitter, no loss: the latency exactly.
    Link exact(LinkSettings{0.1, 0, 0, 1});
    double delay = 0;
    ASSERT_TRUE(exact.transmit(delay));
    EXPECT_EQ(delay, 0.1);
}

TEST(NetsimStatistics, SummaryAndRotationAngle) {
    std::vector<double> values;
    for (int i = 100; i >= 1; --i) values.push_back(i);
    const Summary s = summarise(values);
    EXPECT_DOUBLE_EQ(s.mean, 50.5);
    EXPECT_EQ(s.p95, 95);  // nearest rank: the 95th of 100
    EXPECT_EQ(s.max, 100);
    std::vector<double> none;
    EXPECT_EQ(summarise(none).max, 0);
    std::vector<double> one = {3};
    EXPECT_EQ(summarise(one).p95, 3);

    const glm::dquat q = glm::angleAxis(0.3, glm::normalize(glm::dvec3(1, 2, 3)));
    const glm::dquat r = q * glm::angleAxis(M_PI / 2, glm::dvec3(0, 0, 1));
    EXPECT_NEAR(rotationAngleDegrees(q, r), 90, 1e-12);
    EXPECT_NEAR(rotationAngleDegrees(q, -q), 0, 1e-12);  // the same rotation
}

TEST(NetsimDisplay, NamesRoundTrip) {
    for (const Display d : allDisplays()) {
        Display found = Display::Snap;
        EXPECT_TRUE(findDisplay(displayName(d), found));
        EXPECT_EQ(found, d);
    }
    Display unused;
    EXPECT_FALSE(findDisplay("smooth", unused));
}

// ---------------------------------------------------------------------------------------------
// Simulations

SimulationSettings perfectLink() {
    SimulationSettings settings;
    settings.link = LinkSettings{0, 0, 0, 1};
    settings.duration = 20;
    settings.displays = allDisplays();
    return settings;
}

TEST(NetsimSimulation, PerfectLinkAndFpwOnAStraightLineShowTheTruth) {
    // 5 m/s along +X with the velocity given: FPW extrapolates p + v t exactly.
    std::string text = "t,x,y,z,vx,vy,vz\n";
    for (int i = 0; i <= 30; ++i) text += std::to_string(i) + "," + std::to_string(5 * i) + ",0,2,5,0,0\n";
    Trajectory line;
    std::string error;
    ASSERT_TRUE(parseTrajectoryCsv(text, "line.csv", line, error)) << error;
    SimulationSettings settings = perfectLink();
    settings.models = {DeadReckoningAlgorithm::Fpw};
    TrajectoryResult result;
    ASSERT_TRUE(simulateTrajectory(line, settings, false, result, error)) << error;
    ASSERT_EQ(result.models.size(), 1u);
    const ModelResult& fpw = result.models[0];
    // The first update and a heartbeat every 5 s (t = 0, 5, 10, 15 and 20 or just after).
    EXPECT_GE(fpw.updates, 4u);
    EXPECT_LE(fpw.updates, 5u);
    EXPECT_EQ(fpw.lost, 0u);
    EXPECT_NEAR(result.distance, 100, 1e-9);
    for (const DisplayResult& d : fpw.displays) {
        EXPECT_EQ(d.frames, 1201u) << displayName(d.display);  // 20 s at 60 Hz, both ends
        EXPECT_EQ(d.jumps, 0u) << displayName(d.display);
        EXPECT_LT(d.orientation.max, 1e-9);
        if (d.display == Display::Interpolate) continue;
        // predictDeadReckoning takes the age as a float: half an ulp of up to 5 s (2.4e-7 s)
        // at 5 m/s is 1.2e-6 m.
        EXPECT_LT(d.position.max, 2e-6) << displayName(d.display);
    }
}

TEST(NetsimSimulation, RpbFollowsTheCircuitBetterThanFpwWithFewerUpdates) {
    SimulationSettings settings = perfectLink();
    settings.link.latency = 0.1;
    settings.duration = 60;
    settings.models = {DeadReckoningAlgorithm::Fpw, DeadReckoningAlgorithm::Rpb};
    settings.displays = {Display::Snap, Display::Projective};
    TrajectoryResult result;
    std::string error;
    ASSERT_TRUE(simulateTrajectory(builtin("circuit"), settings, false, result, error)) << error;
    const ModelResult& fpw = result.models[0];
    const ModelResult& rpb = result.models[1];
    EXPECT_LT(rpb.updates, fpw.updates);
    for (std::size_t d = 0; d < 2; ++d) {
        EXPECT_LT(rpb.displays[d].position.mean, fpw.displays[d].position.mean) << d;
        // The sender's threshold (1 m) plus what 100 ms of latency adds on a 40 m corner.
        EXPECT_LT(rpb.displays[d].position.max, 1.5) << d;
    }
}

TEST(NetsimSimulation, SameSettingsSameReportDifferentSeedDifferentLosses) {
    SimulationSettings settings;
    settings.duration = 20;
    settings.link.loss = 0.2;
    settings.models = {DeadReckoningAlgorithm::Static, DeadReckoningAlgorithm::Rvw};
    settings.displays = allDisplays();
    std::vector<TrajectoryResult> first(1), second(1), other(1);
    std::string error;
    const Trajectory t = builtin("run-strafe", 20);
    ASSERT_TRUE(simulateTrajectory(t, settings, true, first[0], error)) << error;
    ASSERT_TRUE(simulateTrajectory(t, settings, true, second[0], error)) << error;
    EXPECT_EQ(textTable(first, settings), textTable(second, settings));
    EXPECT_EQ(svgChart(first[0], 0, settings), svgChart(second[0], 0, settings));
    settings.link.seed = 99;
    ASSERT_TRUE(simulateTrajectory(t, settings, false, other[0], error)) << error;
    EXPECT_NE(textTable(first, settings), textTable(other, settings));
}

TEST(NetsimSimulation, EverythingLostShowsNothing) {
    SimulationSettings settings = perfectLink();
    settings.link.loss = 1;
    settings.models = {DeadReckoningAlgorithm::Fpw};
    TrajectoryResult result;
    std::string error;
    ASSERT_TRUE(simulateTrajectory(builtin("slalom", 20), settings, false, result, error)) << error;
    EXPECT_EQ(result.models[0].lost, result.models[0].updates);
    for (const DisplayResult& d : result.models[0].displays) EXPECT_EQ(d.frames, 0u);
    // The reports say there is no error to report, not a perfect zero.
    const std::string text = textTable({result}, settings);
    EXPECT_EQ(text.find("0.000"), std::string::npos) << text;
    EXPECT_NE(text.find("        -         -         -"), std::string::npos) << text;
    const std::string markdown = markdownTable({result}, settings);
    EXPECT_NE(markdown.find(" - / - / 0 |"), std::string::npos) << markdown;
    EXPECT_EQ(markdown.find("0.00 / 0.00"), std::string::npos) << markdown;
}

// Snapshots: every sender tick sends (60 s at 20 Hz: 1201 ticks, k / 20 for k = 0..1200),
// whatever the thresholds say, and they are counted as snapshots, not as threshold reasons.
TEST(NetsimSimulation, SnapshotSenderSendsEveryTick) {
    SimulationSettings settings = perfectLink();
    settings.snapshots = true;
    settings.sendRate = 20;
    settings.duration = 60;
    settings.models = {DeadReckoningAlgorithm::Fpw};
    TrajectoryResult result;
    std::string error;
    ASSERT_TRUE(simulateTrajectory(builtin("circuit", 60), settings, false, result, error)) << error;
    const ModelResult& m = result.models[0];
    EXPECT_EQ(m.updates, 1201u);
    EXPECT_EQ(m.sentSnapshot, 1201u);
    EXPECT_EQ(m.sentFirst + m.sentPosition + m.sentOrientation + m.sentHeartbeat, 0u);
    EXPECT_NE(settingsLine(settings).find("sender: a snapshot every tick"), std::string::npos);
}

// The sender's reasons are counted per model: the first update once, then position threshold
// crossings and heartbeats; every update has at least one reason.
TEST(NetsimSimulation, SendReasonsAreCounted) {
    SimulationSettings settings = perfectLink();
    settings.models = {DeadReckoningAlgorithm::Static, DeadReckoningAlgorithm::Fpw};
    TrajectoryResult result;
    std::string error;
    ASSERT_TRUE(simulateTrajectory(builtin("slalom", 20), settings, false, result, error)) << error;
    for (const ModelResult& m : result.models) {
        EXPECT_EQ(m.sentFirst, 1u);
        EXPECT_GE(m.sentFirst + m.sentPosition + m.sentOrientation + m.sentHeartbeat, m.updates);
        EXPECT_LE(m.sentPosition, m.updates);
    }
    // STATIC on a car at 20 m/s: past the 1 m threshold every 0.05 s, i.e. every 30 Hz tick or
    // so, all for position; FPW sends far less.
    // (1 m at 20 m/s is 0.05 s: every other 30 Hz tick, 15 Hz over 20 s.)
    EXPECT_GE(result.models[0].sentPosition, 290u);
    EXPECT_LT(result.models[1].updates, result.models[0].updates / 2);
}

TEST(NetsimReport, TablesNameEveryRowAndTheSvgHasItsAxes) {
    SimulationSettings settings;
    settings.duration = 5;
    settings.models = {DeadReckoningAlgorithm::Fpw, DeadReckoningAlgorithm::Rpb};
    settings.displays = allDisplays();
    std::vector<TrajectoryResult> results(1);
    std::string error;
    ASSERT_TRUE(simulateTrajectory(builtin("slalom", 5), settings, true, results[0], error)) << error;
    const std::string markdown = markdownTable(results, settings);
    EXPECT_EQ(markdown.rfind("| Trajectory | Model | Updates/s | snap | linear | pvb | decay | interpolate |\n", 0),
              0u);
    EXPECT_NE(markdown.find("| slalom | RPB |"), std::string::npos);
    const std::string text = textTable(results, settings);
    EXPECT_NE(text.find("slalom           FPW    interpolate"), std::string::npos) << text;
    const std::string svg = svgChart(results[0], 1, settings);
    for (const char* part :
         {"<svg", "time [s]", "position error [m]", "slalom, RPB", "snap (p95", "interpolate (p95", "</svg>"})
        EXPECT_NE(svg.find(part), std::string::npos) << part;
}

}  // namespace
