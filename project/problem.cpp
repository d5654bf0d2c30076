#include "project/problem.hpp"

#include <fmt/format.h>

namespace kerf::project {

std::string to_string(const Problem& p) {
    const char* level = p.level == Level::error ? "error" : p.level == Level::warning ? "warning" : "note";
    if (p.file.empty()) return fmt::format("{}: {}", level, p.message);
    if (p.line > 0) return fmt::format("{}:{}:{}: {}: {}", p.file, p.line, p.column, level, p.message);
    return fmt::format("{}: {}: {}", p.file, level, p.message);
}

std::vector<Problem> input_problems(const std::string& file, const std::vector<ast::InputProblem>& problems) {
    std::vector<Problem> out;
    for (const ast::InputProblem& p : problems) {
        const Level level = p.severity == ast::Severity::error     ? Level::error
                            : p.severity == ast::Severity::warning ? Level::warning
                                                                   : Level::note;
        std::string message = p.message;
        if (!p.hint.empty()) message += fmt::format("; {}", p.hint);
        const int line = static_cast<int>(p.line);
        out.push_back({level, file, line, line > 0 ? 1 : 0, std::move(message)});
    }
    return out;
}

Problem from_load_error(std::string_view source, const dialects::LoadError& e) {
    std::string_view message = e.message;
    const std::string prefix = std::string(source) + ": ";
    if (message.starts_with(prefix)) message.remove_prefix(prefix.size());
    return {Level::error, std::string(source), e.line, e.column, std::string(message)};
}

}  // namespace kerf::project
