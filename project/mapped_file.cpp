#include "project/mapped_file.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <thread>

#include "ast/source.hpp"
#include "project/files.hpp"

namespace kerf::project {

namespace {

// The decoder reads a mapped file in windows of this size, dropping each behind it.
constexpr std::size_t kScanWindow = std::size_t{16} << 20;
// From this size the decoder reads the file in two parts on two threads.
constexpr std::size_t kTwoPartsFrom = std::size_t{8} << 20;

}  // namespace

std::optional<MappedFile> MappedFile::open(const std::filesystem::path& path, const ast::InputLimits& limits,
                                           ReadResult& failure) {
    MappedFile file;
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    struct stat st {};
    if (fd >= 0 && fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
        if (const auto too_large = ast::check_file_size(static_cast<std::uint64_t>(st.st_size), limits)) {
            ::close(fd);
            failure = refusal(path, *too_large);
            return std::nullopt;
        }
        void* p = mmap(nullptr, static_cast<std::size_t>(st.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
        ::close(fd);
        if (p != MAP_FAILED) {
            madvise(p, static_cast<std::size_t>(st.st_size), MADV_SEQUENTIAL);
            file.mapped_ = static_cast<const char*>(p);
            file.size_ = static_cast<std::size_t>(st.st_size);
            file.input_ = file.scan(limits);
            if (file.input_.encoding == ast::Encoding::utf8) {
                if (!file.input_.refused()) return file;
                for (const ast::InputProblem& problem : file.input_.problems)
                    if (problem.severity == ast::Severity::error) failure = refusal(path, problem);
                return std::nullopt;
            }
            // UTF-16/32: decoded into memory (such files are small: written by editors, not CAM).
            munmap(const_cast<char*>(file.mapped_), file.size_);
            file.mapped_ = nullptr;
            file.size_ = 0;
        }
    } else if (fd >= 0) {
        ::close(fd);
    }
    ReadResult read = DiskFileSystem().read(path, limits);   // pipes, empty and special files; UTF-16/32
    if (!read.text) {
        failure = std::move(read);
        return std::nullopt;
    }
    file.copy_ = std::move(*read.text);
    file.input_.encoding = read.encoding;
    file.input_.bom = read.bom;
    file.input_.problems = std::move(read.problems);
    return file;
}

ast::DecodedInput MappedFile::scan(const ast::InputLimits& limits) const {
    const std::string_view text(mapped_, size_);
    const auto scan_part = [&](ast::InputScanner& scanner, std::size_t from, std::size_t to) {
        for (std::size_t at = from; at < to; at += kScanWindow) {
            const std::size_t end = std::min(to, at + kScanWindow);
            scanner.feed(text.substr(at, end - at));
            release(at, end);
        }
    };
    ast::InputScanner scanner(limits);
    // A long file in two parts cut at a line break, the second on another thread: the scan was
    // 0.05 s of a 100 MB program's dry run before its first block ran, one core idle.
    const std::size_t cut = size_ >= kTwoPartsFrom ? ast::last_line_end_before(text, size_ / 2) : std::string_view::npos;
    if (cut == std::string_view::npos || cut == 0) {
        scan_part(scanner, 0, size_);
        return scanner.finish();
    }
    ast::InputScanner second(limits);
    std::thread worker([&] { scan_part(second, cut, size_); });
    scan_part(scanner, 0, cut);
    worker.join();
    scanner.append(second);
    return scanner.finish();
}

MappedFile::MappedFile(MappedFile&& other) noexcept
    : mapped_(other.mapped_), size_(other.size_), copy_(std::move(other.copy_)), input_(std::move(other.input_)) {
    other.mapped_ = nullptr;
    other.size_ = 0;
}

MappedFile::~MappedFile() {
    if (mapped_) munmap(const_cast<char*>(mapped_), size_);
}

void MappedFile::release(std::size_t begin, std::size_t end) const {
    if (!mapped_) return;
    const std::size_t page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    const std::size_t first = (begin + page - 1) / page * page;
    const std::size_t last = end >= size_ ? (size_ + page - 1) / page * page : end / page * page;
    if (last > first) madvise(const_cast<char*>(mapped_) + first, last - first, MADV_DONTNEED);
}

}  // namespace kerf::project
