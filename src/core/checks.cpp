#include "bounce/core/checks.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <regex>
#include <fmt/format.h>

#include "bounce/core/error.hpp"

namespace bounce {

std::string format_value(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[32];
  auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, end);
}

std::string message_kind(std::string_view message) {
  static const std::regex number(R"([-+]?[0-9]+(\.[0-9]*)?([eE][-+]?[0-9]+)?)");
  return std::regex_replace(std::string(message), number, "");
}

std::string one_of(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i) s += (i == 0 ? "" : ", ") + names[i];
  return s;
}

double require_finite(std::string_view parameter, double value) {
  if (!std::isfinite(value)) {
    throw InvalidArgument(std::string(parameter), format_value(value), "a finite number");
  }
  return value;
}

double require_positive(std::string_view parameter, double value, std::string_view what) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw InvalidArgument(std::string(parameter), format_value(value),
                          fmt::format("{} > 0 and finite", what));
  }
  return value;
}

double require_non_negative(std::string_view parameter, double value, std::string_view what) {
  if (!std::isfinite(value) || value < 0.0) {
    throw InvalidArgument(std::string(parameter), format_value(value),
                          fmt::format("{} >= 0 and finite", what));
  }
  return value;
}

double require_at_least(std::string_view parameter, double value, double lowest, std::string_view before,
                        std::string_view after) {
  if (!std::isfinite(value) || value < lowest) {
    throw InvalidArgument(std::string(parameter), format_value(value),
                          fmt::format("{}{}{}", before, format_value(lowest), after));
  }
  return value;
}

double require_open_interval(std::string_view parameter, double value, double lo, double hi,
                             std::string_view what) {
  if (!std::isfinite(value) || value <= lo || value >= hi) {
    throw InvalidArgument(std::string(parameter), format_value(value),
                          fmt::format("{} < {} < {}", format_value(lo), what, format_value(hi)));
  }
  return value;
}

std::string read_text_file(std::string_view parameter, const std::string& path, std::string_view what) {
  const std::string name(parameter), allowed(what);
  std::error_code ec;
  if (path.empty()) throw InvalidArgument(name, "\"\"", allowed);
  if (std::filesystem::is_directory(path, ec)) throw InvalidArgument(name, path, allowed + ", not a directory");
  std::ifstream file(path);
  std::ostringstream text;
  if (file) text << file.rdbuf();
  if (!file || file.bad()) throw InvalidArgument(name, path, allowed);
  return text.str();
}

}  // namespace bounce

namespace bounce {

std::string json_error_words(int id, std::string_view what) {
  if (id >= 100 && id < 200) {  // parse errors: "... at line 1, column 2: ..."
    const auto at = what.find("line ");
    const auto end = at == std::string_view::npos ? at : what.find(':', at);
    if (at != std::string_view::npos && end != std::string_view::npos) {
      return fmt::format("not JSON (a syntax error at {})", what.substr(at, end - at));
    }
    return "not JSON (a syntax error)";
  }
  if (id == 406) return "not JSON (a number beyond double precision)";
  return "a field missing or of the wrong type";
}

}  // namespace bounce
