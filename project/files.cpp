#include "project/files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <mutex>
#include <sstream>

namespace kerf::project {

namespace fs = std::filesystem;

fs::path normal_path(const fs::path& path) {
    std::error_code ec;
    fs::path absolute = fs::absolute(path, ec);
    return (ec ? path : absolute).lexically_normal();
}

ReadResult FileSystem::read_head(const fs::path& path, std::size_t bytes) const {
    ReadResult r = read(path);
    if (r.text && r.text->size() > bytes) r.text->resize(bytes);
    return r;
}

ReadResult DiskFileSystem::read(const fs::path& path) const {
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
    r.text = std::move(text);
    return r;
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
    return r;
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

ReadResult OverlayFileSystem::read(const fs::path& path) const {
    {
        const std::shared_lock lock(mutex_);
        if (const auto it = documents_.find(normal_path(path)); it != documents_.end()) return {it->second, {}};
    }
    return base_->read(path);
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
    for (const auto& [path, text] : documents_)
        if (path.parent_path() == normal && std::find_if(out.begin(), out.end(), [&](const fs::path& p) {
                                                 return normal_path(p) == path;
                                             }) == out.end())
            out.push_back(path);
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace kerf::project
