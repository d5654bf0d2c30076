// The invariants of kerf's fuzz targets (fuzz/README.md), in one library used by the libFuzzer
// targets (fuzz/fuzz_target.cpp: a broken invariant is a crash) and by the test suite, which runs
// every file of fuzz/regressions/<target>/ through the same check (tests/test_fuzz_regressions.cpp).
//
// Program inputs (interpreter, analyzer, formatter): byte 0 picks the dialect as in fuzz_grammar
// ((byte + 6) % 9: the digits '0'..'8' of the seeds pick the nine built-in dialects in order) and
// the options (byte / 9: lenient run, style choices); the rest is the program text. TOML inputs
// (machine, dialect) are the file text.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace kerf::fuzz {

// What broke, or nullopt.
using Broken = std::optional<std::string>;

// The largest input a check reads (longer ones pass unchecked): a dry run is step-limited, but a
// long program still makes every run slow.
inline constexpr std::size_t kMaxProgramInput = 64 * 1024;

// Dry run (step- and move-limited, strict or lenient): every event valid (kind, source inside
// the file, no NaN position, length, time or feed; arcs with a centre), nothing but messages after
// an alarm, every event writes as one valid JSON line, the run within its bounds.
Broken check_interpreter(std::string_view input);

// kerf check: every finding's range inside the text, its rule known, at most the cap per rule
// (plus one "and N more"); every fix's edits inside the text; the fixes apply and the fixed text
// parses losslessly with no more syntax errors than the original.
Broken check_analyzer(std::string_view input);

// kerf fmt, on what it formats (texts without syntax errors): the output parses losslessly;
// formatting it again changes nothing (idempotent); --verify finds the two runs equal.
Broken check_formatter(std::string_view input);

// kerf convert (issue 16): byte 0 picks the source dialect as above and, above it, the target
// (one of the same nine), the U/W style and --expand. The edits are in order, inside the text and
// never overlap; the output parses losslessly in the target; a text without syntax errors that
// converts cleanly has none in the target and dry-runs to the same motion (the motion profile of
// --verify, 0.001 mm, on one machine description); a conversion between a lathe and a mill dialect
// changes nothing.
Broken check_converter(std::string_view input);

// Machine TOML: the loader returns errors with positions inside the text or a machine; a machine
// resolves for every dialect and its Setup dry-runs a fixed program with valid events.
Broken check_machine_toml(std::string_view input);

// Dialect TOML: the loader returns errors with positions inside the text or dialects; each new
// dialect parses, binds and dry-runs a fixed program with valid events.
Broken check_dialect_toml(std::string_view input);

// The input decoder (ast/input.hpp), as every reader of files calls it: decode_input and the
// InputScanner fed the same bytes in pieces (split where the input says) agree on the encoding,
// the refusal and every problem; a UTF-8 input read is returned byte for byte; a transcoded input
// without bad sequences encodes back into its own bytes (fmt --write keeps a UTF-16 file as it was);
// every refusal and note has a message.
Broken check_input(std::string_view input);

// .kerf.toml (project/config.hpp): parse_config never throws, every problem has a message and a
// position inside the text (or none), and its text names the file.
Broken check_kerf_toml(std::string_view input);

// The language server's message loop (`kerf lsp`: lsp::Server reading a pipe as it reads stdin):
// the input is a script of messages (fuzz/check_lsp.cpp): raw bytes, frames with a wrong
// Content-Length or a body that is not JSON-RPC, and the requests and notifications of every
// feature with document texts, edits, positions and ranges taken from the input. The server ends
// once the input does (or at `exit`), with 0 after shutdown and exit, else 1; every frame it writes
// is a JSON-RPC 2.0 message; a response answers a request that was sent, once; when the script
// has no broken framing, every request before `exit` is answered.
Broken check_lsp(std::string_view input);

}  // namespace kerf::fuzz
