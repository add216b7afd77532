#pragma once
// The collision atlas (docs/atlas.md): eps, the outcome, the sticking velocity, the contact time
// and the energy budget of head-on collisions of one pair of materials and one model, tabulated
// over the reduced radius, the effective density and the impact speed, with a measured error,
// for coagulation codes that look them up millions of times.
//
// Why three axes: a head-on collision depends on the bodies only through R_eff and m_eff
// (and the materials), and m_eff is not a function of R_eff (two equal spheres have four
// times the m_eff of a sphere of radius R_eff on a wall). With rho_eff = m_eff / (4 pi R_eff^3 / 3)
// the third axis is bounded: for like materials rho <= rho_eff <= 4 rho.
//
// The grid: x = ln R_eff (nodes refined where they are needed), y = ln rho_eff and
// z = ln(v - v_s(x, y)) (uniform), with
// v_s the sticking velocity (0 for models that cannot stick). In z the tabulated factor
// c = eps sqrt(v / (v - v_s)) is smooth down to the threshold (eps ~ sqrt(v - v_s) there),
// so a tensor cubic interpolation holds the error the build measured. v_s itself is held as
// the ratio w = v_ref / v_s to a reference v_ref = exp(a - 5/6 x - y/2) that scales like
// JKR's threshold K13 (25): w is O(1) and smooth, and goes to 0 where v_s diverges (small
// grains under krijt stick at every speed below some radius; docs/atlas.md).

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bounce/analysis/collide.hpp"
#include "bounce/core/parameters.hpp"
#include "bounce/pair/material.hpp"

namespace bounce::analysis {

/// An axis: uniform, value(i) = start + i * step, i = 0 .. count - 1, or given by its nodes
/// (ascending; then start is the first and step the narrowest cell).
struct AtlasAxis {
  double start = 0.0;
  double step = 0.0;
  std::size_t count = 0;
  std::vector<double> nodes;  ///< a non-uniform axis's nodes; empty: uniform
  double value(std::size_t i) const { return nodes.empty() ? start + static_cast<double>(i) * step : nodes[i]; }
  double end() const { return value(count - 1); }
};

/// The fields tabulated at every grid point, in this order.
enum class AtlasField : std::size_t {
  cor_factor = 0,     ///< eps sqrt(v / (v - v_s)) [-]
  ln_contact_time,    ///< ln(contact time / 1 s)
  bulk_fraction,      ///< bulk viscous dissipation / (1/2) m_eff v^2, K13 (C.3)
  crack_fraction,     ///< dissipation at the crack tip / (1/2) m_eff v^2, K13 (C.2)
};
inline constexpr std::size_t atlas_field_count = 4;

/// A model parameter as the file records it.
struct AtlasParameter {
  std::string name, value, unit;
};

/// What a build measured against direct collisions at held-out points.
struct AtlasErrors {
  double cor = 0.0;            ///< stated bound on |eps_atlas - eps_collide| (2x the largest measured)
  double cor_measured = 0.0;   ///< the largest |eps_atlas - eps_collide| at the check points
  double v_stick = 0.0;        ///< stated bound on the relative error of v_s (2x the largest measured)
  double v_stick_measured = 0.0;
  double contact_time = 0.0;   ///< largest relative error of the contact time measured
  double energy = 0.0;         ///< largest error of the bulk and crack fractions measured
  long check_points = 0;       ///< collisions compared with the finished atlas
  long v_stick_points = 0;     ///< sticking velocities (bisections) compared
  double tolerance = 0.0;      ///< the --tol the build was asked for
};

/// One lookup: every tabulated quantity at one (R1, R2, v).
struct AtlasValue {
  double cor = 0.0;
  bool sticks = false;
  double v_stick = 0.0;  ///< [m/s]; +inf where the grains stick at every speed of the atlas (v_s > v_max)
  /// Contact time [s] and energy fractions: none for a sticking collision (the grains stay
  /// together; docs/atlas.md).
  std::optional<double> contact_time, bulk_fraction, crack_fraction;
};

/// Radii of the two bodies: R2 = +inf is a wall (of material 2).
struct AtlasQuery {
  double radius1 = 0.0, radius2 = 0.0, velocity = 0.0;
};

class Atlas {
 public:
  // --- what the file says of itself ---------------------------------------------------
  std::string model;                        ///< the registry's keyword
  std::vector<AtlasParameter> parameters;   ///< the model's parameters (given and defaults)
  Material material1, material2;            ///< body 1 and body 2 (a wall of material 2 with R2 = inf)
  std::string bounce_version;
  double radius_min = 0.0, radius_max = 0.0;      ///< range of R_eff [m]
  double velocity_min = 0.0, velocity_max = 0.0;  ///< range of v [m/s]
  double density_min = 0.0, density_max = 0.0;    ///< range of rho_eff [kg/m^3] of all pairs
  bool can_stick = false;                   ///< the model is adhesive (v_s > 0)
  AtlasErrors errors;
  std::vector<std::string> warnings;        ///< validity warnings of its collisions, one per kind

