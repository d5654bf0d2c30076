#include "formatter/diff.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "ast/source.hpp"

namespace kerf::formatter {

namespace {

// Lines with their breaks ("\n", "\r\n" or a lone "\r", ast/source.hpp).
std::vector<std::string_view> split_lines(std::string_view text) {
    std::vector<std::string_view> lines;
    ast::LineBreaks breaks(text);
    for (std::size_t pos = 0; pos < text.size();) {
        const std::size_t next = breaks.line_from(pos).next;
        lines.push_back(text.substr(pos, next - pos));
        pos = next;
    }
    return lines;
}

enum class Op : char { equal = ' ', remove = '-', insert = '+' };

struct Edit {
    Op op;
    int a = 0;   // line index in a (equal, remove)
    int b = 0;   // line index in b (equal, insert)
};

using Lines = std::vector<std::string_view>;

// Myers' greedy shortest edit script of a[a0, a1) → b[b0, b1); false when it needs more than
// kMaxEdits edits.
bool myers(const Lines& a, int a0, int a1, const Lines& b, int b0, int b1, std::vector<Edit>& out) {
    const int n = a1 - a0, m = b1 - b0, max = std::min(n + m, kMaxEdits);
    std::vector<int> v(2 * static_cast<std::size_t>(max) + 3, 0);
    const int offset = max + 1;
    std::vector<std::vector<int>> trace;
    for (int d = 0; d <= max; ++d) {
        trace.emplace_back(v.begin() + offset - d, v.begin() + offset + d + 1);   // V before step d: k in [-d, d]
        for (int k = -d; k <= d; k += 2) {
            int x = (k == -d || (k != d && v[offset + k - 1] < v[offset + k + 1])) ? v[offset + k + 1] : v[offset + k - 1] + 1;
            int y = x - k;
            while (x < n && y < m && a[a0 + x] == b[b0 + y]) ++x, ++y;
            v[offset + k] = x;
            if (x < n || y < m) continue;
            // Back from (n, m) through the saved V of every step.
            std::vector<Edit> reversed;
            for (int e = d; e > 0; --e) {
                const std::vector<int>& prev = trace[static_cast<std::size_t>(e)];
                auto at = [&](int kk) { return prev[static_cast<std::size_t>(kk + e)]; };
                const int kk = x - y;
                const int prev_k = (kk == -e || (kk != e && at(kk - 1) < at(kk + 1))) ? kk + 1 : kk - 1;
                const int px = at(prev_k), py = px - prev_k;
                while (x > px && y > py) --x, --y, reversed.push_back({Op::equal, a0 + x, b0 + y});
                if (x == px) --y, reversed.push_back({Op::insert, a0 + x, b0 + y});
                else --x, reversed.push_back({Op::remove, a0 + x, b0 + y});
            }
            while (x > 0 && y > 0) --x, --y, reversed.push_back({Op::equal, a0 + x, b0 + y});
            out.insert(out.end(), reversed.rbegin(), reversed.rend());
            return true;
        }
    }
    return false;
}

std::vector<Edit> edit_script(const Lines& a, const Lines& b) {
    const int n = static_cast<int>(a.size()), m = static_cast<int>(b.size());
    int head = 0;
    while (head < n && head < m && a[head] == b[head]) ++head;
    int tail = 0;
    while (tail < n - head && tail < m - head && a[n - 1 - tail] == b[m - 1 - tail]) ++tail;
    std::vector<Edit> edits;
    for (int i = 0; i < head; ++i) edits.push_back({Op::equal, i, i});
    if (!myers(a, head, n - tail, b, head, m - tail, edits)) {
        for (int i = head; i < n - tail; ++i) edits.push_back({Op::remove, i, head});
        for (int j = head; j < m - tail; ++j) edits.push_back({Op::insert, n - tail, j});
    }
    for (int i = 0; i < tail; ++i) edits.push_back({Op::equal, n - tail + i, m - tail + i});
    return edits;
}

void append_line(std::string& out, char prefix, std::string_view line) {
    out += prefix;
    if (!line.empty() && line.back() == '\r') {
        // A CR-only line: shown as a line of the diff (a bare CR would overwrite it on a terminal).
        line.remove_suffix(1);
        out += line;
        out += '\n';
        return;
    }
    out += line;
    if (line.empty() || line.back() != '\n') out += "\n\\ No newline at end of file\n";
}

// "@@ -3,7 +3,6 @@": 1-based first line and count; an empty range names the line before it.
std::string range_header(int first, int count) {
    return fmt::format("{},{}", count == 0 ? first : first + 1, count);
}

}  // namespace

std::string unified_diff(std::string_view a_text, std::string_view b_text, std::string_view a_name,
                         std::string_view b_name, int context) {
    if (a_text == b_text) return {};
    const Lines a = split_lines(a_text), b = split_lines(b_text);
    const std::vector<Edit> edits = edit_script(a, b);
    std::string out = fmt::format("--- {}\n+++ {}\n", a_name, b_name);
    const int count = static_cast<int>(edits.size());
    for (int i = 0; i < count;) {
        if (edits[i].op == Op::equal) {
            ++i;
            continue;
        }
        // A hunk: `context` lines before this change, up to `context` lines after the last change
        // that follows the previous one within 2·context equal lines (then the hunks would touch).
        const int begin = std::max(0, i - context);
        int last = i;
        for (int j = i; j < count && j - last <= 2 * context; ++j)
            if (edits[j].op != Op::equal) last = j;
        const int end = std::min(count, last + 1 + context);
        int a_count = 0, b_count = 0;
        for (int k = begin; k < end; ++k) {
            a_count += edits[k].op != Op::insert;
            b_count += edits[k].op != Op::remove;
        }
        out += fmt::format("@@ -{} +{} @@\n", range_header(edits[begin].a, a_count), range_header(edits[begin].b, b_count));
        for (int k = begin; k < end; ++k) {
            const Edit& e = edits[k];
            append_line(out, static_cast<char>(e.op), e.op == Op::insert ? b[e.b] : a[e.a]);
        }
        i = end;
    }
    return out;
}

}  // namespace kerf::formatter
