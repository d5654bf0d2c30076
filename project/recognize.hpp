// Is this file an NC program? Folder walks (project/walk.hpp) and the program index ask it of every
// file they meet: CNC files are named every way (O1234 without extension, .nc .eia .gcode .prg .min
// .iso .ptp .txt .src ...), so the content decides, not the name. Pure: the caller reads the head.
//
// How it decides, in order:
//   1. empty → not a program; binary → not a program: a NUL byte (UTF-16/32 text with a BOM is read
//      as text), a known magic number (PNG, JPEG, GIF, PDF, ZIP, gzip, ELF, ...), or more than 2% of
//      control bytes (the DNC characters DC1–DC4 and the DOS end-of-file byte are allowed);
//   2. a name with an NC program extension (kProgramExtensions) → a program;
//   3. otherwise the lines of the head (comments removed: (...), //, /*, ;) are sorted into
//      NC blocks (address words G01 T0101, macro statements #1=2, IF[..]GOTO, WHILE..DO),
//      prose (two or more words of three letters or more that are no NC keyword, Markdown tables and
//      headings) and neither, up to 200 lines or until 32 NC blocks without prose have decided it; a
//      program has an NC block and at least as many NC blocks as lines of prose. A README, a manifest, a CSV or a script is not a program; a listing with a few
//      English lines in comments is.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace kerf::project {

// NC program extensions, lower case, with the dot: a file so named is a program unless it is
// empty or binary.
inline constexpr std::string_view kProgramExtensions[] = {".nc",  ".ngc", ".tap", ".cnc", ".mpf", ".spf", ".eia",
                                                          ".gcode", ".prg", ".min", ".iso", ".ptp", ".nc1", ".anc"};

// How many bytes of a file the recognition reads.
inline constexpr std::size_t kRecognitionHead = 16 * 1024;

struct Recognition {
    bool program = false;
    std::string reason;   // why: "extension .nc", "12 NC blocks", "binary: PNG image", "prose: 40 lines, 2 NC blocks"
};

// `name`: the file name (for its extension); `head`: its first bytes (kRecognitionHead or all).
Recognition recognize_program(std::string_view name, std::string_view head);

}  // namespace kerf::project
