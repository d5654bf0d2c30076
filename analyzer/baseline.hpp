// A baseline of accepted findings, so a legacy repository can adopt kerf without fixing
// everything first. A finding is matched by file, rule and the text of its block (not by line
// number): edits elsewhere in the file do not break the baseline; editing the block itself does.
// The file is JSON: {"version": 1, "findings": [{"file": ..., "rule": ..., "block": ...}, ...]}.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "analyzer/finding.hpp"
#include "ast/syntax.hpp"

namespace kerf::analyzer {

struct BaselineEntry {
    std::string file;
    std::string rule;
    std::string block;   // the block's text without its line break
    friend auto operator<=>(const BaselineEntry&, const BaselineEntry&) = default;
};

// The text of the block that holds `offset`, without trailing blanks and line break.
std::string block_text(const ast::SyntaxTree& tree, std::uint32_t offset);

std::string write_baseline(std::vector<BaselineEntry> entries);
std::optional<std::vector<BaselineEntry>> read_baseline(std::string_view json, std::string& error);

// Each entry accepts one finding (two identical findings need two entries).
class BaselineFilter {
public:
    explicit BaselineFilter(const std::vector<BaselineEntry>& entries);
    bool accepts(const BaselineEntry& finding);   // consumes a matching entry

private:
    std::map<BaselineEntry, int> left_;
};

}  // namespace kerf::analyzer
