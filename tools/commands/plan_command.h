#pragma once
/// @file plan_command.h
/// `foresight plan FILE|-`: throw planning (foresight/throw_planner.h) from a JSON document:
/// a scenario's `gravity` and `world` and a list of `throws` (start, target, fuse, speed cap,
/// ...); the output lists, per throw, the plans found (launch velocity, final position,
/// distance, bounces, first impact and, on request, the trajectory). Format and rules:
/// docs/plan-format.md. Validation as `foresight predict` (scenario.h): one line `path: message`
/// per problem, all of them in one run, exit status 2 with nothing on standard output.

#include "scenario.h"

#include <string>
#include <vector>

namespace foresight_cli {

/// One validated entry of `throws`.
struct ThrowRequest {
    std::string path;  ///< "throws[i]", for messages.
    Json id;           ///< echoed back; null when absent.
    foresight::ThrowPlanRequest request;
    bool trajectory = false;  ///< print each plan's trajectory.
};

/// What one throw produced.
struct ThrowOutcome {
    foresight::ThrowPlanResult result;
    std::vector<foresight::ThrowPlan> plans;                            ///< result.planCount
    std::vector<std::vector<foresight::TrajectoryPoint>> trajectories;  ///< per plan, if asked
};

/// Most projectile steps one plan document may ask for in all: the sum over its throws of the
/// search's bound (max_predictions x fuse / step, foresight::throwPlanWork) plus the printed
/// trajectories' steps (fuse / step per plan). 2^25: two searches at their own cap (2^24), or 559
/// default throws; some seconds of work.
inline constexpr std::uint64_t kMaxPlanFileSteps = std::uint64_t(1) << 25;

/// The steps `throws` may take in all, as kMaxPlanFileSteps counts them.
std::uint64_t planFileWork(const std::vector<ThrowRequest>& throws);

/// Reads a plan document: the scenario's world (built with buildScenario) and the throws; a
/// document over kMaxPlanFileSteps is refused at "throws". Returns diagnostics.ok().
bool buildPlanDocument(const Json& document, const std::filesystem::path& baseDirectory, Scenario& world,
                       std::vector<ThrowRequest>& throws, Diagnostics& diagnostics);

/// Plans every throw; refusals of the library become errors. Returns diagnostics.ok().
bool runPlans(const Scenario& world, const std::vector<ThrowRequest>& throws, std::vector<ThrowOutcome>& outcomes,
              Diagnostics& diagnostics);

/// The output document {"throws": [...]}, in input order.
Json planResultDocument(const std::vector<ThrowRequest>& throws, const std::vector<ThrowOutcome>& outcomes);

/// `foresight plan FILE` ("-": standard input). Returns the exit status: 0, or 2 with nothing
/// on standard output (invalid input, unreadable file or mesh).
int planCommand(const std::string& file);

}  // namespace foresight_cli