  // --- the grid ------------------------------------------------------------------------
  AtlasAxis x, y, z;             ///< ln R_eff (non-uniform), ln rho_eff, ln(v - v_s) (uniform)
  double ln_v_reference = 0.0;          ///< a of v_ref = exp(a - 5/6 x - y/2) [ln(m/s)]
  std::vector<double> stick_ratio;      ///< (x, y): w = v_ref / v_s; continued linearly in x where
                                        ///< the grains stick up to the sound speed (w <= 0: v_s = inf)
  std::vector<std::uint8_t> defined;    ///< (x, y): 1 where the node's values come from collisions, 0
                                        ///< where continued from its row (v_s far above v_max)
  std::vector<double> values;           ///< (field, x, y, z), z fastest

  /// Checks sizes, finiteness and the stencils (InvalidArgument naming `source` otherwise) and
  /// prepares the lookups. Called by the builder and the reader.
  void prepare(const std::string& source);

  // --- lookups (InvalidArgument outside the table: never an extrapolation) -------------
  double cor(double radius1, double radius2, double velocity) const;
  bool sticks(double radius1, double radius2, double velocity) const;
  double v_stick(double radius1, double radius2) const;
  AtlasValue at(const AtlasQuery& q) const;

  /// The same without checks, for the C API's hot loop: NaN outside the table.
  double cor_unchecked(double radius1, double radius2, double velocity) const noexcept;
  /// cor_unchecked at n points, in passes over blocks of them (the logarithms of every point, then
  /// the sticking velocities, then eps), so that the points' independent work overlaps.
  void cor_many(std::size_t n, const double* radius1, const double* radius2, const double* velocity,
                double* out) const noexcept;
  double v_stick_unchecked(double radius1, double radius2) const noexcept;
  int sticks_unchecked(double radius1, double radius2, double velocity) const noexcept;  ///< 1, 0, -1 outside

  std::size_t points() const { return x.count * y.count * z.count; }
  /// ln v_ref at (ln R_eff, ln rho_eff): v_ref scales like JKR's sticking velocity, K13 (25).
  double ln_reference_velocity(double ln_r, double ln_rho) const noexcept {
    return ln_v_reference - 5.0 / 6.0 * ln_r - 0.5 * ln_rho;
  }
  /// v_ref at (ln R_eff, ln rho_eff) [m/s].
  double reference_velocity(double ln_r, double ln_rho) const { return std::exp(ln_reference_velocity(ln_r, ln_rho)); }
  /// v_s at a node (+inf where w <= 0).
  double node_v_stick(std::size_t ix, std::size_t iy) const;
  double value(AtlasField f, std::size_t ix, std::size_t iy, std::size_t iz) const {
    return values[((static_cast<std::size_t>(f) * x.count + ix) * y.count + iy) * z.count + iz];
  }

