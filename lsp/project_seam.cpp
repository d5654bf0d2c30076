#include "lsp/project_seam.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <fstream>

#include "ast/typed.hpp"
#include "grammar/detect.hpp"
#include "grammar/parse.hpp"
#include "interpreter/default_setup.hpp"
#include "machine/machine.hpp"

namespace kerf::lsp {

namespace fs = std::filesystem;

// One .kerf.toml as the server reads it (or the defaults without one).
struct ProjectSeam::Config {
    fs::path file;
    std::string dialect;
    std::optional<fs::path> machine;
    std::shared_ptr<const dialects::Registry> registry;
    formatter::Style style;
    analyzer::CheckConfig check;
    std::vector<std::string> problems;
};

namespace {

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::string load_error_text(const dialects::LoadError& e) {
    return e.line ? fmt::format("{} (line {}, column {})", e.message, e.line, e.column) : e.message;
}

// The program's first comment: on its O line or the comment-only lines right after it.
std::string first_comment(const ast::TypedFile& typed, const ast::Program& p) {
    const ast::SyntaxTree& tree = typed.tree();
    for (std::uint32_t b = p.first_block; b < p.end_block && b < p.first_block + 3; ++b) {
        for (const std::uint32_t t : typed.block(b).comments()) {
            std::string_view s = tree.spelling(tree.tokens[t]);
            if (!s.empty() && s.front() == '(') s.remove_prefix(1);
            if (!s.empty() && s.back() == ')') s.remove_suffix(1);
            while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
            while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
            return std::string(s);
        }
        const ast::BlockKind kind = tree.blocks[b].kind;
        if (b > p.first_block && kind != ast::BlockKind::comment_only && kind != ast::BlockKind::blank) break;
    }
    return {};
}

std::vector<IndexedProgram> indexed(const fs::path& file, const ast::TypedFile& typed) {
    std::vector<IndexedProgram> out;
    const ast::SyntaxTree& tree = typed.tree();
    for (std::uint32_t i = 0; i < typed.programs().size(); ++i) {
        const ast::Program& p = typed.programs()[i];
        if (!p.number) continue;
        const ast::Range first = tree.block_range(p.first_block);
        const std::uint32_t end = p.end_block < tree.block_count() ? tree.blocks[p.end_block].begin : static_cast<std::uint32_t>(tree.text.size());
        out.push_back({file, *p.number, i, first.begin, end, first_comment(typed, p)});
    }
    return out;
}

std::vector<IndexedProgram> scan(const fs::path& file, std::string_view text) {
    if (text.find('\0') != std::string_view::npos) return {};
    // Program boundaries depend on the lexical rules only through ';' and comments: the detected
    // dialect's rules are good enough for the index (the project layer's scan replaces this).
    const dialects::Dialect* d = dialects::builtin_registry().find(grammar::detect_dialect(text).dialect);
    if (!d) return {};
    ast::SyntaxTree tree = grammar::parse(std::string(text), d->lexical);
    const ast::TypedFile typed = ast::TypedFile::bind(tree, *d);
    return indexed(file, typed);
}

}  // namespace

bool is_program_file(const fs::path& path) {
    static const std::string kExtensions[] = {".nc", ".ngc", ".tap", ".cnc", ".mpf", ".eia", ".txt"};
    const std::string ext = lower(path.extension().string());
    if (std::find(std::begin(kExtensions), std::end(kExtensions), ext) != std::end(kExtensions)) return true;
    if (!ext.empty()) return false;
    const std::string name = path.filename().string();
    return name.size() >= 2 && (name[0] == 'O' || name[0] == 'o') &&
           std::all_of(name.begin() + 1, name.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

ProjectSeam::ProjectSeam(Reader reader) : reader_(std::move(reader)) {}

void ProjectSeam::set_client(ClientSettings settings) {
    const std::lock_guard lock(mutex_);
    client_ = std::move(settings);
}

ClientSettings ProjectSeam::client() const {
    const std::lock_guard lock(mutex_);
    return client_;
}

void ProjectSeam::forget_configs() {
    const std::lock_guard lock(mutex_);
    configs_.clear();
}

std::optional<fs::path> ProjectSeam::config_of(const fs::path& file) const {
    std::error_code ec;
    for (fs::path dir = file.parent_path(); !dir.empty(); dir = dir.parent_path()) {
        const fs::path candidate = dir / ".kerf.toml";
        if (fs::exists(candidate, ec)) return candidate;
        if (dir == dir.root_path()) break;
    }
    return std::nullopt;
}

std::shared_ptr<const ProjectSeam::Config> ProjectSeam::config_for(const std::optional<fs::path>& file) {
    const fs::path key = file.value_or(fs::path());
    {
        const std::lock_guard lock(mutex_);
        if (const auto it = configs_.find(key); it != configs_.end()) return it->second;
    }
    auto c = std::make_shared<Config>();
    c->file = key;
    std::vector<fs::path> dialect_files;
    if (file) {
        const std::optional<std::string> text = reader_(*file);
        if (!text) {
            c->problems.push_back(fmt::format("{}: cannot read the file", file->string()));
        } else {
            try {
                const toml::table t = toml::parse(*text, file->string());
                if (const auto d = t["dialect"].value<std::string>()) c->dialect = *d;
                if (const auto m = t["machine"].value<std::string>()) c->machine = file->parent_path() / *m;
                if (const toml::array* files = t["dialect_files"].as_array())
                    for (const toml::node& f : *files)
                        if (const auto s = f.value<std::string>()) dialect_files.push_back(file->parent_path() / *s);
            } catch (const toml::parse_error& e) {
                c->problems.push_back(fmt::format("{}:{}:{}: {}", file->string(), e.source().begin.line, e.source().begin.column, e.description()));
            }
            formatter::StyleResult style = formatter::style_from_toml(*text, file->string());
            c->style = style.style;
            for (const formatter::StyleError& e : style.errors) c->problems.push_back(e.message);
            analyzer::ConfigResult check = analyzer::parse_check_config(*text, file->string());
            c->check = std::move(check.config);
            for (std::string& e : check.errors) c->problems.push_back(std::move(e));
        }
    }
    if (dialect_files.empty()) {
        c->registry = std::shared_ptr<const dialects::Registry>(&dialects::builtin_registry(), [](const dialects::Registry*) {});
    } else {
        auto registry = std::make_shared<dialects::Registry>(dialects::builtin_registry());
        for (const fs::path& f : dialect_files) {
            const std::optional<std::string> text = reader_(f);
            if (!text) {
                c->problems.push_back(fmt::format("{}: cannot read the dialect file", f.string()));
                continue;
            }
            for (const dialects::LoadError& e : registry->add_text(*text, f.string())) c->problems.push_back(load_error_text(e));
        }
        c->registry = std::move(registry);
    }
    const std::lock_guard lock(mutex_);
    return configs_.emplace(key, std::move(c)).first->second;
}

namespace {

// The entries of a baseline that name `file`: the path as `kerf check` wrote it, absolute or
// relative to the baseline's folder (the usual: run from the repository root).
void load_baseline(const fs::path& baseline, const fs::path& file, FileSettings& s) {
    std::ifstream in(baseline, std::ios::binary);
    if (!in) {
        s.problems.push_back(fmt::format("{}: cannot read the baseline (kerf.baseline)", baseline.string()));
        return;
    }
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::string error;
    const auto entries = analyzer::read_baseline(text, error);
    if (!entries) {
        s.problems.push_back(fmt::format("{}: {}", baseline.string(), error));
        return;
    }
    for (const analyzer::BaselineEntry& e : *entries) {
        const fs::path named(e.file);
        const fs::path absolute = named.is_absolute() ? named : (baseline.parent_path() / named);
        if (absolute.lexically_normal() == file.lexically_normal()) s.baseline.push_back(e);
    }
}

}  // namespace

std::shared_ptr<const FileSettings> ProjectSeam::resolve(const fs::path& file, std::string_view text) {
    const std::shared_ptr<const Config> config = config_for(config_of(file));
    const ClientSettings client = this->client();
    auto s = std::make_shared<FileSettings>();
    s->registry = config->registry;
    s->config_file = config->file;
    s->problems = config->problems;
    s->style = config->style;
    s->check = config->check;
    s->language = client.language;
    // The dialect: the client's setting, the .kerf.toml's, then the header and detection.
    const auto pick = [&](const std::string& id, std::string why) {
        if (id.empty() || id == "auto" || s->dialect) return;
        s->dialect = s->registry->find(id);
        if (s->dialect) s->dialect_why = fmt::format("{} from {}", id, why);
        else s->problems.push_back(fmt::format("unknown dialect '{}' ({}); `kerf dialects` lists them", id, why));
    };
    pick(client.dialect, "the client setting kerf.dialect");
    pick(config->dialect, config->file.string());
    if (!s->dialect) {
        const grammar::Detection d = grammar::detect_dialect(text);
        s->dialect = s->registry->find(d.dialect);
        s->detection = d.reasons;
        s->dialect_why = fmt::format("{} detected from the text", d.dialect);
    }
    // The machine: the client's kerf.machine, the .kerf.toml's `machine`, the dialect's built-in one.
    std::optional<fs::path> machine_file;
    std::string machine_origin;
    if (!client.machine.empty()) {
        machine_file = fs::path(client.machine);
        machine_origin = "the client setting kerf.machine";
    } else if (config->machine) {
        machine_file = config->machine;
        machine_origin = config->file.string();
    }
    s->setup = interpreter::default_setup(*s->dialect);
    s->machine_why = fmt::format("the built-in machine of {}", s->dialect->id);
    if (machine_file) {
        const std::optional<std::string> mtext = reader_(*machine_file);
        if (!mtext) {
            s->problems.push_back(fmt::format("{}: cannot read the machine file ({}); the built-in machine is used", machine_file->string(), machine_origin));
        } else {
            const machine::LoadResult loaded = machine::load_machine_text(*mtext, machine_file->string());
            for (const dialects::LoadError& e : loaded.errors) s->problems.push_back(load_error_text(e));
            if (loaded.machine && loaded.errors.empty()) {
                s->setup = interpreter::make_setup(machine::resolve_for_dialect(*loaded.machine, *s->dialect));
                s->machine_why = fmt::format("{} from {}", machine_file->string(), machine_origin);
            }
        }
    }
    s->format_context.calculator_decimal = s->setup.calculator_decimal;
    if (!client.baseline.empty()) load_baseline(fs::path(client.baseline), file, *s);
    return s;
}

void ProjectSeam::index_root(const fs::path& root) {
    std::error_code ec;
    fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, ec);
    if (ec) return;
    for (const fs::recursive_directory_iterator end; it != end; it.increment(ec)) {
        if (ec) break;
        const fs::directory_entry& entry = *it;
        const std::string name = entry.path().filename().string();
        if (entry.is_directory(ec)) {
            if (name.size() > 1 && name[0] == '.') it.disable_recursion_pending();
            if (name == "node_modules" || name == "build") it.disable_recursion_pending();
            continue;
        }
        if (!entry.is_regular_file(ec) || !is_program_file(entry.path())) continue;
        if (entry.file_size(ec) > (std::uintmax_t{64} << 20)) continue;   // a 64 MB file is not a subprogram library
        if (const std::optional<std::string> text = reader_(entry.path())) update_file(entry.path(), *text);
    }
}

void ProjectSeam::update_file(const fs::path& file, std::string_view text) {
    std::vector<IndexedProgram> programs = scan(file, text);
    const std::lock_guard lock(mutex_);
    index_[file] = std::move(programs);
}

std::vector<IndexedProgram> ProjectSeam::programs_of(const fs::path& file, const ast::TypedFile& typed) { return indexed(file, typed); }

void ProjectSeam::set_programs(const fs::path& file, std::vector<IndexedProgram> programs) {
    const std::lock_guard lock(mutex_);
    index_[file] = std::move(programs);
}

void ProjectSeam::remove_file(const fs::path& file) {
    const std::lock_guard lock(mutex_);
    index_.erase(file);
}

std::optional<IndexedProgram> ProjectSeam::find_program(std::int64_t number, const fs::path& from) const {
    const std::lock_guard lock(mutex_);
    std::optional<IndexedProgram> best;
    for (const auto& [file, programs] : index_) {
        if (file == from) continue;
        for (const IndexedProgram& p : programs) {
            if (p.number != number) continue;
            const bool same_folder = file.parent_path() == from.parent_path();
            if (!best || (same_folder && best->file.parent_path() != from.parent_path())) best = p;
            break;
        }
    }
    return best;
}

std::vector<IndexedProgram> ProjectSeam::programs_in(const fs::path& file) const {
    const std::lock_guard lock(mutex_);
    const auto it = index_.find(file);
    return it == index_.end() ? std::vector<IndexedProgram>{} : it->second;
}

std::vector<IndexedProgram> ProjectSeam::all_programs() const {
    const std::lock_guard lock(mutex_);
    std::vector<IndexedProgram> out;
    for (const auto& [file, programs] : index_) out.insert(out.end(), programs.begin(), programs.end());
    return out;
}

std::vector<fs::path> ProjectSeam::files() const {
    const std::lock_guard lock(mutex_);
    std::vector<fs::path> out;
    for (const auto& [file, programs] : index_) out.push_back(file);
    return out;
}

interpreter::ProgramSet::Loader ProjectSeam::loader_for(const fs::path& file) const {
    return [this, file](std::int64_t number) -> std::optional<std::pair<std::string, std::string>> {
        const std::optional<IndexedProgram> p = find_program(number, file);
        if (!p) return std::nullopt;
        std::optional<std::string> text = reader_(p->file);
        if (!text) return std::nullopt;
        return std::make_pair(p->file.string(), std::move(*text));
    };
}

}  // namespace kerf::lsp
