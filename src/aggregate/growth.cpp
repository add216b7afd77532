// Ballistic aggregation (docs/aggregates.md): BPCA adds one monomer at a time, BCCA joins equal
// clusters pairwise; each arrives on a straight line of random direction and offset and sticks
// where it first touches. Compiled with -ffp-contract=off (src/CMakeLists.txt), so that a seed
// gives the same aggregate on every platform.
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include <fmt/format.h>

#include "bounce/aggregate/aggregate.hpp"
#include "bounce/core/error.hpp"
#include "cell_list.hpp"
#include "geometry.hpp"
#include "projected_grid.hpp"
#include "random.hpp"

namespace bounce::aggregate {

using namespace detail;  // Vector arithmetic, Random (this file's)

namespace {

// Shots that all miss before a build gives up: a shot hits with probability >= (2r / reach)^2
// (the shadow of one monomer in the aiming disk), >= 1e-6 at reach <= 1000 r.
constexpr long max_misses = 100000000;

// A line aimed at the cluster: direction u, passing through `through` at s = 0.
struct Shot {
  Vector u;
  Vector through;
};

// A direction uniform on the sphere and a point uniform in the disk of radius `reach` about
// `centre` perpendicular to it: a uniform flux of parallel lines over the cluster's shadow.
Shot aim(Random& random, const Vector& centre, double reach) {
  Shot shot;
  shot.u = random.direction();
  Vector e1, e2;
  detail::plane_basis(shot.u, e1, e2);
  double x = 0.0, y = 0.0, s = 0.0;
  random.disk(x, y, s);
  shot.through = centre + (reach * x) * e1 + (reach * y) * e2;
  return shot;
}

void check(const BuildRequest& r) {
  const std::string n = std::to_string(r.n);
  if (r.n < 1 || r.n > max_monomers) {
    throw InvalidArgument("n", n, fmt::format("a number of monomers 1 <= n <= {}", max_monomers));
  }
  if (r.kind == Kind::bcca && (r.n & (r.n - 1)) != 0) {
    throw InvalidArgument("n", n, "a power of 2 for bcca (clusters join in equal pairs: 1, 2, 4, ..., 1024, ...)");
  }
  if (!(r.radius > 0.0) || !std::isfinite(r.radius)) {
    throw InvalidArgument("radius", fmt::format("{}", r.radius), "monomer radius r [m] > 0 and finite");
  }
}

// BPCA: a monomer at a time from a uniform flux over the disk of radius max|x_i| + 2r about the
// first monomer; the first monomer it touches holds it. R_g after each addition in `history`.
Aggregate grow_bpca(const BuildRequest& request, const Progress& progress) {
  const double contact = 2.0 * request.radius;
  Aggregate a{request, {Vector{0, 0, 0}}, {GrowthPoint{1, 0.0}}};
  a.centres.reserve(request.n);
  Random random(request.seed);
  detail::CellList cells(request.radius);
  cells.add(a.centres.front(), 0);
  Vector sum{0, 0, 0};
  double sum_squares = 0.0, extent = 0.0;
  long misses = 0;
  while (a.centres.size() < request.n) {
    const Shot shot = aim(random, Vector{0, 0, 0}, extent + contact);
    const double first = cells.first_touch(shot.through, shot.u, a.centres);
    if (std::isinf(first)) {
      if (++misses > max_misses) throw NumericalError("bpca: no shot hit the aggregate (aiming bug)");
      continue;
    }
    const Vector p = shot.through + first * shot.u;
    cells.add(p, a.centres.size());
    a.centres.push_back(p);
    sum = sum + p;
    sum_squares += dot(p, p);
    extent = std::max(extent, std::sqrt(dot(p, p)));
    const double n = static_cast<double>(a.centres.size());
    const Vector mean = (1.0 / n) * sum;
    a.history.push_back({a.centres.size(), std::sqrt(std::max(0.0, sum_squares / n - dot(mean, mean)))});
    if (progress && a.centres.size() % 1024 == 0) progress(a.centres.size(), request.n);
  }
  return a;
}

// The centres moved so that their mean is the origin.
void centre(std::vector<Vector>& xs) {
  Vector sum{0, 0, 0};
  for (const Vector& x : xs) sum = sum + x;
  const Vector mean = (1.0 / static_cast<double>(xs.size())) * sum;
  for (Vector& x : xs) x = x - mean;
}

double extent_of(const std::vector<Vector>& xs) {
  double e = 0.0;
  for (const Vector& x : xs) e = std::max(e, dot(x, x));
  return std::sqrt(e);
}

// BCCA: B, turned by a random rotation, comes along a random line toward A (both centred); the
// first touching pair (i, j) over all pairs, found through A's grid in the plane across the
// line, fixes where B stops. Returns A and B joined, centred.
std::vector<Vector> join(const std::vector<Vector>& a, const std::vector<Vector>& b, double contact, Random& random) {
  const detail::Rotation turn = random.rotation();
  std::vector<Vector> turned(b.size());
  for (std::size_t j = 0; j < b.size(); ++j) turned[j] = {dot(turn[0], b[j]), dot(turn[1], b[j]), dot(turn[2], b[j])};
  const double reach = extent_of(a) + extent_of(turned) + contact;
  for (long misses = 0; misses <= max_misses; ++misses) {
    const Shot shot = aim(random, Vector{0, 0, 0}, reach);
    const detail::ProjectedGrid grid(a, shot.u, contact);
    double first = std::numeric_limits<double>::infinity();
    for (const Vector& y : turned) first = std::min(first, grid.first_touch(y + shot.through));
    if (std::isinf(first)) continue;
    std::vector<Vector> joined = a;
    for (const Vector& y : turned) joined.push_back(y + shot.through + first * shot.u);
    centre(joined);
    return joined;
  }
  throw NumericalError("bcca: no shot hit the cluster (aiming bug)");
}

Aggregate grow_bcca(const BuildRequest& request, const Progress& progress) {
  const double contact = 2.0 * request.radius;
  Random random(request.seed);
  std::vector<std::vector<Vector>> clusters(request.n, std::vector<Vector>{Vector{0, 0, 0}});
  Aggregate out{request, {}, {GrowthPoint{1, 0.0}}};
  while (clusters.size() > 1) {
    std::vector<std::vector<Vector>> next;
    double log_sum = 0.0;
    for (std::size_t k = 0; k + 1 < clusters.size(); k += 2) {
      next.push_back(join(clusters[k], clusters[k + 1], contact, random));
      log_sum += std::log(radius_of_gyration(next.back()));
    }
    clusters = std::move(next);
    out.history.push_back({clusters.front().size(), std::exp(log_sum / static_cast<double>(clusters.size()))});
    if (progress) progress(clusters.front().size(), request.n);
  }
  out.centres = std::move(clusters.front());
  return out;
}

}  // namespace

const char* kind_name(Kind kind) { return kind == Kind::bpca ? "bpca" : "bcca"; }

double radius_of_gyration(const std::vector<Vector>& centres) {
  Vector sum{0, 0, 0};
  for (const Vector& x : centres) sum = sum + x;
  const Vector mean = (1.0 / static_cast<double>(centres.size())) * sum;
  double squares = 0.0;
  for (const Vector& x : centres) squares += dot(x - mean, x - mean);
  return std::sqrt(squares / static_cast<double>(centres.size()));
}

Aggregate build(const BuildRequest& request, const Progress& progress) {
  check(request);
  Aggregate a = request.kind == Kind::bpca ? grow_bpca(request, progress) : grow_bcca(request, progress);
  centre(a.centres);
  return a;
}

}  // namespace bounce::aggregate
