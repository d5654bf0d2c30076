#include "project/problem.hpp"

#include <fmt/format.h>

namespace kerf::project {

std::string to_string(const Problem& p) {
    const char* level = p.level == Level::error ? "error" : "warning";
    if (p.file.empty()) return fmt::format("{}: {}", level, p.message);
    if (p.line > 0) return fmt::format("{}:{}:{}: {}: {}", p.file, p.line, p.column, level, p.message);
    return fmt::format("{}: {}: {}", p.file, level, p.message);
}

Problem from_load_error(std::string_view source, const dialects::LoadError& e) {
    std::string_view message = e.message;
    const std::string prefix = std::string(source) + ": ";
    if (message.starts_with(prefix)) message.remove_prefix(prefix.size());
    return {Level::error, std::string(source), e.line, e.column, std::string(message)};
}

}  // namespace kerf::project
