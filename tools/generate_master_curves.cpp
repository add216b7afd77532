// Build-time generator of the viscoelastic master curves (docs/viscoelastic.md).
//
// Integrates the scaled collision with the long-double reference of
// master_reference.hpp at Chebyshev nodes of every domain, fits Chebyshev
// series, checks that each has converged (the build fails otherwise) and writes
// the coefficients as C++ source.
//
// Usage: generate_master_curves OUTPUT.cpp
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include <Eigen/Dense>

#include "master_reference.hpp"

using bounce::reference::MasterQuantities;
using bounce::reference::Real;
using bounce::reference::master_quantities;

namespace {

constexpr int small_nodes = 32;
constexpr int octave_count = 27;
constexpr int octave_max_nodes = 32;
constexpr int overlap_octaves = 3;
constexpr Real overlap_tail_start = 8;
constexpr int tail_nodes = 20;

Real node(int j, int n) { return std::cos(M_PIl * (j + Real(0.5)) / n); }  // first kind

std::vector<Real> chebyshev(const std::vector<Real>& values) {
  const int n = static_cast<int>(values.size());
  std::vector<Real> c(static_cast<std::size_t>(n));
  for (int m = 0; m < n; ++m) {
    Real s = 0;
    for (int j = 0; j < n; ++j) s += values[static_cast<std::size_t>(j)] * std::cos(M_PIl * m * (j + Real(0.5)) / n);
    c[static_cast<std::size_t>(m)] = 2 * s / n;
  }
  c[0] /= 2;
  return c;
}

// Convergence of a Chebyshev series: the largest of its last four coefficients
// relative to the largest coefficient.
Real tail_estimate(const std::vector<Real>& c) {
  Real big = 0, tail = 0;
  for (Real v : c) big = std::max(big, std::fabs(v));
  for (std::size_t i = c.size() - 4; i < c.size(); ++i) tail = std::max(tail, std::fabs(c[i]));
  return tail / big;
}

// Evaluate the reference at many kappa in parallel (two cores at build time).
std::vector<MasterQuantities> evaluate(const std::vector<Real>& kappas, const std::vector<bool>& overlap) {
  std::vector<MasterQuantities> out(kappas.size());
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i; (i = next++) < kappas.size();) out[i] = master_quantities(kappas[i], overlap[i]);
  };
  const unsigned threads = std::max(1u, std::min(4u, std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  return out;
}

std::string row(const std::vector<Real>& c, int width) {
  std::string s = "{";
  for (int i = 0; i < width; ++i) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", i < static_cast<int>(c.size()) ? static_cast<double>(c[static_cast<std::size_t>(i)]) : 0.0);
    s += (i ? ", " : "") + std::string(buf);
  }
  return s + "}";
}

// Least-squares fit of r(kappa) = sum_{j<p} c_j kappa^j with rows weighted by kappa^w
// (the reference error of r grows like kappa^-w near zero).
std::vector<Real> polyfit(const std::vector<Real>& k, const std::vector<Real>& r, Real kmax, int p, Real w) {
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < k.size(); ++i) {
    if (k[i] <= kmax) rows.push_back(i);
  }
  using Matrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
  using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
  Matrix a(static_cast<Eigen::Index>(rows.size()), p);
  Vector y(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Real weight = std::pow(k[rows[i]], w);
    for (int j = 0; j < p; ++j) a(static_cast<Eigen::Index>(i), j) = std::pow(k[rows[i]], j) * weight;
    y(static_cast<Eigen::Index>(i)) = r[rows[i]] * weight;
  }
  const Vector c = a.colPivHouseholderQr().solve(y);
  return std::vector<Real>(c.data(), c.data() + c.size());
}

