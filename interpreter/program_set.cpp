#include "interpreter/program_set.hpp"

#include "grammar/parse.hpp"

namespace kerf::interpreter {

std::uint32_t ProgramSet::add(std::string name, std::string text, const dialects::Dialect& dialect) {
    auto f = std::make_unique<LoadedFile>();
    f->name = std::move(name);
    f->tree = grammar::parse(std::move(text), dialect.lexical);
    f->typed = std::make_unique<ast::TypedFile>(ast::TypedFile::bind(f->tree, dialect));
    f->lines = std::make_unique<ast::LineIndex>(f->tree.text);
    files_.push_back(std::move(f));
    return static_cast<std::uint32_t>(files_.size() - 1);
}

std::optional<ProgramRef> ProgramSet::find(std::int64_t number, std::uint32_t from_file) const {
    auto search = [&](std::uint32_t fi) -> std::optional<ProgramRef> {
        const auto& programs = files_[fi]->typed->programs();
        for (std::uint32_t p = 0; p < programs.size(); ++p)
            if (programs[p].number == number) return ProgramRef{fi, p};
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
    if (file >= files_.size() || files_[file]->typed->programs().empty()) return std::nullopt;
    return ProgramRef{file, 0};
}

}  // namespace kerf::interpreter