 private:
  struct Stencil;
  struct Point {
    double ln_r, ln_rho;
  };
  Point point(double radius1, double radius2) const noexcept;
  /// point(), with InvalidArgument naming radii outside the atlas.
  Point reduced(double radius1, double radius2) const;
  bool speed_inside(double velocity) const noexcept;
  double stated_v_stick(double v_s) const noexcept;
  double lo_x_ = 0.0, hi_x_ = 0.0;
  std::array<double, 3> inverse_step_{};  ///< 1 / step of x (its index bins), y, z (a lookup multiplies)
  std::vector<std::uint32_t> x_cell_;      ///< per bin of width x.step: the cell at the bin's start
  std::vector<double> x_weight_scale_;     ///< per stencil start: 1 / prod_{b != a} (x_a - x_b), a = 0..3
  void prepare_x(const std::function<void(const std::string&)>& bad);
  void locate(double ln_r, double ln_rho, Stencil& s) const noexcept;
  double stick_weight(const Stencil& s) const noexcept;
  double v_stick_at(const Stencil& s, double ln_r, double ln_rho) const noexcept;
  double field_at(const Stencil& s, AtlasField f, double zq) const noexcept;
  double cor_above(const Stencil& s, double gap, double velocity) const noexcept;
  AtlasValue evaluate(double radius1, double radius2, double velocity, bool fields) const;
};

/// rho_eff = rho1 rho2 (R1 + R2)^3 / (rho1 R1^3 + rho2 R2^3); rho1 for a wall (R2 = inf).
double effective_density(double density1, double density2, double radius1, double radius2);

/// What to build: the model's inputs as bound by the front door.
struct AtlasRequest {
  Parameters pair_parameters;   ///< materials (radius and wall not used)
  std::string model;
  Parameters model_parameters;
  CollideOptions options;
  double radius_min = 0.0, radius_max = 0.0;
  std::size_t radius_nodes = 0;       ///< the first grid's nodes in ln R_eff (>= 4)
  double velocity_min = 0.0, velocity_max = 0.0;
  std::size_t velocity_nodes = 0;     ///< sets the first step in z: ln(v_max / v_min) / (N - 1)
  double tolerance = 1e-4;            ///< |eps_atlas - eps_collide| to reach at held-out points
  unsigned threads = 0;               ///< 0: every core
};

/// How a build runs its collisions. The cache file (resume) and the progress bar are the
/// caller's; `distribute` may spread a batch of independent jobs over MPI ranks (the CLI's).
struct AtlasRunner {
  /// (collisions done, 0) as the atlas grows, and the stage it is at.
  std::function<void(std::size_t done, const std::string& stage)> progress;
  /// A file of results computed so far: a build that was interrupted resumes from it. Empty:
  /// none. Only a runner with `writes_cache` appends to it (MPI: rank 0).
  std::string cache_path;
  bool writes_cache = true;
  /// Runs job(i) for i in [0, count); the default runs them on `threads` threads. A job's
  /// results are its own (the cache keeps them), so any split among processes works as long
  /// as every process ends with every job done (the CLI's MPI runner shares them).
  std::function<void(std::size_t count, const std::function<void(std::size_t)>& job)> distribute;
  /// After each batch: this process's new results (cache lines) and its error, if any, in; every
  /// process's results out, or every process's first error raised on all of them (so that none
  /// waits for another that failed). First called with what the cache held (MPI: rank 0's).
  std::function<std::string(const std::string& mine, std::exception_ptr error)> share;
};

/// Builds the atlas, refining each axis until the interpolant agrees with direct collisions
/// at held-out points within tolerance / 2. InvalidArgument for inputs it cannot tabulate
/// (a model that sticks again above v_s, a range above the sound speed, ...).
Atlas build_atlas(const AtlasRequest& request, const AtlasRunner& runner = {});

/// HDF5 (docs/atlas.md, "Format"). write_atlas writes to a temporary file and renames it, so
/// an interrupted write leaves no half-written atlas. read_atlas checks the checksum, the
/// format version and every array (InvalidArgument naming the file otherwise); with
/// `expected_model`, a file of another model is refused.
void write_atlas(const Atlas& atlas, const std::string& path);
Atlas read_atlas(const std::string& path, const std::string& expected_model = {});
/// One row per grid point: R_eff, rho_eff, v_s, v, eps, contact time, fractions.
std::string atlas_csv(const Atlas& atlas);

}  // namespace bounce::analysis
