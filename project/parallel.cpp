#include "project/parallel.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

namespace kerf::project {

void run_parallel(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& work,
                  const std::function<void(std::size_t, std::size_t)>& done) {
    if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
    threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(count, 1)));
    std::mutex mutex;
    std::condition_variable progressed;
    std::size_t next = 0, finished = 0;
    auto worker = [&] {
        while (true) {
            std::size_t i = 0;
            {
                const std::lock_guard lock(mutex);
                if (next >= count) return;
                i = next++;
            }
            work(i);
            {
                const std::lock_guard lock(mutex);
                ++finished;
            }
            progressed.notify_one();
        }
    };
    // `threads` workers in all. With a progress callback the calling thread only reports (it was
    // one of the workers and reported between items: a folder check ran on one core of two);
    // without one it is a worker itself.
    std::vector<std::thread> pool;
    const unsigned helpers = done ? threads : threads - 1;
    for (unsigned t = 0; t < helpers; ++t) pool.emplace_back(worker);
    if (!done) {
        worker();
    } else {
        std::unique_lock lock(mutex);
        while (finished < count) {
            const std::size_t now = finished;
            lock.unlock();
            done(now, count);
            lock.lock();
            progressed.wait_for(lock, std::chrono::milliseconds(100), [&] { return finished == count; });
        }
    }
    for (std::thread& t : pool) t.join();
    if (done) done(finished, count);
}

}  // namespace kerf::project
