#include <algorithm>

#include "dialects/dialect.hpp"

namespace kerf::dialects {

const Dialect* Registry::find(std::string_view id) const {
    for (const Dialect& d : dialects_)
        if (d.id == id) return &d;
    return nullptr;
}

std::vector<std::string> Registry::ids() const {
    std::vector<std::string> out;
    for (const Dialect& d : dialects_) out.push_back(d.id);
    return out;
}

void Registry::add(Dialect dialect) {
    for (Dialect& d : dialects_) {
        if (d.id == dialect.id) {
            d = std::move(dialect);
            return;
        }
    }
    dialects_.push_back(std::move(dialect));
}

std::vector<LoadError> Registry::add_text(std::string_view toml_text, std::string_view source_name) {
    LoadResult loaded = load_dialect_text(toml_text, source_name);
    if (!loaded.file) return loaded.errors;
    DialectFile& file = *loaded.file;
    if (!file.overlay) {
        add(std::move(file.dialect));
        return {};
    }
    std::vector<LoadError> errors;
    for (std::size_t i = 0; i < file.applies_to.size(); ++i) {
        const Dialect* base = find(file.applies_to[i]);
        if (!base) {
            errors.push_back({std::string(source_name) + ": overlay applies to unknown dialect '" +
                                  file.applies_to[i] + "'",
                              0, 0});
            continue;
        }
        add(apply_overlay(*base, file, file.combined_ids[i]));
    }
    overlays_.push_back(std::move(file));
    return errors;
}

namespace {
Registry make_builtin() {
    Registry registry;
    // Bases first, then overlays (they combine with bases already present).
    for (int pass = 0; pass < 2; ++pass) {
        for (const auto& [stem, text] : builtin_dialect_texts()) {
            const bool is_overlay = text.find("overlay = true") != std::string_view::npos;
            if (is_overlay != (pass == 1)) continue;
            // Built-in data is checked by tests/dialects; a broken file must not take the tool down.
            (void)registry.add_text(text, std::string(stem) + ".toml");
        }
    }
    return registry;
}
}  // namespace

const Registry& builtin_registry() {
    static const Registry registry = make_builtin();
    return registry;
}

}  // namespace kerf::dialects
