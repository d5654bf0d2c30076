#include <algorithm>

#include "dialects/dialect.hpp"

namespace kerf::dialects {

const Dialect* Registry::find(std::string_view id) const {
    for (const Dialect& d : dialects_)
        if (d.id == id) return &d;
    return nullptr;
}

const Dialect* Registry::find_foreign(std::string_view id) const {
    for (const Dialect& d : foreign_)
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
    if (file.dialect.foreign) {
        const auto same = std::find_if(foreign_.begin(), foreign_.end(), [&](const Dialect& d) { return d.id == file.dialect.id; });
        if (same != foreign_.end()) *same = std::move(file.dialect);
        else foreign_.push_back(std::move(file.dialect));
        return {};
    }
    if (!file.base.empty()) return add_derived(std::move(file), source_name);
    if (!file.overlay) {
        std::vector<LoadError> errors = check_detect(file.dialect, source_name);
        if (errors.empty()) add(std::move(file.dialect));
        return errors;
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
        Dialect combined = apply_overlay(*base, file, file.combined_ids[i]);
        std::vector<LoadError> detect = check_detect(combined, source_name);
        errors.insert(errors.end(), detect.begin(), detect.end());
        if (detect.empty()) add(std::move(combined));
    }
    overlays_.push_back(std::move(file));
    return errors;
}

std::vector<LoadError> Registry::add_derived(DialectFile file, std::string_view source_name) {
    const Dialect* base = find(file.base);
    if (!base) {
        std::string known;
        for (const std::string& id : ids()) known += (known.empty() ? "" : ", ") + id;
        return {{std::string(source_name) + ": base: unknown dialect '" + file.base + "' (known: " + known +
                     "; a base in a user file must be loaded before the files that derive from it)",
                 file.base_line, file.base_column}};
    }
    std::vector<LoadError> errors;
    Dialect d = derive_dialect(*base, file, source_name, errors);
    if (!errors.empty()) return errors;
    errors = check_detect(d, source_name);
    if (errors.empty()) add(std::move(d));
    return errors;
}

namespace {
Registry make_builtin() {
    Registry registry;
    std::vector<std::pair<DialectFile, std::string>> derived, overlays;
    for (const auto& [stem, text] : builtin_dialect_texts()) {
        LoadResult loaded = load_dialect_text(text, stem);
        // Built-in data is checked by tests/dialects; a broken file must not take the tool down.
        if (!loaded.file) continue;
        if (loaded.file->overlay) overlays.emplace_back(std::move(*loaded.file), std::string(stem));
        else if (!loaded.file->base.empty()) derived.emplace_back(std::move(*loaded.file), std::string(stem));
        else registry.add_file(std::move(*loaded.file), stem);
    }
    // Derived dialects after their bases (a base may derive too: rounds until none is left or no
    // round makes progress), overlays last: they combine with what is there.
    while (!derived.empty()) {
        std::vector<std::pair<DialectFile, std::string>> later;
        for (auto& [file, stem] : derived) {
            if (registry.find(file.base)) registry.add_file(std::move(file), stem);
            else later.emplace_back(std::move(file), std::move(stem));
        }
        if (later.size() == derived.size()) break;
        derived = std::move(later);
    }
    for (auto& [file, stem] : overlays) registry.add_file(std::move(file), stem);
    return registry;
}
}  // namespace
const Registry& builtin_registry() {
    static const Registry registry = make_builtin();
    return registry;
}

}  // namespace kerf::dialects
