#include "text_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <system_error>

namespace foresight_cli {

namespace {

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};

bool readStream(std::FILE* stream, std::string& text, std::string& reason) {
    text.clear();
    char buffer[1 << 16];
    for (;;) {
        const std::size_t count = std::fread(buffer, 1, sizeof buffer, stream);
        text.append(buffer, count);
        if (count < sizeof buffer) break;
    }
    if (std::ferror(stream)) {
        const int error = errno;
        reason = error != 0 ? std::strerror(error) : "read error";
        return false;
    }
    return true;
}

} // namespace

bool readTextFile(const std::string& file, std::string& text, std::string& reason) {
    if (file == "-") {
        errno = 0;
        return readStream(stdin, text, reason);
    }
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec)) {
        reason = std::strerror(EISDIR);
        return false;
    }
    errno = 0;
    std::unique_ptr<std::FILE, FileCloser> stream(std::fopen(file.c_str(), "rb"));
    if (!stream) {
        reason = std::strerror(errno != 0 ? errno : ENOENT);
        return false;
    }
    return readStream(stream.get(), text, reason);
}

bool writeTextFile(const std::string& file, const std::string& text, std::string& reason) {
    errno = 0;
    std::FILE* stream = file == "-" ? stdout : std::fopen(file.c_str(), "wb");
    if (stream == nullptr) {
        reason = std::strerror(errno != 0 ? errno : EACCES);
        return false;
    }
    const std::size_t written = std::fwrite(text.data(), 1, text.size(), stream);
    bool ok = written == text.size();
    int error = ok ? 0 : errno;
    if (std::fflush(stream) != 0 && ok) {
        ok = false;
        error = errno;
    }
    if (stream != stdout && std::fclose(stream) != 0 && ok) {
        ok = false;
        error = errno;
    }
    if (!ok) reason = error != 0 ? std::strerror(error) : "write error";
    return ok;
}

} // namespace foresight_cli
