#include "project/config.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <tuple>

#include <toml++/toml.h>

namespace kerf::project {

namespace fs = std::filesystem;

namespace {

constexpr std::array<KeyInfo, 20> kKeys = {{
    {"", "dialect", "string", "dialect id for every program under this file (`kerf dialects`), or \"auto\""},
    {"", "dialect_files", "array of strings", "user dialect files (dialects/SCHEMA.md), relative to this file"},
    {"", "machine", "string", "machine file (machine/SCHEMA.md), relative to this file"},
    {"", "check", "table", "kerf check: include, exclude, rules"},
    {"", "rules", "table", "rule severities (the same as [check.rules])"},
    {"", "format", "table", "kerf fmt style (docs/fmt.md)"},
    {"", "run", "table", "dry run: call, set, passes"},
    {"", "programs", "table", "program index: library, resident"},
    {"", "limits", "table", "bounds of every command: max_file_bytes, max_line_bytes, time_limit"},
    {"run", "call", "string", "the caller's block of a macro run, \"G65 P9010 A1.\""},
    {"run", "set", "array of strings", "common variables before the run, [\"#100=5\"]"},
    {"run", "passes", "integer", "passes of a main program ending in M99 (bar-feed loop), 1 or more"},
    {"programs", "library", "array of strings", "folders whose programs calls can reach, relative to this file"},
    {"programs", "resident", "array of strings", "program ranges kept in the machine, [\"O9000-O9999\"]"},
    {"limits", "max_file_bytes", "integer", "refuse program files larger than this many bytes (default 512 MiB; 0 = no limit)"},
    {"limits", "max_line_bytes", "integer", "refuse program files with a longer line (default 64 KiB; 0 = no limit)"},
    {"limits", "time_limit", "number", "stop a dry run after this many seconds with alarm 90005 (default 10; 0 = none)"},
    {"check", "include", "array of strings", "globs of the files to check, relative to this file"},
    {"check", "exclude", "array of strings", "globs of the files never to check"},
    {"check", "rules", "table", "rule id or name = \"error\" | \"warning\" | \"info\" | \"hint\" | \"off\""},
}};

class Reader {
public:
    Reader(const fs::path& file, ConfigResult& result) : file_(file), result_(result) {}

    void error(const toml::source_region& at, std::string message) {
        result_.problems.push_back(
            {Level::error, file_.string(), static_cast<int>(at.begin.line), static_cast<int>(at.begin.column), std::move(message)});
    }

