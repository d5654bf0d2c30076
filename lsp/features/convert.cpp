// Code actions "Convert this program to <dialect name> (<id>)": `kerf convert` (converter/convert.hpp,
// docs/convert.md) on the open document, one action per other dialect of the same kind of machine
// in the document's registry (the built-ins and the project's dialect files), the lathe G-code
// systems among them ("FANUC lathe, G-code system B"). The edit is the converter's own: byte ranges
// of the text and their replacements, so the client changes only what the conversion changes. A
// small document's actions carry their edit and say how many constructs stay as they are; a
// larger one's are resolved when chosen (codeAction/resolve), as "renumber blocks" is.
//
// The source reads numbers as the document's machine does (its Setup); the target as its own
// dialect's defaults say (a machine file's overrides are the command line's business: `kerf
// convert --machine`).
#include <fmt/format.h>

#include <algorithm>

#include "converter/convert.hpp"
#include "lsp/features.hpp"
#include "lsp/features/common.hpp"

namespace kerf::lsp {

namespace {

// Up to this size the actions carry their edits (a conversion of 64 KB takes about a millisecond).
constexpr std::size_t kEagerBytes = std::size_t{64} << 10;

struct Converted {
    json::object edit;
    std::size_t left = 0;   // constructs left as they are, syntax errors
};

converter::Options options_for(const Document& doc, const dialects::Dialect& to) {
    converter::Options o;
    o.from = converter::reading_of(doc.dialect(), doc.settings().setup);
    o.to = converter::reading_of(to);
    o.setup = doc.settings().setup;
    o.name = doc.path().string();
    o.time_limit_ms = 2000;   // the G52 dry run of an endless program stops here
    return o;
}

Converted convert_document(const Document& doc, const dialects::Dialect& to) {
    const converter::Conversion c = converter::convert(doc.typed(), to, options_for(doc, to));
    json::array edits;
    for (std::size_t i = 0; i < c.edits.size(); ++i) {
        const converter::Edit e = c.edits[i];
        edits.push_back(text_edit(doc, e.range, e.text));
    }
    Converted r;
    r.edit = json::object{{"changes", json::object{{doc.uri(), std::move(edits)}}}};
    r.left = static_cast<std::size_t>(std::count_if(c.reports.begin(), c.reports.end(), [](const converter::Report& rep) {
        return rep.kind == converter::ReportKind::unconverted || rep.kind == converter::ReportKind::syntax_error;
    }));
    return r;
}

std::string title_of(const dialects::Dialect& to) { return fmt::format("Convert this program to {} ({})", to.name, to.id); }

// The other dialects of the document's kind, the ones derived from the same base first (the
// G-code systems of a lathe, a SPINNER variant's siblings), then the rest by id.
std::vector<const dialects::Dialect*> targets(const Document& doc) {
    const dialects::Dialect& from = doc.dialect();
    const dialects::Registry& registry = *doc.settings().registry;
    const auto root = [](const dialects::Dialect& d) { return d.bases.empty() ? d.id : d.bases.back(); };
    std::vector<const dialects::Dialect*> out;
    for (const std::string& id : registry.ids()) {
        const dialects::Dialect* d = registry.find(id);
        if (d && d->id != from.id && d->machine == from.machine) out.push_back(d);
    }
    std::stable_sort(out.begin(), out.end(), [&](const dialects::Dialect* a, const dialects::Dialect* b) {
        const bool sa = root(*a) == root(from) && a->overlays == from.overlays;
        const bool sb = root(*b) == root(from) && b->overlays == from.overlays;
        return sa > sb;
    });
    return out;
}

}  // namespace

void conversion_actions(const Snapshot& s, json::array& out) {
    const Document& doc = s.document();
    const bool eager = doc.text().size() < kEagerBytes;
    for (const dialects::Dialect* to : targets(doc)) {
        if (s.cancelled()) return;
        // A whole-program action, like source.fixAll: kind source.convert.kerf.
        json::object action{{"title", title_of(*to)}, {"kind", "source.convert.kerf"}};
        if (!eager) {
            action["data"] = json::object{{"kerf", "convert"}, {"to", to->id}, {"uri", doc.uri()}, {"version", doc.version()}};
            out.push_back(std::move(action));
            continue;
        }
        Converted c = convert_document(doc, *to);
        if (c.left > 0) action["title"] = fmt::format("{}: {} left as {} {}", title_of(*to), c.left, c.left == 1 ? "it" : "they",
                                                      c.left == 1 ? "is" : "are");
        action["edit"] = std::move(c.edit);
        out.push_back(std::move(action));
    }
}

json::value resolve_conversion(const Snapshot& s, json::object action) {
    const Document& doc = s.document();
    const json::value* to = find_path(action, {"data", "to"});
    const dialects::Dialect* target = to && to->is_string() ? doc.settings().registry->find(std::string(to->as_string())) : nullptr;
    if (!target) throw RpcError(error_code::request_failed, "the conversion's target dialect is not known here");
    action["edit"] = convert_document(doc, *target).edit;
    return action;
}

}  // namespace kerf::lsp
