#pragma once
// Private: the atlas build (atlas_build.cpp: nodes; atlas_refine.cpp: assembly, held-out
// checks and refinement).

#include <algorithm>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <vector>

#include "atlas_grid.hpp"
#include "atlas_memo.hpp"
#include "bounce/analysis/atlas.hpp"
#include "bounce/models/model.hpp"

namespace bounce::analysis::detail {

/// The first z point of a sticking node lies threshold_margin(tol) v_s above v_s. Closer, the
/// lookup holds c = eps sqrt(v / (v - v_s)) at its value there, so eps is at most the first
/// point's: eps rises like (v - v_s)^p from the threshold, p = 1 under krijt (eps ~ 2.5 (v -
/// v_s) / v_s for 1 um ice), 1/2 under JKR's equilibrium; at v - v_s = tol/100 v_s that is
/// well below tol either way (docs/atlas.md).
inline double threshold_margin(double tolerance) { return std::min(1e-4, tolerance / 100.0); }
/// Nodes with v_s above this many times v_max have no collisions of their own: a lookup that
/// bounces meets them only at the edge of its stencil, and their fields are continued along x.
inline constexpr double column_cap = 4.0;
/// The relative error of v_s the checks must reach (the stated bound is twice what they find).
inline constexpr double v_stick_target = 5e-7;

/// A held-out point of a round's checks (docs/atlas.md, "Error control").
enum Kind { on_nodes, x_kind, y_kind, anywhere, x_middle };
struct Probe {
  std::array<double, 2> radii;
  double v = 0.0;  ///< 0: a sticking velocity
  Kind kind = on_nodes;
  double ln_r = 0.0;
};

/// What one round of held-out checks measured.
struct AtlasCheck {
  double z = 0.0, x = 0.0, y = 0.0, full = 0.0;     ///< largest |eps error| by kind of point
  double vs_x = 0.0, vs_y = 0.0, vs_full = 0.0;     ///< largest relative v_s error
  double contact_time = 0.0, energy = 0.0;
  long points = 0, thresholds = 0;
  std::vector<double> x_failing;  ///< ln R_eff of the points whose error the x cells explain
  double cor() const { return std::max({z, x, y, full}); }
  double v_stick() const { return std::max({vs_x, vs_y, vs_full}); }
};

std::vector<AtlasParameter> model_parameters(const AtlasRequest& request);

class AtlasBuild {
 public:
  AtlasBuild(const AtlasRequest& request, const AtlasRunner& runner);
  Atlas run();

 private:
  std::uint64_t fingerprint() const;
  AtlasCollision collision(const std::array<double, 2>& radii, double v);
  AtlasThreshold threshold(const std::array<double, 2>& radii);
  void report(const char* stage);
  void run_jobs(std::size_t count, const std::function<void(std::size_t)>& job);
  std::array<double, 2> node_radii(const AtlasAxis& x, const AtlasAxis& y, std::size_t ix, std::size_t iy) const;
  std::vector<std::pair<std::size_t, double>> column_speeds(const AtlasThreshold& t, const AtlasAxis& z) const;
  bool has_column(const AtlasThreshold& t) const;
  void compute_nodes(const AtlasLevels& levels);
  void fix_z_axis(const AtlasAxis& x, const AtlasAxis& y);
  void initial_grid();
  Atlas assemble(const AtlasLevels& levels);
  void fill_column(Atlas& a, std::size_t ix, std::size_t iy);
  void fill_undefined(Atlas& a) const;
  AtlasCheck check(const Atlas& a, int round);
  std::vector<Probe> probes(const Atlas& a, int round) const;
  double check_collision(const Atlas& a, const std::array<double, 2>& radii, double v, double& band, AtlasCheck& c);
  double check_threshold(const Atlas& a, const std::array<double, 2>& radii);
  bool refine(AtlasLevels& levels, const AtlasCheck& c) const;

  const AtlasRequest& request_;
  const AtlasRunner& runner_;
  Material m1_, m2_;
  models::Model model_;
  bool can_stick_ = false;
  double c_t_ = 0.0;
  std::array<double, 2> density_{};
  std::optional<AtlasMemo> memo_;
  AtlasGridBase base_;
  std::vector<bool> known_ratio_;  ///< per node of the grid being assembled: v_s below the sound speed
  double ln_v_reference_ = 0.0;  ///< a of v_ref = exp(a - 5/6 x - y/2): JKR's threshold at the grid's middle
  bool z_fixed_ = false;
  std::mutex progress_mutex_;
};

}  // namespace bounce::analysis::detail
