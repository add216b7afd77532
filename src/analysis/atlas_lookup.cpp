// The atlas's lookups (docs/atlas.md): tensor cubic Lagrange interpolation on the uniform
// (ln R_eff, ln rho_eff, ln(v - v_s)) grid, with the stencils chosen once per cell.
#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "bounce/analysis/atlas.hpp"
#include "bounce/core/error.hpp"
#include "vector_math.hpp"

namespace bounce::analysis {

namespace {

// Cubic Lagrange weights on the nodes 0, 1, 2, 3 at s (s in [0, 3]).
void lagrange4(double s, double w[4]) noexcept {
  const double a = s, b = s - 1.0, c = s - 2.0, d = s - 3.0, sixth = 1.0 / 6.0;  // a product, not a division
  w[0] = -b * c * d * sixth;
  w[1] = a * c * d * 0.5;
  w[2] = -a * b * d * 0.5;
  w[3] = a * b * c * sixth;
}

// The cell of a coordinate u on an axis of n >= 4 nodes (u clamped into [0, n - 1]).
std::size_t cell_of(double u, std::size_t n) noexcept {
  const auto i = static_cast<std::size_t>(u > 0.0 ? u : 0.0);  // a select, not a branch (NaN: 0)
  return std::min(i, n - 2);
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__GLIBC__)  // ifunc
#define BOUNCE_BATCH_CLONES [[gnu::target_clones("arch=x86-64-v3", "default")]]
#else
#define BOUNCE_BATCH_CLONES
#endif

// R_eff = R1 R2 / (R1 + R2) and rho_eff = 3 m_eff / (4 pi R_eff^3) = rho1 rho2 / (rho1 p^3 + rho2 q^3),
// p = R1 / (R1 + R2), q = R2 / (R1 + R2), with two divisions, symmetric and without overflow for finite
// radii (1e300 m is a wall); a wall (R2 = inf) gives R1 and rho1.
struct Reduced {
  double r, rho;
};
[[gnu::always_inline]] inline Reduced reduce(double density1, double density2, double radius1, double radius2) noexcept {
  const double inverse = 1.0 / (radius1 + radius2), p = radius1 * inverse, q = radius2 * inverse;
  const bool wall = std::isinf(radius2);
  // The same bits with the bodies swapped, also where a multiply-add is fused (min and max order
  // the terms): the smaller radius times the larger one's share, the smaller cube plus the larger.
  const double r = std::min(radius1, radius2) * (std::max(radius1, radius2) * inverse);
  const double cube1 = density1 * p * p * p, cube2 = density2 * q * q * q;
  return {wall ? radius1 : r, wall ? density1 : density1 * density2 / (std::min(cube1, cube2) + std::max(cube1, cube2))};
}

double relative_slack(double x) { return 1e-12 * std::abs(x); }

}  // namespace

double effective_density(double density1, double density2, double radius1, double radius2) {
  return reduce(density1, density2, radius1, radius2).rho;
}

struct Atlas::Stencil {
  std::size_t bx = 0, by = 0;
  double wx[4] = {}, wy[4] = {};
};

double Atlas::node_v_stick(std::size_t ix, std::size_t iy) const {
  const double w = stick_ratio[ix * y.count + iy];
  if (!can_stick) return 0.0;
  return w > 0.0 ? reference_velocity(x.value(ix), y.value(iy)) / w : std::numeric_limits<double>::infinity();
}

void Atlas::prepare(const std::string& source) {
  const auto bad = [&](const std::string& what) {
    throw InvalidArgument("atlas", source, "an atlas written by bounce atlas build: " + what);
  };
  if (x.count < 4 || y.count < 4 || z.count < 4) bad("every axis has at least 4 nodes");
  for (const AtlasAxis* a : {&x, &y, &z}) {
    if (!std::isfinite(a->start) || !(a->step > 0.0) || !std::isfinite(a->end())) bad("finite axes with steps > 0");
  }
  if (!y.nodes.empty() || !z.nodes.empty()) bad("uniform y and z axes");
  prepare_x(bad);
  const std::size_t nxy = x.count * y.count;
  if (stick_ratio.size() != nxy || defined.size() != nxy) bad("one sticking velocity per (R_eff, rho_eff) node");
  if (!std::isfinite(ln_v_reference)) bad("a finite reference velocity");
  if (values.size() != atlas_field_count * points()) bad(fmt::format("{} values per grid point", atlas_field_count));
  for (double v : values) {
    if (!std::isfinite(v)) bad("finite values");
  }
  for (const Material* m : {&material1, &material2}) {
    if (!(m->density > 0.0 && m->density < 1e30)) bad("material densities between 0 and 1e30 kg/m^3");
  }
  for (std::size_t i = 0; i < nxy; ++i) {
    if (!std::isfinite(stick_ratio[i]) || defined[i] > 1) bad("finite sticking velocities and 0/1 flags");
    if (!can_stick && defined[i] != 1) bad("a model that cannot stick has collisions at every node");
  }
  if (!(radius_min > 0.0 && radius_max >= radius_min && velocity_min > 0.0 && velocity_max >= velocity_min &&
        density_min > 0.0 && density_max >= density_min && std::isfinite(radius_max) && std::isfinite(velocity_max) &&
        std::isfinite(density_max))) {
    bad("positive, finite, ordered ranges");
  }
  inverse_step_ = {1.0 / x.step, 1.0 / y.step, 1.0 / z.step};
  lo_x_ = std::log(radius_min) - relative_slack(std::log(radius_min)) - 1e-12;
  hi_x_ = std::log(radius_max) + relative_slack(std::log(radius_max)) + 1e-12;
  if (lo_x_ < x.start - 1e-9 || hi_x_ > x.end() + 1e-9 || std::log(density_min) < y.start - 1e-6 ||
      std::log(density_max) > y.end() + 1e-6) {
    bad("grids that cover the stated ranges");
  }
}

// The x axis's lookup tables: for bins of the narrowest cell's width the cell at each bin's
// start (a point then lies in that cell or the next, locate()), and per stencil its Lagrange
// denominators.
void Atlas::prepare_x(const std::function<void(const std::string&)>& bad) {
  if (x.nodes.empty()) {  // a uniform axis: its nodes
    for (std::size_t i = 0; i < x.count; ++i) x.nodes.push_back(x.start + static_cast<double>(i) * x.step);
  }
  if (x.nodes.size() != x.count || x.nodes.front() != x.start) bad("x nodes that match the axis");
  double narrowest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < x.count; ++i) {
    if (!(x.nodes[i + 1] > x.nodes[i])) bad("ascending x nodes");
    narrowest = std::min(narrowest, x.nodes[i + 1] - x.nodes[i]);
  }
  if (!(narrowest >= 1e-6 * (x.end() - x.start))) bad("x cells at least 1e-6 of the axis wide");
  x.step = narrowest;
  inverse_step_[0] = 1.0 / narrowest;
  const auto bins = static_cast<std::size_t>((x.end() - x.start) * inverse_step_[0]) + 2;
  x_cell_.assign(bins, 0);
  std::size_t i = 0;
  for (std::size_t b = 0; b < bins; ++b) {
    const double at = x.start + static_cast<double>(b) * narrowest;
    while (i + 2 < x.count && x.nodes[i + 1] <= at) ++i;
    x_cell_[b] = static_cast<std::uint32_t>(i);
  }
  x_weight_scale_.assign(4 * (x.count - 3), 0.0);
  for (std::size_t b = 0; b + 3 < x.count; ++b) {
    for (std::size_t a = 0; a < 4; ++a) {
      double d = 1.0;
      for (std::size_t c = 0; c < 4; ++c) d *= c == a ? 1.0 : x.nodes[b + a] - x.nodes[b + c];
      x_weight_scale_[4 * b + a] = 1.0 / d;
    }
  }
}

