#pragma once
// Private: the CVODE engine of stiff.hpp (BDF, dense direct linear solver with the
// system's analytic Jacobian, CVODE's own event location).

#include <memory>
#include <string>
#include <vector>

#include "stiff.hpp"

namespace bounce::dynamics::detail {

class CvodeIntegrator final : public StiffIntegrator {
 public:
  CvodeIntegrator(const StiffSystem& system, const std::vector<double>& y0, double t0,
                  const StiffSettings& settings);
  ~CvodeIntegrator() override;
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

  Step step() override;
  std::vector<double> state() const override;
  std::vector<double> state_at(double t) const override;
  long steps() const override;
  void disable_event(int index) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bounce::dynamics::detail
