// The measured restitution curve of one experiment (docs/fitting.md): reading its CSV and the
// residuals K13 (31) sums.
#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "bounce/analysis/fit.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/core/parameters.hpp"

namespace bounce::analysis {

namespace {

// e > 1 would be a collision that creates energy: no model here can reach it, and K13's
// chi^2 would weigh it against e <= 1 alone. Scatter above 1 is the experimenter's to clip
// or drop (docs/fitting.md).
constexpr double max_cor = 1.0;
// An error bar of the COR above 1.5 is not a measurement (a column mix-up, a percentage).
constexpr double max_cor_error = 1.5;
constexpr double min_cor_error = 1e-6;
// A million measurements is beyond any experiment; more is a wrong file.
constexpr std::size_t max_points = 1'000'000;

constexpr std::array<const char*, 4> columns = {"velocity", "cor", "cor_error", "outcome"};

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    out.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

std::string shown(std::string_view value) { return value.empty() ? "\"\"" : std::string(value); }

class Reader {
 public:
  explicit Reader(std::string_view source) : source_(source) {}

  [[noreturn]] void refuse(std::size_t line, std::string_view field, std::string_view value,
                           const std::string& allowed) const {
    const std::string where = field.empty() ? fmt::format("{}:{}", source_, line)
                                            : fmt::format("{}:{}: {}", source_, line, field);
    throw InvalidArgument(where, shown(value), allowed);
  }

  void header(std::size_t line, std::string_view text) {
    const auto names = split_fields(text);
    index_.fill(-1);
    for (std::size_t i = 0; i < names.size(); ++i) {
      const auto it = std::find(columns.begin(), columns.end(), names[i]);
      if (it == columns.end()) {
        refuse(line, "header", names[i], "columns named velocity, cor and optionally cor_error, outcome");
      }
      int& slot = index_[static_cast<std::size_t>(it - columns.begin())];
      if (slot >= 0) refuse(line, "header", names[i], "each column once");
      slot = static_cast<int>(i);
    }
    if (index_[0] < 0 || index_[1] < 0) {
      refuse(line, "header", text, "a header line naming at least the columns velocity and cor");
    }
    width_ = names.size();
  }

  Measurement row(std::size_t line, std::string_view text) const {
    const auto fields = split_fields(text);
    if (fields.size() != width_) {
      refuse(line, "", text, fmt::format("{} comma-separated fields, as in the header", width_));
    }
    auto field = [&](std::size_t column) { return fields[static_cast<std::size_t>(index_[column])]; };
    auto number = [&](std::size_t column) {
      const std::string_view v = field(column);
      try {
        return parse_real(columns[column], v);
      } catch (const InvalidArgument&) {
        refuse(line, columns[column], v, "a number");
      }
    };
    Measurement m;
    m.line = line;
    m.velocity = number(0);
    if (!(m.velocity > 0.0) || !std::isfinite(m.velocity)) {
      refuse(line, "velocity", field(0), "an impact speed > 0 m/s and finite");
    }
    m.cor = number(1);
    if (!(m.cor >= 0.0 && m.cor <= max_cor)) {
      refuse(line, "cor", field(1), fmt::format("a coefficient of restitution 0 <= cor <= {}", max_cor));
    }
    m.stuck = m.cor == 0.0;
    if (index_[2] >= 0) {
      m.cor_error = number(2);
      // Below 1e-6 no COR is measured; the bound keeps ((e - e_m) / sigma)^2 summed over
      // 1e6 rows below 1e19 (an error of 1e-300 made the proper chi^2 infinite).
      if (!(*m.cor_error >= min_cor_error && *m.cor_error <= max_cor_error)) {
        refuse(line, "cor_error", field(2),
               fmt::format("an error of the COR {} <= cor_error <= {} (the column is optional)", min_cor_error,
                           max_cor_error));
      }
    }
    if (index_[3] >= 0) {
      const std::string_view outcome = field(3);
      if (outcome == "stick") {
        if (m.cor != 0.0) refuse(line, "outcome", outcome, "stick only with cor = 0 (the grains did not separate)");
        m.stuck = true;
      } else if (outcome == "bounce") {
        if (m.cor == 0.0) refuse(line, "outcome", outcome, "bounce only with cor > 0 (cor = 0 is a sticking collision)");
      } else if (!outcome.empty()) {
        refuse(line, "outcome", outcome, "bounce or stick (or empty: from cor)");
      }
    }
    return m;
  }

 private:
  std::string_view source_;
  std::array<int, columns.size()> index_{};
  std::size_t width_ = 0;
};

}  // namespace

bool Experiment::has_errors() const {
  return !points.empty() &&
         std::all_of(points.begin(), points.end(), [](const Measurement& m) { return m.cor_error.has_value(); });
}

Experiment parse_experiment(std::string_view text, std::string_view source) {
  Experiment e;
  e.source = std::string(source);
  Reader reader(source);
  bool header = false;
  std::size_t line = 0, start = 0;
  while (start <= text.size()) {
    const auto end = text.find('\n', start);
    std::string_view raw = text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start);
    ++line;
    start = end == std::string_view::npos ? text.size() + 1 : end + 1;
    if (const auto hash = raw.find('#'); hash != std::string_view::npos) raw = raw.substr(0, hash);
    const std::string_view content = trim(raw);
    if (content.empty()) continue;
    if (!header) {
      reader.header(line, content);
      header = true;
      continue;
    }
    if (e.points.size() == max_points) reader.refuse(line, "", content, fmt::format("at most {} measurements", max_points));
    e.points.push_back(reader.row(line, content));
  }
  if (!header) throw InvalidArgument("data", e.source, "a CSV with a header line naming velocity and cor (none found)");
  if (e.points.empty()) throw InvalidArgument("data", e.source, "at least one measurement below the header (none found)");
  return e;
}

double mean_squared_residual(const Experiment& data, std::span<const double> cor) {  // K13 (31)
  double sum = 0.0;
  for (std::size_t i = 0; i < data.points.size(); ++i) {
    const double r = data.points[i].cor - cor[i];
    sum += r * r;
  }
  return sum / static_cast<double>(data.points.size());
}

double weighted_chi2(const Experiment& data, std::span<const double> cor) {
  double sum = 0.0;
  for (std::size_t i = 0; i < data.points.size(); ++i) {
    const double r = (data.points[i].cor - cor[i]) / *data.points[i].cor_error;
    sum += r * r;
  }
  return sum;
}

}  // namespace bounce::analysis
