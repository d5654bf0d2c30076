// Batch work on all cores (design.md "Command line": batch work runs on all cores): `kerf check`
// and `kerf fmt` over folders, and the language server's workspace-wide passes.
#pragma once

#include <cstddef>
#include <functional>

namespace kerf::project {

// Runs `work(i)` for i in [0, count) on `threads` threads (0: all cores). `work` must be safe to
// call concurrently for different i. `done(finished, count)` is called on the calling thread
// about every 100 ms and at the end, for a progress bar; it may be empty.
void run_parallel(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& work,
                  const std::function<void(std::size_t, std::size_t)>& done = {});

}  // namespace kerf::project
