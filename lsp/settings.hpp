// What analysing, formatting and running one document needs, resolved once per document from the
// client's settings and the .kerf.toml over it (project::Workspace through lsp/project_seam.hpp). Immutable: documents and
// the analysis worker share one through a shared pointer.
#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "analyzer/baseline.hpp"
#include "analyzer/config.hpp"
#include "dialects/dialect.hpp"
#include "formatter/format.hpp"
#include "formatter/style.hpp"
#include "interpreter/setup.hpp"
#include "project/workspace.hpp"

namespace kerf::lsp {

// The client's settings (`kerf.*`, workspace/configuration or didChangeConfiguration).
struct ClientSettings {
    std::string dialect;    // "" or "auto": the .kerf.toml, the header, detection
    std::string machine;    // a machine file; "": the .kerf.toml's, else the dialect's built-in
    std::string language = "en";   // hover texts: "en" or "ru" (else the client's locale at initialize)
    std::string baseline;   // a baseline file of `kerf check --write-baseline`: its findings are not shown
    friend bool operator==(const ClientSettings&, const ClientSettings&) = default;
};

struct FileSettings {
    std::shared_ptr<const dialects::Registry> registry;   // keeps `dialect` alive
    const dialects::Dialect* dialect = nullptr;
    std::string dialect_why;                // "fanuc-mill from the client setting kerf.dialect"
    bool detected = false;                  // the dialect was detected from the text (a header edit may change it)
    std::vector<std::string> detection;     // detection's reasons when it decided
    interpreter::Setup setup;
    std::string machine_why;
    formatter::Style style;                 // .kerf.toml [format]
    formatter::FormatContext format_context;
    analyzer::CheckConfig check;            // .kerf.toml [check]
    std::chrono::milliseconds time_limit{0};   // of the dry run: .kerf.toml [limits] time_limit, as kerf check (0 = none)
    // The accepted findings of the client's kerf.baseline file that name this file (analyzer/baseline.hpp).
    std::vector<analyzer::BaselineEntry> baseline;
    std::filesystem::path config_file;      // the .kerf.toml, empty when none
    // The project as the workspace resolved it for this file (its [run], [programs], a foreign
    // control): the check options are project::project_check_options of it, as for kerf check.
    project::Resolved resolved;
    std::vector<std::string> problems;      // what could not be read, said to the user
    std::string language = "en";
};

}  // namespace kerf::lsp
