#include "analyzer/baseline.hpp"

#include <algorithm>
#include <boost/json.hpp>

namespace kerf::analyzer {

namespace json = boost::json;

std::string block_text(const ast::SyntaxTree& tree, std::uint32_t offset) {
    const auto& blocks = tree.blocks;
    std::size_t lo = 0, hi = blocks.size();
    while (hi - lo > 1) {   // the last block starting at or before offset
        const std::size_t mid = (lo + hi) / 2;
        (blocks[mid].begin <= offset ? lo : hi) = mid;
    }
    if (blocks.size() == 0) return {};
    std::string_view text = tree.slice(tree.block_range(lo));
    while (!text.empty() && std::string_view(" \t\r\n").find(text.back()) != std::string_view::npos) text.remove_suffix(1);
    return std::string(text);
}

std::string write_baseline(std::vector<BaselineEntry> entries) {
    std::sort(entries.begin(), entries.end());
    json::array findings;
    for (const BaselineEntry& e : entries)
        findings.push_back(json::object{{"file", e.file}, {"rule", e.rule}, {"block", e.block}});
    std::string out = "{\"version\": 1, \"findings\": [";
    for (std::size_t i = 0; i < findings.size(); ++i) out += (i ? ",\n  " : "\n  ") + json::serialize(findings[i]);
    out += findings.empty() ? "]}\n" : "\n]}\n";
    return out;
}

std::optional<std::vector<BaselineEntry>> read_baseline(std::string_view text, std::string& error) {
    json::error_code ec;
    const json::value v = json::parse(text, ec);
    if (ec) {
        error = "not JSON: " + ec.message();
        return std::nullopt;
    }
    const json::object* root = v.if_object();
    const json::array* findings = root && root->contains("findings") ? root->at("findings").if_array() : nullptr;
    if (!findings) {
        error = "a baseline is an object with a \"findings\" array";
        return std::nullopt;
    }
    std::vector<BaselineEntry> out;
    for (const json::value& f : *findings) {
        const json::object* o = f.if_object();
        auto field = [&](const char* key) -> const json::string* {
            return o && o->contains(key) ? o->at(key).if_string() : nullptr;
        };
        const json::string *file = field("file"), *rule = field("rule"), *block = field("block");
        if (!file || !rule || !block) {
            error = "each finding needs the strings \"file\", \"rule\" and \"block\"";
            return std::nullopt;
        }
        out.push_back({std::string(*file), std::string(*rule), std::string(*block)});
    }
    return out;
}

BaselineFilter::BaselineFilter(const std::vector<BaselineEntry>& entries) {
    for (const BaselineEntry& e : entries) ++left_[e];
}

bool BaselineFilter::accepts(const BaselineEntry& finding) {
    const auto it = left_.find(finding);
    if (it == left_.end() || it->second == 0) return false;
    --it->second;
    return true;
}

}  // namespace kerf::analyzer
