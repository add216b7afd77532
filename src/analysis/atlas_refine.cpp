// The atlas build's rounds (docs/atlas.md, "Error control"): assemble the grid from the
// nodes' results, compare it with direct collisions at held-out points, refine the axis
// whose points fail.
#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "atlas_checks.hpp"
#include "bounce/core/error.hpp"
#include "bounce/core/version.hpp"

namespace bounce::analysis::detail {

std::vector<AtlasParameter> model_parameters(const AtlasRequest& request) {
  std::vector<AtlasParameter> out;
  for (const ParameterSpec& spec : request.model_parameters.specs()) {
    const bool given = request.model_parameters.given(spec.name);
    if (!given && !spec.default_value) continue;
    std::string value = given ? request.model_parameters.typed(spec.name) : spec.default_text();
    out.push_back({spec.name, value, spec.unit});
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name < b.name; });  // the file's order
  return out;
}

void AtlasBuild::initial_grid() {
  const double lx = std::log(request_.radius_min), hx = std::log(request_.radius_max);
  base_.x = AtlasAxis{lx, (hx - lx) / static_cast<double>(request_.radius_nodes - 1), request_.radius_nodes, {}};
  const double ly = std::log(density_[0]), hy = std::log(density_[1]);
  // rho_eff spans a factor of at most 4 for like materials: 4 nodes to start (one cubic).
  base_.y = AtlasAxis{ly, std::max(hy - ly, 1e-6) / 3.0, 4, {}};
}

void AtlasBuild::fill_column(Atlas& a, std::size_t ix, std::size_t iy) {
  const auto radii = node_radii(a.x, a.y, ix, iy);
  const AtlasThreshold t = threshold(radii);
  const std::size_t node = ix * a.y.count + iy, nz = a.z.count;
  a.stick_ratio[node] = t.defined && can_stick_ ? a.reference_velocity(a.x.value(ix), a.y.value(iy)) / t.velocity : 0.0;
  known_ratio_[node] = t.defined;
  a.defined[node] = has_column(t) ? 1 : 0;
  if (a.defined[node] == 0) return;
  std::optional<std::array<double, atlas_field_count>> first, last;
  std::vector<std::optional<std::array<double, atlas_field_count>>> column(nz);
  for (const auto& [k, v] : column_speeds(t, a.z)) {
    const double gap = std::exp(a.z.value(k));  // as column_speeds added it to v_s
    const AtlasCollision c = collision(radii, v);
    if (c.sticks) {
      throw InvalidArgument("model", request_.model,
                            fmt::format("a model with one sticking velocity per pair: at R_eff = {:.6g} m, rho_eff = "
                                        "{:.6g} kg/m^3 the grains stick at {:.6g} m/s, above v_s = {:.6g} m/s (the "
                                        "atlas tabulates eps above one threshold; docs/atlas.md)",
                                        std::exp(a.x.value(ix)), std::exp(a.y.value(iy)), v, t.velocity));
    }
    column[k] = {c.cor * std::sqrt(v / gap), std::log(c.contact_time), c.bulk_fraction, c.crack_fraction};
    if (!first) first = column[k];
    last = column[k];
  }
  if (!first) first = last = std::array<double, atlas_field_count>{1.0, 0.0, 0.0, 0.0};
  bool before = true;
  for (std::size_t k = 0; k < nz; ++k) {
    if (column[k]) before = false;
    const auto& v = column[k] ? *column[k] : (before ? *first : *last);  // c held below, the top above
    for (std::size_t f = 0; f < atlas_field_count; ++f) a.values[((f * a.x.count + ix) * a.y.count + iy) * nz + k] = v[f];
  }
}

