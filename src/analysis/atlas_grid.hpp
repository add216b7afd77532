#pragma once
// Private: the atlas build's geometry (docs/atlas.md): the range of the effective density,
// the pair of bodies that has a given (R_eff, rho_eff), and the grid at a refinement level.

#include <array>
#include <cstddef>

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

/// A grid level: the first grid's steps halved `level` times on each axis (nodes of a coarser
/// level are nodes of every finer one, at exactly the same coordinates).
struct AtlasLevels {
  int x = 0, y = 0, z = 0;
};

struct AtlasGridBase {
  AtlasAxis x, y, z;  ///< level 0
  AtlasAxis at(const AtlasAxis& base, int level) const;
  AtlasAxis x_at(const AtlasLevels& l) const { return at(x, l.x); }
  AtlasAxis y_at(const AtlasLevels& l) const { return at(y, l.y); }
  AtlasAxis z_at(const AtlasLevels& l) const { return at(z, l.z); }
};

}  // namespace bounce::analysis::detail
