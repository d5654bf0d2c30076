#include "interpreter/loaded_file.hpp"

#include <algorithm>
#include <cstring>

namespace kerf::interpreter {

struct LoadedFile::Held {
    std::size_t piece = 0;
    ast::SyntaxTree tree;
    std::unique_ptr<ast::TypedFile> typed;
    std::unique_ptr<ast::LineIndex> lines;
    std::uint64_t last_use = 0;
};

LoadedFile::LoadedFile(std::string name, std::string text, const dialects::Dialect& dialect)
    : name_(std::move(name)), dialect_(dialect) {
    auto held = std::make_unique<Held>();
    held->tree = grammar::parse(std::move(text), dialect.lexical);
    held->typed = std::make_unique<ast::TypedFile>(ast::TypedFile::bind(held->tree, dialect));
    held->lines = std::make_unique<ast::LineIndex>(held->tree.text);
    text_ = held->tree.text;
    Piece piece;
    piece.end_block = static_cast<std::uint32_t>(held->tree.block_count());
    piece.text_end = text_.size();
    pieces_.push_back(piece);
    programs_ = held->typed->programs();
    held_.push_back(std::move(held));
    complete_ = true;
}

LoadedFile::LoadedFile(std::string name, std::string_view text, const dialects::Dialect& dialect,
                       StreamOptions options)
    : name_(std::move(name)), text_(text), dialect_(dialect), options_(std::move(options)) {
    options_.piece_bytes = std::max<std::size_t>(options_.piece_bytes, 1);
}

LoadedFile::~LoadedFile() = default;

const ast::SyntaxTree* LoadedFile::whole_tree() const {
    return pieces_.size() == 1 && complete_ && !held_.empty() ? &held_.front()->tree : nullptr;
}

// The next piece ends at the last line end within `piece_bytes`, or at the first line end after
// it when a single line is longer: blocks never span lines (grammar/parse.cpp).
bool LoadedFile::read_next_piece() const {
    if (complete_) return false;
    Piece piece;
    piece.text_begin = pieces_.empty() ? 0 : pieces_.back().text_end;
    piece.first_block = total_blocks();
    piece.first_line = next_line_;
    piece.parse_start = next_state_;
    piece.linear_at_start = next_linear_;
    const std::size_t size = text_.size();
    std::size_t end = size;
    if (size - piece.text_begin > options_.piece_bytes) {
        const std::string_view window = text_.substr(piece.text_begin, options_.piece_bytes);
        const std::size_t last_nl = window.rfind('\n');
        if (last_nl != std::string_view::npos) {
            end = piece.text_begin + last_nl + 1;
        } else {
            const std::size_t next_nl = text_.find('\n', piece.text_begin + options_.piece_bytes);
            end = next_nl == std::string_view::npos ? size : next_nl + 1;
        }
    }
    piece.text_end = end;
    pieces_.push_back(piece);
    const std::size_t index = pieces_.size() - 1;

    const Held& held = hold(index);
    Piece& read = pieces_[index];
    read.end_block = read.first_block + static_cast<std::uint32_t>(held.tree.block_count());
    const std::string_view piece_text = text_.substr(read.text_begin, read.text_end - read.text_begin);
    next_line_ += static_cast<std::uint32_t>(std::count(piece_text.begin(), piece_text.end(), '\n'));
    next_linear_ = held.typed->linear_at_end();
    for (std::uint32_t b = 0; b < held.tree.block_count(); ++b) splitter_.feed(held.tree, b, read.first_block + b);
    if (next_state_.ended || read.text_end >= size) {
        complete_ = true;
        splitter_.finish(read.end_block);
    }
    publish_programs();
    if (options_.release) options_.release(read.text_begin, read.text_end);
    return true;
}

void LoadedFile::publish_programs() const {
    programs_ = splitter_.programs();
    if (const auto open = splitter_.open_program()) {
        programs_.push_back(*open);
        programs_.back().end_block = kOpenEnd;
    }
}

// Parses piece `index` into a held slot (the least recently used one that is not pinned, once
// `pieces_held` + 1 are held). A piece read for the first time also sets `next_state_`.
const LoadedFile::Held& LoadedFile::hold(std::size_t index) const {
    ++clock_;
    for (const auto& h : held_) {
        if (h->piece == index) {
            h->last_use = clock_;
            return *h;
        }
    }
    Held* slot = nullptr;
    if (held_.size() > options_.pieces_held) {
        for (const auto& h : held_)
            if (h->piece != pinned_piece_ && (!slot || h->last_use < slot->last_use)) slot = h.get();
    }
    if (!slot) {
        held_.push_back(std::make_unique<Held>());
        slot = held_.back().get();
    }
    const Piece& piece = pieces_[index];
    const std::string_view text = text_.substr(piece.text_begin, piece.text_end - piece.text_begin);
    slot->piece = index;
    slot->last_use = clock_;
    slot->typed.reset();
    const grammar::ParseState end = grammar::parse_into(slot->tree, text, dialect_.lexical, piece.parse_start);
    if (index + 1 == pieces_.size()) next_state_ = end;
    slot->typed = std::make_unique<ast::TypedFile>(ast::TypedFile::bind(slot->tree, dialect_, piece.linear_at_start));
    slot->lines = std::make_unique<ast::LineIndex>(slot->tree.text);
    if (options_.release && index + 1 < pieces_.size()) options_.release(piece.text_begin, piece.text_end);
    return *slot;
}

std::size_t LoadedFile::piece_of(std::uint32_t block) const {
    const auto it = std::upper_bound(pieces_.begin(), pieces_.end(), block,
                                     [](std::uint32_t b, const Piece& p) { return b < p.first_block; });
    return static_cast<std::size_t>(it - pieces_.begin()) - 1;
}

const LoadedFile::Held& LoadedFile::held_for(std::uint32_t block) const {
    while (block >= total_blocks() && read_next_piece()) {
    }
    return hold(piece_of(block));
}

ast::BlockView LoadedFile::block(std::uint32_t index) const {
    const Held& held = held_for(index);
    return held.typed->block(index - pieces_[held.piece].first_block);
}

bool LoadedFile::has_block(std::uint32_t index) const {
    while (index >= total_blocks() && read_next_piece()) {
    }
    return index < total_blocks();
}

void LoadedFile::pin(std::uint32_t index) const {
    if (has_block(index)) pinned_piece_ = piece_of(index);
}

bool LoadedFile::in_program(std::uint32_t i, std::uint32_t block) const {
    if (block < programs_[i].first_block) return false;
    if (programs_[i].end_block == kOpenEnd && !has_block(block)) return false;
    // Reading ahead may have closed the program.
    return programs_[i].end_block == kOpenEnd || block < programs_[i].end_block;
}

std::optional<std::uint32_t> LoadedFile::find_program(std::int64_t number) const {
    do {
        for (std::uint32_t i = 0; i < programs_.size(); ++i)
            if (programs_[i].number == number) return i;
    } while (read_next_piece());
    return std::nullopt;
}

std::optional<std::uint32_t> LoadedFile::first_program() const {
    while (programs_.empty() && read_next_piece()) {
    }
    if (programs_.empty()) return std::nullopt;
    return 0;
}

const LoadedFile::Held* LoadedFile::owner(const ast::BlockView& view) const {
    for (const auto& h : held_)
        if (&h->tree == &view.tree()) return h.get();
    return nullptr;
}

ast::Range LoadedFile::file_range(const ast::BlockView& view) const {
    const ast::Range local = view.range();
    const auto* held = owner(view);
    const std::size_t base = held ? pieces_[held->piece].text_begin : 0;
    return {static_cast<std::uint32_t>(local.begin + base), static_cast<std::uint32_t>(local.end + base)};
}

std::uint32_t LoadedFile::line_of(const ast::BlockView& view, std::uint32_t hint) const {
    const auto* held = owner(view);
    if (!held) return 0;
    const std::uint32_t first_line = pieces_[held->piece].first_line;
    const std::uint32_t local_hint = hint >= first_line ? hint - first_line : 0;
    return first_line + held->lines->line_near(view.range().begin, local_hint);
}

}  // namespace kerf::interpreter
