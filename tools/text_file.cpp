#include "text_file.h"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <memory>
#include <sys/stat.h>
#include <unistd.h>

namespace foresight_cli {

namespace {

struct Descriptor {
    int fd = -1;
    ~Descriptor() {
        if (fd >= 0) ::close(fd);
    }
};

std::string sizeText(std::size_t bytes) {
    return bytes >= (std::size_t(1) << 20) ? std::to_string(bytes >> 20) + " MiB" : std::to_string(bytes) + " bytes";
}

// Reads `fd` to its end, refusing more than maxBytes.
bool readDescriptor(int fd, std::size_t maxBytes, std::string& text, std::string& reason) {
    text.clear();
    char buffer[1 << 16];
    for (;;) {
        const ssize_t count = ::read(fd, buffer, sizeof buffer);
        if (count < 0) {
            if (errno == EINTR) continue;
            reason = std::strerror(errno);
            return false;
        }
        if (count == 0) return true;
        if (text.size() + static_cast<std::size_t>(count) > maxBytes) {
            reason = "larger than " + sizeText(maxBytes) + " (the limit for this input)";
            return false;
        }
        text.append(buffer, static_cast<std::size_t>(count));
    }
}

// Opens `file` without blocking on a named pipe, checks its kind, then reads it.
bool readNamed(const std::string& file, bool allowPipes, std::size_t maxBytes, std::string& text, std::string& reason) {
    Descriptor d;
    d.fd = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (d.fd < 0) {
        reason = std::strerror(errno != 0 ? errno : ENOENT);
        return false;
    }
    struct stat info {};
    if (::fstat(d.fd, &info) != 0) {
        reason = std::strerror(errno);
        return false;
    }
    if (S_ISDIR(info.st_mode)) {
        reason = std::strerror(EISDIR);
        return false;
    }
    const bool pipe = S_ISFIFO(info.st_mode);
    if (!S_ISREG(info.st_mode) && !(allowPipes && pipe)) {
        reason = allowPipes ? "not a regular file or pipe (a device?)" : "not a regular file";
        return false;
    }
    if (!pipe && static_cast<std::uint64_t>(info.st_size) > maxBytes) {
        reason = "larger than " + sizeText(maxBytes) + " (the limit for this input)";
        return false;
    }
    // Blocking reads from here on (a pipe with a writer waits for its data).
    const int flags = ::fcntl(d.fd, F_GETFL);
    if (flags >= 0) ::fcntl(d.fd, F_SETFL, flags & ~O_NONBLOCK);
    return readDescriptor(d.fd, maxBytes, text, reason);
}

}  // namespace

bool readTextFile(const std::string& file, std::string& text, std::string& reason, std::size_t maxBytes) {
    if (file == "-") return readDescriptor(STDIN_FILENO, maxBytes, text, reason);
    return readNamed(file, true, maxBytes, text, reason);
}

bool readRegularFile(const std::filesystem::path& file, std::size_t maxBytes, std::string& text, std::string& reason) {
    return readNamed(file.string(), false, maxBytes, text, reason);
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

}  // namespace foresight_cli