// The centred 4x4 stencil of the cell that holds (ln R_eff, ln rho_eff) (one-sided at the edges).
[[gnu::always_inline]] inline void Atlas::locate(double ln_r, double ln_rho, Stencil& s) const noexcept {
  const double ux = (ln_r - x.start) * inverse_step_[0], uy = (ln_rho - y.start) * inverse_step_[1];
  std::size_t i = x_cell_[std::min(static_cast<std::size_t>(std::max(ux, 0.0)), x_cell_.size() - 1)];
  // A bin is as wide as the narrowest cell, so the point lies in its cell or the next: one step,
  // without a branch (random points would mispredict it). Should round-off in the bin's index
  // leave the point past a second node, it lies within ulps of that node, where the stencil one
  // cell back interpolates the same value (a second step costs more than it saves: docs/benchmarks.md).
  i += static_cast<std::size_t>((i + 2 < x.count) & (ln_r >= x.nodes[std::min(i + 1, x.count - 1)]));
  const std::size_t j = cell_of(uy, y.count);
  s.bx = std::min(i > 0 ? i - 1 : 0, x.count - 4);
  s.by = std::min(j > 0 ? j - 1 : 0, y.count - 4);
  const double* n = &x.nodes[s.bx];
  const double t0 = ln_r - n[0], t1 = ln_r - n[1], t2 = ln_r - n[2], t3 = ln_r - n[3];
  const double* scale = &x_weight_scale_[4 * s.bx];
  s.wx[0] = t1 * t2 * t3 * scale[0];
  s.wx[1] = t0 * t2 * t3 * scale[1];
  s.wx[2] = t0 * t1 * t3 * scale[2];
  s.wx[3] = t0 * t1 * t2 * scale[3];
  lagrange4(uy - static_cast<double>(s.by), s.wy);
}

