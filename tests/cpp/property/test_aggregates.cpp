// Aggregates (docs/aggregates.md) on random kinds, sizes, radii and seeds: no two monomers
// overlap, the contacts form a tree that holds every monomer (each touches another, and BPCA's
// and BCCA's sticking at first touch makes exactly n - 1 contacts), and a seed gives the same
// aggregate twice.
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "bounce/aggregate/aggregate.hpp"
#include "property/generators.hpp"

using namespace bounce;
using namespace bounce::aggregate;

namespace {

// Round-off of a centre distance: each centre is a sum of ~10 rounded terms of the aggregate's
// size (<= ~100 r here), so |d - 2r| stays below ~10 * 1.1e-16 * 100 r = 1.1e-13 r; 1e-12 r bounds it.
constexpr double round_off = 1e-12;

rc::Gen<BuildRequest> requests() {
  return rc::gen::exec([] {
    BuildRequest r;
    r.kind = *rc::gen::element(Kind::bpca, Kind::bcca);
    r.n = r.kind == Kind::bpca ? *rc::gen::inRange<std::size_t>(1, 300) : std::size_t{1} << *rc::gen::inRange(0, 9);
    r.radius = *property::log_uniform(1e-9, 1e-2);
    r.seed = *rc::gen::arbitrary<std::uint64_t>();
    return r;
  });
}

// The case, to replay it (in the property's log, printed when it fails).
BuildRequest logged(const BuildRequest& r) {
  std::ostringstream os;
  os.precision(17);
  os << "kind " << kind_name(r.kind) << " n " << r.n << " radius " << r.radius << " seed " << r.seed;
  RC_LOG() << os.str() << "\n";
  return r;
}

std::size_t root(std::vector<std::size_t>& parent, std::size_t i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

}  // namespace

RC_GTEST_PROP(Aggregates, NoOverlapAndTheContactsAreOneTreeOfEveryMonomer, ()) {
  const BuildRequest request = logged(*requests());
  const Aggregate a = build(request);
  RC_ASSERT(a.centres.size() == request.n);
  const double contact = 2.0 * request.radius;
  std::vector<std::size_t> parent(a.centres.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  std::size_t touching = 0;
  for (std::size_t i = 0; i < a.centres.size(); ++i) {
    for (std::size_t j = i + 1; j < a.centres.size(); ++j) {
      const double d = std::hypot(a.centres[i][0] - a.centres[j][0], a.centres[i][1] - a.centres[j][1],
                                  a.centres[i][2] - a.centres[j][2]);
      RC_ASSERT(d >= contact * (1.0 - round_off));  // no overlap
      if (d <= contact * (1.0 + round_off)) {       // touching, to round-off
        ++touching;
        parent[root(parent, i)] = root(parent, j);
      }
    }
  }
  RC_ASSERT(touching == request.n - 1);  // one new contact per monomer (BPCA) or per join (BCCA)
  for (std::size_t i = 0; i < parent.size(); ++i) RC_ASSERT(root(parent, i) == root(parent, 0));  // connected
  RC_ASSERT(count_contacts(a.centres, request.radius, contact_tolerance) == touching);  // the cell grid agrees
}

RC_GTEST_PROP(Aggregates, TheSameSeedGivesTheSameAggregateBitForBit, ()) {
  const BuildRequest request = logged(*requests());
  RC_ASSERT(build(request).centres == build(request).centres);
  if (request.n >= 3) {
    BuildRequest other = request;
    other.seed = request.seed + 1;
    RC_ASSERT(build(other).centres != build(request).centres);
  }
}
