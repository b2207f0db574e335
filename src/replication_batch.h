#pragma once
// Internal: the instruction sets DeadReckoningBatch::extrapolate is compiled for, and a way
// for the tests to run each of them.

#include <foresight/replication.h>

#include <cstdint>
#include <span>

// AVX2 passes beside the baseline ones: x86 with GCC or clang (their target pragmas).
#if (defined(__x86_64__) || defined(__i386__)) && (defined(__GNUC__) || defined(__clang__))
#define FORESIGHT_BATCH_AVX2 1
#else
#define FORESIGHT_BATCH_AVX2 0
#endif

FORESIGHT_NAMESPACE_BEGIN
namespace detail {

/// The instruction sets of DeadReckoningBatch's passes. Each gives the same bytes (the same
/// source and IEEE operations, no contraction).
enum class BatchSimd : std::uint8_t {
    Baseline,  ///< every processor of the target
    Avx2,      ///< x86 processors with AVX2, with GCC or clang
};

/// DeadReckoningBatch's frame, with a chosen instruction set.
struct BatchAccess {
    /// True when this build has `simd`'s passes and this processor runs them.
    static bool available(BatchSimd simd);
    /// The widest available: what DeadReckoningBatch::extrapolate uses.
    static BatchSimd best();
    /// DeadReckoningBatch::extrapolate with `simd`'s passes (the baseline's when `simd` is not
    /// available).
    static std::size_t extrapolate(const DeadReckoningBatch& batch, BatchSimd simd, double time,
                                   float extrapolationLimit, std::span<DeadReckoningResult> out);
};

}  // namespace detail
FORESIGHT_NAMESPACE_END
