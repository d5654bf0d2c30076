#include "interpreter/loaded_file.hpp"

#include <algorithm>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <mutex>
#include <thread>
#include <utility>

namespace kerf::interpreter {

struct LoadedFile::Held {
    std::size_t piece = 0;
    ast::SyntaxTree tree;
    std::unique_ptr<ast::TypedFile> typed;
    std::unique_ptr<ast::LineIndex> lines;
    PieceScans scans;   // of a streamed piece: its blocks scanned where it was parsed (empty for a whole file)
    std::uint64_t last_use = 0;
    // A file parsed by its owner (the language server's document): read there, not copied.
    std::shared_ptr<const void> owner;
    const ast::SyntaxTree* shared_tree = nullptr;
    const ast::TypedFile* shared_typed = nullptr;
    const ast::LineIndex* shared_lines = nullptr;
    const ast::SyntaxTree& the_tree() const { return shared_tree ? *shared_tree : tree; }
    const ast::TypedFile& the_typed() const { return shared_typed ? *shared_typed : *typed; }
    const ast::LineIndex& the_lines() const { return shared_lines ? *shared_lines : *lines; }
};

LoadedFile::LoadedFile(std::string name, std::string text, const dialects::Dialect& dialect)
    : name_(std::move(name)), dialect_(dialect) {
    auto held = std::make_unique<Held>();
    held->tree = grammar::parse(std::move(text), dialect.lexical, grammar::parse_threads());
    // The line index reads only the text: for a long file it is built on a second core while the
    // tree is bound (kerf check of 100 MB: both about 0.1 s, bench/RESULTS.md).
    constexpr std::size_t kLinesBesideBindMin = std::size_t{4} << 20;
    if (held->tree.text.size() >= kLinesBesideBindMin) {
        std::thread lines([&held] { held->lines = std::make_unique<ast::LineIndex>(held->tree.text); });
        held->typed = std::make_unique<ast::TypedFile>(ast::TypedFile::bind(held->tree, dialect));
        lines.join();
    } else {
        held->typed = std::make_unique<ast::TypedFile>(ast::TypedFile::bind(held->tree, dialect));
        held->lines = std::make_unique<ast::LineIndex>(held->tree.text);
    }
    text_ = held->tree.text;
    Piece piece;
    piece.end_block = static_cast<std::uint32_t>(held->tree.block_count());
    piece.text_end = text_.size();
    piece.last = true;
    pieces_.push_back(piece);
    programs_ = held->typed->programs();
    held_.push_back(std::move(held));
    complete_ = true;
    owned_whole_ = true;
}

LoadedFile::LoadedFile(std::string name, std::shared_ptr<const void> owner, const ast::TypedFile& typed,
                       const ast::LineIndex& lines)
    : name_(std::move(name)), dialect_(typed.dialect()) {
    auto held = std::make_unique<Held>();
    held->owner = std::move(owner);
    held->shared_tree = &typed.tree();
    held->shared_typed = &typed;
    held->shared_lines = &lines;
    text_ = typed.tree().text;
    Piece piece;
    piece.end_block = static_cast<std::uint32_t>(typed.block_count());
    piece.text_end = text_.size();
    piece.last = true;
    pieces_.push_back(piece);
    programs_ = typed.programs();
    held_.push_back(std::move(held));
    complete_ = true;
    owned_whole_ = true;
}

LoadedFile::LoadedFile(std::string name, std::string_view text, const dialects::Dialect& dialect,
                       StreamOptions options)
    : name_(std::move(name)), text_(text), dialect_(dialect), options_(std::move(options)) {
    options_.piece_bytes = std::max<std::size_t>(options_.piece_bytes, 1);
}

LoadedFile::~LoadedFile() { read_ahead_.reset(); }   // the thread stops before the slots go

const ast::SyntaxTree* LoadedFile::whole_tree() const {
    return owned_whole_ ? &held_.front()->the_tree() : nullptr;
}
const ast::TypedFile* LoadedFile::whole_typed() const { return owned_whole_ ? &held_.front()->the_typed() : nullptr; }
const ast::LineIndex* LoadedFile::whole_lines() const { return owned_whole_ ? &held_.front()->the_lines() : nullptr; }

// The next piece ends at the last line end within `piece_bytes`, or at the first line end after
// it when a single line is longer: blocks never span lines (grammar/parse.cpp).
LoadedFile::Piece LoadedFile::parse_piece(Cursor& cursor, Held& held) const {
    Piece piece;
    piece.start = cursor;
    const std::size_t size = text_.size();
    std::size_t end = size;
    if (size - piece.text_begin() > options_.piece_bytes) {
        // Line breaks as the grammar reads them ("\n", "\r\n", a lone "\r": ast/source.hpp).
        const std::string_view rest = text_.substr(piece.text_begin());
        const std::size_t last = ast::last_line_end_before(rest, options_.piece_bytes);
        if (last != std::string_view::npos) {
            end = piece.text_begin() + last;
        } else {
            ast::LineBreaks breaks(rest);
            end = piece.text_begin() + breaks.line_from(0).next;
        }
    }
    piece.text_end = end;
    const std::string_view text = text_.substr(piece.text_begin(), end - piece.text_begin());
    held.typed.reset();
    cursor.state = grammar::parse_into(held.tree, text, dialect_.lexical, piece.start.state);
    held.typed = std::make_unique<ast::TypedFile>(ast::TypedFile::bind(held.tree, dialect_, piece.start.linear));
    held.lines = std::make_unique<ast::LineIndex>(held.tree.text);
    // Scanned here, on the read-ahead thread when there is one: the run's thread only copies.
    held.scans.build(*held.typed, *held.lines, piece.text_begin(), piece.start.first_line);
    piece.end_block = piece.first_block() + static_cast<std::uint32_t>(held.tree.block_count());
    cursor.text_begin = end;
    cursor.first_block = piece.end_block;
    cursor.first_line += static_cast<std::uint32_t>(ast::count_line_breaks(text));
    cursor.linear = held.typed->linear_at_end();
    cursor.done = cursor.state.ended || end >= size;
    piece.last = cursor.done;
    if (options_.release) options_.release(piece.text_begin(), piece.text_end);
    return piece;
}

void LoadedFile::parse_again(const Piece& piece, Held& held) const {
    Cursor cursor = piece.start;
    parse_piece(cursor, held);
}

// The read-ahead thread parses the pieces in order, at most two ahead of the run, into slots the
// run hands back when it drops a piece.
class LoadedFile::ReadAhead {
public:
    explicit ReadAhead(const LoadedFile& file) : file_(file), thread_([this] { work(); }) {}
    ~ReadAhead() {
        {
            std::lock_guard lock(mutex_);
            stop_ = true;
        }
        changed_.notify_all();
        thread_.join();
    }
    struct Ready {
        Piece piece;
        std::unique_ptr<Held> held;
        ProgramsAfter programs;
    };
    // The next piece in file order, waiting for it; nullopt after the last.
    std::optional<Ready> take() {
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return !ready_.empty() || finished_; });
        if (ready_.empty()) return std::nullopt;
        auto next = std::move(ready_.front());
        ready_.pop_front();
        changed_.notify_all();
        return next;
    }
    void give_back(std::unique_ptr<Held> slot) {
        std::lock_guard lock(mutex_);
        spare_.push_back(std::move(slot));
    }

