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
    return add_file(std::move(*loaded.file), source_name);
}

std::vector<LoadError> Registry::add_file(DialectFile file, std::string_view source_name) {
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
    std::vector<std::pair<DialectFile, std::string>> overlays;
    for (const auto& [stem, text] : builtin_dialect_texts()) {
        LoadResult loaded = load_dialect_text(text, stem);
        // Built-in data is checked by tests/dialects; a broken file must not take the tool down.
        if (!loaded.file) continue;
        if (loaded.file->overlay) overlays.emplace_back(std::move(*loaded.file), std::string(stem));
        else registry.add_file(std::move(*loaded.file), stem);
    }
    // Overlays combine with bases, so they come last.
    for (auto& [file, stem] : overlays) registry.add_file(std::move(file), stem);
    return registry;
}
}  // namespace
const Registry& builtin_registry() {
    static const Registry registry = make_builtin();
    return registry;
}

}  // namespace kerf::dialects
