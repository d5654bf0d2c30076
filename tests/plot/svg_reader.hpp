// Small readers for the SVG that plot/svg.cpp writes, for the plot tests: attribute values, path
// data as commands, and a tag-balance check. Not a general SVG parser.
#pragma once

#include <cctype>
#include <cstdlib>
#include <string>
#include <vector>

namespace kerf::test {

// The element start tags ("<path ...>") whose text contains `needle`, in order.
inline std::vector<std::string> elements_with(const std::string& svg, const std::string& needle) {
    std::vector<std::string> out;
    for (std::size_t at = svg.find('<'); at != std::string::npos; at = svg.find('<', at + 1)) {
        const std::size_t end = svg.find('>', at);
        if (end == std::string::npos) break;
        const std::string tag = svg.substr(at, end - at + 1);
        if (tag.find(needle) != std::string::npos) out.push_back(tag);
    }
    return out;
}

// The value of attribute `name` in a start tag, "" if absent.
inline std::string attribute(const std::string& tag, const std::string& name) {
    const std::string key = " " + name + "=\"";
    const std::size_t at = tag.find(key);
    if (at == std::string::npos) return "";
    const std::size_t begin = at + key.size();
    return tag.substr(begin, tag.find('"', begin) - begin);
}

inline double number_attribute(const std::string& tag, const std::string& name) {
    return std::strtod(attribute(tag, name).c_str(), nullptr);
}

struct PathCommand {
    char letter = 'M';
    std::vector<double> args;
};

// "M1 2 L3 4 A5 5 0 0 1 6 7" → {M,[1,2]}, {L,[3,4]}, {A,[5,5,0,0,1,6,7]}.
inline std::vector<PathCommand> path_commands(const std::string& d) {
    std::vector<PathCommand> out;
    const char* p = d.c_str();
    while (*p) {
        if (std::isalpha(static_cast<unsigned char>(*p))) {
            out.push_back({*p, {}});
            ++p;
        } else if (*p == ' ' || *p == ',') {
            ++p;
        } else {
            char* end = nullptr;
            const double v = std::strtod(p, &end);
            if (end == p) return {};   // not a number: let the caller's checks fail
            if (!out.empty()) out.back().args.push_back(v);
            p = end;
        }
    }
    return out;
}

// Every start tag closed in order, self-closing tags allowed, one root. Enough to catch a missing
// or misplaced close tag; attributes are not validated.
inline bool tags_balanced(const std::string& svg) {
    std::vector<std::string> open;
    int roots = 0;
    for (std::size_t at = svg.find('<'); at != std::string::npos; at = svg.find('<', at + 1)) {
        const std::size_t end = svg.find('>', at);
        if (end == std::string::npos) return false;
        const std::string tag = svg.substr(at + 1, end - at - 1);
        if (tag.empty()) return false;
        if (tag[0] == '/') {
            if (open.empty() || open.back() != tag.substr(1)) return false;
            open.pop_back();
            continue;
        }
        if (open.empty()) ++roots;
        if (tag.back() == '/') continue;
        open.push_back(tag.substr(0, tag.find_first_of(" \n")));
    }
    return open.empty() && roots == 1;
}

}  // namespace kerf::test
