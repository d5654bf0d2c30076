// What the executor reads of a block's tokens before it runs the block: its codes with their
// classes and parameter letters, whether it has statements, comma words or direct drawing, its N,
// where it is. Read the same way wherever a block comes from; a streamed file's pieces read it on
// the thread that parses them (interpreter/loaded_file.hpp), so the run's thread only copies it.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "ast/source.hpp"
#include "ast/typed.hpp"
#include "interpreter/events.hpp"

namespace kerf::interpreter {

// What a block's tokens say besides its codes and place: kept as it is for a block scanned ahead.
struct TokenFacts {
    std::uint32_t data_letters = 0;   // union of the codes' parameter letters
    bool statements = false;
    bool comma_words = false;
    bool direct_drawing = false;
    bool macro_call = false;          // G65/G66
    std::uint32_t classes = 0;        // the union of its codes' classes (Executor::kCycleCode ...)
    std::optional<double> sequence;   // N
};

// One block as scanned (executor.cpp scan_block).
struct BlockScan : TokenFacts {
    std::vector<ast::CodeRef> g;   // reused from block to block
    std::vector<ast::CodeRef> m;
    std::uint32_t block = 0;       // its index in the file
    SourceRef source;
};

// What a code of the dialect is, as bits (Executor::kCycleCode ...): its traits, computed once when
// the dialect is indexed (dialects/functions.hpp `traits`, each with a bit of its own).
inline std::uint32_t code_class_of(const dialects::CodeInfo& code) { return code.traits; }

// Fills everything of `scan` but `block` and `source` from the block's tokens.
void scan_tokens(const ast::BlockView& view, BlockScan& scan);

// The scans of the blocks of one piece of a file, without their vectors (the codes of all blocks
// in one array): a few dozen bytes a block, made where the piece is parsed.
class PieceScans {
public:
    // Scans every block of `typed`, a piece whose text starts at `text_begin` and on 0-based line
    // `first_line` of its file; `lines` is the piece's line index.
    void build(const ast::TypedFile& typed, const ast::LineIndex& lines, std::size_t text_begin, std::uint32_t first_line);
    void clear();
    bool empty() const { return blocks_.empty(); }
    // Fills everything of `scan` but `block` and `source.file` for block `index` of the piece, as
    // scan_tokens and the file's range and line of the block would.
    void fill(std::size_t index, BlockScan& scan) const;

private:
    struct Facts {
        TokenFacts tokens;
        std::uint32_t first_code = 0;   // into codes_: the G codes, then the M codes
        std::uint32_t g_codes = 0;
        std::uint32_t m_codes = 0;
        std::uint32_t line = 0;         // 0-based line of the file
        ast::Range range;               // in the file
    };
    std::vector<Facts> blocks_;
    std::vector<ast::CodeRef> codes_;
};

}  // namespace kerf::interpreter
