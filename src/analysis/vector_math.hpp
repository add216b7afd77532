#pragma once
// Logarithms and exponentials of arrays, several at a time by glibc's vector math library
// (libmvec) on x86-64, for the atlas's batched lookups: 4 logarithms cost what one does
// (docs/benchmarks.md). libmvec's results are within 4 ulp of std::log and std::exp (glibc's
// manual), not bit-equal to them, and they differ between the AVX2 and SSE2 paths in the last
// bit. Where the build found no libmvec, std::log and std::exp one at a time.
#include <cstddef>

namespace bounce::analysis {

/// x[i] = ln x[i], i < n.
void vector_log(double* x, std::size_t n) noexcept;
/// x[i] = exp x[i], i < n.
void vector_exp(double* x, std::size_t n) noexcept;

}  // namespace bounce::analysis
