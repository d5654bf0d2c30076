// Allocator for the tree's big arrays. Large buffers come straight from mmap with transparent huge
// pages requested (MADV_HUGEPAGE: this kernel's THP mode is "madvise"), and the parser maps the
// next stretch ahead of its writes (prefault), so a 100 MB program costs a few hundred faults
// instead of sixty thousand: 20% of the parse time (bench/RESULTS.md). Reserved capacity that is
// never written costs address space, not memory.
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
            madvise(p, bytes, MADV_HUGEPAGE);   // fewer, larger faults; only a hint
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

template <typename T>
using LargeVector = std::vector<T, LargeAllocator<T>>;

}  // namespace kerf::ast
