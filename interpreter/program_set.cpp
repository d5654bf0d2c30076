#include "interpreter/program_set.hpp"


namespace kerf::interpreter {

std::uint32_t ProgramSet::add(std::string name, std::string text, const dialects::Dialect& dialect) {
    files_.push_back(std::make_unique<LoadedFile>(std::move(name), std::move(text), dialect));
    return static_cast<std::uint32_t>(files_.size() - 1);
}

std::uint32_t ProgramSet::add_parsed(std::string name, std::shared_ptr<const void> owner, const ast::TypedFile& typed,
                                     const ast::LineIndex& lines) {
    files_.push_back(std::make_unique<LoadedFile>(std::move(name), std::move(owner), typed, lines));
    return static_cast<std::uint32_t>(files_.size() - 1);
}

std::uint32_t ProgramSet::add_stream(std::string name, std::string_view text, const dialects::Dialect& dialect,
                                     StreamOptions options) {
    files_.push_back(std::make_unique<LoadedFile>(std::move(name), text, dialect, std::move(options)));
    return static_cast<std::uint32_t>(files_.size() - 1);
}

std::optional<ProgramRef> ProgramSet::find(std::int64_t number, std::uint32_t from_file) const {
    auto search = [&](std::uint32_t fi) -> std::optional<ProgramRef> {
        if (const auto p = files_[fi]->find_program(number)) return ProgramRef{fi, *p};
        return std::nullopt;
    };
    if (from_file < files_.size())
        if (auto r = search(from_file)) return r;
    for (std::uint32_t fi = 0; fi < files_.size(); ++fi)
        if (fi != from_file)
            if (auto r = search(fi)) return r;
    return std::nullopt;
}

std::optional<ProgramRef> ProgramSet::find_or_load(std::int64_t number, std::uint32_t from_file) {
    if (auto found = find(number, from_file)) return found;
    if (!loader_ || !loader_dialect_) return std::nullopt;
    auto loaded = loader_(number);
    if (!loaded) return std::nullopt;
    add(std::move(loaded->first), std::move(loaded->second), *loader_dialect_);
    return find(number, from_file);
}

std::optional<ProgramRef> ProgramSet::first_program(std::uint32_t file) const {
    if (file >= files_.size()) return std::nullopt;
    if (const auto p = files_[file]->first_program()) return ProgramRef{file, *p};
    return std::nullopt;
}

}  // namespace kerf::interpreter
