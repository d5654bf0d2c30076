#include "cli/source_files.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <set>
#include <thread>

#include <fmt/format.h>

namespace kerf::cli {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string text) {
    for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return text;
}

bool has_program_extension(const fs::path& path) {
    const std::string ext = lower(path.extension().string());
    return std::find(std::begin(kProgramExtensions), std::end(kProgramExtensions), ext) !=
           std::end(kProgramExtensions);
}

std::string read_head(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::string head(512, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    return head;
}

bool is_hidden(const fs::path& path) {
    const std::string name = path.filename().string();
    return name.size() > 1 && name[0] == '.' && name != "..";
}

void walk_folder(const fs::path& folder, std::vector<fs::path>& out, std::vector<std::string>& errors) {
    std::error_code ec;
    fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec);
    if (ec) {
        errors.push_back(fmt::format("{}: {}", folder.string(), ec.message()));
        return;
    }
    std::vector<fs::path> found;
    for (const fs::recursive_directory_iterator end; it != end; it.increment(ec)) {
        if (ec) {
            errors.push_back(fmt::format("{}: {}", it->path().string(), ec.message()));
            ec.clear();
            continue;
        }
        const fs::directory_entry& entry = *it;
        if (entry.is_directory(ec)) {
            if (is_hidden(entry.path())) it.disable_recursion_pending();
            continue;
        }
        if (!entry.is_regular_file(ec)) continue;
        const fs::path& path = entry.path();
        if (has_program_extension(path) || (!path.has_extension() && looks_like_program(read_head(path))))
            found.push_back(path);
    }
    std::sort(found.begin(), found.end());
    out.insert(out.end(), found.begin(), found.end());
}

}  // namespace

bool looks_like_program(std::string_view head) {
    if (head.find('\0') != std::string_view::npos) return false;
    if (head.substr(0, 3) == "\xEF\xBB\xBF") head.remove_prefix(3);
    auto skip_blanks = [&] {
        while (!head.empty() && std::isspace(static_cast<unsigned char>(head.front()))) head.remove_prefix(1);
    };
    skip_blanks();
    if (!head.empty() && head.front() == '%') {
        const std::size_t eol = head.find('\n');
        head = eol == std::string_view::npos ? std::string_view{} : head.substr(eol + 1);
        skip_blanks();
    }
    if (head.size() < 2) return false;
    const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(head[0])));
    const bool digit_next = std::isdigit(static_cast<unsigned char>(head[1])) != 0;
    return (letter == 'O' || letter == ':' || letter == 'N' || letter == 'G') && digit_next;
}

SourceFiles collect_source_files(const std::vector<fs::path>& arguments) {
    SourceFiles result;
    for (const fs::path& argument : arguments) {
        std::error_code ec;
        const fs::file_status status = fs::status(argument, ec);
        if (ec || !fs::exists(status)) {
            result.errors.push_back(fmt::format("{}: no such file or folder", argument.string()));
        } else if (fs::is_directory(status)) {
            walk_folder(argument, result.files, result.errors);
        } else {
            result.files.push_back(argument);
        }
    }
    std::set<fs::path> seen;
    std::vector<fs::path> unique;
    for (fs::path& file : result.files) {
        std::error_code ec;
        fs::path key = fs::weakly_canonical(file, ec);
        if (ec) key = file;
        if (seen.insert(key).second) unique.push_back(std::move(file));
    }
    result.files = std::move(unique);
    return result;
}

void run_parallel(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& work,
                  const std::function<void(std::size_t, std::size_t)>& done) {
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(count, 1)));
    std::atomic<std::size_t> next{0};
    std::atomic<std::size_t> finished{0};
    auto worker = [&] {
        for (std::size_t i = next++; i < count; i = next++) {
            work(i);
            ++finished;
        }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
    if (!done) {
        worker();
    } else {
        // The calling thread reports progress while the pool works; with one thread it works too.
        if (pool.empty()) {
            for (std::size_t i = next++; i < count; i = next++) {
                work(i);
                ++finished;
                done(finished.load(), count);
            }
        } else {
            while (finished.load() < count) {
                done(finished.load(), count);
                std::this_thread::sleep_for(std::chrono::milliseconds(100));
            }
        }
    }
    for (std::thread& t : pool) t.join();
    if (done) done(finished.load(), count);
}

ProgressBar::ProgressBar(std::string label) : label_(std::move(label)), enabled_(isatty(STDERR_FILENO) != 0) {}

ProgressBar::~ProgressBar() {
    if (drawn_) std::fputs("\r\033[K", stderr);
}

void ProgressBar::update(std::size_t finished, std::size_t total) {
    if (!enabled_ || total < 2) return;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(kWidth * finished / total);
    fmt::print(stderr, "\r{} [{:=<{}}{: <{}}] {}/{}", label_, "", filled, "", kWidth - filled, finished, total);
    std::fflush(stderr);
    drawn_ = true;
}

}  // namespace kerf::cli