private:
    static constexpr std::size_t kAhead = 2;
    void work() {
        Cursor cursor;
        while (!cursor.done) {
            std::unique_ptr<Held> slot;
            {
                std::unique_lock lock(mutex_);
                changed_.wait(lock, [&] { return stop_ || ready_.size() < kAhead; });
                if (stop_) return;
                if (!spare_.empty()) {
                    slot = std::move(spare_.back());
                    spare_.pop_back();
                }
            }
            if (!slot) slot = std::make_unique<Held>();
            Piece piece = file_.parse_piece(cursor, *slot);
            ProgramsAfter programs = split_programs(splitter_, slot->tree, piece);
            {
                std::lock_guard lock(mutex_);
                ready_.push_back({piece, std::move(slot), std::move(programs)});
            }
            changed_.notify_all();
        }
        std::lock_guard lock(mutex_);
        finished_ = true;
        changed_.notify_all();
    }

    const LoadedFile& file_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<Ready> ready_;
    ast::ProgramSplitter splitter_;   // this thread reads the pieces in order
    std::vector<std::unique_ptr<Held>> spare_;
    bool stop_ = false;
    bool finished_ = false;
    std::thread thread_;   // last: starts once the rest is built
};

bool LoadedFile::read_next_piece() const {
    if (complete_) return false;
    last_held_ = nullptr;   // a held slot may be replaced below
    if (options_.read_ahead && !read_ahead_ && text_.size() > options_.piece_bytes)
        read_ahead_ = std::make_unique<ReadAhead>(*this);
    const std::size_t slot = slot_index();
    if (slot == held_.size()) held_.emplace_back();
    Piece piece;
    ProgramsAfter programs;
    if (read_ahead_) {
        auto next = read_ahead_->take();
        if (!next) {   // the last piece sets `complete_`: not reached
            complete_ = true;
            return false;
        }
        piece = next->piece;
        if (held_[slot]) read_ahead_->give_back(std::move(held_[slot]));
        held_[slot] = std::move(next->held);
        programs = std::move(next->programs);
    } else {
        if (!held_[slot]) held_[slot] = std::make_unique<Held>();
        piece = parse_piece(cursor_, *held_[slot]);
        programs = split_programs(splitter_, held_[slot]->tree, piece);
    }
    Held& held = *held_[slot];
    pieces_.push_back(piece);
    held.piece = pieces_.size() - 1;
    held.last_use = ++clock_;
    if (piece.last) complete_ = true;
    publish_programs(std::move(programs));
    return true;
}

