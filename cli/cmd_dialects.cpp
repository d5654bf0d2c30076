// kerf dialects; kerf explain CODE --dialect D [--lang en|ru]
#include <fmt/format.h>

#include <iostream>

#include "analyzer/output.hpp"
#include "cli/commands.hpp"
#include "cli/progress.hpp"
#include "project/workspace.hpp"

namespace kerf::cli {

namespace {

const char* availability_text(dialects::Availability a) {
    switch (a) {
        case dialects::Availability::standard: return "standard";
        case dialects::Availability::optional: return "optional";
        case dialects::Availability::not_fitted: return "not fitted";
        case dialects::Availability::machine_specific: return "machine-specific";
        case dialects::Availability::unlisted: return "not in the seed table";
    }
    return "?";
}

std::string join(const std::vector<std::string>& items, const char* sep) {
    std::string out;
    for (const std::string& s : items) out += (out.empty() ? "" : sep) + s;
    return out;
}

struct ExplainOptions {
    std::string code;
    std::string dialect = "fanuc-lathe-a";
    std::string lang = "en";
    std::vector<std::string> dialect_files;
};

int run_explain(const ExplainOptions& o) {
    if (const analyzer::Rule* rule = analyzer::builtin_rules().find(o.code)) {   // K1001 or its name
        std::cout << analyzer::format_rule_docs(*rule);
        return kExitClean;
    }
    const project::DialectRegistry reg =
        project::load_dialects({o.dialect_files.begin(), o.dialect_files.end()}, project::DiskFileSystem());
    ProblemPrinter().print(reg.problems);
    const dialects::Dialect* d = reg.registry.find(o.dialect);
    if (!d) {
        std::cerr << fmt::format("kerf: unknown dialect '{}'; `kerf dialects` lists them\n", o.dialect);
        return kExitUsage;
    }
    if (o.lang != "en" && o.lang != "ru") {
        std::cerr << "kerf: --lang must be en or ru\n";
        return kExitUsage;
    }
    const dialects::CodeInfo* info = d->code(o.code);
    if (!info) {
        std::cerr << fmt::format("kerf: {} is not a code of {} (alarm 010 on the control)\n", o.code, d->id);
        return kExitFindings;
    }
    const bool ru = o.lang == "ru";
    std::cout << fmt::format("{} — {}\n", info->spelling, ru ? info->ru : info->en);
    if (!info->aliases.empty()) std::cout << fmt::format("  {}: {}\n", ru ? "также" : "also written", join(info->aliases, ", "));
    std::cout << fmt::format("  {}: {}\n", ru ? "диалект" : "dialect", d->id);
    if (info->letter == 'G') {
        std::cout << fmt::format("  {}: {}{}\n", ru ? "группа" : "group", info->group,
                                 info->group == "00" ? (ru ? " (однократный)" : " (one-shot)")
                                                     : (ru ? " (модальный)" : " (modal)"));
        if (info->power_on_default) std::cout << (ru ? "  активен при включении и сбросе\n" : "  active at power-on and reset\n");
    }
    std::cout << fmt::format("  {}: {}\n", ru ? "функция" : "function", info->function);
    if (!info->words.empty()) std::cout << fmt::format("  {}: {}\n", ru ? "адреса" : "words", join(info->words, " "));
    if (!info->required.empty()) std::cout << fmt::format("  {}: {}\n", ru ? "обязательные" : "required", join(info->required, " "));
    for (const auto& alternatives : info->required_one_of)
        std::cout << fmt::format("  {}: {}\n", ru ? "одно из" : "one of", join(alternatives, " "));
    std::cout << fmt::format("  {}: {}{}\n", ru ? "наличие" : "availability", availability_text(info->availability),
                             info->availability_note.empty() ? "" : " — " + info->availability_note);
    if (!info->notes.empty()) std::cout << fmt::format("  {}: {}\n", ru ? "примечания" : "notes", info->notes);
    std::cout << fmt::format("  {}: {}\n", ru ? "источник" : "reference", info->reference);
    return kExitClean;
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
    CLI::App* cmd = app.add_subcommand("explain", "describe a G or M code of a dialect, or a check rule (K1001)");
    cmd->add_option("code", o->code, "G71, M98, G12.1 ...")->required();
    cmd->add_option("--dialect", o->dialect, "dialect id (default fanuc-lathe-a)");
    cmd->add_option("--lang", o->lang, "en or ru")->check(CLI::IsMember({"en", "ru"}));
    cmd->add_option("--dialect-file", o->dialect_files, "also load a dialect data file (TOML)");
    return [o] { return run_explain(*o); };
}

}  // namespace kerf::cli
