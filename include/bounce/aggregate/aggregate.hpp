#pragma once
// Aggregates of equal spheres grown by ballistic aggregation (docs/aggregates.md): BPCA
// (particle-cluster) and BCCA (cluster-cluster), seeded and the same on every platform; their
// structure (radius of gyration, contacts, fractal dimension) and their LAMMPS data file.

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace bounce::aggregate {

enum class Kind {
  bpca,  ///< ballistic particle-cluster: one monomer at a time sticks at first touch
  bcca,  ///< ballistic cluster-cluster: two equal clusters stick at first touch, level by level
};
/// "bpca", "bcca".
const char* kind_name(Kind kind);

using Vector = std::array<double, 3>;

/// What to grow: `n` monomers of radius `radius` [m] (BCCA: n a power of 2).
struct BuildRequest {
  Kind kind = Kind::bpca;
  std::size_t n = 0;
  double radius = 0.0;
  std::uint64_t seed = 0;
};

/// The largest aggregate built (2^17): BPCA's cost grows as n^2 (about 5 s at the largest,
/// docs/aggregates.md).
inline constexpr std::size_t max_monomers = 131072;

/// One point of the growth history: a cluster of `n` monomers and its radius of gyration [m]
/// (BCCA: the geometric mean over every cluster of that size the build made).
struct GrowthPoint {
  std::size_t n = 0;
  double radius_of_gyration = 0.0;
};

struct Aggregate {
  BuildRequest request;
  std::vector<Vector> centres;        ///< monomer centres [m], centre of mass at the origin
  std::vector<GrowthPoint> history;   ///< R_g as the aggregate grew (BPCA: every n; BCCA: every level)
};

/// Called with (monomers placed, total) as a build goes.
using Progress = std::function<void(std::size_t, std::size_t)>;

/// Grows the aggregate: the same request gives the same centres, bit for bit, on every platform
/// (std::mt19937_64 and transforms of its integers by +, *, / and sqrt alone). Throws
/// InvalidArgument for n < 1 or n > max_monomers, BCCA's n not a power of 2, radius <= 0.
Aggregate build(const BuildRequest& request, const Progress& progress = {});

/// R_g = sqrt(<|x - x_cm|^2>) of the centres [m] (a monomer's own size not added, as in the
/// literature's fits: docs/aggregates.md).
double radius_of_gyration(const std::vector<Vector>& centres);

/// A fit of log R_g = a + log(n) / D over the growth points with n_min <= n <= n_max.
struct FractalFit {
  double dimension = 0.0;  ///< D
  double prefactor = 0.0;  ///< k_f in n = k_f (R_g / r)^D
  std::size_t n_min = 0, n_max = 0, points = 0;
};
/// Least squares in (log n, log R_g) over the history; BPCA's points are thinned to ~20 per decade
/// of n so that each decade weighs the same. Needs two or more points in the range.
FractalFit fit_fractal_dimension(const std::vector<GrowthPoint>& history, double radius, std::size_t n_min,
                                 std::size_t n_max);
/// The range bounce fits by default (docs/aggregates.md, "Fractal dimension"): BPCA n from
/// min(max(n/10, 100), n/2) to n (the filling factor is constant from n ~ 100 on); BCCA every
/// level from 16 (below, the local slope is still rising).
FractalFit default_fit(const Aggregate& aggregate);
/// The fewest monomers default_fit takes: BPCA 20 (a third of a decade of growth), BCCA 32 (two levels from 16).
std::size_t min_fit_monomers(Kind kind);
/// The same fit over `samples` aggregates of the request, seeds seed, seed + 1, ...: R_g at each n
/// the geometric mean over them (an ensemble average, as Arakawa et al. 2019 fit BCCA). One
/// aggregate's history scatters (BPCA n = 1000: D from 2.9 to 3.5); the mean over 20 does not.
FractalFit ensemble_fit(const BuildRequest& request, std::size_t samples, const Progress& progress = {});

/// Touching pairs: |x_i - x_j| <= 2r (1 + contact_tolerance).
inline constexpr double contact_tolerance = 1e-9;
struct Structure {
  double radius_of_gyration = 0.0;  ///< [m]
  std::size_t contacts = 0;
  double coordination = 0.0;        ///< mean contacts per monomer, 2 contacts / n
  double filling_factor = 0.0;      ///< n (r / R_c)^3 with R_c = sqrt(5/3) R_g (Mukai et al. 1992)
  double min_distance = 0.0;        ///< the smallest centre distance [m] (>= 2r to round-off)
  std::optional<FractalFit> fit;    ///< default_fit; none below min_fit_monomers
};
Structure structure(const Aggregate& aggregate);
/// The number of pairs closer than 2r (1 + tolerance) and the smallest distance, with a cell grid.
std::size_t count_contacts(const std::vector<Vector>& centres, double radius, double tolerance,
                           double* min_distance = nullptr);

/// The aggregate as a LAMMPS data file (atom_style sphere, units si: id type diameter density
/// x y z), in a box `margin` [m] beyond the monomers' surfaces; `title` its first line.
std::string lammps_data(const Aggregate& aggregate, double density, double margin, const std::string& title);

}  // namespace bounce::aggregate
