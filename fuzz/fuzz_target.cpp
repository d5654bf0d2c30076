// One libFuzzer target per check of fuzz/checks.hpp: KERF_FUZZ_CHECK names the check (set by
// fuzz/CMakeLists.txt). A broken invariant prints what broke and traps, which libFuzzer reports as
// a crash and saves the input (fuzz/README.md).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string_view>

#include "fuzz/checks.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    if (const kerf::fuzz::Broken broken = kerf::fuzz::KERF_FUZZ_CHECK(input)) {
        std::fprintf(stderr, "%s: invariant broken: %s\n", KERF_FUZZ_NAME, broken->c_str());
        std::fflush(stderr);
        __builtin_trap();
    }
    return 0;
}