    // Unknown keys of `table` are errors that name the valid ones.
    void check_keys(const toml::table& table, std::string_view name, std::span<const std::string_view> allowed) {
        for (const auto& [key, node] : table) {
            if (std::find(allowed.begin(), allowed.end(), key.str()) != allowed.end()) continue;
            std::string list;
            for (const std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
            const std::string path = name.empty() ? std::string(key.str()) : fmt::format("{}.{}", name, key.str());
            error(key.source(), fmt::format("{}: unknown key; the keys {} are {} (docs/config.md)", path,
                                            name.empty() ? "at the top level" : fmt::format("of [{}]", name), list));
        }
    }

    std::optional<std::string> string(const toml::node* node, std::string_view path) {
        if (!node) return std::nullopt;
        if (node->is_string()) return node->value<std::string>();
        error(node->source(), fmt::format("{}: expected a string", path));
        return std::nullopt;
    }

    std::vector<std::string> strings(const toml::node* node, std::string_view path) {
        std::vector<std::string> out;
        if (!node) return out;
        const toml::array* array = node->as_array();
        if (!array) {
            error(node->source(), fmt::format("{}: expected an array of strings", path));
            return out;
        }
        for (const toml::node& item : *array) {
            if (item.is_string()) out.push_back(*item.value<std::string>());
            else error(item.source(), fmt::format("{}: expected a string", path));
        }
        return out;
    }

    const toml::table* table(const toml::node* node, std::string_view name) {
        if (!node) return nullptr;
        if (const toml::table* t = node->as_table()) return t;
        error(node->source(), fmt::format("{}: expected a table ([{}])", name, name));
        return nullptr;
    }

    fs::path relative(const std::string& path) const { return (file_.parent_path() / path).lexically_normal(); }

private:
    const fs::path& file_;
    ConfigResult& result_;
};

constexpr std::array<std::string_view, 9> kTopKeys = {"dialect", "dialect_files", "machine", "check",
                                                      "rules", "format", "run", "programs", "limits"};
constexpr std::array<std::string_view, 3> kRunKeys = {"call", "set", "passes"};
constexpr std::array<std::string_view, 2> kProgramsKeys = {"library", "resident"};
constexpr std::array<std::string_view, 3> kLimitsKeys = {"max_file_bytes", "max_line_bytes", "time_limit"};

// "#100=5", "#500 = -1.5": a common variable and a value (the run's evaluator reads it later).

void read_run(Reader& in, const toml::table& t, RunSettings& run) {
    in.check_keys(t, "run", kRunKeys);
    if ((run.call = in.string(t.get("call"), "run.call")) && run.call->empty()) {
        in.error(t.get("call")->source(), "run.call: expected the caller's block, e.g. \"G65 P9010 A1.\"");
        run.call.reset();
    }
    for (const std::string& s : in.strings(t.get("set"), "run.set")) {
        if (parse_assignment(s)) run.set.push_back(s);
        else in.error(t.get("set")->source(), fmt::format("run.set: '{}' is not an assignment such as \"#100=5\"", s));
    }
    if (const toml::node* passes = t.get("passes")) {
        const std::optional<std::int64_t> n = passes->is_integer() ? passes->value<std::int64_t>() : std::nullopt;
        if (n && *n >= 1 && *n <= 1000000) run.passes = static_cast<int>(*n);
        else in.error(passes->source(), "run.passes: expected a whole number from 1 to 1000000");
    }
}

void read_programs(Reader& in, const toml::table& t, ProgramSettings& programs) {
    in.check_keys(t, "programs", kProgramsKeys);
    for (const std::string& s : in.strings(t.get("library"), "programs.library")) programs.library.push_back(in.relative(s));
    if (const toml::array* resident = t.get("resident") ? t.get("resident")->as_array() : nullptr) {
        for (const toml::node& item : *resident) {
            const std::optional<std::string> s = item.is_string() ? item.value<std::string>() : std::nullopt;
            const std::optional<ProgramRange> range = s ? parse_program_range(*s) : std::nullopt;
            if (range) programs.resident.push_back(*range);
            else in.error(item.source(), "programs.resident: expected a range of program numbers, \"O9000-O9999\" or \"O9010\"");
        }
    } else {
        in.strings(t.get("resident"), "programs.resident");   // the type error, if any
    }
}

// [limits]: sizes in bytes (integers, 0 = no limit), the time in seconds (a number, 0 = none).
void read_limits(Reader& in, const toml::table& t, LimitSettings& limits) {
    in.check_keys(t, "limits", kLimitsKeys);
    for (const std::string_view key : {std::string_view("max_file_bytes"), std::string_view("max_line_bytes")}) {
        const toml::node* node = t.get(key);
        if (!node) continue;
        const std::optional<std::int64_t> n = node->is_integer() ? node->value<std::int64_t>() : std::nullopt;
        if (!n || *n < 0) {
            in.error(node->source(), fmt::format("limits.{}: expected a number of bytes, 0 for no limit", key));
            continue;
        }
        (key == "max_file_bytes" ? limits.max_file_bytes : limits.max_line_bytes) = static_cast<std::uint64_t>(*n);
    }
    if (const toml::node* node = t.get("time_limit")) {
        const std::optional<double> s = node->is_number() ? node->value<double>() : std::nullopt;
        if (s && *s >= 0 && *s <= 1e6) limits.time_limit_s = *s;
        else in.error(node->source(), "limits.time_limit: expected seconds from 0 (no limit) to 1000000");
    }
}

void read_top(Reader& in, const toml::table& root, Config& c) {
    in.check_keys(root, "", kTopKeys);
    if (const auto d = in.string(root.get("dialect"), "dialect"); d && *d != "auto") c.dialect = *d;
    for (const std::string& f : in.strings(root.get("dialect_files"), "dialect_files")) c.dialect_files.push_back(in.relative(f));
    if (const auto m = in.string(root.get("machine"), "machine")) c.machine = in.relative(*m);
    if (const toml::table* run = in.table(root.get("run"), "run")) read_run(in, *run, c.run);
    if (const toml::table* programs = in.table(root.get("programs"), "programs")) read_programs(in, *programs, c.programs);
    if (const toml::table* limits = in.table(root.get("limits"), "limits")) read_limits(in, *limits, c.limits);
    in.table(root.get("format"), "format");   // its keys: formatter::style_from_toml
}

void add_format(std::string_view text, const fs::path& file, ConfigResult& r) {
    formatter::StyleResult style = formatter::style_from_toml(text, file.string());
    r.config.format = style.style;
    const std::string prefix = file.string() + ": ";
    for (formatter::StyleError& e : style.errors) {
        std::string message = std::move(e.message);
        if (message.starts_with(prefix)) message.erase(0, prefix.size());
        r.problems.push_back({Level::error, file.string(), e.line, e.column, std::move(message)});
    }
}

void add_check(std::string_view text, const fs::path& file, ConfigResult& r) {
    analyzer::ConfigResult check = analyzer::parse_check_config(text);
    r.config.check = std::move(check.config);
    for (analyzer::ConfigError& e : check.errors)
        r.problems.push_back({Level::error, file.string(), e.line, e.column, std::move(e.message)});
}

std::optional<std::int64_t> program_number(std::string_view s) {
    while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
    while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
    if (!s.empty() && (s.front() == 'O' || s.front() == 'o')) s.remove_prefix(1);
    if (s.empty() || s.size() > 8) return std::nullopt;
    std::int64_t n = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
    if (ec != std::errc{} || end != s.data() + s.size() || n < 0) return std::nullopt;
    return n;
}

}  // namespace

std::optional<std::pair<int, double>> parse_assignment(std::string_view text) {
    const auto blank = [](char c) { return c == ' ' || c == '\t'; };
    const auto trim = [&](std::string_view v) {
        while (!v.empty() && blank(v.front())) v.remove_prefix(1);
        while (!v.empty() && blank(v.back())) v.remove_suffix(1);
        return v;
    };
    text = trim(text);
    const std::size_t eq = text.find('=');
    if (text.size() < 4 || text.front() != '#' || eq == std::string_view::npos) return std::nullopt;
    const std::string_view name = trim(text.substr(1, eq - 1)), value = trim(text.substr(eq + 1));
    int number = 0;
    const auto [end, error] = std::from_chars(name.data(), name.data() + name.size(), number);
    if (error != std::errc() || end != name.data() + name.size() || number < 1 || number > 99999) return std::nullopt;
    // A number as a program writes it: sign, digits, a point (`5`, `-1.5`, `.25`).
    const std::string v(value);
    char* stop = nullptr;
    const double x = v.empty() || v.find_first_not_of("+-.0123456789") != std::string::npos ? NAN : std::strtod(v.c_str(), &stop);
    if (!std::isfinite(x) || stop != v.c_str() + v.size()) return std::nullopt;
    return std::pair<int, double>{number, x};
}

std::optional<ProgramRange> parse_program_range(std::string_view text) {
    const std::size_t dash = text.find('-');
    const auto first = program_number(text.substr(0, dash));
    const auto last = dash == std::string_view::npos ? first : program_number(text.substr(dash + 1));
    if (!first || !last || *first > *last) return std::nullopt;
    return ProgramRange{*first, *last};
}

Limits resolve_limits(const LimitSettings& over, const LimitSettings& under) {
    Limits limits;
    if (const auto v = over.max_file_bytes ? over.max_file_bytes : under.max_file_bytes) limits.input.max_file_bytes = *v;
    if (const auto v = over.max_line_bytes ? over.max_line_bytes : under.max_line_bytes) limits.input.max_line_bytes = *v;
    const double seconds = std::min(over.time_limit_s.value_or(under.time_limit_s.value_or(kDefaultTimeLimitS)), 1e6);
    limits.time_limit = std::chrono::milliseconds(static_cast<std::int64_t>(std::llround(seconds * 1000)));
    return limits;
}

bool ProgramSettings::resident_contains(std::int64_t number) const {
    return std::any_of(resident.begin(), resident.end(), [&](const ProgramRange& r) { return r.contains(number); });
}

ConfigResult parse_config(std::string_view text, const fs::path& file) {
    ConfigResult result;
    result.config.file = file;
    Reader in(file, result);
    toml::table root;
    try {
        root = toml::parse(text, file.string());
    } catch (const toml::parse_error& e) {
        in.error(e.source(), std::string(e.description()));
        return result;
    }
    read_top(in, root, result.config);
    add_check(text, file, result);
    add_format(text, file, result);
    std::stable_sort(result.problems.begin(), result.problems.end(), [](const Problem& a, const Problem& b) {
        return std::tie(a.line, a.column) < std::tie(b.line, b.column);
    });
    return result;
}

std::span<const KeyInfo> config_keys() { return kKeys; }

}  // namespace kerf::project
