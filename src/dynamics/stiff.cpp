#include "stiff.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#ifndef BOUNCE_WITHOUT_CVODE
#include "cvode_integrator.hpp"
#endif
#include "rodas_integrator.hpp"

namespace bounce::dynamics::detail {

namespace {
// The original state on the stack (these run several times per step).
constexpr int max_size = 16;
using Small = std::array<double, max_size>;
}  // namespace


SwappedIndependent::SwappedIndependent(const StiffSystem& inner, int index, double sign)
    : inner_(inner), index_(index), sign_(sign) {
  if (inner.size() > max_size) throw NumericalError("SwappedIndependent: system too large");
}

std::vector<double> SwappedIndependent::original(double s, const double* z) const {
  std::vector<double> y(z, z + size());
  y[static_cast<std::size_t>(index_)] = sign_ * s;
  return y;
}

int SwappedIndependent::rhs(double s, const double* z, double* dzds) const {
  Small y;
  std::copy(z, z + size(), y.begin());
  y[static_cast<std::size_t>(index_)] = sign_ * s;
  const int flag = inner_.rhs(z[index_], y.data(), dzds);
  if (flag != 0) return flag;
  const double rate = dzds[index_];  // d y_index / dt
  if (!(std::isfinite(rate) && rate != 0.0)) return 1;
  for (int i = 0; i < size(); ++i) dzds[i] = i == index_ ? sign_ / rate : sign_ * dzds[i] / rate;
  return 0;
}

int SwappedIndependent::jacobian(double s, const double* z, double* j, double* dfds) const {
  Small f;
  return linearize(s, z, f.data(), j, dfds, nullptr);
}

int SwappedIndependent::linearize(double s, const double* z, double* dzds, double* j, double* dfds, double* g) const {
  const int n = size();
  Small y, f, rate_row;
  std::copy(z, z + n, y.begin());
  y[static_cast<std::size_t>(index_)] = sign_ * s;
  const int flag = inner_.linearize(z[index_], y.data(), f.data(), j, nullptr, g);  // the inner system is autonomous
  if (flag != 0) return flag;
  const double rate = f[static_cast<std::size_t>(index_)];  // d y_index / dt
  if (!(std::isfinite(rate) && rate != 0.0)) return 1;
  for (int i = 0; i < n; ++i) {
    dzds[i] = i == index_ ? sign_ / rate : sign_ * f[static_cast<std::size_t>(i)] / rate;
  }
  // With x = y_index and F_i = f_i / f_x (F_x = 1 / f_x): dF_i/dy_k = (J_ik - f_i J_xk / f_x) / f_x
  // for the original components, with f_x replaced by 1 in row x. Column x becomes the
  // time (autonomous: zero) and dF/ds = sign dF/dy_x.
  std::copy(j + index_ * n, j + (index_ + 1) * n, rate_row.begin());
  for (int i = 0; i < n; ++i) {
    const double fi = i == index_ ? 1.0 : f[static_cast<std::size_t>(i)];
    for (int k = 0; k < n; ++k) {
      double& out = j[i * n + k];
      const double jik = i == index_ ? 0.0 : out;
      const double d = (jik - fi * rate_row[static_cast<std::size_t>(k)] / rate) / rate;  // dF_i/dy_k
      if (k == index_) {
        if (dfds != nullptr) dfds[i] = sign_ * sign_ * d;  // dz_i/ds = sign F_i, dy_x/ds = sign
        out = 0.0;
      } else {
        out = sign_ * d;
      }
    }
  }
  return 0;
}

void SwappedIndependent::events(double s, const double* z, double* g) const {
  Small y;
  std::copy(z, z + size(), y.begin());
  y[static_cast<std::size_t>(index_)] = sign_ * s;
  inner_.events(z[index_], y.data(), g);
}

std::unique_ptr<StiffIntegrator> make_stiff_integrator(StiffEngine engine, const StiffSystem& system,
                                                       const std::vector<double>& y0, double t0,
                                                       const StiffSettings& settings) {
#ifndef BOUNCE_WITHOUT_CVODE
  if (engine == StiffEngine::cvode) return std::make_unique<CvodeIntegrator>(system, y0, t0, settings);
#else  // the browser explorer's build (docs/explorer.md): RODAS only
  if (engine == StiffEngine::cvode) throw NumericalError("SUNDIALS CVODE is not part of this build (the browser explorer's); RODAS only");
#endif
  return std::make_unique<RodasIntegrator>(system, y0, t0, settings);
}

}  // namespace bounce::dynamics::detail
