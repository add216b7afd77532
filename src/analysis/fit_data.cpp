// The measured restitution curve of one experiment (docs/fitting.md): reading its CSV and the
// residuals K13 (31) sums.
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "bounce/analysis/fit.hpp"
#include "bounce/core/checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/core/parameters.hpp"
#include "csv_format.hpp"

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

using detail::lower;
using detail::trim;

std::string delimiter_name(char delimiter) {
  return delimiter == '\t' ? "tab" : delimiter == ';' ? "semicolon" : "comma";
}

std::string shown(std::string_view value) { return value.empty() ? "\"\"" : std::string(value); }

// The file's name of each of our columns: ours unless --columns maps it.
std::string file_name(const ColumnNames& names, std::string_view column) {
  const auto it = names.find(std::string(column));
  return it == names.end() ? std::string(column) : detail::read_header_name(it->second).name;
}

class Reader {
 public:
  Reader(std::string_view source, const ColumnNames& names) : source_(source), names_(names) {}

  [[noreturn]] void refuse(std::size_t line, std::string_view field, std::string_view value,
                           const std::string& allowed) const {
    const std::string where = field.empty() ? fmt::format("{}:{}", source_, line)
                                            : fmt::format("{}:{}: {}", source_, line, field);
    throw InvalidArgument(where, shown(value), allowed);
  }

  void header(std::size_t line, std::string_view text) {
    delimiter_ = detail::sniff_delimiter(text);
    const auto cells = fields(line, text);
    index_.fill(-1);
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const detail::HeaderName h = detail::read_header_name(cells[i]);
      const std::size_t column = column_of(line, cells[i], h.name);
      int& slot = index_[column];
      if (slot >= 0) refuse(line, "header", cells[i], "each column once");
      slot = static_cast<int>(i);
      const auto factor = detail::unit_factor(columns[column], h.unit);
      if (!factor) {
        refuse(line, "header", cells[i],
               column == 0 ? "a speed in m/s, cm/s or mm/s (velocity [m/s]; no unit: m/s)"
                           : "no unit (a ratio: [-], [1] or none)");
      }
      if (column == 0) velocity_factor_ = *factor;
    }
    if (index_[0] < 0 || index_[1] < 0) {
      refuse(line, "header", text,
             fmt::format("a header line naming at least the columns {} and {}", file_name(names_, "velocity"),
                         file_name(names_, "cor")));
    }
    width_ = cells.size();
  }

  Measurement row(std::size_t line, std::string_view text) const {
    const auto fields = this->fields(line, text);
    if (fields.size() != width_) {
      refuse(line, "", text, fmt::format("{} {}-separated fields, as in the header", width_, delimiter_name(delimiter_)));
    }
    auto field = [&](std::size_t column) -> const std::string& { return fields[static_cast<std::size_t>(index_[column])]; };
    auto number = [&](std::size_t column) {
      const std::string& v = field(column);
      try {
        return parse_real(columns[column], detail::decimal_point(v, delimiter_));
      } catch (const InvalidArgument&) {
        refuse(line, columns[column], v, "a number");
      }
    };
    Measurement m;
    m.line = line;
    m.velocity = number(0) * velocity_factor_;
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
      const std::string outcome = lower(field(3));
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
  std::vector<std::string> fields(std::size_t line, std::string_view text) const {
    auto cells = detail::split_fields(text, delimiter_);
    if (!cells) refuse(line, "", text, "a closing double quote for each opening one");
    return std::move(*cells);
  }

  // Which of our columns a header cell names (`name`: in lower case, without its unit).
  std::size_t column_of(std::size_t line, std::string_view cell, std::string_view name) const {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (name == file_name(names_, columns[c])) return c;
    }
    if (!names_.empty()) {
      refuse(line, "header", cell,
             fmt::format("columns named {}, {} and optionally {}, {} (with --columns)", file_name(names_, "velocity"),
                         file_name(names_, "cor"), file_name(names_, "cor_error"), file_name(names_, "outcome")));
    }
    refuse(line, "header", cell,
           "columns named velocity, cor and optionally cor_error, outcome (any case, a unit in brackets as in "
           "velocity [m/s]; --columns velocity=NAME,cor=NAME maps other names)");
  }

  std::string_view source_;
  ColumnNames names_;
  char delimiter_ = ',';
  double velocity_factor_ = 1.0;
  std::array<int, columns.size()> index_{};
  std::size_t width_ = 0;
};

}  // namespace

bool Experiment::has_errors() const {
  return !points.empty() &&
         std::all_of(points.begin(), points.end(), [](const Measurement& m) { return m.cor_error.has_value(); });
}

ColumnNames parse_column_names(std::string_view text) {
  const std::string allowed =
      "OURS=NAME pairs separated by commas, OURS one of velocity, cor, cor_error, outcome (each once), NAME the "
      "file's header name";
  ColumnNames names;
  const auto pairs = detail::split_fields(text, ',');
  if (!pairs) throw InvalidArgument("columns", shown(text), allowed);
  for (const std::string& pair : *pairs) {
    const auto eq = pair.find('=');
    if (eq == std::string::npos) throw InvalidArgument("columns", shown(text), allowed);
    const std::string ours = lower(trim(std::string_view(pair).substr(0, eq)));
    const std::string theirs(trim(std::string_view(pair).substr(eq + 1)));
    const bool known = std::find(columns.begin(), columns.end(), ours) != columns.end();
    if (!known || theirs.empty() || !names.emplace(ours, theirs).second) {
      throw InvalidArgument("columns", shown(text), allowed);
    }
  }
  return names;
}

Experiment parse_experiment(std::string_view text, std::string_view source, const ColumnNames& names) {
  Experiment e;
  e.source = std::string(source);
  text = detail::strip_byte_order_mark(text, source);
  Reader reader(source, names);
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
