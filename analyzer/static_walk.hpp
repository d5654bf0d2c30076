// The static walk's pieces (internal to analyzer/): the checks of the active rules with their
// reporters, and one step of the block loop. check_static (analyze.cpp) walks every block with
// them; incremental checking (incremental.cpp) walks the stretch an edit touched.
#pragma once

#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "analyzer/analyze.hpp"
#include "analyzer/registry.hpp"
#include "analyzer/rule.hpp"

namespace kerf::analyzer::detail {

using ActiveRules = std::vector<const Rule*>;

ActiveRules active_rules(const Registry& registry, const CheckConfig& config);
const Registry& registry_of(const CheckOptions& options);
// The parser's or binder's diagnostics as the findings of the rules that own their codes.
void map_diagnostics(const ast::SyntaxTree& tree, const std::vector<ast::Diagnostic>& diagnostics, const Registry& registry,
                     const ActiveRules& rules, const std::function<RuleTally*(const Rule&)>& tally_of, std::vector<Finding>& out);

// Every program check of `rules` on every program of the file (rule.hpp ProgramCheck).
void run_program_checks(const FileContext& ctx, const ActiveRules& rules, const std::function<RuleTally*(const Rule&)>& tally_of,
                        std::vector<Finding>& out);

inline bool modal_code(const dialects::CodeInfo& c) { return c.modal && !c.group.empty() && c.group != "00"; }

inline void update_modal(ModalState& modal, std::span<const ast::CodeRef> g) {
    for (const ast::CodeRef& ref : g)
        if (ref.info && modal_code(*ref.info)) modal.set(*ref.info);
}

struct StaticRun {
    const Rule* rule = nullptr;
    std::unique_ptr<StaticCheck> check;
    Reporter out;
};

// Shows block `b` of program `program` to every check, when it is a block the checks see (code
// and the O line), and moves the modal state past it. Keeps the code vectors between blocks.
class BlockStep {
public:
    void operator()(const FileContext& ctx, std::vector<StaticRun>& checks, ModalState& modal, std::size_t program, std::uint32_t b) {
        const ast::BlockView view = ctx.typed.block(b);
        const ast::BlockKind kind = view.block().kind;
        if (kind != ast::BlockKind::code && kind != ast::BlockKind::program_start) return;
        view.collect_codes(g_, m_);
        const BlockContext block{ctx, view, g_, m_, modal, program, {}, {}};
        for (StaticRun& c : checks) c.check->block(block, c.out);
        update_modal(modal, g_);
    }

private:
    std::vector<ast::CodeRef> g_, m_;
};

}  // namespace kerf::analyzer::detail
