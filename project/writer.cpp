#include "project/writer.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace kerf::project {

namespace fs = std::filesystem;

namespace {

// The permissions of the file being replaced, or those of a new file (umask applied).
mode_t mode_for(const fs::path& path) {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0) return st.st_mode & 07777;
    const mode_t mask = ::umask(0);
    ::umask(mask);
    return 0666 & ~mask;
}

bool write_all(int fd, std::string_view text) {
    for (std::size_t at = 0; at < text.size();) {
        const ssize_t n = ::write(fd, text.data() + at, text.size() - at);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        at += static_cast<std::size_t>(n);
    }
    return true;
}

}  // namespace

std::optional<std::string> write_atomically(const fs::path& path, std::string_view text) {
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on "." + string + "...".
    std::string name = ".";
    name += path.filename().string();
    name += ".kerf-XXXXXX";
    std::string temp = (folder / name).string();
    const int fd = ::mkstemp(temp.data());
    if (fd < 0) return fmt::format("cannot create a temp file next to it: {}; the file is left as it was", std::strerror(errno));
    const char* failure = nullptr;
    int error = 0;
    const auto fail = [&](const char* what) {
        if (!failure) failure = what, error = errno;
    };
    if (::fchmod(fd, mode_for(path)) != 0) fail("cannot set the permissions");
    if (!failure && !write_all(fd, text)) fail("cannot write");
    if (!failure && ::fsync(fd) != 0) fail("cannot flush to the disk");
    if (::close(fd) != 0) fail("cannot close the temp file");
    if (!failure && ::rename(temp.c_str(), path.c_str()) != 0) fail("cannot replace the file");
    if (!failure) return std::nullopt;
    ::unlink(temp.c_str());
    return fmt::format("{}: {}; the file is left as it was", failure, std::strerror(error ? error : EIO));
}

}  // namespace kerf::project
