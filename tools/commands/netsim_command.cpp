// `foresight netsim`: options, checks, the JSON report, files and progress (the simulation and
// the other reports are in netsim/netsim.cpp).

#include "netsim_command.h"

#include "json_output.h"
#include "text_file.h"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace foresight_cli {

namespace {

using foresight::DeadReckoningAlgorithm;
namespace ns = netsim;

/// The models run when --models is not given: no dead reckoning (STATIC: every move beyond the
/// threshold is an update), then the DIS models a game would pick.
const std::vector<DeadReckoningAlgorithm> kDefaultModels = {DeadReckoningAlgorithm::Static, DeadReckoningAlgorithm::Fpw,
                                                            DeadReckoningAlgorithm::Rvw, DeadReckoningAlgorithm::Rpb,
                                                            DeadReckoningAlgorithm::Rvb};

bool fail(const std::string& message) {
    std::cerr << "foresight netsim: " << message << '\n';
    return false;
}

/// Checks `value` in [low, high] (strict ends when asked) and says so when it is not.
bool inRange(const char* option, double value, double low, double high, bool lowOpen, const char* unit) {
    const bool ok = std::isfinite(value) && (lowOpen ? value > low : value >= low) && value <= high;
    if (ok) return true;
    return fail(std::string(option) + " must be " + (lowOpen ? "> " : ">= ") + shortNumber(low) +
                " and <= " + shortNumber(high) + (unit[0] ? std::string(" ") + unit : std::string()) + " (got " +
                shortNumber(value) + ")");
}

bool parseLoss(const std::string& text, double& loss) {
    std::string_view number = text;
    const bool percent = !number.empty() && number.back() == '%';
    if (percent) number.remove_suffix(1);
    double value = 0;
    const auto result = std::from_chars(number.data(), number.data() + number.size(), value);
    if (number.empty() || result.ec != std::errc() || result.ptr != number.data() + number.size() ||
        !std::isfinite(value))
        return fail("--loss: expected a fraction (0.02) or a percentage (2%), got \"" + text + "\"");
    if (percent) value /= 100;
    if (!(value >= 0 && value <= 1))
        return fail("--loss must be between 0 and 1 (a fraction: 0.02 is 2%; or write 2%), got \"" + text + "\"");
    loss = value;
    return true;
}

std::vector<std::string> splitList(const std::vector<std::string>& items) {
    std::vector<std::string> out;
    for (const auto& item : items) {
        std::size_t begin = 0;
        for (;;) {
            const std::size_t comma = item.find(',', begin);
            const std::string part = item.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin);
            if (!part.empty()) out.push_back(part);
            if (comma == std::string::npos) break;
            begin = comma + 1;
        }
    }
    return out;
}

}  // namespace

