// Allocator for the tree's big arrays. Large buffers come straight from mmap, and the parser maps
// the next stretch ahead of its writes (prefault: one system call per MiB instead of a fault per
// page). Reserved capacity that is never written costs address space, not memory.
//
// No transparent huge pages: on the VMs kerf is measured on, a fresh 2 MiB page costs the kernel
// (and the host) far more to clear than 512 small pages taken in one prefault: `kerf parse` of
// 100 MB spent 0.09-0.85 s of system time with MADV_HUGEPAGE and a steady 0.14-0.20 s without
// (bench/RESULTS.md, 2026-11-28). They were asked for when each page still faulted on its own.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace kerf::ast {

template <typename T>
struct LargeAllocator {
    using value_type = T;
    static constexpr std::size_t kThreshold = std::size_t{4} << 20;   // 4 MiB

    LargeAllocator() = default;
    template <typename U>
    LargeAllocator(const LargeAllocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        const std::size_t bytes = n * sizeof(T);
#if defined(__linux__)
        if (bytes >= kThreshold) {
            void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
            if (p == MAP_FAILED) throw std::bad_alloc();
            return static_cast<T*>(p);
        }
#endif
        return std::allocator<T>().allocate(n);
    }

    void deallocate(T* p, std::size_t n) noexcept {
        const std::size_t bytes = n * sizeof(T);
#if defined(__linux__)
        if (bytes >= kThreshold) {
            munmap(p, bytes);
            return;
        }
#endif
        std::allocator<T>().deallocate(p, n);
    }

    template <typename U>
    bool operator==(const LargeAllocator<U>&) const noexcept { return true; }
};

// Maps the pages of [p, p + bytes) ahead of their first write, in one system call instead of one
// fault per page (Linux 5.14+; elsewhere a no-op and the pages fault in as usual).
inline void prefault(void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    const auto page = reinterpret_cast<std::uintptr_t>(p) & ~std::uintptr_t{4095};
    madvise(reinterpret_cast<void*>(page), bytes + (reinterpret_cast<std::uintptr_t>(p) - page), MADV_POPULATE_WRITE);
#else
    (void)p;
    (void)bytes;
#endif
}

// Gives the whole pages inside [p, p + bytes) back to the system: they read as zeros afterwards.
// For a large array's stretch that will not be read again (Linux; elsewhere a no-op).
inline void release(void* p, std::size_t bytes) {
#if defined(__linux__)
    const auto from = (reinterpret_cast<std::uintptr_t>(p) + 4095) & ~std::uintptr_t{4095};
    const auto to = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~std::uintptr_t{4095};
    if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_DONTNEED);
#else
    (void)p;
    (void)bytes;
#endif
}

template <typename T>
using LargeVector = std::vector<T, LargeAllocator<T>>;

}  // namespace kerf::ast