LoadedFile::ProgramsAfter LoadedFile::split_programs(ast::ProgramSplitter& splitter, const ast::SyntaxTree& tree,
                                                     const Piece& piece) {
    const std::size_t closed_before = splitter.programs().size();
    for (std::uint32_t b = 0; b < tree.block_count(); ++b) splitter.feed(tree, b, piece.first_block() + b);
    if (piece.last) splitter.finish(piece.end_block);
    ProgramsAfter after;
    after.closed.assign(splitter.programs().begin() + static_cast<std::ptrdiff_t>(closed_before), splitter.programs().end());
    after.open = splitter.open_program();
    return after;
}

void LoadedFile::publish_programs(ProgramsAfter after) const {
    closed_programs_.insert(closed_programs_.end(), after.closed.begin(), after.closed.end());
    programs_ = closed_programs_;
    if (after.open) {
        programs_.push_back(*after.open);
        programs_.back().end_block = kOpenEnd;
    }
}

// The slot for another piece: a new one while fewer than `pieces_held` + 1 are held, else the
// least recently used one that is not pinned (held_.size() means "append one").
std::size_t LoadedFile::slot_index() const {
    std::size_t slot = held_.size();
    if (held_.size() <= options_.pieces_held) return slot;
    for (std::size_t i = 0; i < held_.size(); ++i) {
        if (held_[i]->piece == pinned_piece_) continue;
        if (slot == held_.size() || held_[i]->last_use < held_[slot]->last_use) slot = i;
    }
    return slot;
}

// Piece `index`, parsed again if it is not held.
const LoadedFile::Held& LoadedFile::hold(std::size_t index) const {
    ++clock_;
    for (const auto& h : held_) {
        if (h->piece == index) {
            h->last_use = clock_;
            return *h;
        }
    }
    const std::size_t slot = slot_index();
    if (slot == held_.size()) held_.push_back(std::make_unique<Held>());
    Held& held = *held_[slot];
    last_held_ = nullptr;   // the slot may be the one block() remembered
    parse_again(pieces_[index], held);
    held.piece = index;
    held.last_use = clock_;
    return held;
}

std::size_t LoadedFile::piece_of(std::uint32_t block) const {
    const auto it = std::upper_bound(pieces_.begin(), pieces_.end(), block,
                                     [](std::uint32_t b, const Piece& p) { return b < p.first_block(); });
    return static_cast<std::size_t>(it - pieces_.begin()) - 1;
}

const LoadedFile::Held& LoadedFile::held_for(std::uint32_t block) const {
    while (block >= total_blocks() && read_next_piece()) {
    }
    return hold(piece_of(block));
}

ast::BlockView LoadedFile::block(std::uint32_t index) const {
    if (last_held_ && index >= last_first_ && index < last_end_) return last_held_->the_typed().block(index - last_first_);
    const Held& held = held_for(index);
    const Piece& piece = pieces_[held.piece];
    last_held_ = &held;
    last_first_ = piece.first_block();
    last_end_ = piece.end_block;
    return held.the_typed().block(index - piece.first_block());
}

bool LoadedFile::has_block(std::uint32_t index) const {
    while (index >= total_blocks() && read_next_piece()) {
    }
    return index < total_blocks();
}

void LoadedFile::pin(std::uint32_t index) const {
    if (last_held_ && index >= last_first_ && index < last_end_) {
        pinned_piece_ = last_held_->piece;
        return;
    }
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
    if (last_held_ && &last_held_->the_tree() == &view.tree()) return last_held_;
    for (const auto& h : held_)
        if (&h->the_tree() == &view.tree()) return h.get();
    return nullptr;
}

bool LoadedFile::scanned(const ast::BlockView& view, BlockScan& scan) const {
    const Held* held = owner(view);
    if (!held || held->scans.empty()) return false;
    held->scans.fill(view.index(), scan);
    return true;
}

ast::Range LoadedFile::file_range(const ast::BlockView& view) const {
    const ast::Range local = view.range();
    const auto* held = owner(view);
    const std::size_t base = held ? pieces_[held->piece].text_begin() : 0;
    return {static_cast<std::uint32_t>(local.begin + base), static_cast<std::uint32_t>(local.end + base)};
}

std::uint32_t LoadedFile::line_of(const ast::BlockView& view, std::uint32_t hint) const {
    const auto* held = owner(view);
    if (!held) return 0;
    const std::uint32_t first_line = pieces_[held->piece].start.first_line;
    const std::uint32_t local_hint = hint >= first_line ? hint - first_line : 0;
    return first_line + held->the_lines().line_near(view.range().begin, local_hint);
}

}  // namespace kerf::interpreter
