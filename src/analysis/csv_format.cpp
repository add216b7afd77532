#include "csv_format.hpp"

#include <algorithm>
#include <cctype>

#include "bounce/core/error.hpp"

namespace bounce::analysis::detail {

namespace {

bool starts_with_bytes(std::string_view text, std::string_view bytes) { return text.substr(0, bytes.size()) == bytes; }

}  // namespace

std::string_view strip_byte_order_mark(std::string_view text, std::string_view source) {
  using namespace std::string_view_literals;
  if (starts_with_bytes(text, "\xEF\xBB\xBF"sv)) return text.substr(3);
  if (starts_with_bytes(text, "\xFF\xFE"sv) || starts_with_bytes(text, "\xFE\xFF"sv) ||
      starts_with_bytes(text, "\x00\x00\xFE\xFF"sv)) {
    throw InvalidArgument("data", std::string(source),
                          "a text file in UTF-8 or ASCII (this one is UTF-16 or UTF-32: save it as \"CSV UTF-8\")");
  }
  return text;
}

char sniff_delimiter(std::string_view header) {
  bool quoted = false, semicolon = false;
  for (char c : header) {
    if (c == '"') quoted = !quoted;
    if (quoted) continue;
    if (c == '\t') return '\t';
    semicolon = semicolon || c == ';';
  }
  return semicolon ? ';' : ',';
}

std::optional<std::vector<std::string>> split_fields(std::string_view line, char delimiter) {
  std::vector<std::string> out;
  std::string field;
  bool quoted = false, was_quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c != '"') {
        field += c;
      } else if (i + 1 < line.size() && line[i + 1] == '"') {
        field += '"';
        ++i;
      } else {
        quoted = false;
      }
    } else if (c == '"' && trim(field).empty()) {
      quoted = was_quoted = true;
      field.clear();
    } else if (c == delimiter) {
      out.emplace_back(was_quoted ? field : std::string(trim(field)));
      field.clear();
      was_quoted = false;
    } else if (!(was_quoted && (c == ' ' || c == '\t' || c == '\r'))) {
      field += c;  // a character after a closing quote other than spaces stays in the field
    }
  }
  if (quoted) return std::nullopt;
  out.emplace_back(was_quoted ? field : std::string(trim(field)));
  return out;
}

HeaderName read_header_name(std::string_view cell) {
  std::string_view s = trim(cell);
  HeaderName h;
  const char close = s.empty() ? '\0' : s.back();
  const char open = close == ']' ? '[' : close == ')' ? '(' : '\0';
  if (const auto at = open ? s.rfind(open) : std::string_view::npos; at != std::string_view::npos) {
    h.unit = std::string(trim(s.substr(at + 1, s.size() - at - 2)));
    s = trim(s.substr(0, at));
  }
  h.name = lower(s);
  return h;
}

std::string decimal_point(std::string_view field, char delimiter) {
  std::string out(field);
  if (delimiter != ',' && std::count(out.begin(), out.end(), ',') == 1 && out.find('.') == std::string::npos) {
    std::replace(out.begin(), out.end(), ',', '.');
  }
  return out;
}

std::optional<double> unit_factor(std::string_view column, std::string_view unit) {
  std::string u;
  for (char c : lower(unit)) {
    if (c != ' ' && c != '*' && c != '^') u += c;  // "m s^-1", "m*s^-1" -> "ms-1"
  }
  if (u.empty()) return 1.0;  // SI: m/s, or no unit
  if (column != "velocity") return u == "-" || u == "1" ? std::optional(1.0) : std::nullopt;
  for (const auto& [prefix, factor] : {std::pair{"", 1.0}, std::pair{"c", 1e-2}, std::pair{"m", 1e-3}}) {
    const std::string m = std::string(prefix) + "m";
    if (u == m + "/s" || u == m + "s-1") return factor;
  }
  return std::nullopt;
}

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

}  // namespace bounce::analysis::detail
