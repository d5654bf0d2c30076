// kerf dialects; kerf explain CODE --dialect D [--lang en|ru]
#include <fmt/format.h>

#include <iostream>

#include "analyzer/explain.hpp"
#include "analyzer/output.hpp"
#include "analyzer/registry.hpp"
#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "project/workspace.hpp"

namespace kerf::cli {

namespace {

struct ExplainOptions {
    std::string code;
    std::string dialect;   // empty: every dialect that has the code
    std::string lang = "en";
    std::vector<std::string> dialect_files;
};

// analyzer::explain does the work (the server's hover renders the same data); this prints it.
int run_explain(const ExplainOptions& o) {
    const project::DialectRegistry reg =
        project::load_dialects({o.dialect_files.begin(), o.dialect_files.end()}, project::DiskFileSystem());
    ProblemPrinter().print(reg.problems);
    const analyzer::Language lang = o.lang == "ru" ? analyzer::Language::ru : analyzer::Language::en;
    const analyzer::Explanation e = analyzer::explain({o.code, o.dialect, lang}, reg.registry, analyzer::builtin_rules());
    const std::string text = analyzer::format_explanation(e, lang);
    switch (e.kind) {
        case analyzer::Explanation::Kind::rule:
        case analyzer::Explanation::Kind::code: std::cout << text; return kExitClean;
        case analyzer::Explanation::Kind::unknown_dialect:
        case analyzer::Explanation::Kind::not_understood: std::cerr << text; return kExitUsage;
        default: std::cerr << text; return kExitFindings;
    }
}

}  // namespace

Command add_dialects_command(CLI::App& app) {
    auto files = std::make_shared<std::vector<std::string>>();
    auto functions = std::make_shared<bool>(false);
    CLI::App* cmd = app.add_subcommand("dialects", "list the dialects");
    cmd->add_option("--dialect-file", *files, "also load a dialect data file (TOML)");
    cmd->add_flag("--functions", *functions, "print the function id tables of docs/functions.md (markdown)");
    return [files, functions] {
        const project::DialectRegistry reg =
            project::load_dialects({files->begin(), files->end()}, project::DiskFileSystem());
        const bool errors = ProblemPrinter().print(reg.problems);
        if (*functions) {
            std::cout << dialects::function_tables_markdown(reg.registry);
            return errors ? kExitUsage : kExitClean;
        }
        for (const std::string& id : reg.registry.ids()) {
            const dialects::Dialect* d = reg.registry.find(id);
            std::size_t g = 0, m = 0;
            for (const dialects::CodeInfo& c : d->codes()) (c.letter == 'G' ? g : m)++;
            std::cout << fmt::format("{:<18} {:<5} {:>3} G {:>3} M  {}\n", id,
                                     d->machine == dialects::MachineKind::lathe ? "lathe" : "mill", g, m, d->name);
        }
        return errors ? kExitUsage : kExitClean;
    };
}

Command add_explain_command(CLI::App& app) {
    auto o = std::make_shared<ExplainOptions>();
    CLI::App* cmd = app.add_subcommand("explain", "describe a G or M code of a dialect, a check rule (K1001) or a diagnostic id (S0101)");
    cmd->add_option("code", o->code, "G71, M98, G12.1 ...")->required();
    cmd->add_option("--dialect", o->dialect, "dialect id (default: every dialect that has the code)");
    cmd->add_option("--lang", o->lang, "en or ru")->check(CLI::IsMember({"en", "ru"}));
    cmd->add_option("--dialect-file", o->dialect_files, "also load a dialect data file (TOML)");
    return [o] { return run_explain(*o); };
}

}  // namespace kerf::cli
