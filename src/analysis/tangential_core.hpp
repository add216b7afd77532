#pragma once
// Private: the eps^T lookup, C99 (tangential_table_core.h: the same text the C headers
// carry), compiled into the library here, with a view of a TangentialTable for it.
#include <math.h>

#include "bounce/analysis/tables.hpp"

namespace bounce::analysis::detail {

// The lookup is C99 (written into the C headers as it is), so it keeps C's casts and
// conversions.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wconversion"
#include "tangential_table_core.h"
#pragma GCC diagnostic pop

inline tt_table view(const TangentialTable& t) {
  return tt_table{static_cast<int>(t.row_count()), static_cast<int>(t.s.size()), t.order, t.x0, t.dx,
                  t.asperity_size, t.s.data(), t.rows.data(), t.nodes.data()};
}

}  // namespace bounce::analysis::detail