// w = v_ref / v_s by the centred bicubic.
[[gnu::always_inline]] inline double Atlas::stick_weight(const Stencil& s) const noexcept {
  double w = 0.0;
  for (std::size_t a = 0; a < 4; ++a) {
    const double* row = &stick_ratio[(s.bx + a) * y.count + s.by];
    w += s.wx[a] * (s.wy[0] * row[0] + s.wy[1] * row[1] + s.wy[2] * row[2] + s.wy[3] * row[3]);
  }
  return w;
}

// v_s = v_ref / w; +inf where w <= 0 (beyond the radius where v_s diverges).
[[gnu::always_inline]] inline double Atlas::v_stick_at(const Stencil& s, double ln_r, double ln_rho) const noexcept {
  if (!can_stick) return 0.0;
  const double w = stick_weight(s);
  return w > 0.0 ? reference_velocity(ln_r, ln_rho) / w : std::numeric_limits<double>::infinity();
}

[[gnu::always_inline]] inline double Atlas::field_at(const Stencil& s, AtlasField f, double zq) const noexcept {
  double uz = (zq - z.start) * inverse_step_[2];
  uz = std::clamp(uz, 0.0, static_cast<double>(z.count - 1));  // below: the sqrt law's constant c
  const std::size_t k = cell_of(uz, z.count);
  const std::size_t bz = std::min(k > 0 ? k - 1 : 0, z.count - 4);
  double wz[4];
  lagrange4(uz - static_cast<double>(bz), wz);
  const std::size_t nz = z.count, ny = y.count;
  const double* base = &values[(static_cast<std::size_t>(f) * x.count * ny) * nz];
  double sum = 0.0;
  for (std::size_t a = 0; a < 4; ++a) {
    double row_sum = 0.0;
    for (std::size_t b = 0; b < 4; ++b) {
      const double* p = base + ((s.bx + a) * ny + s.by + b) * nz + bz;
      row_sum += s.wy[b] * (wz[0] * p[0] + wz[1] * p[1] + wz[2] * p[2] + wz[3] * p[3]);
    }
    sum += s.wx[a] * row_sum;
  }
  return sum;
}

// eps at `velocity`, `gap` = velocity - v_s above the sticking velocity (gap > 0).
[[gnu::always_inline]] inline double Atlas::cor_above(const Stencil& s, double gap, double velocity) const noexcept {
  return std::clamp(field_at(s, AtlasField::cor_factor, std::log(gap)) * std::sqrt(gap / velocity), 0.0, 1.0);
}

