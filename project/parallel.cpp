#include "project/parallel.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

namespace kerf::project {

void run_parallel(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& work,
                  const std::function<void(std::size_t, std::size_t)>& done) {
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(count, 1)));
    std::atomic<std::size_t> next{0};
    std::atomic<std::size_t> finished{0};
    auto worker = [&] {
        for (std::size_t i = next++; i < count; i = next++) {
            work(i);
            ++finished;
        }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
    if (!done) {
        worker();
    } else {
        // The calling thread reports progress while the pool works; with one thread it works too.
        if (pool.empty()) {
            for (std::size_t i = next++; i < count; i = next++) {
                work(i);
                ++finished;
                done(finished.load(), count);
            }
        } else {
            while (finished.load() < count) {
                done(finished.load(), count);
                std::this_thread::sleep_for(std::chrono::milliseconds(100));
            }
        }
    }
    for (std::thread& t : pool) t.join();
    if (done) done(finished.load(), count);
}

}  // namespace kerf::project
