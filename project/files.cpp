#include "project/files.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <fstream>
#include <functional>
#include <mutex>
#include <sstream>
#include <thread>

#include "ast/large_allocator.hpp"

namespace kerf::project {

namespace fs = std::filesystem;

fs::path normal_path(const fs::path& path) {
    std::error_code ec;
    fs::path absolute = fs::absolute(path, ec);
    return (ec ? path : absolute).lexically_normal();
}

namespace {

// "PATH:LINE: message; hint" of the decoder's refusal.
std::string refusal_text(const fs::path& path, const ast::InputProblem& p) {
    std::string s = p.line > 0 ? fmt::format("{}:{}: {}", path.string(), p.line, p.message) : fmt::format("{}: {}", path.string(), p.message);
    if (!p.hint.empty()) s += fmt::format("; {}", p.hint);
    return s;
}

// A head cut anywhere may end inside a character or a line: only the encoding matters here.
ReadResult decode_head(ReadResult r) {
    if (!r.text) return r;
    ast::DecodedInput input = ast::decode_input(*r.text, ast::InputLimits{0, 0});
    if (!input.refused()) {
        r.text = std::move(input.text);
        r.encoding = input.encoding;
        r.bom = input.bom;
    }
    return r;
}

// Calls work(from, to) on [0, size) in two halves, the second on another thread when the size
// pays for one (a thread costs tens of microseconds; a megabyte takes about as long to copy).
void in_halves(std::size_t size, const std::function<void(std::size_t, std::size_t)>& work) {
    constexpr std::size_t kTwoThreadsAtLeast = std::size_t{8} << 20;
    if (size < kTwoThreadsAtLeast) return work(0, size);
    const std::size_t half = size / 2;
    std::thread second([&] { work(half, size); });
    work(0, half);
    second.join();
}

// A regular file of exactly `size` bytes: its string's pages mapped in one system call per half
// (a fault per page was half the time), zeroed once by resize, then filled by pread from the page
// cache, each half on its own core. A 100 MB program: 0.075 s -> 0.035 s before the decoder starts
// (bench/RESULTS.md, 2026-11-28 third session). nullopt when the file changed size or a read fails.
std::optional<std::string> read_regular_file(const fs::path& path, std::size_t size) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return std::nullopt;
    struct stat st {};
    if (fstat(fd, &st) != 0 || static_cast<std::size_t>(st.st_size) != size) {
        ::close(fd);
        return std::nullopt;
    }
    std::string text;
    text.reserve(size);
    in_halves(size, [&](std::size_t from, std::size_t to) { ast::prefault(text.data() + from, to - from); });
    text.resize(size);
    std::atomic<bool> complete{true};
    in_halves(size, [&](std::size_t from, std::size_t to) {
        while (from < to) {
            const ssize_t n = ::pread(fd, text.data() + from, to - from, static_cast<off_t>(from));
            if (n <= 0) {
                if (n < 0 && errno == EINTR) continue;
                complete = false;
                return;
            }
            from += static_cast<std::size_t>(n);
        }
    });
    ::close(fd);
    if (!complete) return std::nullopt;
    return text;
}

// Below this a file is read through a stream as usual.
constexpr std::uintmax_t kDirectReadAtLeast = std::uintmax_t{1} << 20;

}  // namespace

ReadResult refusal(const fs::path& path, ast::InputProblem problem) {
    ReadResult r;
    r.error = refusal_text(path, problem);
    r.problems.push_back(std::move(problem));
    return r;
}

ReadResult decode_file(const fs::path& path, std::string bytes, const ast::InputLimits& limits) {
    ast::DecodedInput input = ast::decode_input(std::move(bytes), limits);
    ReadResult r;
    r.encoding = input.encoding;
    r.bom = input.bom;
    r.problems = std::move(input.problems);
    for (const ast::InputProblem& p : r.problems)
        if (p.severity == ast::Severity::error && r.error.empty()) r.error = refusal_text(path, p);
    if (r.error.empty()) r.text = std::move(input.text);
    return r;
}

