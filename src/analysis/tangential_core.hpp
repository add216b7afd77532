#pragma once
// Private: the eps^T lookup, C99 (tangential_table_core.h: the same text the C headers
// carry), compiled into the library here, with a view of a TangentialTable for it.
#include <math.h>

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "bounce/analysis/tables.hpp"
#include "bounce/core/error.hpp"

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
// max_lookup_breaks was altered (a g_tangential_max raised from 1 to 1e6 replayed 8.8e7
// breaks, 28 s a lookup; the fuzzer found such a table) or asks more than a lookup should do.
inline constexpr double max_lookup_breaks = 1e5;

// Refuses t when a lookup at its g^T max would replay more than max_lookup_breaks breaks (the
// most over its rows), naming `name` = `value` (and `source`, what such a table comes from).
inline void require_bounded_lookups(const TangentialTable& t, const std::string& name, const std::string& value,
                                    const std::string& source) {
  double most = 0.0;
  for (std::size_t r = 0; r < t.row_count(); ++r) {
    const double tau_end = t.rows[r * tt_row_values], time_unit = std::exp(t.rows[r * tt_row_values + 1]);
    most = std::max(most, tau_end * t.gt_max * time_unit / t.asperity_size);
  }
  if (!(most <= max_lookup_breaks)) {
    throw InvalidArgument(name, value,
                          fmt::format("a g^T range whose lookups replay at most {:g} asperity breaks (this one: {:.3g}{})",
                                      max_lookup_breaks, most, source));
  }
}

inline tt_table view(const TangentialTable& t) {
  return tt_table{static_cast<int>(t.row_count()), static_cast<int>(t.s.size()), t.order, t.x0, t.dx,
                  t.asperity_size, t.s.data(), t.rows.data(), t.nodes.data()};
}

}  // namespace bounce::analysis::detail
