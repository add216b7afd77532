#pragma once
// A cluster's centres projected onto the plane across a direction u and binned in square cells
// of the contact distance 2r: a line along u can touch only the monomers of the 3 x 3 cells
// around its own, so BCCA's first touch costs O(n) per shot instead of O(n^2).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "geometry.hpp"

namespace bounce::aggregate::detail {

class ProjectedGrid {
 public:
  ProjectedGrid(const std::vector<Vector>& centres, const Vector& u, double contact)
      : centres_(centres), u_(u), contact_(contact) {
    plane_basis(u, e1_, e2_);
    cells_.reserve(centres.size());
    for (std::size_t i = 0; i < centres.size(); ++i) {
      cells_.emplace_back(key(cell(dot(centres[i], e1_)), cell(dot(centres[i], e2_))), i);
    }
    std::sort(cells_.begin(), cells_.end());
  }

  /// The smallest s at which a sphere on the line q + s u touches one of the centres (+inf: none).
  double first_touch(const Vector& q) const {
    const std::int64_t cx = cell(dot(q, e1_)), cy = cell(dot(q, e2_));
    double first = std::numeric_limits<double>::infinity();
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        const std::uint64_t k = key(cx + dx, cy + dy);
        auto it = std::lower_bound(cells_.begin(), cells_.end(), std::pair<std::uint64_t, std::size_t>{k, 0});
        for (; it != cells_.end() && it->first == k; ++it) {
          first = std::min(first, detail::first_touch(q, u_, centres_[it->second], contact_));
        }
      }
    }
    return first;
  }

 private:
  std::int64_t cell(double coordinate) const { return static_cast<std::int64_t>(std::floor(coordinate / contact_)); }
  static std::uint64_t key(std::int64_t x, std::int64_t y) {
    constexpr std::int64_t offset = std::int64_t{1} << 31;  // cells within +-2^31: aggregates of < 1e9 monomers across
    return (static_cast<std::uint64_t>(x + offset) << 32) | static_cast<std::uint64_t>(y + offset);
  }

  const std::vector<Vector>& centres_;
  Vector u_, e1_{}, e2_{};
  double contact_;
  std::vector<std::pair<std::uint64_t, std::size_t>> cells_;
};

}  // namespace bounce::aggregate::detail
