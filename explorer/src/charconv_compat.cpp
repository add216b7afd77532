// std::from_chars / std::to_chars for double where emscripten's libc++ lacks them
// (charconv_compat.hpp says when and why).
#include "charconv_compat.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <strings.h>

namespace {

const char* skip_digits(const char* p, const char* last) {
  while (p != last && std::isdigit(static_cast<unsigned char>(*p))) ++p;
  return p;
}

// The end of the longest "[-]digits[.digits][e[+-]digits]" at `first` (first when none).
const char* decimal_end(const char* first, const char* last) {
  const char* p = first != last && *first == '-' ? first + 1 : first;
  const char* integer = p;
  p = skip_digits(p, last);
  bool digits = p != integer;
  if (p != last && *p == '.') {
    const char* fraction = p + 1;
    const char* end = skip_digits(fraction, last);
    digits = digits || end != fraction;
    p = end;
  }
  if (!digits) return first;
  if (p != last && (*p == 'e' || *p == 'E')) {
    const char* e = p + 1;
    if (e != last && (*e == '+' || *e == '-')) ++e;
    const char* end = skip_digits(e, last);
    if (end != e) p = end;
  }
  return p;
}

// "inf", "infinity" or "nan" (any case) at `first`, after an optional '-': its end, or first.
const char* word_end(const char* first, const char* last) {
  const char* p = first != last && *first == '-' ? first + 1 : first;
  const auto n = static_cast<std::size_t>(last - p);
  if (n >= 8 && strncasecmp(p, "infinity", 8) == 0) return p + 8;
  if (n >= 3 && (strncasecmp(p, "inf", 3) == 0 || strncasecmp(p, "nan", 3) == 0)) return p + 3;
  return first;
}

// The shortest "%.*e" text of `value` that strtod reads back exactly.
std::string shortest_scientific(double value) {
  char buffer[40];
  for (int precision = 0; precision < 17; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*e", precision, value);
    if (std::strtod(buffer, nullptr) == value) return buffer;
  }
  std::snprintf(buffer, sizeof buffer, "%.16e", value);
  return buffer;
}

// The same digits in fixed notation ("1.25e-03" -> "0.00125", "1.5e+02" -> "150").
std::string as_fixed(const std::string& scientific) {
  const std::size_t e = scientific.find('e');
  const int exponent = std::atoi(scientific.c_str() + e + 1);
  const bool negative = scientific[0] == '-';
  std::string digits;
  for (std::size_t i = negative ? 1 : 0; i < e; ++i) {
    if (scientific[i] != '.') digits += scientific[i];
  }
  const int point = exponent + 1;  // digits before the decimal point
  std::string out;
  if (point <= 0) {
    out = "0." + std::string(static_cast<std::size_t>(-point), '0') + digits;
  } else if (static_cast<std::size_t>(point) >= digits.size()) {
    out = digits + std::string(static_cast<std::size_t>(point) - digits.size(), '0');
  } else {
    out = digits.substr(0, static_cast<std::size_t>(point)) + "." + digits.substr(static_cast<std::size_t>(point));
  }
  return negative ? "-" + out : out;
}

}  // namespace

namespace std {

#ifdef BOUNCE_COMPAT_FROM_CHARS
from_chars_result from_chars(const char* first, const char* last, double& value, chars_format) {
  const char* end = decimal_end(first, last);
  if (end == first) end = word_end(first, last);
  if (end == first) return {first, errc::invalid_argument};
  const std::string text(first, end);
  errno = 0;
  const double parsed = std::strtod(text.c_str(), nullptr);
  if (errno == ERANGE) return {end, errc::result_out_of_range};
  value = parsed;
  return {end, errc()};
}
#endif

#ifdef BOUNCE_COMPAT_TO_CHARS
to_chars_result to_chars(char* first, char* last, double value) {
  std::string text;
  if (std::isnan(value)) {
    text = std::signbit(value) ? "-nan" : "nan";
  } else if (std::isinf(value)) {
    text = value < 0 ? "-inf" : "inf";
  } else {
    const std::string scientific = shortest_scientific(value);
    const std::string fixed = as_fixed(scientific);
    text = fixed.size() <= scientific.size() ? fixed : scientific;
  }
  if (static_cast<std::size_t>(last - first) < text.size()) return {last, errc::value_too_large};
  std::memcpy(first, text.data(), text.size());
  return {first + text.size(), errc()};
}
#endif

}  // namespace std
