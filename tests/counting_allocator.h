#pragma once
// Replaces global operator new/delete (every form) with counting versions. Include it in
// exactly one source file of a test binary: the replacement is for the whole binary. Read the
// count with ftest::gAllocations.

#include <atomic>
#include <cstdlib>
#include <new>

namespace ftest {
/// Heap allocations made so far by this binary (every operator new, and whatever calls
/// countAllocation).
inline std::atomic<long> gAllocations{0};
/// Counts one allocation made outside operator new (e.g. a library's own allocator hook).
inline void countAllocation() { gAllocations.fetch_add(1, std::memory_order_relaxed); }
}  // namespace ftest

namespace {
using ftest::gAllocations;

void* countedAllocate(std::size_t size) {
    gAllocations.fetch_add(1, std::memory_order_relaxed);
    if (size == 0) size = 1;
    return std::malloc(size);
}

void* countedAllocateAligned(std::size_t size, std::align_val_t alignment) {
    gAllocations.fetch_add(1, std::memory_order_relaxed);
    const auto align = static_cast<std::size_t>(alignment);
    std::size_t rounded = (size + align - 1) / align * align;
    if (rounded == 0) rounded = align;
    return std::aligned_alloc(align, rounded);
}

// Out of line so that GCC's -Wmismatched-new-delete does not pair it with the operators.
[[gnu::noinline]] void countedRelease(void* p) noexcept { std::free(p); }
}  // namespace

void* operator new(std::size_t size) {
    if (void* p = countedAllocate(size)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
    if (void* p = countedAllocate(size)) return p;
    throw std::bad_alloc();
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return countedAllocate(size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return countedAllocate(size); }
void* operator new(std::size_t size, std::align_val_t alignment) {
    if (void* p = countedAllocateAligned(size, alignment)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
    if (void* p = countedAllocateAligned(size, alignment)) return p;
    throw std::bad_alloc();
}
void* operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
    return countedAllocateAligned(size, alignment);
}
void* operator new[](std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
    return countedAllocateAligned(size, alignment);
}
void operator delete(void* p) noexcept { countedRelease(p); }
void operator delete[](void* p) noexcept { countedRelease(p); }
void operator delete(void* p, std::size_t) noexcept { countedRelease(p); }
void operator delete[](void* p, std::size_t) noexcept { countedRelease(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { countedRelease(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { countedRelease(p); }
void operator delete(void* p, std::align_val_t) noexcept { countedRelease(p); }
void operator delete[](void* p, std::align_val_t) noexcept { countedRelease(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { countedRelease(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { countedRelease(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { countedRelease(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { countedRelease(p); }