Atlas AtlasBuild::assemble(const AtlasLevels& levels) {
  Atlas a;
  a.model = request_.model;
  a.parameters = model_parameters(request_);
  a.material1 = m1_;
  a.material2 = m2_;
  a.bounce_version = std::string(bounce::version());
  a.radius_min = request_.radius_min;
  a.radius_max = request_.radius_max;
  a.velocity_min = request_.velocity_min;
  a.velocity_max = request_.velocity_max;
  a.density_min = density_[0];
  a.density_max = density_[1];
  a.can_stick = can_stick_;
  a.x = base_.x_at(levels);
  a.y = base_.y_at(levels);
  a.z = base_.z_at(levels);
  const std::size_t nxy = a.x.count * a.y.count;
  a.ln_v_reference = ln_v_reference_;
  a.stick_ratio.assign(nxy, 0.0);
  known_ratio_.assign(nxy, false);
  a.defined.assign(nxy, 0);
  a.values.assign(atlas_field_count * a.points(), 0.0);
  for (std::size_t ix = 0; ix < a.x.count; ++ix) {
    for (std::size_t iy = 0; iy < a.y.count; ++iy) fill_column(a, ix, iy);
  }
  fill_undefined(a);
  a.errors.tolerance = request_.tolerance;
  return a;
}

namespace {

// Linear continuation in x along a row of nodes from its two nearest `known` ones (on the side
// of larger x where there are two there, else the other): value(ix) for an unknown ix.
template <class Value>
double continued(const AtlasAxis& x, const std::vector<std::size_t>& known, std::size_t ix, Value value) {
  if (known.empty()) return NAN;
  if (known.size() == 1) return value(known.front());
  const auto above = std::upper_bound(known.begin(), known.end(), ix);
  const bool right = above != known.end() && above + 1 != known.end();
  const std::size_t d1 = right ? *above : known[known.size() - 2], d2 = right ? *(above + 1) : known.back();
  const double f1 = value(d1), f2 = value(d2);
  return f1 + (f2 - f1) * (x.value(ix) - x.value(d1)) / (x.value(d2) - x.value(d1));
}

}  // namespace

// Nodes without collisions, row by row (docs/atlas.md): w where the grains stick up to the
// sound speed (held at most at half of v_ref / c_t: v_s at least twice c_t), and the fields
// where v_s is above column_cap v_max, continued linearly in x. A lookup meets them only in
// stencils near where v_s diverges; the held-out checks measure what that costs.
void AtlasBuild::fill_undefined(Atlas& a) const {
  const std::size_t nx = a.x.count, ny = a.y.count, nz = a.z.count;
  for (std::size_t iy = 0; iy < ny; ++iy) {
    std::vector<std::size_t> with_ratio, with_column;
    for (std::size_t ix = 0; ix < nx; ++ix) {
      if (known_ratio_[ix * ny + iy]) with_ratio.push_back(ix);
      if (a.defined[ix * ny + iy] != 0) with_column.push_back(ix);
    }
    for (std::size_t ix = 0; ix < nx; ++ix) {
      if (!known_ratio_[ix * ny + iy]) {
        const double cap = 0.5 * a.reference_velocity(a.x.value(ix), a.y.value(iy)) / c_t_;
        const double w = continued(a.x, with_ratio, ix, [&](std::size_t k) { return a.stick_ratio[k * ny + iy]; });
        a.stick_ratio[ix * ny + iy] = std::isnan(w) ? cap : std::min(cap, w);
      }
      if (a.defined[ix * ny + iy] != 0) continue;
      for (std::size_t f = 0; f < atlas_field_count; ++f) {
        for (std::size_t iz = 0; iz < nz; ++iz) {
          const auto at = [&](std::size_t k) { return a.values[((f * nx + k) * ny + iy) * nz + iz]; };
          const double v = continued(a.x, with_column, ix, at);
          a.values[((f * nx + ix) * ny + iy) * nz + iz] = std::isnan(v) ? (f == 0 ? 1.0 : 0.0) : v;
        }
      }
    }
  }
}

}  // namespace bounce::analysis::detail
