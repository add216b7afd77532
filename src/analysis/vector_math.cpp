// The vector logarithms and exponentials of vector_math.hpp: glibc's libmvec on x86-64 (AVX2
// four at a time where the machine has it, SSE2 two at a time otherwise), std:: elsewhere.
#include "vector_math.hpp"

#include <cmath>

#if defined(BOUNCE_HAVE_MVEC) && defined(__x86_64__)  // the build found libmvec (src/CMakeLists.txt)
#include <immintrin.h>

// libmvec's entry points, named by the x86-64 vector function ABI (b: SSE2, d: AVX2; N2/N4 lanes).
extern "C" __m128d _ZGVbN2v_log(__m128d);
extern "C" __m128d _ZGVbN2v_exp(__m128d);
extern "C" [[gnu::target("avx2")]] __m256d _ZGVdN4v_log(__m256d);  // AVX2's calling convention
extern "C" [[gnu::target("avx2")]] __m256d _ZGVdN4v_exp(__m256d);

namespace bounce::analysis {
namespace {

bool machine_has_avx2() noexcept {
  static const bool avx2 = [] {
    __builtin_cpu_init();  // GCC's rule for code that may run before the library's constructors
    return __builtin_cpu_supports("avx2") != 0;
  }();
  return avx2;
}

[[gnu::target("avx2")]] std::size_t log_avx2(double* x, std::size_t n) noexcept {
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) _mm256_storeu_pd(x + i, _ZGVdN4v_log(_mm256_loadu_pd(x + i)));
  return i;
}
[[gnu::target("avx2")]] std::size_t exp_avx2(double* x, std::size_t n) noexcept {
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4) _mm256_storeu_pd(x + i, _ZGVdN4v_exp(_mm256_loadu_pd(x + i)));
  return i;
}
std::size_t log_sse2(double* x, std::size_t n) noexcept {
  std::size_t i = 0;
  for (; i + 2 <= n; i += 2) _mm_storeu_pd(x + i, _ZGVbN2v_log(_mm_loadu_pd(x + i)));
  return i;
}
std::size_t exp_sse2(double* x, std::size_t n) noexcept {
  std::size_t i = 0;
  for (; i + 2 <= n; i += 2) _mm_storeu_pd(x + i, _ZGVbN2v_exp(_mm_loadu_pd(x + i)));
  return i;
}

using Lanes = std::size_t (*)(double*, std::size_t) noexcept;

// The whole vectors by `four` lanes (AVX2) or `two` (SSE2), then the last few, padded with `pad`,
// through the same function, so that a value's result does not depend on where it stands.
void apply(double* x, std::size_t n, Lanes four, Lanes two, double pad) noexcept {
  const Lanes lanes = machine_has_avx2() ? four : two;
  const std::size_t i = lanes(x, n);
  if (i == n) return;
  double tail[4] = {pad, pad, pad, pad};
  for (std::size_t k = i; k < n; ++k) tail[k - i] = x[k];
  lanes(tail, 4);
  for (std::size_t k = i; k < n; ++k) x[k] = tail[k - i];
}

}  // namespace

void vector_log(double* x, std::size_t n) noexcept { apply(x, n, log_avx2, log_sse2, 1.0); }
void vector_exp(double* x, std::size_t n) noexcept { apply(x, n, exp_avx2, exp_sse2, 0.0); }

}  // namespace bounce::analysis

#else

namespace bounce::analysis {

void vector_log(double* x, std::size_t n) noexcept {
  for (std::size_t i = 0; i < n; ++i) x[i] = std::log(x[i]);
}
void vector_exp(double* x, std::size_t n) noexcept {
  for (std::size_t i = 0; i < n; ++i) x[i] = std::exp(x[i]);
}

}  // namespace bounce::analysis

#endif