bool buildNetsimSettings(const NetsimOptions& o, ns::SimulationSettings& settings) {
    if (!inRange("--duration", o.duration, 0, ns::kMaxDuration, true, "s") ||
        !inRange("--latency", o.latency, 0, 10000, false, "ms") ||
        !inRange("--jitter", o.jitter, 0, 10000, false, "ms") ||
        !inRange("--send-rate", o.sendRate, 1, 1000, false, "Hz") ||
        !inRange("--render-rate", o.renderRate, 1, 1000, false, "Hz") ||
        !inRange("--position-threshold", o.positionThreshold, 0, 1e6, true, "m") ||
        !inRange("--orientation-threshold", o.orientationThreshold, 0, 180, true, "degrees") ||
        !inRange("--heartbeat", o.heartbeat, 0, 3600, true, "s") ||
        !inRange("--jump-threshold", o.jumpThreshold, 0, 1e6, true, "m") ||
        !inRange("--blend-time", o.blendTime, 0, 60000, true, "ms") ||
        !inRange("--decay-half-life", o.decayHalfLife, 0, 60000, true, "ms") ||
        !inRange("--teleport-distance", o.teleportDistance, 0, 1e6, true, "m") ||
        (o.interpolationDelayGiven && !inRange("--interpolation-delay", o.interpolationDelay, 0, 60000, true, "ms")) ||
        (o.extrapolationLimitGiven && !inRange("--extrapolation-limit", o.extrapolationLimit, 0, 3.6e6, false, "ms")))
        return false;
    if (o.csvGiven && o.csvFile.empty()) return fail("--csv: expected a file name, got \"\"");
    // An option given with nothing in it (--models '') is a mistake, not a request for the default.
    for (const auto& [option, items] :
         {std::pair<const char*, const std::vector<std::string>*>{"--trajectory", &o.trajectories},
          {"--models", &o.models},
          {"--smoothing", &o.smoothings}})
        if (!items->empty() && splitList(*items).empty())
            return fail(std::string(option) + ": expected a name or a comma-separated list, got \"\"");
    {
        // Digits only: CLI11 (and strtoull) would take "-1" as 2^64 - 1 and saturate overflows.
        const std::string& text = o.seed;
        std::uint64_t seed = 0;
        const auto result = std::from_chars(text.data(), text.data() + text.size(), seed);
        if (text.empty() || text.front() == '-' || text.front() == '+' || result.ec != std::errc() ||
            result.ptr != text.data() + text.size())
            return fail("--seed: expected an unsigned 64-bit integer (0 to 18446744073709551615), got \"" + text +
                        "\"");
        settings.link.seed = seed;
    }
    // The sender sends when the receivers' extrapolation drifts, seconds apart on a smooth
    // path: a receiver that stops extrapolating after Source's 0.25 s would stand still.
    settings.receiver.extrapolationLimit = !o.extrapolationLimitGiven ? std::numeric_limits<float>::infinity()
                                                                      : static_cast<float>(o.extrapolationLimit / 1000);
    settings.receiver.teleportDistance = static_cast<float>(o.teleportDistance);
    settings.duration = o.duration;
    settings.sendRate = o.sendRate;
    if (o.sender == "snapshots")
        settings.snapshots = true;
    else if (o.sender != "thresholds")
        return fail("--sender: expected thresholds or snapshots, got \"" + o.sender + "\"");
    settings.renderRate = o.renderRate;
    settings.link.latency = o.latency / 1000;
    settings.link.jitter = o.jitter / 1000;
    if (!parseLoss(o.loss, settings.link.loss)) return false;
    settings.sender.positionThreshold = static_cast<float>(o.positionThreshold);
    settings.sender.orientationThreshold = static_cast<float>(o.orientationThreshold * 3.14159265358979323846 / 180);
    settings.sender.heartbeat = static_cast<float>(o.heartbeat);
    settings.jumpThreshold = o.jumpThreshold;
    settings.receiver.blendTime = static_cast<float>(o.blendTime / 1000);
    settings.receiver.decayHalfLife = static_cast<float>(o.decayHalfLife / 1000);
    // Sender and receiver share one clock here, so interpolation must wait out the network
    // delay as well as Source's 100 ms.
    const double delay = !o.interpolationDelayGiven ? o.latency + o.jitter + 100 : o.interpolationDelay;
    settings.receiver.interpolationDelay = static_cast<float>(delay / 1000);

    const auto models = splitList(o.models);
    if (models.empty()) settings.models = kDefaultModels;
    for (const auto& name : models) {
        std::string upper = name;
        std::transform(upper.begin(), upper.end(), upper.begin(),
                       [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
        if (upper == "ALL") {
            for (int a = 1; a <= foresight::kDeadReckoningAlgorithmCount; ++a)
                settings.models.push_back(static_cast<DeadReckoningAlgorithm>(a));
            continue;
        }
        DeadReckoningAlgorithm algorithm;
        if (!foresight::findDeadReckoningAlgorithm(upper, algorithm))
            return fail("--models: unknown model \"" + name +
                        "\" (expected STATIC, FPW, RPW, RVW, FVW, FPB, RPB, RVB, FVB or all)");
        if (std::find(settings.models.begin(), settings.models.end(), algorithm) == settings.models.end())
            settings.models.push_back(algorithm);
    }
    const auto displays = splitList(o.smoothings);
    if (displays.empty()) settings.displays = ns::allDisplays();
    for (const auto& name : displays) {
        if (name == "all") {
            for (const ns::Display d : ns::allDisplays())
                if (std::find(settings.displays.begin(), settings.displays.end(), d) == settings.displays.end())
                    settings.displays.push_back(d);
            continue;
        }
        ns::Display display;
        if (!ns::findDisplay(name, display))
            return fail("--smoothing: unknown smoothing \"" + name +
                        "\" (expected snap, linear, pvb, decay, interpolate or all)");
        if (std::find(settings.displays.begin(), settings.displays.end(), display) == settings.displays.end())
            settings.displays.push_back(display);
    }
    if (o.json && o.markdown) return fail("--json and --markdown contradict each other");
    if (o.svgFile == "-") return fail("--svg: give a file name (standard output carries the report)");
    return true;
}

namespace {

Json rounded(double value) {
    // Micrometres and micro-degrees: enough for any chart, and short to read.
    return jsonDouble(std::round(value * 1e6) / 1e6);
}

Json summaryJson(const ns::Summary& s) {
    Json out = Json::object();
    out["mean"] = rounded(s.mean);
    out["p95"] = rounded(s.p95);
    out["max"] = rounded(s.max);
    return out;
}

std::string reportJson(const std::vector<ns::TrajectoryResult>& results, const ns::SimulationSettings& s) {
    Json settings = Json::object();
    settings["duration"] = jsonDouble(s.duration);
    settings["send_rate"] = jsonDouble(s.sendRate);
    settings["sender"] = s.snapshots ? "snapshots" : "thresholds";
    settings["render_rate"] = jsonDouble(s.renderRate);
    settings["latency"] = jsonDouble(s.link.latency);
    settings["jitter"] = jsonDouble(s.link.jitter);
    settings["loss"] = jsonDouble(s.link.loss);
    settings["seed"] = s.link.seed;
    settings["position_threshold"] = jsonFloat(s.sender.positionThreshold);
    settings["orientation_threshold"] =
        rounded(static_cast<double>(s.sender.orientationThreshold) * 180 / 3.14159265358979323846);
    settings["heartbeat"] = jsonFloat(s.sender.heartbeat);
    settings["blend_time"] = jsonFloat(s.receiver.blendTime);
    settings["decay_half_life"] = jsonFloat(s.receiver.decayHalfLife);
    settings["interpolation_delay"] = jsonFloat(s.receiver.interpolationDelay);
    // null: no limit (JSON has no infinity).
    settings["extrapolation_limit"] =
        std::isinf(s.receiver.extrapolationLimit) ? Json(nullptr) : jsonFloat(s.receiver.extrapolationLimit);
    settings["teleport_distance"] = jsonFloat(s.receiver.teleportDistance);
    settings["jump_threshold"] = jsonDouble(s.jumpThreshold);
    Json trajectories = Json::array();
    for (const auto& t : results) {
        Json models = Json::array();
        for (const auto& m : t.models) {
            Json displays = Json::array();
            for (const auto& d : m.displays) {
                Json display = Json::object();
                display["display"] = ns::displayName(d.display);
                display["frames"] = d.frames;
                // null when no frame was shown (every update lost): no error, not a zero one.
                display["position_error"] = d.frames == 0 ? Json(nullptr) : summaryJson(d.position);
                display["orientation_error"] = d.frames == 0 ? Json(nullptr) : summaryJson(d.orientation);
                display["snaps"] = d.snaps;
                display["jumps"] = d.jumps;
                display["dropped"] = d.dropped;
                displays.push_back(std::move(display));
            }
            Json model = Json::object();
            model["model"] = foresight::deadReckoningAlgorithmName(m.model);
            model["updates"] = m.updates;
            model["updates_per_second"] = rounded(m.updatesPerSecond);
            model["lost"] = m.lost;
            model["late"] = m.late;
            model["reordered"] = m.reordered;
            Json reasons = Json::object();
            reasons["first"] = m.sentFirst;
            reasons["position"] = m.sentPosition;
            reasons["orientation"] = m.sentOrientation;
            reasons["heartbeat"] = m.sentHeartbeat;
            reasons["snapshot"] = m.sentSnapshot;
            model["send_reasons"] = std::move(reasons);
            model["displays"] = std::move(displays);
            models.push_back(std::move(model));
        }
        Json trajectory = Json::object();
        trajectory["name"] = t.name;
        trajectory["description"] = t.description;
        trajectory["duration"] = rounded(t.duration);
        trajectory["distance"] = rounded(t.distance);
        trajectory["models"] = std::move(models);
        trajectories.push_back(std::move(trajectory));
    }
    Json document = Json::object();
    document["settings"] = std::move(settings);
    document["trajectories"] = std::move(trajectories);
    return formatJson(document);
}

}  // namespace

CLI::App* addNetsimCommand(CLI::App& app, NetsimOptions& o) {
    CLI::App* netsim =
        app.add_subcommand("netsim",
                           "Send trajectories through a simulated link (latency, jitter, loss) with dead reckoning and "
                           "measure what receivers show");
    netsim
        ->add_option("--trajectory", o.trajectories,
                     "built-in trajectories: run-strafe, slalom, circuit, aircraft-turn or all (default: all; "
                     "comma-separated or repeated)")
        ->type_name("NAME");
    netsim->add_option("--csv", o.csvFile, "a trajectory from CSV: t,x,y,z[,qw,qx,qy,qz][,vx,vy,vz][,wx,wy,wz]")
        ->type_name("FILE");
    CLI::Option* duration =
        netsim->add_option("--duration", o.duration, "simulated seconds (default 60, at most 3600)")->type_name("S");
    netsim->add_option("--latency", o.latency, "one-way delay in ms (default 100)")->type_name("MS");
    netsim->add_option("--jitter", o.jitter, "delay varies uniformly by +/- this many ms (default 20)")
        ->type_name("MS");
    netsim->add_option("--loss", o.loss, "fraction of packets lost, 0.02 or 2% (default 2%)")->type_name("P");
    netsim->add_option("--seed", o.seed, "the link's random seed (default 1)")->type_name("N");
    netsim->add_option("--send-rate", o.sendRate, "sender ticks per second (default 30)")->type_name("HZ");
    netsim->add_option("--render-rate", o.renderRate, "receiver frames per second (default 60)")->type_name("HZ");
    netsim
        ->add_option("--sender", o.sender,
                     "thresholds: dead reckoning, send when the error crosses a threshold (default); snapshots: "
                     "send every tick (with --send-rate 20: Source's snapshots)")
        ->type_name("KIND");
    netsim->add_option("--models", o.models, "DIS models, comma-separated, or all (default STATIC,FPW,RVW,RPB,RVB)")
        ->type_name("LIST");
    netsim
        ->add_option("--smoothing", o.smoothings,
                     "receivers: snap, linear, pvb, decay, interpolate, comma-separated, or all (default all)")
        ->type_name("LIST");
    netsim->add_option("--position-threshold", o.positionThreshold, "the sender's position threshold in m (default 1)")
        ->type_name("M");
    netsim
        ->add_option("--orientation-threshold", o.orientationThreshold,
                     "the sender's orientation threshold in degrees (default 3)")
        ->type_name("DEG");
    netsim->add_option("--heartbeat", o.heartbeat, "send at least this often, in s (default 5)")->type_name("S");
    netsim
        ->add_option("--jump-threshold", o.jumpThreshold,
                     "a frame whose shown motion differs from the true motion by more than this many m is a "
                     "visible jump (default 0.25)")
        ->type_name("M");
    netsim->add_option("--blend-time", o.blendTime, "linear and pvb blend duration in ms (default 200)")
        ->type_name("MS");
    netsim->add_option("--decay-half-life", o.decayHalfLife, "decay's half-life in ms (default 100)")->type_name("MS");
    CLI::Option* interpolationDelay =
        netsim
            ->add_option("--interpolation-delay", o.interpolationDelay,
                         "how far in the past interpolate renders, in ms (default latency + jitter + 100)")
            ->type_name("MS");
    CLI::Option* extrapolationLimit =
        netsim
            ->add_option("--extrapolation-limit", o.extrapolationLimit,
                         "receivers hold after extrapolating this many ms past the newest update (default: never)")
            ->type_name("MS");
    netsim
        ->add_option("--teleport-distance", o.teleportDistance,
                     "receivers snap instead of blending a correction (interpolate: an update off the previous "
                     "one's prediction) longer than this many m (default 10)")
        ->type_name("M");
    netsim->add_flag("--json", o.json, "write every result as JSON instead of the table");
    netsim->add_flag("--markdown", o.markdown, "write the summary table of docs/results.md (Markdown) instead");
    netsim
        ->add_option("--svg", o.svgFile,
                     "also write position error over time (first trajectory, first model other than STATIC) to FILE")
        ->type_name("FILE");
    // CLI11 reads an empty number ("--latency ''") as 0: the numeric options refuse it (the
    // others say so in their own parsers).
    const CLI::Validator number(
        [](std::string& value) {
            return value.find_first_not_of(" \t") == std::string::npos
                       ? std::string("expected a number, got \"") + value + "\""
                       : std::string();
        },
        "", "number");
    for (CLI::Option* option : netsim->get_options()) {
        const std::string unit = option->get_type_name();
        if (unit == "MS" || unit == "S" || unit == "HZ" || unit == "M" || unit == "DEG") option->check(number);
    }
    CLI::Option* csv = netsim->get_option("--csv");
    netsim->final_callback([&o, duration, interpolationDelay, extrapolationLimit, csv] {
        o.durationGiven = duration->count() > 0;
        o.interpolationDelayGiven = interpolationDelay->count() > 0;
        o.extrapolationLimitGiven = extrapolationLimit->count() > 0;
        o.csvGiven = csv->count() > 0;
    });
    return netsim;
}

int netsimCommand(NetsimOptions options) {
    ns::SimulationSettings settings;
    if (!buildNetsimSettings(options, settings)) return 2;

    // The trajectories: the built-ins asked for (all by default, none when only --csv is given),
    // then the CSV file.
    std::vector<std::string> names = splitList(options.trajectories);
    if (names.empty() && options.csvFile.empty()) names.push_back("all");
    // "all" expanded, each trajectory once (as --models does for models), in the order given.
    std::vector<std::string> wanted;
    for (const auto& name : names) {
        std::vector<std::string> expanded =
            name == "all" ? ns::builtinTrajectoryNames() : std::vector<std::string>{name};
        for (auto& n : expanded)
            if (std::find(wanted.begin(), wanted.end(), n) == wanted.end()) wanted.push_back(std::move(n));
    }
    std::vector<ns::Trajectory> trajectories;
    for (const auto& name : wanted) {
        ns::Trajectory t;
        if (!ns::makeBuiltinTrajectory(name, settings.duration, t)) {
            fail("--trajectory: unknown trajectory \"" + name +
                 "\" (expected run-strafe, slalom, circuit, aircraft-turn or all)");
            return 2;
        }
        trajectories.push_back(std::move(t));
    }
    if (!options.csvFile.empty()) {
        const std::string name = options.csvFile == "-" ? std::string("<stdin>") : options.csvFile;
        std::string text, reason;
        if (!readTextFile(options.csvFile, text, reason)) {
            std::cerr << name << ": cannot read: " << reason << '\n';
            return 2;
        }
        ns::Trajectory t;
        if (!ns::parseTrajectoryCsv(text, name, t, reason)) {
            std::cerr << reason << '\n';
            return 2;
        }
        if (options.durationGiven && t.end - t.start < settings.duration)
            std::cerr << "warning: " << name << " covers " << shortNumber(t.end - t.start)
                      << " s; simulating that, not " << shortNumber(settings.duration) << " s\n";
        trajectories.push_back(std::move(t));
    }

    const bool showProgress = isatty(STDERR_FILENO) == 1;
    std::vector<ns::TrajectoryResult> results;
    for (std::size_t i = 0; i < trajectories.size(); ++i) {
        ns::TrajectoryResult result;
        std::string error;
        const bool ok = ns::simulateTrajectory(trajectories[i], settings, i == 0 && !options.svgFile.empty(), result,
                                               error, [&](std::size_t done, std::size_t total) {
                                                   if (showProgress)
                                                       std::fprintf(stderr, "\rnetsim: %s (%zu/%zu), model %zu/%zu   ",
                                                                    trajectories[i].name.c_str(), i + 1,
                                                                    trajectories.size(), done, total);
                                               });
        if (!ok) {
            if (showProgress) std::fprintf(stderr, "\n");
            std::cerr << "foresight netsim: " << trajectories[i].name << ": " << error << '\n';
            return 2;
        }
        results.push_back(std::move(result));
    }
    if (showProgress) std::fprintf(stderr, "\r%70s\r", "");

    std::string reason;
    // The chart shows the first dead-reckoning model (STATIC, when listed first, is the
    // no-prediction baseline: the table has it), else the first model.
    std::size_t chartModel = 0;
    const auto& chartModels = results.front().models;
    while (chartModel + 1 < chartModels.size() &&
           chartModels[chartModel].model == foresight::DeadReckoningAlgorithm::Static)
        ++chartModel;
    if (!options.svgFile.empty() &&
        !writeTextFile(options.svgFile, ns::svgChart(results.front(), chartModel, settings), reason)) {
        std::cerr << options.svgFile << ": cannot write: " << reason << '\n';
        return 2;
    }
    const std::string text = options.json       ? reportJson(results, settings)
                             : options.markdown ? ns::markdownTable(results, settings)
                                                : ns::textTable(results, settings);
    if (!writeTextFile("-", text, reason)) {
        std::cerr << "foresight netsim: cannot write the report: " << reason << '\n';
        return 1;
    }
    return 0;
}

}  // namespace foresight_cli
