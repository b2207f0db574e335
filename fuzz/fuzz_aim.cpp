// `foresight aim`: shots JSON (docs/aim-format.md) through aimDocument, as aimCommand runs it.
#include "fuzz_json.h"

#include "commands/aim_command.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace foresight_cli;
    Diagnostics diagnostics;
    Json document, output;
    if (foresight_fuzz::parseInput(data, size, document, diagnostics) && aimDocument(document, output, diagnostics))
        foresight_fuzz::formatOutput(output);
    return 0;
}