// Median and spread over fits with several ranges and orders: a coefficient is kept
// while its spread stays below 2% of its value.
struct Coefficient {
  Real value;
  Real uncertainty;
};
std::vector<Coefficient> robust_fit(const std::vector<Real>& k, const std::vector<Real>& r, Real w) {
  std::vector<std::vector<Real>> fits;
  for (Real kmax : {Real(0.04), Real(0.08), Real(0.15)}) {
    for (int p : {5, 7, 9}) fits.push_back(polyfit(k, r, kmax, p, w));
  }
  std::vector<Coefficient> out;
  for (std::size_t j = 0; j < 4; ++j) {
    std::vector<Real> v;
    for (const auto& f : fits) v.push_back(f[j]);
    std::sort(v.begin(), v.end());
    const Real median = v[v.size() / 2];
    const Real spread = std::max(v.back() - median, median - v.front());
    if (spread > Real(0.02) * std::fabs(median)) break;
    out.push_back({median, spread});
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s OUTPUT.cpp\n", argv[0]);
    return 2;
  }
  Real worst = 0;
  auto check = [&](const char* what, int piece, const std::vector<Real>& c, Real limit) {
    const Real t = tail_estimate(c);
    worst = std::max(worst, t);
    if (t > limit) {
      std::fprintf(stderr, "master curves: %s piece %d not converged (tail %.2Le > %.0Le)\n", what, piece, t, limit);
      std::exit(1);
    }
  };
  using Get = std::function<Real(const MasterQuantities&, Real)>;
  const std::vector<Get> quantities = {
      [](const MasterQuantities& q, Real) { return q.cor_overlap; },
      [](const MasterQuantities& q, Real) { return q.contact_time_overlap; },
      [](const MasterQuantities& q, Real) { return q.cor_force; },
      [](const MasterQuantities& q, Real) { return q.contact_time_force; },
      [](const MasterQuantities& q, Real) { return q.max_overlap; },
  };
  const char* names[] = {"cor_overlap", "time_overlap", "cor_force", "time_force", "max_overlap"};

  // Small domain: u = sqrt(kappa) in [0, 1].
  std::vector<Real> kappas;
  std::vector<bool> overlap;
  for (int j = 0; j < small_nodes; ++j) {
    const Real u = (node(j, small_nodes) + 1) / 2;
    kappas.push_back(u * u);
    overlap.push_back(true);
  }
  // Octaves.
  std::vector<int> octave_nodes(octave_count);
  for (int k = 0; k < octave_count; ++k) {
    octave_nodes[static_cast<std::size_t>(k)] = k < overlap_octaves ? 32 : 24;
    for (int j = 0; j < octave_nodes[static_cast<std::size_t>(k)]; ++j) {
      kappas.push_back(std::ldexp(Real(1), k) * (1 + (node(j, octave_nodes[static_cast<std::size_t>(k)]) + 1) / 2));
      overlap.push_back(k < overlap_octaves);
    }
  }
  // Overlap-rule tail: z = (kappa/8)^(-5/3) in (0, 1].
  for (int j = 0; j < tail_nodes; ++j) {
    const Real z = (node(j, tail_nodes) + 1) / 2;
    kappas.push_back(overlap_tail_start * std::pow(z, Real(-0.6)));
    overlap.push_back(true);
  }
  // Series samples (geometric in kappa, 1e-4 .. 0.15).
  const std::size_t series_begin = kappas.size();
  constexpr int series_samples = 160;
  for (int i = 0; i < series_samples; ++i) {
    kappas.push_back(Real(1e-4) * std::pow(Real(1500), Real(i) / (series_samples - 1)));
    overlap.push_back(true);
  }
  const auto results = evaluate(kappas, overlap);
  std::size_t at = 0;

  std::string out = "// Generated by tools/generate_master_curves.cpp at build time. Do not edit.\n"
                    "#include \"master_curve_data.hpp\"\n\nnamespace bounce::analytic::detail {\n\n";
  out += "const double small_coefficients[quantity_count][small_nodes] = {\n";
  for (std::size_t q = 0; q < quantities.size(); ++q) {
    std::vector<Real> values;
    for (int j = 0; j < small_nodes; ++j) values.push_back(quantities[q](results[at + static_cast<std::size_t>(j)], kappas[at + static_cast<std::size_t>(j)]));
    const auto c = chebyshev(values);
    check(names[q], -1, c, 1e-14L);
    out += "    " + row(c, small_nodes) + ",\n";
  }
  out += "};\n\n";
  at += small_nodes;

  out += "const int octave_nodes[octave_count] = {";
  for (int k = 0; k < octave_count; ++k) out += (k ? ", " : "") + std::to_string(octave_nodes[static_cast<std::size_t>(k)]);
  out += "};\n\nconst double octave_coefficients[octave_count][quantity_count][octave_max_nodes] = {\n";
  for (int k = 0; k < octave_count; ++k) {
    const int n = octave_nodes[static_cast<std::size_t>(k)];
    out += "  {\n";
    for (std::size_t q = 0; q < quantities.size(); ++q) {
      std::vector<Real> values;
      const bool used = q == 0 || q == 1 ? k < overlap_octaves : true;
      for (int j = 0; j < n; ++j) {
        const auto& r = results[at + static_cast<std::size_t>(j)];
        const Real kappa = kappas[at + static_cast<std::size_t>(j)];
        Real v = used ? quantities[q](r, kappa) : 0;
        if (q == 0) v *= std::pow(kappa, 5);  // e kappa^5 saturates smoothly at C
        values.push_back(v);
      }
      const auto c = chebyshev(values);
      if (used) check(names[q], k, c, 1e-13L);
      out += "    " + row(used ? c : std::vector<Real>{}, octave_max_nodes) + ",\n";
    }
    out += "  },\n";
    at += static_cast<std::size_t>(n);
  }
  out += "};\n\n";

  // Tail: e kappa^5 must be constant (its corrections are below 1e-15 for kappa >= 8).
  std::vector<Real> phi, constant;
  for (int j = 0; j < tail_nodes; ++j) {
    const auto& r = results[at + static_cast<std::size_t>(j)];
    const Real kappa = kappas[at + static_cast<std::size_t>(j)];
    phi.push_back(r.contact_time_overlap / kappa - Real(8) / 3 * std::log(kappa));
    constant.push_back(r.cor_overlap * std::pow(kappa, 5));
  }
  std::vector<Real> sorted = constant;
  std::sort(sorted.begin(), sorted.end());
  const Real c_tail = sorted[sorted.size() / 2];
  for (Real v : constant) {
    if (std::fabs(v / c_tail - 1) > 1e-12L) {
      std::fprintf(stderr, "master curves: e kappa^5 not constant in the tail (%.17Lg vs %.17Lg)\n", v, c_tail);
      return 1;
    }
  }
  const auto phi_c = chebyshev(phi);
  check("tail time_overlap", 0, phi_c, 1e-13L);
  out += "const double tail_time_coefficients[tail_nodes] = " + row(phi_c, tail_nodes) + ";\n";
  char buf[200];
  std::snprintf(buf, sizeof buf, "const double tail_cor_constant = %.17g;\nconst double fit_error_estimate = %.3g;\n",
                static_cast<double>(c_tail), static_cast<double>(worst));
  out += buf;

  // Series: the overlap rule in integer powers of kappa with the exact c1, c2; the
  // force rule as kappa^{5/2} times a power series with the exact d0.
  const Real b = std::sqrt(M_PIl) * std::tgamma(Real(0.6)) / (5 * std::tgamma(Real(2.1)));
  const Real c1 = -2 * b, c2 = Real(0.6) * 4 * b * b, d0 = 32 / (75 * std::sqrt(Real(5)));
  std::vector<Real> sk, ro, rf;
  for (int i = 0; i < series_samples; ++i) {
    const auto& q = results[series_begin + static_cast<std::size_t>(i)];
    const Real k = kappas[series_begin + static_cast<std::size_t>(i)];
    sk.push_back(k);
    ro.push_back((q.cor_overlap - 1 - c1 * k - c2 * k * k) / (k * k * k));
    rf.push_back(((q.cor_force - q.cor_overlap) / std::pow(k, Real(2.5)) - d0) / k);
  }
  const auto overlap_fit = robust_fit(sk, ro, 3);
  const auto force_fit = robust_fit(sk, rf, Real(3.5));
  std::vector<Real> os{c1, c2}, ou{0, 0}, fs{d0}, fu{0};
  for (const auto& c : overlap_fit) os.push_back(c.value), ou.push_back(c.uncertainty);
  for (const auto& c : force_fit) fs.push_back(c.value), fu.push_back(c.uncertainty);
  out += "\nconst int overlap_series_terms = " + std::to_string(os.size()) + ";\n";
  out += "const double overlap_series[series_capacity] = " + row(os, 8) + ";\n";
  out += "const double overlap_series_uncertainty[series_capacity] = " + row(ou, 8) + ";\n";
  out += "const int force_series_terms = " + std::to_string(fs.size()) + ";\n";
  out += "const double force_series[series_capacity] = " + row(fs, 8) + ";\n";
  out += "const double force_series_uncertainty[series_capacity] = " + row(fu, 8) + ";\n";
  std::fprintf(stderr, "master curves: overlap series c3.. =");
  for (const auto& c : overlap_fit) std::fprintf(stderr, " %.10Lg(+-%.1Lg)", c.value, c.uncertainty);
  std::fprintf(stderr, "; force correction d1.. =");
  for (const auto& c : force_fit) std::fprintf(stderr, " %.10Lg(+-%.1Lg)", c.value, c.uncertainty);
  std::fprintf(stderr, "\n");

  out += "\n}  // namespace bounce::analytic::detail\n";

  std::ofstream(argv[1]) << out;
  std::fprintf(stderr, "master curves: %zu reference integrations, worst Chebyshev tail %.2Le, C = %.15Lg\n",
               kappas.size(), worst, c_tail);
  return 0;
}
