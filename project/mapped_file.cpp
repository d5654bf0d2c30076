#include "project/mapped_file.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include "project/files.hpp"

namespace kerf::project {

std::optional<MappedFile> MappedFile::open(const std::filesystem::path& path, std::string& error) {
    MappedFile file;
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    struct stat st {};
    if (fd >= 0 && fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
        void* p = mmap(nullptr, static_cast<std::size_t>(st.st_size), PROT_READ, MAP_PRIVATE, fd, 0);
        ::close(fd);
        if (p != MAP_FAILED) {
            madvise(p, static_cast<std::size_t>(st.st_size), MADV_SEQUENTIAL);
            file.mapped_ = static_cast<const char*>(p);
            file.size_ = static_cast<std::size_t>(st.st_size);
            return file;
        }
    } else if (fd >= 0) {
        ::close(fd);
    }
    ReadResult read = DiskFileSystem().read(path);   // pipes, empty and special files
    if (!read.text) {
        error = std::move(read.error);
        return std::nullopt;
    }
    file.copy_ = std::move(*read.text);
    return file;
}

MappedFile::MappedFile(MappedFile&& other) noexcept
    : mapped_(other.mapped_), size_(other.size_), copy_(std::move(other.copy_)) {
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
