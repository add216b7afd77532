// An aggregate's structure (docs/aggregates.md): touching pairs through a cell grid, the fractal
// dimension fitted over the growth history, the filling factor; and its LAMMPS data file.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include "bounce/aggregate/aggregate.hpp"
#include "bounce/core/error.hpp"
#include "geometry.hpp"

namespace bounce::aggregate {

using namespace detail;  // Vector arithmetic (this file's)

namespace {

// A cell of a cubic grid as one integer: 21 bits per axis, cells within +-2^20 of the origin.
std::uint64_t cell_key(std::int64_t x, std::int64_t y, std::int64_t z) {
  constexpr std::int64_t offset = std::int64_t{1} << 20;
  return (static_cast<std::uint64_t>(x + offset) << 42) | (static_cast<std::uint64_t>(y + offset) << 21) |
         static_cast<std::uint64_t>(z + offset);
}

}  // namespace

std::size_t count_contacts(const std::vector<Vector>& centres, double radius, double tolerance, double* min_distance) {
  const double reach = 2.0 * radius * (1.0 + tolerance);  // cells of the reach: a pair lies in neighbouring cells
  const auto index = [reach](double x) { return static_cast<std::int64_t>(std::floor(x / reach)); };
  std::vector<std::pair<std::uint64_t, std::size_t>> cells;
  cells.reserve(centres.size());
  for (std::size_t i = 0; i < centres.size(); ++i) {
    cells.emplace_back(cell_key(index(centres[i][0]), index(centres[i][1]), index(centres[i][2])), i);
  }
  std::sort(cells.begin(), cells.end());
  std::size_t contacts = 0;
  double closest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < centres.size(); ++i) {
    const Vector& x = centres[i];
    for (int d = 0; d < 27; ++d) {
      const std::uint64_t k = cell_key(index(x[0]) + d / 9 - 1, index(x[1]) + d / 3 % 3 - 1, index(x[2]) + d % 3 - 1);
      auto it = std::lower_bound(cells.begin(), cells.end(), std::pair<std::uint64_t, std::size_t>{k, 0});
      for (; it != cells.end() && it->first == k; ++it) {
        if (it->second <= i) continue;  // each pair once
        const Vector w = centres[it->second] - x;
        const double distance = std::sqrt(dot(w, w));
        closest = std::min(closest, distance);
        if (distance <= reach) ++contacts;
      }
    }
  }
  if (min_distance != nullptr) *min_distance = closest;
  return contacts;
}

FractalFit fit_fractal_dimension(const std::vector<GrowthPoint>& history, double radius, std::size_t n_min,
                                 std::size_t n_max) {
  // Least squares of y = log R_g on x = log n, points at least 1/20 decade apart.
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, last = -1.0;
  std::size_t m = 0;
  for (const GrowthPoint& p : history) {
    if (p.n < n_min || p.n > n_max || !(p.radius_of_gyration > 0.0)) continue;
    const double x = std::log(static_cast<double>(p.n)), y = std::log(p.radius_of_gyration);
    if (m > 0 && x - last < std::log(10.0) / 20.0) continue;
    last = x;
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++m;
  }
  if (m < 2) {
    throw InvalidArgument("fit range", fmt::format("{}:{}", n_min, n_max),
                          "a range of n holding two or more growth points");
  }
  const double k = static_cast<double>(m);
  const double slope = (k * sxy - sx * sy) / (k * sxx - sx * sx);  // 1/D
  const double intercept = (sy - slope * sx) / k;                  // log R_g at n = 1
  FractalFit f;
  f.dimension = 1.0 / slope;
  f.prefactor = std::exp(f.dimension * (std::log(radius) - intercept));  // n = k_f (R_g / r)^D
  f.n_min = n_min, f.n_max = n_max, f.points = m;
  return f;
}

namespace {

FractalFit fit_default_range(const BuildRequest& r, const std::vector<GrowthPoint>& history) {
  const std::size_t n = r.n;
  const std::size_t n_min = r.kind == Kind::bpca ? std::min(std::max<std::size_t>(n / 10, 100), n / 2) : 16;
  return fit_fractal_dimension(history, r.radius, n_min, n);
}

}  // namespace

std::size_t min_fit_monomers(Kind kind) { return kind == Kind::bpca ? 20 : 32; }

FractalFit default_fit(const Aggregate& a) { return fit_default_range(a.request, a.history); }

FractalFit ensemble_fit(const BuildRequest& request, std::size_t samples, const Progress& progress) {
  if (samples < 1) throw InvalidArgument("ensemble", std::to_string(samples), "a number of aggregates >= 1");
  std::vector<GrowthPoint> mean;
  for (std::size_t k = 0; k < samples; ++k) {
    BuildRequest r = request;
    r.seed = request.seed + k;
    const Aggregate a = build(r);
    if (k == 0) mean.assign(a.history.size(), GrowthPoint{});
    for (std::size_t i = 0; i < a.history.size(); ++i) {  // the same n at each i in every sample
      mean[i].n = a.history[i].n;
      if (a.history[i].radius_of_gyration > 0.0) mean[i].radius_of_gyration += std::log(a.history[i].radius_of_gyration);
    }
    if (progress) progress(k + 1, samples);
  }
  for (GrowthPoint& p : mean) {
    p.radius_of_gyration = p.n > 1 ? std::exp(p.radius_of_gyration / static_cast<double>(samples)) : 0.0;
  }
  return fit_default_range(request, mean);
}

Structure structure(const Aggregate& a) {
  Structure s;
  const double n = static_cast<double>(a.centres.size()), r = a.request.radius;
  s.radius_of_gyration = radius_of_gyration(a.centres);
  s.contacts = count_contacts(a.centres, r, contact_tolerance, &s.min_distance);
  s.coordination = 2.0 * static_cast<double>(s.contacts) / n;
  const double characteristic = std::sqrt(5.0 / 3.0) * s.radius_of_gyration;  // Mukai et al. (1992)
  s.filling_factor = characteristic > 0.0 ? n * std::pow(r / characteristic, 3) : 1.0;  // one monomer fills itself
  if (a.centres.size() == 1) s.min_distance = 0.0;  // no pair (the record prints null)
  if (a.centres.size() >= min_fit_monomers(a.request.kind)) s.fit = default_fit(a);
  return s;
}

std::string lammps_data(const Aggregate& a, double density, double margin, const std::string& title) {
  const double r = a.request.radius;
  Vector lo{0, 0, 0}, hi{0, 0, 0};
  for (const Vector& x : a.centres) {
    for (int d = 0; d < 3; ++d) lo[d] = std::min(lo[d], x[d]), hi[d] = std::max(hi[d], x[d]);
  }
  std::string out = fmt::format("{}\n\n{} atoms\n1 atom types\n\n", title, a.centres.size());
  for (int d = 0; d < 3; ++d) {
    const char axis = static_cast<char>('x' + d);
    out += fmt::format("{} {} {}lo {}hi\n", lo[d] - r - margin, hi[d] + r + margin, axis, axis);
  }
  // atom_style sphere: id type diameter density x y z, each number in its shortest round-trip form
  out += "\nAtoms # sphere\n\n";
  for (std::size_t i = 0; i < a.centres.size(); ++i) {
    const Vector& x = a.centres[i];
    out += fmt::format("{} 1 {} {} {} {} {}\n", i + 1, 2.0 * r, density, x[0], x[1], x[2]);
  }
  return out;
}

}  // namespace bounce::aggregate
