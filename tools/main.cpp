/// `foresight`: the command-line tool of the foresight library.
///   foresight predict FILE|- [--html FILE] [--svg FILE]   scenario JSON in, result JSON out
///   foresight demo [--json FILE|-] [--scenario FILE|-] [--html FILE|--no-html] [--svg FILE]
///   foresight compare FILE|--builtin   the predictions against a Bullet rigid body (ground truth)
///   foresight danger FILE|- [--html FILE] [--svg FILE]
///                                  danger for AI: grenade danger zones, vehicles against characters
///   foresight accuracy             the article against the exact methods (Markdown tables)
///   foresight level [--obj FILE] [--gltf FILE] [--glb FILE] [--room [--room-size X Y Z]]
///   foresight aim FILE|-           firing solutions (aim-format.md): JSON shots in, JSON solutions out
///   foresight plan FILE|-          throw planning: launch velocities that reach a target at the fuse
///   foresight netsim [--trajectory NAME] [--csv FILE] [--json|--markdown] [--svg FILE] ...
///                                  dead reckoning through a simulated link: errors, updates, jumps
/// Exit status: 0 success (also --help, --version); 2 invalid input or usage; 1 internal error.

#include "commands/accuracy_command.h"
#include "commands/aim_command.h"
#include "commands/compare_command.h"
#include "commands/danger_command.h"
#include "commands/demo_command.h"
#include "commands/level_command.h"
#include "commands/netsim_command.h"
#include "commands/plan_command.h"
#include "commands/predict_command.h"
#include "picture_options.h"

#include <foresight/config.h>

#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>
#include <new>

