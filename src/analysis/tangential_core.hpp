#pragma once
// Private: the eps^T lookup, C99 (tangential_table_core.h: the same text the C headers
// carry), compiled into the library here, with a view of a TangentialTable for it.
#include <math.h>

#include <algorithm>
#include <cmath>

#include "bounce/analysis/tables.hpp"

namespace bounce::analysis::detail {

// The lookup is C99 (written into the C headers as it is), so it keeps C's casts and
// conversions.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wconversion"
#include "tangential_table_core.h"
#pragma GCC diagnostic pop

// A lookup at (g^N, g^T) replays about tau_end g^T t_u / zeta0 asperity breaks (|p| climbs
// to zeta0 / (g^T t_u) between two, at a rate below ~1.2). The builder's g^T limit (half of
// dense_breaks = 1e3 breaks per time unit) keeps written tables below ~1.5e3; a table above
// max_lookup_breaks was altered (the fuzzer's g_tangential_max 1 -> 1e6 replayed 8.8e7
// breaks, 28 s a lookup) or asks more than a lookup should do.
inline constexpr double max_lookup_breaks = 1e5;

// The most breaks a lookup of t can replay: at g^T max, over the rows.
inline double expected_breaks(const TangentialTable& t) {
  double most = 0.0;
  for (std::size_t r = 0; r < t.row_count(); ++r) {
    const double tau_end = t.rows[r * tt_row_values], time_unit = std::exp(t.rows[r * tt_row_values + 1]);
    most = std::max(most, tau_end * t.gt_max * time_unit / t.asperity_size);
  }
  return most;
}

inline tt_table view(const TangentialTable& t) {
  return tt_table{static_cast<int>(t.row_count()), static_cast<int>(t.s.size()), t.order, t.x0, t.dx,
                  t.asperity_size, t.s.data(), t.rows.data(), t.nodes.data()};
}

}  // namespace bounce::analysis::detail
