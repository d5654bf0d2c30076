// One file of a run, parsed and bound, whole or in pieces.
//
// A dry run of a 100 MB program must not hold a 400 MB tree (bench/RESULTS.md): a file given as a
// stream is read in pieces of whole lines (about `piece_bytes` each) as the run reaches them. Only
// a few pieces are held at a time; what the run needs again (a jump back, a label search, a call
// into a program seen earlier) is parsed again from the piece's start, whose parser and binder
// states were kept. Blocks keep their index in the whole file, so the executor, its frames and its
// events do not know whether a file is whole or in pieces. A file given as a string is one piece.
//
// Lifetime rule for BlockViews: a view stays valid while its piece is held. The piece of the
// pinned block (the block being executed) is always held; of the others, the last few used are.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ast/source.hpp"
#include "ast/typed.hpp"
#include "grammar/parse.hpp"
#include "interpreter/block_scan.hpp"

namespace kerf::interpreter {

struct StreamOptions {
    std::size_t piece_bytes = std::size_t{256} << 10;   // lines are not cut: a piece ends at a line end
    std::size_t pieces_held = 4;                      // besides the pinned one
    // Parse the pieces ahead of the run on a second thread (the run on one core, the grammar on
    // the other); the pieces and every event are the same either way.
    bool read_ahead = false;
    // Called with a byte range of the text once its piece is parsed and no longer held, so the
    // owner can drop the memory behind it (the CLI's file mapping); the range is read again if
    // the run comes back to it. May be empty; with read_ahead it is called from that thread too.
    std::function<void(std::size_t begin, std::size_t end)> release;
};

class LoadedFile {
public:
    // The whole text, parsed and bound at once.
    LoadedFile(std::string name, std::string text, const dialects::Dialect& dialect);
    // A file parsed and bound by its owner (the language server's open document), used in place:
    // `owner` keeps `typed`, its tree and `lines` alive as long as this object.
    LoadedFile(std::string name, std::shared_ptr<const void> owner, const ast::TypedFile& typed, const ast::LineIndex& lines);
    // A stream over `text`, which must outlive this object.
    LoadedFile(std::string name, std::string_view text, const dialects::Dialect& dialect, StreamOptions options);
    ~LoadedFile();
    LoadedFile(const LoadedFile&) = delete;
    LoadedFile& operator=(const LoadedFile&) = delete;

    const std::string& name() const { return name_; }
    std::size_t text_size() const { return text_.size(); }

    // The view of block `index` (of the whole file); parses ahead as needed. `index` must exist
    // (has_block).
    ast::BlockView block(std::uint32_t index) const;
    bool has_block(std::uint32_t index) const;
    // The scan of `view`'s block made when its piece was parsed (all of it but `block` and
    // `source.file`); false for a file parsed whole, whose blocks the executor scans itself.
    bool scanned(const ast::BlockView& view, BlockScan& scan) const;
    // Keeps the piece of `index` held until the next pin (the executor pins the running block).
    void pin(std::uint32_t index) const;

    // Programs found so far, in file order, with whole-file block indices. The last one may still
    // be open (end_block = kOpenEnd) while the file is read in pieces.
    static constexpr std::uint32_t kOpenEnd = 0xFFFFFFFFu;
    const ast::Program& program(std::uint32_t i) const { return programs_[i]; }
    std::size_t program_count() const { return programs_.size(); }
    // True when `block` belongs to program `i` (reads ahead to find where an open program ends).
    bool in_program(std::uint32_t i, std::uint32_t block) const;
    // The program with O number `number`, reading ahead through the whole file if needed.
    std::optional<std::uint32_t> find_program(std::int64_t number) const;
    // The first program of the file (the main program of `kerf run FILE`), reading ahead to it.
    std::optional<std::uint32_t> first_program() const;

    // Where a block is in the file: its byte range and 0-based line (`hint`: a line at or before it).
    ast::Range file_range(const ast::BlockView& view) const;
    std::uint32_t line_of(const ast::BlockView& view, std::uint32_t hint) const;

    // The whole file's tree, typed file and line index when it was given whole (the analyzer and
    // tests walk them); else null.
    const ast::SyntaxTree* whole_tree() const;
    const ast::TypedFile* whole_typed() const;
    const ast::LineIndex* whole_lines() const;

private:
    struct Cursor {           // where a piece starts: what the parse and bind of the piece before left
        std::size_t text_begin = 0;
        std::uint32_t first_block = 0;
        std::uint32_t first_line = 0;
        grammar::ParseState state;
        bool linear = false;
        bool done = false;    // no piece starts here: the file (or the tape) has ended
    };
    struct Piece {            // what is kept of every piece read: a few dozen bytes per piece
        Cursor start;         // re-reading the piece starts from here
        std::uint32_t end_block = 0;
        std::size_t text_end = 0;
        bool last = false;    // the end of the file, or of the tape (the closing '%')
        std::uint32_t first_block() const { return start.first_block; }
        std::size_t text_begin() const { return start.text_begin; }
    };
    struct Held;              // a parsed piece: tree, typed file, line index
    class ReadAhead;          // the second thread (loaded_file.cpp)
    // What a piece read in file order adds to the programs: those it closed, and the one still
    // open after it. Split by the thread that reads the pieces in order (the read-ahead thread
    // when there is one).
    struct ProgramsAfter {
        std::vector<ast::Program> closed;
        std::optional<ast::Program> open;
    };
    static ProgramsAfter split_programs(ast::ProgramSplitter& splitter, const ast::SyntaxTree& tree, const Piece& piece);

    // Parses the piece at `cursor` into `held` and moves the cursor past it. Touches only the
    // immutable text, dialect and options: safe on the read-ahead thread.
    Piece parse_piece(Cursor& cursor, Held& held) const;
    void parse_again(const Piece& piece, Held& held) const;
    std::size_t slot_index() const;

    const Held& hold(std::size_t piece) const;
    const Held& held_for(std::uint32_t block) const;
    std::size_t piece_of(std::uint32_t block) const;
    const Held* owner(const ast::BlockView& view) const;   // the held piece a view belongs to
    bool read_next_piece() const;   // false at the end of the file
    void publish_programs(ProgramsAfter after) const;

    std::string name_;
    bool owned_whole_ = false;      // given as a string: one piece, always held
    std::string_view text_;
    const dialects::Dialect& dialect_;
    StreamOptions options_;
    // Lazily read: logically const (the same blocks whenever they are read).
    mutable std::vector<Piece> pieces_;
    mutable std::vector<std::unique_ptr<Held>> held_;
    mutable std::size_t pinned_piece_ = 0;
    // The last piece a block was found in (the run reads blocks in order: nearly always a hit).
    mutable const Held* last_held_ = nullptr;
    mutable std::uint32_t last_first_ = 0, last_end_ = 0;
    mutable std::uint64_t clock_ = 0;
    mutable Cursor cursor_;          // the next piece, when read on this thread
    mutable std::unique_ptr<ReadAhead> read_ahead_;
    mutable bool complete_ = false;
    mutable ast::ProgramSplitter splitter_;   // when the pieces are read on this thread
    mutable std::vector<ast::Program> closed_programs_;
    mutable std::vector<ast::Program> programs_;   // closed_programs_ and the open one (end kOpenEnd)
    std::uint32_t total_blocks() const { return pieces_.empty() ? 0 : pieces_.back().end_block; }
};

}  // namespace kerf::interpreter
