#pragma once
// Private: the atlas build's geometry (docs/atlas.md): the range of the effective density,
// the pair of bodies that has a given (R_eff, rho_eff), and the grid at a refinement level.

#include <array>
#include <cstddef>
#include <vector>

#include "bounce/analysis/atlas.hpp"
#include "bounce/pair/pair.hpp"

namespace bounce::analysis::detail {

/// [min, max] of rho_eff over every ratio R1/R2 in [0, inf] (walls included).
std::array<double, 2> density_range(double density1, double density2);

/// Radii (R1, R2) of bodies of these densities with R_eff = r and rho_eff = rho; R2 = inf (a
/// wall) where rho_eff = density1. Any pair with that (R_eff, m_eff) has the same head-on collision.
std::array<double, 2> radii_for(double r, double rho, double density1, double density2);

/// The pair of the atlas's materials with these radii.
Pair atlas_pair(const Material& m1, const Material& m2, const std::array<double, 2>& radii);

/// x nodes lie on a fine lattice: key k is x = start + k (step / 2^x_key_depth) of the first grid.
inline constexpr int x_key_depth = 10;

/// A grid: the x nodes by their keys (cells split where the checks fail: docs/atlas.md), and the
/// first grid's steps of y and z halved `y` and `z` times. Nodes of a coarser grid are nodes of
/// every finer one, at exactly the same coordinates.
struct AtlasLevels {
  std::vector<long> x;  ///< ascending keys
  int y = 0, z = 0;
};

struct AtlasGridBase {
  AtlasAxis x, y, z;  ///< the first grid
  AtlasAxis at(const AtlasAxis& base, int level) const;
  AtlasAxis x_at(const AtlasLevels& l) const;
  AtlasAxis y_at(const AtlasLevels& l) const { return at(y, l.y); }
  AtlasAxis z_at(const AtlasLevels& l) const { return at(z, l.z); }
  /// The first grid's keys.
  std::vector<long> first_x_keys() const;
};

/// Splits the cells whose index is in `cells` (their midpoint becomes a node, where the lattice
/// allows), then any cell more than twice as wide as a neighbour, so that stencils stay graded.
/// Returns false when no cell could be split.
bool split_x_cells(std::vector<long>& keys, const std::vector<std::size_t>& cells);

}  // namespace bounce::analysis::detail
