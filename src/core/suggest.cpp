#include "bounce/core/suggest.hpp"

#include <algorithm>
#include <cctype>

namespace bounce {

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Three rows of the dynamic programme: d[i][j] is the distance of a[:i] and b[:j].
  const std::size_t n = b.size();
  std::vector<std::size_t> before(n + 1), previous(n + 1), current(n + 1);
  for (std::size_t j = 0; j <= n; ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= n; ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        current[j] = std::min(current[j], before[j - 2] + 1);  // a transposition
      }
    }
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return previous[n];
}

std::string closest_name(std::string_view typed, const std::vector<std::string>& names) {
  const std::string key = lower(typed);
  if (key.empty()) return {};
  const std::size_t allowed = std::max<std::size_t>(1, std::min<std::size_t>(3, key.size() / 4));
  const std::string* best = nullptr;
  std::size_t best_distance = allowed + 1;
  for (const std::string& name : names) {
    const std::size_t d = edit_distance(key, lower(name));
    if (d < best_distance) {
      best = &name;
      best_distance = d;
    }
  }
  if (best != nullptr) return *best == typed ? std::string() : *best;  // "Steel" -> steel
  if (key.size() < 3) return {};
  const std::string* only = nullptr;
  for (const std::string& name : names) {
    if (!lower(name).starts_with(key)) continue;
    if (only != nullptr) return {};  // two names begin so: no guess
    only = &name;
  }
  return only != nullptr ? *only : std::string();
}

std::string did_you_mean(std::string_view typed, const std::vector<std::string>& names) {
  const std::string name = closest_name(typed, names);
  return name.empty() ? std::string() : "; did you mean " + name + "?";
}

}  // namespace bounce
