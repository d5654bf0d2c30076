// The typed AST: the syntax tree bound against a dialect table. bind() gives every word its role
// (G code, M code, absolute or incremental axis, parameter, direct-drawing word), splits the file
// into programs, and offers typed views of each block. Views are cheap and computed on demand, so
// re-binding one edited block costs one block (the language server relies on this).
#pragma once

#include <optional>
#include <vector>

#include "ast/syntax.hpp"
#include "dialects/dialect.hpp"

namespace kerf::ast {

struct Program {
    std::optional<std::int64_t> number;   // O number; nullopt for code before the first O line
    std::uint32_t first_block = 0;
    std::uint32_t end_block = 0;          // one past the last block
    std::int32_t o_token = -1;            // index of the O word
};

struct CodeRef {
    std::uint32_t token = 0;                       // index into tree.tokens
    const dialects::CodeInfo* info = nullptr;      // nullptr: not in the dialect (alarm 010)
    std::optional<dialects::CodeKey> key;          // nullopt: computed (G#1) or not a code number
};

struct AxisWord {
    std::uint32_t token = 0;
    char axis = 0;            // the axis moved: X for both X and U
    bool incremental = false; // U/W/H in system A
};

struct SubprogramCall {
    std::int64_t program = 0;
    std::int64_t repeats = 1;
    bool packed = false;       // M98 P41001 form
    std::uint32_t p_token = 0;
};

struct MacroCall {               // G65 / G66 P_ L_ arguments
    std::optional<std::int64_t> program;
    std::int64_t repeats = 1;
    bool modal = false;
    std::vector<std::uint32_t> arguments;   // argument words (A B C I J K ... not P, L)
};

class TypedFile;

// What an edit did to a tree's blocks (the language server's incremental re-parse): the old blocks
// [first, first + removed) became the new blocks [first, first + added); the bytes from old_end on
// moved by `shift`.
struct BlockSplice {
    std::uint32_t first = 0;
    std::uint32_t removed = 0;
    std::uint32_t added = 0;
    std::uint32_t old_begin = 0;   // the old blocks' bytes [old_begin, old_end)
    std::uint32_t old_end = 0;
    std::int64_t shift = 0;
};

class BlockView {
public:
    BlockView(const TypedFile& file, std::size_t index) : file_(&file), index_(index) {}
    std::size_t index() const { return index_; }   // in its TypedFile (a piece of a long file: see interpreter/loaded_file.hpp)
    const SyntaxTree& tree() const;
    const Block& block() const;
    Range range() const;
    std::span<const Token> tokens() const;
    std::uint32_t first_token() const;

    std::optional<double> sequence_number() const;   // N value (nullopt also for a bare N)
    // The N value as an integer label (truncated: N10.5 is a block of label 10), nullopt when there
    // is none or it is too large for one (N12345678901234567890).
    std::optional<std::int64_t> sequence_label() const;
    bool has_sequence_word() const;
    int block_delete_level() const;                  // 0 none, 1 for '/', n for '/n'
    std::vector<CodeRef> g_codes() const;
    std::vector<CodeRef> m_codes() const;
    std::vector<AxisWord> axis_words() const;
    std::vector<std::uint32_t> words_with_role(Role role) const;
    std::vector<std::uint32_t> parameters() const { return words_with_role(Role::parameter); }
    std::vector<std::uint32_t> comma_words() const;
    std::vector<std::uint32_t> comments() const;
    // g_codes() and m_codes() in one pass into vectors the caller reuses (cleared first): no
    // allocation once they have grown, for the interpreter's per-block loop.
    void collect_codes(std::vector<CodeRef>& g, std::vector<CodeRef>& m) const;
    std::vector<std::uint32_t> statements() const;   // statement tokens
    std::optional<std::uint32_t> word(char letter) const;   // first word with this letter
    bool has_code(char letter, dialects::FunctionId function) const;
    std::optional<SubprogramCall> subprogram_call() const;
    std::optional<MacroCall> macro_call() const;

private:
    const TypedFile* file_;
    std::size_t index_;
};

// Splits blocks into programs (an O line starts one, '%' and the tail end one, code before the
// first O line is a program without number), fed block by block so that a file read in pieces
// splits exactly as the whole file. Block indices are the caller's (global in a long file).
class ProgramSplitter {
public:
    void feed(const SyntaxTree& tree, std::uint32_t local_block, std::uint32_t block);
    void finish(std::uint32_t end_block);   // closes the open program at the end of the file
    std::vector<Program>& programs() { return programs_; }
    // The program still open at the last block fed, if it already counts as one (a number or code).
    std::optional<Program> open_program() const;

private:
    void close(std::uint32_t end_block);
    std::vector<Program> programs_;
    Program current_;
    bool open_ = false;
    bool has_code_ = false;
};

class TypedFile {
public:
    // Binds `tree` (sets token roles in place) against `dialect`. Both must outlive the result.
    // `linear_at_start`: the static G01 reading the previous piece of a long file ended with.
    static TypedFile bind(SyntaxTree& tree, const dialects::Dialect& dialect, bool linear_at_start = false);
    // The same on `threads` cores (at most 2): a long tree is bound in two halves at once. A
    // dialect where plain A/R read as direct drawing after G01 (the one role that depends on the
    // blocks before) and a short tree are bound on one. The result is the one-core result.
    static TypedFile bind(SyntaxTree& tree, const dialects::Dialect& dialect, bool linear_at_start, unsigned threads);
    bool linear_at_end() const { return linear_at_end_; }

    const SyntaxTree& tree() const { return *tree_; }
    const dialects::Dialect& dialect() const { return *dialect_; }
    const std::vector<Program>& programs() const { return programs_; }
    const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }
    std::size_t block_count() const { return tree_->block_count(); }
    BlockView block(std::size_t i) const { return BlockView(*this, i); }

    // Binds `tree`, a copy of `before`'s tree edited as `splice` says, binding only the new blocks:
    // the copied tokens kept their roles. A dialect where plain A/R read as direct drawing after
    // G01 (the only role that depends on the blocks before) is bound whole.
    static TypedFile bind_edited(SyntaxTree& tree, const TypedFile& before, const BlockSplice& splice);

    // Re-binds one block after an edit that kept its token range (LSP); modal context is taken from
    // the blocks before it.
    void rebind_block(SyntaxTree& tree, std::size_t index);

private:
    TypedFile(const SyntaxTree& tree, const dialects::Dialect& dialect) : tree_(&tree), dialect_(&dialect) {}
    void split_programs();
    void check_call_forms(const std::vector<std::size_t>& call_blocks);
    const SyntaxTree* tree_;
    const dialects::Dialect* dialect_;
    std::vector<Program> programs_;
    std::vector<Diagnostic> diagnostics_;
    bool linear_at_end_ = false;
};

// Integer value of a numeric word (P41001, T0101), if it is an integer.
std::optional<std::int64_t> integer_value(const SyntaxTree& tree, const Token& t);
// `value` truncated to an integer (N10.5 is a block of label 10), nullopt when it is not finite or
// too large for one (a cast would be undefined: N12345678901234567890, P1e19).
std::optional<std::int64_t> truncated_integer(double value);

}  // namespace kerf::ast
