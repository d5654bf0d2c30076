// The dialect converter (issue 16, docs/convert.md): a bound program in one dialect in, the edits
// that make it the same program in another dialect out, plus a report for every construct it
// could not convert. Pure: no I/O; the project layer reads and writes files, the CLI prints, the
// language server turns the edits into a code action.
//
// Conversion is by meaning, never by number: every G and M code becomes the target's code with the
// same function id (dialects/functions.hpp), so G92 (a thread cycle in system A) becomes G78 (B) or
// G21 (C) while G50 becomes G92; words follow what they mean (U/W ↔ G91 X/Z, the decimal-point
// reading of integer words, G04 P in ms ↔ s, G68's sign, G52's two readings, the M98 forms). Whatever
// the data says differs is read from the dialect tables; nothing asks for a dialect by name.
//
// The result is a list of edits to the lossless tree's text (byte ranges and their replacement),
// so everything not converted stays byte for byte: comments, N numbers, blank lines, spacing, line
// endings, the bytes of a block with a syntax error.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ast/source.hpp"
#include "ast/typed.hpp"
#include "dialects/dialect.hpp"
#include "interpreter/program_set.hpp"
#include "interpreter/setup.hpp"

namespace kerf::converter {

// A → B/C: how incremental moves written with U/W/H are written in a target that has G90/G91.
enum class IncrementalStyle {
    g91,       // G91 X/Z/C, with G90/G91 tracked so every block reads as before (the default, issue 16)
    letters,   // keep U/W/H where the target reads them as incremental addresses
};

// G52 in the machine's reading (machine/SCHEMA.md `g52`, semantics.md §2.4).
enum class LocalSystem { vector_shift, current_point, current_point_g152 };

// How one side's machine reads what the converter rewrites: the machine switches, whose defaults
// are the dialect's (`reading_of(dialect)`); the CLI takes them from the resolved Setups.
struct Reading {
    bool calculator_decimal = false;   // an integer length word is mm (true) or least increments
    int increment_digits = 3;          // decimal places of one increment in mm (and degrees): 3 (IS-B) or 4 (IS-C);
                                       // inch input reads one more (0.0001 in on IS-B, [FANUC] least input increment)
    std::string rotary = "AC";         // axis letters read in degrees (their increment is the mm one under inch too)
    bool dwell_p_seconds = false;      // G04 P (and a cycle's dwell P) in seconds, else ms
    LocalSystem g52 = LocalSystem::vector_shift;
    bool g54_cancels_g52 = false;      // selecting G54–G59 cancels the local system (pcnc-mill)
    bool diameter_x = false;           // lathe X is a diameter (arc centres of --expand)
};
Reading reading_of(const dialects::Dialect& dialect);
Reading reading_of(const dialects::Dialect& dialect, const interpreter::Setup& setup);

struct Options {
    IncrementalStyle incremental = IncrementalStyle::g91;
    // Replace a construct the target cannot express by the plain G00/G01/G02/G03 motion the
    // interpreter computes for it, with a comment naming what it replaced.
    bool expand = false;
    std::optional<Reading> from;   // nullopt: reading_of(source dialect)
    std::optional<Reading> to;     // nullopt: reading_of(target dialect)
    // The dry run some conversions need (G52 between readings, --expand): the source's machine,
    // the loader for subprograms in other files, a name for the file and the run's bounds.
    std::optional<interpreter::Setup> setup;   // nullopt: the source dialect's built-in machine
    interpreter::ProgramSet::Loader loader;
    std::string name = "program.nc";
    std::int64_t time_limit_ms = 0;            // 0: none
};

enum class ReportKind : std::uint8_t {
    unconverted,    // left as it is: the target cannot express it (exit 1)
    syntax_error,   // a parse error: the defective tokens stay verbatim (exit 1)
    expanded,       // replaced by plain motion (--expand); a note
    note,           // converted, with something worth knowing
};
const char* to_string(ReportKind kind);

struct Report {
    ast::Range range;           // where in the source text
    ReportKind kind = ReportKind::unconverted;
    std::string construct;      // "G384", "M98 P41001", "U20.", "(comment)"
    std::string reason;         // why, with the reference section
};

// A replacement of `range` of the source text by `text` (an insertion when the range is empty).
struct Edit {
    ast::Range range;
    std::string_view text;
};

// Edits in text order (ranges ascending, never overlapping; an insertion before a replacement at
// the same place), their texts in one buffer: a conversion of a 100 MB file makes millions.
class Edits {
public:
    void replace(ast::Range range, std::string_view text);
    void insert(std::uint32_t at, std::string_view text) { replace({at, at}, text); }
    void remove(ast::Range range) { replace(range, {}); }
    std::size_t size() const { return edits_.size(); }
    bool empty() const { return edits_.empty(); }
    Edit operator[](std::size_t i) const;
    // Bytes the text grows (or shrinks) by.
    std::int64_t growth() const { return growth_; }

private:
    struct Raw {
        std::uint32_t begin, end, text, length;
    };
    std::vector<Raw> edits_;
    std::string buffer_;
    std::int64_t growth_ = 0;
};

struct Conversion {
    Edits edits;
    std::vector<Report> reports;   // in text order
    // No construct left unconverted and no syntax error.
    bool clean() const;
};

// Converts `file` (bound in its dialect) to `target`.
Conversion convert(const ast::TypedFile& file, const dialects::Dialect& target, const Options& options = {});

// The text with the edits applied.
std::string apply(std::string_view text, const Edits& edits);

}  // namespace kerf::converter
