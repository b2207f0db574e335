#pragma once
/// @file netsim_command.h
/// `foresight netsim`: its options, their checks and the command (reports: netsim.h).

#include "netsim.h"

#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace foresight_cli {

/// The options of `foresight netsim` as given (checked by netsimCommand; docs/netsim.md).
struct NetsimOptions {
    std::vector<std::string> trajectories;  ///< built-in names or "all"; empty: all (none with --csv).
    std::string csvFile;                    ///< a CSV trajectory (netsim::parseTrajectoryCsv).
    double duration = 60;                   ///< [Units: s] (0, 3600].
    bool durationGiven = false;             ///< --duration was given (a CSV shorter than it warns).
    double latency = 100;                   ///< [Units: ms] [0, 10000].
    double jitter = 20;                     ///< [Units: ms] [0, 10000].
    std::string loss = "0.02";              ///< a fraction in [0, 1] or a percentage ("2%").
    std::string seed = "1";                 ///< the link's seed: an unsigned 64-bit decimal.
    double sendRate = 30;                   ///< [Units: Hz] [1, 1000].
    std::string sender = "thresholds";      ///< "thresholds" (DIS dead reckoning) or "snapshots".
    double renderRate = 60;                 ///< [Units: Hz] [1, 1000].
    std::vector<std::string> models;        ///< DIS names (any case) or "all"; empty: the default set.
    std::vector<std::string> smoothings;    ///< display names or "all"; empty: all.
    double positionThreshold = 1;           ///< [Units: m] > 0.
    double orientationThreshold = 3;        ///< [Units: degrees] (0, 180].
    double heartbeat = 5;                   ///< [Units: s] > 0.
    double jumpThreshold = 0.25;            ///< [Units: m] > 0.
    double blendTime = 200;                 ///< [Units: ms] > 0.
    double decayHalfLife = 100;             ///< [Units: ms] > 0.
    double interpolationDelay = 0;          ///< [Units: ms] > 0 (when given).
    bool interpolationDelayGiven = false;   ///< otherwise: latency + jitter + 100.
    double extrapolationLimit = 0;          ///< [Units: ms] >= 0 (when given).
    bool extrapolationLimitGiven = false;   ///< otherwise: none (infinity).
    double teleportDistance = 10;           ///< [Units: m] > 0: receivers snap beyond it.
    bool csvGiven = false;                  ///< --csv was given (an empty name is refused).
    bool json = false;                      ///< JSON on standard output instead of the table.
    bool markdown = false;                  ///< the Markdown table of docs/results.md instead.
    std::string svgFile;                    ///< also write the error chart here.
};

/// Adds the `netsim` subcommand and its options (filling `options`) to `app`.
CLI::App* addNetsimCommand(CLI::App& app, NetsimOptions& options);

/// Checks `options` and turns them into simulation settings, as netsimCommand does first.
/// @return false (the problem printed on standard error) for a bad option.
bool buildNetsimSettings(const NetsimOptions& options, netsim::SimulationSettings& settings);

/// `foresight netsim`. Returns the exit status: 0; 2 for a bad option, an unreadable or bad CSV,
/// an unwritable SVG file (nothing on standard output then); 1 for an internal error.
int netsimCommand(NetsimOptions options);

}  // namespace foresight_cli
