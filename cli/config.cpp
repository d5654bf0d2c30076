#include "cli/config.hpp"

#include <fmt/format.h>

#include <fstream>
#include <sstream>
#include <toml++/toml.h>

namespace kerf::cli {

namespace fs = std::filesystem;

std::optional<std::string> read_file(const fs::path& path, std::string& error) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = fmt::format("{}: cannot open file", path.string());
        return std::nullopt;
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
        error = fmt::format("{}: read error", path.string());
        return std::nullopt;
    }
    return text;
}

ProjectConfig find_config(const fs::path& start, std::vector<std::string>& errors) {
    ProjectConfig config;
    std::error_code ec;
    fs::path dir = fs::absolute(start, ec);
    if (!fs::is_directory(dir, ec)) dir = dir.parent_path();
    for (; !dir.empty(); dir = dir.parent_path()) {
        const fs::path candidate = dir / ".kerf.toml";
        if (fs::exists(candidate, ec)) {
            config.path = candidate;
            break;
        }
        if (dir == dir.root_path()) break;
    }
    if (!config.path) return config;
    std::string error;
    const auto text = read_file(*config.path, error);
    if (!text) {
        errors.push_back(error);
        return config;
    }
    try {
        const toml::table t = toml::parse(*text, config.path->string());
        if (const auto d = t["dialect"].value<std::string>()) config.dialect = *d;
        if (const auto m = t["machine"].value<std::string>()) config.machine_file = config.path->parent_path() / *m;
        if (const toml::array* files = t["dialect_files"].as_array()) {
            for (const toml::node& f : *files)
                if (const auto s = f.value<std::string>()) config.dialect_files.push_back(config.path->parent_path() / *s);
        }
    } catch (const toml::parse_error& e) {
        errors.push_back(fmt::format("{}:{}:{}: {}", config.path->string(), e.source().begin.line,
                                     e.source().begin.column, e.description()));
    }
    return config;
}

RegistryResult make_registry(const std::vector<fs::path>& dialect_files) {
    RegistryResult result{dialects::builtin_registry(), {}};
    for (const fs::path& file : dialect_files) {
        std::string error;
        const auto text = read_file(file, error);
        if (!text) {
            result.errors.push_back(error);
            continue;
        }
        for (const dialects::LoadError& e : result.registry.add_text(*text, file.string()))
            result.errors.push_back(e.line ? fmt::format("{} (line {}, column {})", e.message, e.line, e.column)
                                           : e.message);
    }
    return result;
}

}  // namespace kerf::cli