ReadResult FileSystem::read_head(const fs::path& path, std::size_t bytes) const {
    ReadResult r = read(path, ast::InputLimits{0, 0});
    if (r.text && r.text->size() > bytes) r.text->resize(bytes);
    return r;
}

ReadResult DiskFileSystem::read(const fs::path& path, const ast::InputLimits& limits) const {
    std::error_code ec;
    if (fs::is_regular_file(path, ec)) {
        // Refused before reading: a 50 GB file is not read into memory to be refused.
        const std::uintmax_t size = fs::file_size(path, ec);
        if (!ec) {
            if (auto too_large = ast::check_file_size(size, limits)) return refusal(path, std::move(*too_large));
            if (size >= kDirectReadAtLeast)
                if (std::optional<std::string> text = read_regular_file(path, static_cast<std::size_t>(size)))
                    return decode_file(path, std::move(*text), limits);
        }
    }
    ReadResult r;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        r.error = fmt::format("{}: cannot open file", path.string());
        return r;
    }
    std::string text;
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size > 0) {
        text.resize(static_cast<std::size_t>(size));
        in.seekg(0);
        in.read(text.data(), size);
    } else {
        std::ostringstream ss;   // pipes and special files
        in.seekg(0);
        ss << in.rdbuf();
        text = ss.str();
    }
    if (in.bad()) {
        r.error = fmt::format("{}: read error", path.string());
        return r;
    }
    return decode_file(path, std::move(text), limits);
}

ReadResult DiskFileSystem::read_head(const fs::path& path, std::size_t bytes) const {
    ReadResult r;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        r.error = fmt::format("{}: cannot open file", path.string());
        return r;
    }
    std::string head(bytes, '\0');
    in.read(head.data(), static_cast<std::streamsize>(bytes));
    head.resize(static_cast<std::size_t>(in.gcount()));
    r.text = std::move(head);
    return decode_head(std::move(r));
}

bool DiskFileSystem::is_file(const fs::path& path) const {
    std::error_code ec;
    return fs::is_regular_file(path, ec);
}

std::vector<fs::path> DiskFileSystem::files_in(const fs::path& folder) const {
    std::vector<fs::path> out;
    std::error_code ec;
    for (fs::directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec), end; !ec && it != end;
         it.increment(ec))
        if (it->is_regular_file(ec)) out.push_back(it->path());
    std::sort(out.begin(), out.end());
    return out;
}

void OverlayFileSystem::set(const fs::path& path, std::string text) {
    const std::unique_lock lock(mutex_);
    documents_[normal_path(path)] = std::move(text);
}

void OverlayFileSystem::remove(const fs::path& path) {
    const std::unique_lock lock(mutex_);
    documents_.erase(normal_path(path));
}

ReadResult OverlayFileSystem::read(const fs::path& path, const ast::InputLimits& limits) const {
    {
        const std::shared_lock lock(mutex_);
        if (const auto it = documents_.find(normal_path(path)); it != documents_.end()) {
            ReadResult r;
            r.text = it->second;
            return r;
        }
    }
    return base_->read(path, limits);
}

bool OverlayFileSystem::is_file(const fs::path& path) const {
    {
        const std::shared_lock lock(mutex_);
        if (documents_.contains(normal_path(path))) return true;
    }
    return base_->is_file(path);
}

std::vector<fs::path> OverlayFileSystem::files_in(const fs::path& folder) const {
    std::vector<fs::path> out = base_->files_in(folder);
    const fs::path normal = normal_path(folder);
    const std::shared_lock lock(mutex_);
    for (const auto& document : documents_) {
        // Not a structured binding: clang 14 (make fuzz) does not capture those in a lambda.
        const fs::path& path = document.first;
        if (path.parent_path() == normal && std::find_if(out.begin(), out.end(), [&](const fs::path& p) {
                                                 return normal_path(p) == path;
                                             }) == out.end())
            out.push_back(path);
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace kerf::project
