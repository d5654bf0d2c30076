// --expand: a construct the target cannot express replaced by the plain motion the interpreter
// computed for it (G00/G01/G02/G03, G04 and the target's thread code), absolute, with the same end
// points, centres and feeds, after a comment that names what it replaced (issue 16). Only a block
// whose one execution is plain motion can be expanded: a block that runs several times in different
// places, issues M codes, changes tools, raises an alarm, or runs under compensation or a
// coordinate transform (its events are tool-centre or transformed points) is left and reported.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "converter/codes.hpp"
#include "converter/convert.hpp"
#include "converter/dry_run.hpp"

namespace kerf::converter {

struct ExpandContext {
    const dialects::Dialect& target;
    const CodeMap& codes;
    Reading reading;                 // the target's
    bool feed_per_rev = false;       // the feed mode in force before the block (source text order)
    dialects::PlaneTrait plane = dialects::PlaneTrait::xy;   // the arc plane in force
    bool lower_case = false;         // the block's letters are lower case
    std::string line_ending = "\n";
    std::string prefix;              // N word and kept M codes, written before the comment
    std::string suffix;              // the block's own comments, after it
    std::string construct;           // what is replaced, for the comment ("G384 ... (line 12)")
};

struct Expansion {
    std::optional<std::string> text;   // the block's replacement (without the block's own line break)
    std::string why_not;               // when there is none
};

Expansion expand_block(const BlockRun& run, const ExpandContext& context);

}  // namespace kerf::converter
