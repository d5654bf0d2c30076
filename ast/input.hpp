// Input decoding: the bytes of a file in, the text kerf reads + its encoding + what is wrong with
// it out (issue 17, "input hygiene"). Pure: no file, no terminal. Every reader of program files
// (the CLI today, project/ and the language server next) passes the bytes through here first, so
// every command refuses the same files and reads the same text.
//
// * UTF-8 (with or without BOM, invalid sequences included: the grammar is lossless over any
//   bytes) is passed through untouched: `text` is the input bytes, moved, not copied.
// * UTF-16 and UTF-32, little or big endian, with or without BOM, are recognised (a BOM, or the
//   zero bytes of ASCII text in those encodings) and transcoded to UTF-8; writers put the result
//   back into the same encoding with `encode_output` (fmt --write, check --fix).
// * A binary file (NUL and other control bytes that text does not have) is refused: one problem
//   of severity error, and the caller reads nothing of it.
// * A file over `max_file_bytes`, or with a line over `max_line_bytes`, is refused with the limit
//   and how to raise it (bounded resources: ARCHITECTURE.md "Bounded resources").
// * An empty file, or one of blanks and line breaks only, gets a note.
// Line breaks are those of ast/source.hpp: "\n", "\r\n" and a lone "\r".
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ast/diagnostic.hpp"

namespace kerf::ast {

enum class Encoding : std::uint8_t { utf8, utf16le, utf16be, utf32le, utf32be };
const char* to_string(Encoding e);   // "UTF-8", "UTF-16LE", ...

// Sizes past which a file is refused. 0 = no limit. The defaults are far above any real NC
// program (the largest CAM program of the corpus is a few MB, its longest line under 200 bytes)
// and keep every command within a small multiple of its input (bench/RESULTS.md).
struct InputLimits {
    std::uint64_t max_file_bytes = std::uint64_t{512} << 20;   // 512 MiB
    std::uint64_t max_line_bytes = std::uint64_t{64} << 10;    // 64 KiB
};

enum class InputProblemKind : std::uint8_t {
    binary,          // error: not text
    too_large,       // error: over max_file_bytes
    line_too_long,   // error: a line over max_line_bytes
    bad_encoding,    // warning: UTF-16/32 with sequences that are not characters (read as U+FFFD)
    transcoded,      // note: read from UTF-16/32
    empty,           // note: nothing but blanks and line breaks
};

struct InputProblem {
    InputProblemKind kind = InputProblemKind::binary;
    Severity severity = Severity::error;   // error: the file is refused, nothing of it is read
    std::uint32_t line = 0;                // 1-based line of the problem, 0 for the whole file
    std::string message;                   // what is wrong
    std::string hint;                      // what to do
};

struct DecodedInput {
    std::string text;                      // UTF-8; empty when refused
    Encoding encoding = Encoding::utf8;    // of the input
    bool bom = false;                      // the input started with a byte-order mark
    std::vector<InputProblem> problems;
    bool refused() const;                  // a problem of severity error
};

// The refusal of a file of `size` bytes, before reading it, or nullopt.
std::optional<InputProblem> check_file_size(std::uint64_t size, const InputLimits& limits);

// The whole decision for a buffer the caller hands over.
DecodedInput decode_input(std::string bytes, const InputLimits& limits = {});

// The same checks over bytes the caller keeps and hands in pieces (a mapped file read in
// windows, so that its pages can be released as it goes). `finish` returns what `decode_input`
// would, with an empty `text`; when `encoding` is not UTF-8 the caller has to decode the bytes
// with `decode_input` to read them.
class InputScanner {
public:
    explicit InputScanner(const InputLimits& limits = {}) : limits_(limits) {}
    void feed(std::string_view piece);   // the next bytes of the input, in order
    // Takes over a scanner that was fed the bytes right after this one's, which end at a line
    // break: one text scanned in two parts (on two threads) reads as if scanned in one.
    void append(const InputScanner& later);
    DecodedInput finish();

private:
    InputLimits limits_;
    std::string head_;                 // the first bytes, for the encoding and binary decisions
    std::uint64_t size_ = 0;
    std::uint64_t line_ = 1;           // 1-based line being read
    std::uint64_t line_length_ = 0;    // bytes of it so far
    std::uint64_t longest_line_ = 0;
    std::uint64_t longest_at_ = 0;     // its 1-based line
    bool pending_cr_ = false;          // the last piece ended with '\r' (its '\n' may follow)
    bool only_blank_ = true;
};

// UTF-8 text back into the bytes of `encoding` (with its BOM when `bom`), for a writer that must
// not change the encoding of the file it rewrites. UTF-8 text is returned as it is (a UTF-8 BOM
// is part of the text: the grammar keeps it as a token).
std::string encode_output(std::string_view text, Encoding encoding, bool bom);

}  // namespace kerf::ast