// ln R_eff, or NaN for radii that are not > 0 or whose R_eff lies outside the atlas; and ln rho_eff
// held inside the y axis (which spans every pair of the materials: only round-off is clamped).
Atlas::Point Atlas::point(double radius1, double radius2) const noexcept {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (!(radius1 > 0.0 && radius2 > 0.0 && std::isfinite(radius1))) return {nan, nan};
  const Reduced reduced = reduce(material1.density, material2.density, radius1, radius2);
  const double ln_r = std::log(reduced.r), ln_rho = std::log(reduced.rho);
  return {ln_r >= lo_x_ && ln_r <= hi_x_ ? ln_r : nan, std::clamp(ln_rho, y.start, y.end())};
}

bool Atlas::speed_inside(double velocity) const noexcept {
  return velocity >= velocity_min * (1 - 1e-12) && velocity <= velocity_max * (1 + 1e-12);
}

// v_s as the atlas states it: above its top speed, only that the grains stick at all its speeds.
double Atlas::stated_v_stick(double v_s) const noexcept {
  return v_s > velocity_max ? std::numeric_limits<double>::infinity() : v_s;
}

Atlas::Point Atlas::reduced(double radius1, double radius2) const {
  if (!(radius1 > 0.0) || !std::isfinite(radius1)) {
    throw InvalidArgument("radius1", fmt::format("{}", radius1), "a finite radius > 0 [m]");
  }
  if (!(radius2 > 0.0) || std::isnan(radius2)) {
    throw InvalidArgument("radius2", fmt::format("{}", radius2), "a radius > 0 [m] (inf: a wall)");
  }
  const Point p = point(radius1, radius2);
  if (std::isnan(p.ln_r)) {
    const double r = reduce(material1.density, material2.density, radius1, radius2).r;
    throw InvalidArgument("radius",
                          fmt::format("{} (R_eff = {} m)", std::isinf(radius2) ? fmt::format("{}", radius1)
                                                                               : fmt::format("{}, {}", radius1, radius2),
                                      r),
                          fmt::format("a reduced radius inside the atlas's {} .. {} m (no extrapolation)", radius_min,
                                      radius_max));
  }
  return p;
}

AtlasValue Atlas::evaluate(double radius1, double radius2, double velocity, bool fields) const {
  const Point p = reduced(radius1, radius2);
  if (!speed_inside(velocity)) {
    throw InvalidArgument("velocity", fmt::format("{}", velocity),
                          fmt::format("an impact speed inside the atlas's {} .. {} m/s (no extrapolation)",
                                      velocity_min, velocity_max));
  }
  Stencil s;
  locate(p.ln_r, p.ln_rho, s);
  AtlasValue out;
  const double v_s = v_stick_at(s, p.ln_r, p.ln_rho);
  out.v_stick = stated_v_stick(v_s);
  if (velocity <= v_s) {
    out.sticks = true;
    return out;
  }
  const double gap = velocity - v_s, zq = std::log(gap);
  out.cor = cor_above(s, gap, velocity);
  if (fields) {
    out.contact_time = std::exp(field_at(s, AtlasField::ln_contact_time, zq));
    out.bulk_fraction = std::clamp(field_at(s, AtlasField::bulk_fraction, zq), 0.0, 1.0);
    out.crack_fraction = std::clamp(field_at(s, AtlasField::crack_fraction, zq), 0.0, 1.0);
  }
  return out;
}

AtlasValue Atlas::at(const AtlasQuery& q) const { return evaluate(q.radius1, q.radius2, q.velocity, true); }
double Atlas::cor(double radius1, double radius2, double velocity) const {
  return evaluate(radius1, radius2, velocity, false).cor;
}
bool Atlas::sticks(double radius1, double radius2, double velocity) const {
  return evaluate(radius1, radius2, velocity, false).sticks;
}

double Atlas::v_stick(double radius1, double radius2) const {
  const Point p = reduced(radius1, radius2);
  Stencil s;
  locate(p.ln_r, p.ln_rho, s);
  return stated_v_stick(v_stick_at(s, p.ln_r, p.ln_rho));
}

double Atlas::v_stick_unchecked(double radius1, double radius2) const noexcept {
  const Point p = point(radius1, radius2);
  if (std::isnan(p.ln_r)) return p.ln_r;
  Stencil s;
  locate(p.ln_r, p.ln_rho, s);
  return stated_v_stick(v_stick_at(s, p.ln_r, p.ln_rho));
}