namespace {

int run(int argc, char** argv) {
    CLI::App app{"foresight: movement prediction for games (characters, projectiles, vehicles)", "foresight"};
    app.set_version_flag("--version", "foresight " FORESIGHT_VERSION_STRING);
    app.require_subcommand(1);
    app.footer("Exit status: 0 success, 2 invalid input or usage (nothing on standard output), 1 internal error.");

    std::string scenarioFile;
    CLI::App* predict = app.add_subcommand(
        "predict", "Run every prediction of a JSON scenario and write the JSON result to standard output");
    predict->add_option("FILE", scenarioFile, "scenario file, or - for standard input")->required()->type_name("FILE");
    foresight_cli::PictureOptions predictPictures;
    predict->add_option("--html", predictPictures.htmlFile, "also write an interactive 3D view (one HTML file) to FILE")
        ->type_name("FILE");
    predict->add_option("--svg", predictPictures.svgFile, "also write a top and a side view (SVG) to FILE")
        ->type_name("FILE");

    std::string jsonFile;
    std::string demoScenarioFile;
    CLI::App* demo =
        app.add_subcommand("demo", "Compare the reference article's predictions with exact ones on built-in scenarios");
    demo->add_option("--json", jsonFile,
                     "also write the full result (with trajectories) as JSON to FILE (- for stdout)")
        ->type_name("FILE");
    foresight_cli::PictureOptions demoPictures;
    bool demoNoHtml = false;
    demo->add_option("--html", demoPictures.htmlFile,
                     "write the interactive 3D view to FILE (default: foresight-demo.html in the current directory)")
        ->type_name("FILE");
    demo->add_flag("--no-html", demoNoHtml, "do not write the viewer page");
    demo->add_option("--svg", demoPictures.svgFile, "also write a top and a side view (SVG) to FILE")
        ->type_name("FILE");
    demo->add_option("--scenario", demoScenarioFile,
                     "also write the demo's input scenario to FILE (- for stdout), for `foresight predict`")
        ->type_name("FILE");

    std::string compareFile;
    foresight_cli::CompareOptions compareOptions;
    CLI::App* compare = app.add_subcommand(
        "compare", "Measure the projectile predictions (stepped and exact) against a Bullet rigid-body simulation");
    compare->add_option("FILE", compareFile, "scenario file, or - for standard input")->type_name("FILE");
    compare->add_flag("--builtin", compareOptions.builtin,
                      "the built-in scenes (floor, wall, ramp, stairs, room mesh, demo level): a Markdown table");
    compare->add_option("--frequency", compareOptions.frequency, "Bullet's step rate in Hz (240 to 100000)")
        ->type_name("HZ")
        ->default_val(960);
    compare->add_flag("--spin", compareOptions.spin,
                      "let the simulated sphere rotate (default: no spin, as a point mass)");
    compare->add_option("--json", compareOptions.jsonFile, "also write every detail as JSON to FILE (- for stdout)")
        ->type_name("FILE");
    compare
        ->add_option("--engine", compareOptions.engine,
                     "run the projectiles in a real engine instead (jolt, physx, rapier, ammo, bullet, godot3, "
                     "godot3-bullet, box2d; its runtime must be installed) beside the engine-matched predictions")
        ->type_name("NAME");
    compare
        ->add_option("--harness-dir", compareOptions.harnessDir,
                     "the engine harnesses' folder (default: tests/engines of the source tree, or "
                     "$FORESIGHT_ENGINE_HARNESSES)")
        ->type_name("DIR");

    CLI::App* accuracy = app.add_subcommand(
        "accuracy", "Measure how far the article's methods are from the exact ones (Markdown tables)");

    foresight_cli::LevelOptions levelOptions;
    CLI::App* level =
        app.add_subcommand("level", "Write the demo level (a walled courtyard) or a closed room as OBJ and glTF files");
    level->add_option("--obj", levelOptions.objFile, "write Wavefront OBJ to FILE")->type_name("FILE");
    level->add_option("--gltf", levelOptions.gltfFile, "write glTF (JSON, buffer embedded) to FILE.gltf")
        ->type_name("FILE");
    level->add_option("--glb", levelOptions.glbFile, "write binary glTF to FILE.glb")->type_name("FILE");
    level->add_flag("--room", levelOptions.room, "a closed room seen from inside instead of the courtyard");
    level
        ->add_option("--room-size", levelOptions.roomSize,
                     "the room's size in metres (default 10 4 10; implies --room)")
        ->expected(3)
        ->type_name("X Y Z");

    std::string aimFile;
    CLI::App* aim =
        app.add_subcommand("aim", "Firing solutions: launch velocities that meet moving targets (JSON in and out)");
    aim->add_option("FILE", aimFile, "shots file, or - for standard input")->required()->type_name("FILE");

    std::string planFile;
    CLI::App* plan = app.add_subcommand(
        "plan", "Find launch velocities that put a grenade near a target when its fuse runs out (JSON in and out)");
    plan->add_option("FILE", planFile, "plan document, or - for standard input")->required()->type_name("FILE");

    std::string dangerFile;
    CLI::App* danger = app.add_subcommand(
        "danger", "Danger for AI: grenade danger zones and safe points, vehicles against characters (JSON in and out)");
    danger->add_option("FILE", dangerFile, "danger file (a scenario with danger keys), or - for standard input")
        ->required()
        ->type_name("FILE");
    foresight_cli::PictureOptions dangerPictures;
    danger
        ->add_option("--html", dangerPictures.htmlFile,
                     "also write an interactive 3D view with the danger zones to FILE")
        ->type_name("FILE");
    danger
        ->add_option("--svg", dangerPictures.svgFile,
                     "also write a top and a side view (SVG) with the danger zones to FILE")
        ->type_name("FILE");

    foresight_cli::NetsimOptions netsimOptions;
    CLI::App* netsim = foresight_cli::addNetsimCommand(app, netsimOptions);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        // --help and --version exit 0; every usage error exits 2 (CLI11 uses 105, 106, ...).
        const int status = app.exit(error);
        return status == 0 ? 0 : 2;
    }

    if (predict->parsed()) return foresight_cli::predictCommand(scenarioFile, predictPictures);
    if (demo->parsed()) {
        if (demoNoHtml && !demoPictures.htmlFile.empty()) {
            std::cerr << "foresight demo: --html and --no-html contradict each other\n";
            return 2;
        }
        return foresight_cli::demoCommand(jsonFile, demoScenarioFile, demoPictures, !demoNoHtml);
    }
    if (compare->parsed())
        return compareOptions.engine.empty() ? foresight_cli::compareCommand(compareFile, compareOptions)
                                             : foresight_cli::compareEngineCommand(compareFile, compareOptions);
    if (accuracy->parsed()) return foresight_cli::accuracyCommand();
    if (level->parsed()) return foresight_cli::levelCommand(levelOptions);
    if (danger->parsed()) return foresight_cli::dangerCommand(dangerFile, dangerPictures);
    if (aim->parsed()) return foresight_cli::aimCommand(aimFile);
    if (plan->parsed()) return foresight_cli::planCommand(planFile);
    if (netsim->parsed()) return foresight_cli::netsimCommand(netsimOptions);
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::bad_alloc&) {
        std::cerr << "foresight: out of memory\n";
    } catch (const std::exception& error) {
        std::cerr << "foresight: internal error: " << error.what() << '\n';
    } catch (...) {
        std::cerr << "foresight: internal error\n";
    }
    return 1;
}
