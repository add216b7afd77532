#pragma once
// Forced into every file of the wasm build (explorer/CMakeLists.txt) where emscripten's libc++
// lacks std::from_chars / std::to_chars for double or std::bit_cast (3.1.6 on Debian 12 has none
// of them; the build probes for each): the overloads bounce calls, with the standard's results,
// on musl's correctly rounded strtod and snprintf. Native builds (libstdc++) never see this file.
#include <charconv>
#include <type_traits>

namespace std {
#ifdef BOUNCE_COMPAT_FROM_CHARS
/// [charconv.from.chars] for chars_format::general: no leading space or '+', "inf"/"nan" words,
/// result_out_of_range where the value is outside double's range (nothing stored then).
from_chars_result from_chars(const char* first, const char* last, double& value, chars_format = chars_format::general);
#endif
#ifdef BOUNCE_COMPAT_TO_CHARS
/// [charconv.to.chars] without a format: the shortest text that reads back as `value`, fixed or
/// scientific, whichever is shorter (fixed on a tie).
to_chars_result to_chars(char* first, char* last, double value);
#endif
#ifdef BOUNCE_COMPAT_BIT_CAST
/// [bit.cast], on the compiler's builtin.
template <class To, class From>
  requires(sizeof(To) == sizeof(From) && is_trivially_copyable_v<To> && is_trivially_copyable_v<From>)
constexpr To bit_cast(const From& from) noexcept {
  return __builtin_bit_cast(To, from);
}
#endif
}  // namespace std