int Atlas::sticks_unchecked(double radius1, double radius2, double velocity) const noexcept {
  const Point p = point(radius1, radius2);
  if (std::isnan(p.ln_r) || !speed_inside(velocity)) return -1;
  Stencil s;
  locate(p.ln_r, p.ln_rho, s);
  return velocity <= v_stick_at(s, p.ln_r, p.ln_rho) ? 1 : 0;
}

double Atlas::cor_unchecked(double radius1, double radius2, double velocity) const noexcept {
  const Point p = point(radius1, radius2);
  if (std::isnan(p.ln_r) || !speed_inside(velocity)) return std::numeric_limits<double>::quiet_NaN();
  Stencil s;
  locate(p.ln_r, p.ln_rho, s);
  const double gap = velocity - v_stick_at(s, p.ln_r, p.ln_rho);
  return gap > 0.0 ? cor_above(s, gap, velocity) : 0.0;
}

// GCC compiles the batch twice, for x86-64 and for x86-64-v3 (AVX2, FMA), and the loader picks the
// one the machine runs.
BOUNCE_BATCH_CLONES void Atlas::cor_many(std::size_t n, const double* radius1, const double* radius2,
                                         const double* velocity, double* out) const noexcept {
  constexpr std::size_t block = 32;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  double ln_r[block], ln_rho[block], speed[block], ref[block], gap[block], ln_gap[block];
  Stencil s[block];
  std::uint8_t list[block];
  static_assert(block <= 256, "list holds indices in a block as bytes");
  for (std::size_t first = 0; first < n; first += block) {
    const std::size_t m = std::min(block, n - first);
    for (std::size_t i = 0; i < m; ++i) {  // R_eff and rho_eff (inputs read here: out may alias them)
      const double a = radius1[first + i], b = radius2[first + i];
      speed[i] = velocity[first + i];
      const bool ok = a > 0.0 && b > 0.0 && std::isfinite(a);
      const Reduced reduced = reduce(material1.density, material2.density, a, b);
      ln_r[i] = ok ? reduced.r : nan;
      ln_rho[i] = ok ? reduced.rho : 1.0;
    }
    vector_log(ln_r, m);
    vector_log(ln_rho, m);
    for (std::size_t i = 0; i < m; ++i) {  // w, and the exponent of v_ref
      gap[i] = nan;
      ref[i] = 0.0;
      if (!(ln_r[i] >= lo_x_ && ln_r[i] <= hi_x_) || !speed_inside(speed[i])) continue;
      ln_rho[i] = std::clamp(ln_rho[i], y.start, y.end());
      locate(ln_r[i], ln_rho[i], s[i]);
      gap[i] = can_stick ? stick_weight(s[i]) : 0.0;
      ref[i] = ln_reference_velocity(ln_r[i], ln_rho[i]);
    }
    vector_exp(ref, m);
    std::size_t bouncing = 0;  // the points with gap > 0 are listed, so that eps runs without a branch
    for (std::size_t i = 0; i < m; ++i) {  // v_s: gap > 0 bounces, 0 sticks, NaN outside
      const double w = gap[i];
      const double v_s = !can_stick ? 0.0 : w > 0.0 ? ref[i] / w : std::numeric_limits<double>::infinity();
      gap[i] = std::isnan(w) ? w : std::max(0.0, speed[i] - v_s);
      out[first + i] = gap[i] > 0.0 ? 0.0 : gap[i];  // 0 (sticks) or NaN (outside); eps below
      list[bouncing] = static_cast<std::uint8_t>(i);
      ln_gap[bouncing] = gap[i] > 0.0 ? gap[i] : 1.0;
      bouncing += gap[i] > 0.0 ? 1 : 0;
    }
    vector_log(ln_gap, bouncing);
    for (std::size_t k = 0; k < bouncing; ++k) {  // eps above v_s
      const std::size_t i = list[k];
      out[first + i] = std::clamp(field_at(s[i], AtlasField::cor_factor, ln_gap[k]) * std::sqrt(gap[i] / speed[i]), 0.0, 1.0);
    }
  }
}

}  // namespace bounce::analysis
