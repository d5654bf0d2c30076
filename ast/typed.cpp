#include "ast/typed.hpp"

#include <fmt/format.h>

#include <cmath>
#include <thread>

#include "ast/diagnostic_ids.hpp"
#include "dialects/functions.hpp"

namespace kerf::ast {

namespace fn = dialects::functions;

std::optional<std::int64_t> integer_value(const SyntaxTree& tree, const Token& t) {
    if (!t.is_number()) return std::nullopt;
    const double v = tree.number_value(t);
    if (!std::isfinite(v) || std::fabs(v) > 9.0e15 || v != std::floor(v)) return std::nullopt;
    return static_cast<std::int64_t>(v);
}

namespace {

std::optional<dialects::CodeKey> code_key_of(const SyntaxTree& tree, const Token& t) {
    if (!t.is_number() || t.has(token_flags::negative)) return std::nullopt;
    // Exact decimal: G01 is 1/10^0, G12.1 is 121/10^1, G01.0 is 10/10^1.
    const std::int32_t mantissa = t.mantissa();
    if (!t.has(token_flags::value_big) && mantissa >= 0 && mantissa < 100000) {
        const int scale = t.scale();
        if (scale == 0) return mantissa * 10;
        if (scale == 1) return mantissa;
        static constexpr int kPow10[] = {1, 10, 100, 1000, 10000, 100000, 1000000, 10000000, 100000000, 1000000000};
        if (scale < 10 && mantissa % kPow10[scale - 1] == 0) return mantissa / kPow10[scale - 1];
        return std::nullopt;
    }
    return dialects::code_key(tree.number_value(t));
}

const dialects::CodeInfo* code_info(const SyntaxTree& tree, const dialects::Dialect& d, const Token& t) {
    const auto key = code_key_of(tree, t);
    return key ? d.fast_code(t.letter, *key) : nullptr;
}

// What the binder carries from block to block: the letter table of the dialect, and the static
// reading of the motion group, used only to recognise plain A/R direct-drawing words
// (dialects.md §11.4). The interpreter keeps the real state.
struct BindContext {
    explicit BindContext(const dialects::LexicalRules& rules) {
        for (char L = 'A'; L <= 'Z'; ++L) {
            Role r = Role::parameter;
            if (rules.incremental_axis_of(L)) r = Role::axis_incremental;
            else if (rules.is_axis(L)) r = Role::axis_absolute;
            letter_role[static_cast<std::size_t>(L - 'A')] = r;
        }
        letter_role['N' - 'A'] = Role::sequence;
        letter_role['O' - 'A'] = Role::program;
        letter_role['M' - 'A'] = Role::m_code;
        letter_role['G' - 'A'] = Role::g_code;
    }
    Role letter_role[26];
    bool linear = false;   // the motion group's code is G01
};

struct BlockFacts {
    bool calls = false;            // an M code that calls a subprogram (checked further in bind())
    std::uint32_t second_n = 0;    // token index of a second N word, 0 if none
    bool motion = false;           // a motion-group code (it set BindContext::linear)
};

std::uint32_t letter_bit(char L) { return std::uint32_t{1} << (L - 'A'); }

BlockFacts bind_block(SyntaxTree& tree, const dialects::Dialect& d, std::size_t index, BindContext& context) {
    using Info = dialects::CodeInfo;
    const std::uint32_t first = tree.blocks[index].first_token;
    const std::uint32_t end = tree.block_token_end(index);
    BlockFacts facts;
    // First the block's codes: they decide what the other letters mean.
    std::uint32_t traits = 0;        // union of the codes' traits
    std::uint32_t data_letters = 0;  // letters that are data in this block (G04 X, G71 U), one bit each
    for (std::uint32_t i = first; i < end; ++i) {
        Token& t = tree.tokens[i];
        if (t.kind != TokenKind::word || (t.letter != 'G' && t.letter != 'M')) continue;
        t.set_role(t.letter == 'G' ? Role::g_code : Role::m_code);
        const Info* info = code_info(tree, d, t);
        if (!info) continue;
        traits |= info->traits;
        data_letters |= info->parameter_mask;
        facts.calls |= info->has(dialects::traits::calls_subprogram);
        if (info->has(dialects::traits::motion_group)) {
            context.linear = info->has(dialects::traits::linear);
            facts.motion = true;
        }
    }
    if (traits & dialects::traits::takes_arguments) {
        // G65/G66: every other word is an argument, M too (`M13` → #13, dialects.md §3.7).
        data_letters = ~std::uint32_t{0};
        facts.calls = false;
        for (std::uint32_t i = first; i < end; ++i)
            if (Token& t = tree.tokens[i]; t.kind == TokenKind::word && t.letter == 'M') t.set_role(Role::parameter);
    }
    const bool direct_drawing = d.lexical.plain_direct_drawing && context.linear && !(traits & dialects::traits::one_shot);
    bool seen_n = false;
    for (std::uint32_t i = first; i < end; ++i) {
        Token& t = tree.tokens[i];
        const char L = t.letter;
        if (t.kind != TokenKind::word || L == 'G' || L == 'M' || L < 'A' || L > 'Z') continue;
        Role role = context.letter_role[L - 'A'];
        if (role == Role::sequence) {
            if (seen_n && !facts.second_n) facts.second_n = i;
            seen_n = true;
        } else if (role != Role::program) {
            if (data_letters & letter_bit(L)) role = Role::parameter;
            else if (direct_drawing && (L == 'A' || L == 'R')) role = Role::direct_drawing;
        }
        t.set_role(role);
    }
    return facts;
}

}  // namespace

void ProgramSplitter::close(std::uint32_t end_block) {
    if (open_ && (has_code_ || current_.number)) {
        current_.end_block = end_block;
        programs_.push_back(current_);
    }
    open_ = false;
    has_code_ = false;
}

void ProgramSplitter::finish(std::uint32_t end_block) { close(end_block); }

std::optional<Program> ProgramSplitter::open_program() const {
    if (!open_ || !(has_code_ || current_.number)) return std::nullopt;
    return current_;
}

void ProgramSplitter::feed(const SyntaxTree& tree, std::uint32_t local, std::uint32_t block) {
    const Block& b = tree.blocks[local];
    auto open_here = [&] {
        if (open_) return;
        current_ = Program{};
        current_.first_block = block;
        open_ = true;
    };
    // The O word that starts a program: the first word of a program_start block, or the word right
    // after the '%' of a percent block (`%O0003(...)`: the tape's leader and the program number on
    // one line start program O0003 as on the control).
    auto o_word = [&]() -> std::int32_t {
        for (std::uint32_t t = b.first_token; t < tree.block_token_end(local); ++t) {
            const Token& token = tree.tokens[t];
            if (token.kind == TokenKind::word && token.letter == 'O') return static_cast<std::int32_t>(t);
            if (b.kind == BlockKind::percent && token.kind != TokenKind::percent && token.kind != TokenKind::comment &&
                token.kind != TokenKind::bom)
                return -1;
        }
        return -1;
    };
    auto start = [&](std::int32_t o) {
        close(block);
        current_ = Program{};
        current_.first_block = block;
        current_.o_token = o;
        if (o >= 0) current_.number = integer_value(tree, tree.tokens[static_cast<std::size_t>(o)]);
        open_ = true;
        has_code_ = true;
    };
    switch (b.kind) {
        case BlockKind::program_start:
            start(o_word());
            break;
        case BlockKind::percent:
            close(block);
            if (const std::int32_t o = o_word(); o >= 0) start(o);
            break;
        case BlockKind::tail:
            close(block);
            break;
        case BlockKind::code:
            open_here();
            has_code_ = true;
            break;
        case BlockKind::blank:
        case BlockKind::comment_only:
            open_here();
            break;
    }
}

namespace {
Diagnostic second_n_diagnostic(const SyntaxTree& tree, std::uint32_t token) {
    const Token& n = tree.tokens[token];
    return {tree.range(n), Severity::error, ast::diagnostic_id::second_sequence_number, fmt::format("second sequence number '{}' in one block", tree.spelling(n)),
            "a block has one N word, at its start; remove this one or split the block"};
}
}  // namespace

void TypedFile::split_programs() {
    ProgramSplitter splitter;
    for (std::uint32_t i = 0; i < tree_->block_count(); ++i) splitter.feed(*tree_, i, i);
    splitter.finish(static_cast<std::uint32_t>(tree_->block_count()));
    programs_ = std::move(splitter.programs());
}

// Call forms that contradict each other (dialects.md §3.6).
void TypedFile::check_call_forms(const std::vector<std::size_t>& call_blocks) {
    for (const std::size_t i : call_blocks) {
        const BlockView view = block(i);
        const auto call = view.subprogram_call();
        const auto l = view.word('L');
        if (call && call->packed && l) {
            const Token& p = tree_->tokens[call->p_token];
            diagnostics_.push_back(
                {tree_->range(p), Severity::error, ast::diagnostic_id::packed_p_with_l,
                 fmt::format("M98 '{}' packs the repeat count into P and also has L", tree_->spelling(p)),
                 "use one form: M98 P<repeats><4-digit program> or M98 P<program> L<repeats>"});
        }
    }
}

namespace {

// What binding a range of blocks found besides the roles it set: the blocks with a subprogram call
// (checked further by check_call_forms), the second N words, the G01 reading at its end.
struct BoundRange {
    std::vector<std::size_t> call_blocks;
    std::vector<std::uint32_t> second_n;   // token indices
    bool linear = false;
    bool motion_seen = false;              // a motion-group code was in the range
};

BoundRange bind_range(SyntaxTree& tree, const dialects::Dialect& dialect, std::size_t first, std::size_t end,
                      bool linear_at_start) {
    BoundRange out;
    BindContext context(dialect.lexical);
    context.linear = linear_at_start;
    for (std::size_t i = first; i < end; ++i) {
        const BlockFacts facts = bind_block(tree, dialect, i, context);
        if (facts.calls) out.call_blocks.push_back(i);
        if (facts.second_n) out.second_n.push_back(facts.second_n);
        out.motion_seen |= facts.motion;
    }
    out.linear = context.linear;
    return out;
}

// Below this many blocks a second thread costs more than half the binding saves.
constexpr std::size_t kTwoThreadBindBlocks = 200000;

}  // namespace

TypedFile TypedFile::bind(SyntaxTree& tree, const dialects::Dialect& dialect, bool linear_at_start) {
    return bind(tree, dialect, linear_at_start, 1);
}

TypedFile TypedFile::bind(SyntaxTree& tree, const dialects::Dialect& dialect, bool linear_at_start, unsigned threads) {
    TypedFile file(tree, dialect);
    const std::size_t blocks = tree.block_count();
    std::vector<BoundRange> ranges;
    if (threads >= 2 && !dialect.lexical.plain_direct_drawing && blocks >= kTwoThreadBindBlocks) {
        // Each block's roles depend only on the block (plain direct drawing excepted), and each
        // half writes only its own blocks' tokens: the halves bind side by side.
        const std::size_t half = blocks / 2;
        BoundRange second;
        std::thread worker([&] { second = bind_range(tree, dialect, half, blocks, false); });
        ranges.push_back(bind_range(tree, dialect, 0, half, linear_at_start));
        worker.join();
        ranges.push_back(std::move(second));
    } else {
        ranges.push_back(bind_range(tree, dialect, 0, blocks, linear_at_start));
    }
    std::vector<std::size_t> call_blocks;
    file.linear_at_end_ = linear_at_start;
    for (const BoundRange& r : ranges) {
        call_blocks.insert(call_blocks.end(), r.call_blocks.begin(), r.call_blocks.end());
        for (const std::uint32_t token : r.second_n) file.diagnostics_.push_back(second_n_diagnostic(tree, token));
        if (r.motion_seen) file.linear_at_end_ = r.linear;
    }
    file.split_programs();
    file.check_call_forms(call_blocks);
    return file;
}

TypedFile TypedFile::bind_edited(SyntaxTree& tree, const TypedFile& before, const BlockSplice& splice) {
    const dialects::Dialect& dialect = *before.dialect_;
    if (dialect.lexical.plain_direct_drawing) return bind(tree, dialect);
    TypedFile file(tree, dialect);
    for (const Diagnostic& d : before.diagnostics_)
        if (d.range.begin < splice.old_begin) file.diagnostics_.push_back(d);
    BindContext context(dialect.lexical);   // `linear` matters only for plain direct drawing
    std::vector<std::size_t> call_blocks;
    for (std::size_t i = splice.first; i < splice.first + splice.added; ++i) {
        const BlockFacts facts = bind_block(tree, dialect, i, context);
        if (facts.calls) call_blocks.push_back(i);
        if (facts.second_n) file.diagnostics_.push_back(second_n_diagnostic(tree, facts.second_n));
    }
    file.check_call_forms(call_blocks);
    for (Diagnostic d : before.diagnostics_) {
        if (d.range.begin < splice.old_end) continue;
        d.range.begin = static_cast<std::uint32_t>(d.range.begin + splice.shift);
        d.range.end = static_cast<std::uint32_t>(d.range.end + splice.shift);
        file.diagnostics_.push_back(std::move(d));
    }
    file.linear_at_end_ = before.linear_at_end_;
    file.split_programs();
    return file;
}

void TypedFile::rebind_block(SyntaxTree& tree, std::size_t index) {
    BindContext context(dialect_->lexical);
    // Modal context: the last motion code before this block.
    bool found = false;
    for (std::size_t i = index; i-- > 0 && !found;) {
        for (const CodeRef& g : block(i).g_codes()) {
            if (g.info && g.info->has(dialects::traits::motion_group)) {
                context.linear = g.info->has(dialects::traits::linear);
                found = true;
            }
        }
    }
    bind_block(tree, *dialect_, index, context);
}

// --- views -----------------------------------------------------------------------------------------

const SyntaxTree& BlockView::tree() const { return file_->tree(); }
const Block& BlockView::block() const { return file_->tree().blocks[index_]; }
Range BlockView::range() const { return file_->tree().block_range(index_); }
std::span<const Token> BlockView::tokens() const { return file_->tree().block_tokens(index_); }
std::uint32_t BlockView::first_token() const { return block().first_token; }

std::vector<std::uint32_t> BlockView::words_with_role(Role role) const {
    std::vector<std::uint32_t> out;
    const std::uint32_t first = first_token();
    const auto tokens_ = tokens();
    for (std::uint32_t i = 0; i < tokens_.size(); ++i)
        if (tokens_[i].kind == TokenKind::word && tokens_[i].role() == role) out.push_back(first + i);
    return out;
}

std::optional<double> BlockView::sequence_number() const {
    for (const Token& t : tokens())
        if (t.kind == TokenKind::word && t.letter == 'N' && t.is_number()) return file_->tree().number_value(t);
    return std::nullopt;
}

std::optional<std::int64_t> truncated_integer(double value) {
    if (!(std::fabs(value) < 9.0e18)) return std::nullopt;   // also NaN
    return static_cast<std::int64_t>(value);
}

std::optional<std::int64_t> BlockView::sequence_label() const {
    const std::optional<double> n = sequence_number();
    return n ? truncated_integer(*n) : std::nullopt;
}

bool BlockView::has_sequence_word() const {
    for (const Token& t : tokens())
        if (t.kind == TokenKind::word && t.letter == 'N') return true;
    return false;
}

int BlockView::block_delete_level() const {
    for (const Token& t : tokens())
        if (t.kind == TokenKind::block_delete) return t.letter ? t.letter - '0' : 1;
    return 0;
}

namespace {
std::vector<CodeRef> codes(const TypedFile& file, const BlockView& view, Role role) {
    std::vector<CodeRef> out;
    for (const std::uint32_t i : view.words_with_role(role)) {
        const Token& t = file.tree().tokens[i];
        CodeRef ref;
        ref.token = i;
        ref.key = code_key_of(file.tree(), t);
        if (ref.key) ref.info = file.dialect().fast_code(t.letter, *ref.key);
        out.push_back(ref);
    }
    return out;
}
}  // namespace

std::vector<CodeRef> BlockView::g_codes() const { return codes(*file_, *this, Role::g_code); }

void BlockView::collect_codes(std::vector<CodeRef>& g, std::vector<CodeRef>& m) const {
    g.clear();
    m.clear();
    const std::uint32_t first = first_token();
    const auto toks = tokens();
    for (std::uint32_t i = 0; i < toks.size(); ++i) {
        const Token& t = toks[i];
        if (t.kind != TokenKind::word || (t.role() != Role::g_code && t.role() != Role::m_code)) continue;
        CodeRef ref;
        ref.token = first + i;
        ref.key = code_key_of(file_->tree(), t);
        if (ref.key) ref.info = file_->dialect().fast_code(t.letter, *ref.key);
        (t.role() == Role::g_code ? g : m).push_back(ref);
    }
}
std::vector<CodeRef> BlockView::m_codes() const { return codes(*file_, *this, Role::m_code); }

std::vector<AxisWord> BlockView::axis_words() const {
    std::vector<AxisWord> out;
    const dialects::LexicalRules& rules = file_->dialect().lexical;
    const std::uint32_t first = first_token();
    const auto toks = tokens();
    for (std::uint32_t i = 0; i < toks.size(); ++i) {
        const Token& t = toks[i];
        if (t.kind != TokenKind::word) continue;
        if (t.role() == Role::axis_absolute) out.push_back({first + i, t.letter, false});
        else if (t.role() == Role::axis_incremental) out.push_back({first + i, rules.incremental_axis_of(t.letter), true});
    }
    return out;
}

namespace {
std::vector<std::uint32_t> tokens_of_kind(const BlockView& view, TokenKind kind) {
    std::vector<std::uint32_t> out;
    const auto toks = view.tokens();
    for (std::uint32_t i = 0; i < toks.size(); ++i)
        if (toks[i].kind == kind) out.push_back(view.first_token() + i);
    return out;
}
}  // namespace

std::vector<std::uint32_t> BlockView::comma_words() const { return tokens_of_kind(*this, TokenKind::comma_word); }
std::vector<std::uint32_t> BlockView::comments() const { return tokens_of_kind(*this, TokenKind::comment); }
std::vector<std::uint32_t> BlockView::statements() const { return tokens_of_kind(*this, TokenKind::statement); }

std::optional<std::uint32_t> BlockView::word(char letter) const {
    const auto toks = tokens();
    for (std::uint32_t i = 0; i < toks.size(); ++i)
        if (toks[i].kind == TokenKind::word && toks[i].letter == letter) return first_token() + i;
    return std::nullopt;
}

bool BlockView::has_code(char letter, dialects::FunctionId function) const {
    for (const CodeRef& c : letter == 'G' ? g_codes() : m_codes())
        if (c.info && c.info->function == function) return true;
    return false;
}

std::optional<SubprogramCall> BlockView::subprogram_call() const {
    if (!has_code('M', fn::subprogram_call)) return std::nullopt;
    const SyntaxTree& tree = file_->tree();
    const auto p = word('P');
    if (!p) return std::nullopt;
    const auto value = integer_value(tree, tree.tokens[*p]);
    if (!value || *value < 0) return std::nullopt;
    SubprogramCall call;
    call.p_token = *p;
    const auto l = word('L');
    const auto repeats_l = l ? integer_value(tree, tree.tokens[*l]) : std::nullopt;
    const dialects::SubprogramCall form = file_->dialect().lexical.subprogram_call;
    // dialects.md §3.6: the last four digits are the program, the digits before them the repeats.
    const bool packed = form == dialects::SubprogramCall::packed ||
                        (form == dialects::SubprogramCall::both && (!l || *value > 9999));
    if (packed) {
        call.packed = *value > 9999;
        call.program = *value % 10000;
        call.repeats = *value > 9999 ? *value / 10000 : 1;
    } else {
        call.program = *value;
        call.repeats = repeats_l.value_or(1);
    }
    return call;
}

std::optional<MacroCall> BlockView::macro_call() const {
    const bool simple = has_code('G', fn::macro_call);
    const bool modal = has_code('G', fn::modal_macro_call);
    if (!simple && !modal) return std::nullopt;
    const SyntaxTree& tree = file_->tree();
    MacroCall call;
    call.modal = modal;
    if (const auto p = word('P')) call.program = integer_value(tree, tree.tokens[*p]);
    if (const auto l = word('L')) call.repeats = integer_value(tree, tree.tokens[*l]).value_or(1);
    const auto toks = tokens();
    for (std::uint32_t i = 0; i < toks.size(); ++i) {
        const Token& t = toks[i];
        if (t.kind == TokenKind::word && t.role() == Role::parameter && t.letter != 'P' && t.letter != 'L')
            call.arguments.push_back(first_token() + i);
    }
    return call;
}

}  // namespace kerf::ast
