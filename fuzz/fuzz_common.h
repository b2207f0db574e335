#pragma once
/// @file fuzz_common.h
/// Helpers shared by the harnesses: a private temporary directory (for the loaders that read
/// files), writing an input there, and the abort that reports a broken contract.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <unistd.h>

namespace foresight_fuzz {

/// The most projectile steps a JSON harness runs for one input (plan documents over it are read
/// and validated, not run): 2^18 steps take about 2 s in the instrumented build, a fifth of the
/// 10 s that scripts/fuzz.sh allows an input.
inline constexpr std::uint64_t kMaxFuzzSteps = std::uint64_t(1) << 18;

/// A directory of this process, made once (removed at exit), for the files the loaders read.
inline const std::filesystem::path& scratchDirectory() {
    static const std::filesystem::path directory = [] {
        std::string pattern = (std::filesystem::temp_directory_path() / "foresight-fuzz.XXXXXX").string();
        if (mkdtemp(pattern.data()) == nullptr) {
            std::perror("foresight fuzz: mkdtemp");
            std::abort();
        }
        static std::filesystem::path made(pattern);
        std::atexit([] {
            std::error_code ec;
            std::filesystem::remove_all(made, ec);
        });
        return made;
    }();
    return directory;
}

/// Writes `bytes` to scratchDirectory()/name (replacing it) and returns the path.
inline std::filesystem::path writeScratchFile(const std::string& name, std::string_view bytes) {
    const std::filesystem::path path = scratchDirectory() / name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
        std::fprintf(stderr, "foresight fuzz: cannot write %s\n", path.c_str());
        std::abort();
    }
    return path;
}

/// A broken contract: print it and abort, so that libFuzzer saves the input.
[[noreturn]] inline void contractViolation(const char* what) {
    std::fprintf(stderr, "foresight fuzz: contract violated: %s\n", what);
    std::abort();
}

#define FORESIGHT_FUZZ_CHECK(condition)                                                      \
    do {                                                                                     \
        if (!(condition)) ::foresight_fuzz::contractViolation(#condition " (" __FILE__ ")"); \
    } while (false)

}  // namespace foresight_fuzz
