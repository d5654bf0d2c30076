#include "cli/dry_run.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <optional>
#include <string_view>

#include "grammar/detect.hpp"
#include "interpreter/default_setup.hpp"
#include "machine/machine.hpp"

namespace kerf::cli {

namespace fs = std::filesystem;

namespace {

// Dialect files from the flags first, then from .kerf.toml.
std::vector<fs::path> dialect_files(const DryRunOptions& o, const ProjectConfig& config) {
    std::vector<fs::path> files(o.dialect_files.begin(), o.dialect_files.end());
    files.insert(files.end(), config.dialect_files.begin(), config.dialect_files.end());
    return files;
}

// LoadError messages start with their source ("<file>: <key>: what is wrong"); printed as
// file:line:col: error: <key>: what is wrong, the form of every other kerf diagnostic.
void print_load_error(const std::string& source, const dialects::LoadError& e) {
    std::string_view message = e.message;
    const std::string prefix = source + ": ";
    if (message.starts_with(prefix)) message.remove_prefix(prefix.size());
    if (e.line > 0)
        std::cerr << fmt::format("{}:{}:{}: error: {}\n", source, e.line, e.column, message);
    else
        std::cerr << fmt::format("{}: error: {}\n", source, message);
}

// The machine of a file (machine/SCHEMA.md), resolved for the dialect ("dialect" values), or
// nullopt after saying why. Any load error is fatal: a misspelt key must not run with a default.
std::optional<machine::Machine> load_machine(const fs::path& file, const dialects::Dialect& dialect) {
    std::string error;
    const std::optional<std::string> text = read_file(file, error);
    if (!text) {
        std::cerr << "kerf: " << error << "\n";
        return std::nullopt;
    }
    const machine::LoadResult loaded = machine::load_machine_text(*text, file.string());
    for (const dialects::LoadError& e : loaded.errors) print_load_error(file.string(), e);
    if (!loaded.machine || !loaded.errors.empty()) return std::nullopt;
    machine::Machine m = machine::resolve_for_dialect(*loaded.machine, dialect);
    if (m.kind != dialect.machine)
        std::cerr << fmt::format("kerf: warning: machine '{}' is a {} but dialect '{}' is for {}s\n", m.id,
                                 m.kind == dialects::MachineKind::lathe ? "lathe" : "mill", dialect.id,
                                 dialect.machine == dialects::MachineKind::lathe ? "lathe" : "mill");
    return m;
}

fs::path machine_file(const DryRunOptions& o, const ProjectConfig& config) {
    if (!o.machine_file.empty()) return o.machine_file;
    return config.machine_file.value_or(fs::path{});
}

// Hooks the mapped program up as a stream (the run parses it piece by piece and the pages of
// parsed pieces are dropped: memory stays flat however long the file), the folder loader, and
// finds the main program.
int load_program(DryRun& run, const std::string& file) {
    interpreter::StreamOptions stream;
    stream.read_ahead = true;   // the grammar on the second core (bench/RESULTS.md)
    stream.release = [source = run.source.get()](std::size_t begin, std::size_t end) { source->release(begin, end); };
    const std::uint32_t main_file = run.programs.add_stream(file, run.source->text(), *run.dialect, stream);
    const fs::path folder = fs::path(file).parent_path();
    run.programs.set_loader([folder](std::int64_t n) { return load_from_folder(folder, n); }, run.dialect);
    const std::optional<interpreter::ProgramRef> main = run.programs.first_program(main_file);
    if (!main) {
        std::cerr << fmt::format("kerf: {}: no program to run\n", file);
        return kExitFindings;
    }
    run.main = *main;
    return kExitClean;
}

}  // namespace

// Subprograms not in the file: the same folder, as O1000, O1000.nc or 1000.nc (issue 3).
std::optional<std::pair<std::string, std::string>> load_from_folder(const fs::path& folder, std::int64_t number) {
    const std::string o = fmt::format("O{:04}", number);
    for (const std::string& name : {o, o + ".nc", fmt::format("{:04}.nc", number), fmt::format("{}.nc", number)}) {
        const fs::path p = folder / name;
        std::error_code ec;
        if (!fs::is_regular_file(p, ec)) continue;
        std::string error;
        if (auto text = read_file(p, error)) return std::make_pair(p.string(), std::move(*text));
    }
    return std::nullopt;
}

// --dialect, else .kerf.toml's dialect, else detection from the text.
std::string choose_dialect(const std::string& flag, const ProjectConfig& config, std::string_view text) {
    if (flag != "auto") return flag;
    if (!config.dialect.empty() && config.dialect != "auto") return config.dialect;
    return grammar::detect_dialect(text).dialect;
}

// The Setup: the machine file if one is named, else the dialect's built-in machine.
std::optional<interpreter::Setup> setup_for(const fs::path& machine_file, const dialects::Dialect& dialect) {
    if (machine_file.empty()) return interpreter::default_setup(dialect);
    const std::optional<machine::Machine> m = load_machine(machine_file, dialect);
    if (!m) return std::nullopt;
    return interpreter::make_setup(*m);
}

void add_dry_run_options(CLI::App& command, DryRunOptions& o) {
    command.add_option("file", o.file, "program file")->required();
    command.add_option("--dialect", o.dialect, "dialect id, or auto (default)");
    command.add_option("--dialect-file", o.dialect_files, "load a dialect data file (TOML)");
    command.add_option("--machine", o.machine_file, "machine configuration file (TOML, machine/SCHEMA.md)");
    command.add_flag("--lenient", o.lenient, "run blocks with syntax errors without their defective words");
}

std::variant<std::unique_ptr<DryRun>, int> prepare_dry_run(const DryRunOptions& o) {
    std::string error;
    std::optional<MappedFile> source = MappedFile::open(o.file, error);
    if (!source) {
        std::cerr << "kerf: " << error << "\n";
        return kExitUsage;
    }
    std::vector<std::string> config_errors;
    const ProjectConfig config = find_config(o.file, config_errors);
    auto run = std::make_unique<DryRun>();
    run->source = std::make_unique<MappedFile>(std::move(*source));
    run->dialects = make_registry(dialect_files(o, config));
    for (const std::string& e : config_errors) std::cerr << "kerf: " << e << "\n";
    for (const std::string& e : run->dialects.errors) std::cerr << "kerf: " << e << "\n";
    run->dialect_id = choose_dialect(o.dialect, config, run->source->text());
    run->dialect = run->dialects.registry.find(run->dialect_id);
    if (!run->dialect) {
        std::cerr << fmt::format("kerf: unknown dialect '{}'; `kerf dialects` lists them\n", run->dialect_id);
        return kExitUsage;
    }
    std::optional<interpreter::Setup> setup = setup_for(machine_file(o, config), *run->dialect);
    if (!setup) return kExitUsage;
    run->setup = std::move(*setup);
    run->lenient = o.lenient;
    if (const int code = load_program(*run, o.file); code != kExitClean) return code;
    return run;
}

interpreter::RunResult execute(DryRun& run, interpreter::EventSink& sink, bool emit_state) {
    interpreter::RunOptions options;
    options.lenient = run.lenient;
    options.emit_state = emit_state;
    return interpreter::run(run.programs, run.main, *run.dialect, run.setup, sink, options);
}

int report_alarms(const DryRun& run, const interpreter::RunResult& result) {
    for (const interpreter::Event& a : result.alarms)
        std::cerr << fmt::format("{}:{}: error: alarm {}: {}\n", run.programs.file(a.source.file).name(), a.source.line,
                                 a.code, a.text);
    return result.alarms.empty() ? kExitClean : kExitFindings;
}

}  // namespace kerf::cli
