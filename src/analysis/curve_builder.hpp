#pragma once
// Private: builds a PiecewiseCubic of a function that is smooth between jumps (eps^N of the
// speed, with jumps where the outcome changes; docs/tables.md): jumps located by bisection,
// then every interval halved until cubic Hermite predicts its midpoint to a quarter of the
// bound.

#include <functional>
#include <map>
#include <utility>

#include "bounce/analysis/tables.hpp"

namespace bounce::analysis::detail {

struct Sample {
  double value;
  double label;
};
using Function = std::function<Sample(double)>;

class CurveBuilder {
 public:
  CurveBuilder(Function f, double bound, std::function<void()> tick);
  /// The curve on [lo, hi], starting from `initial` equal intervals.
  PiecewiseCubic build(double lo, double hi, int initial);

 private:
  Sample eval(double at);
  double slope(double at, const Sample& s);
  /// [a, b] holds a change away from `left` (the label at a; `at_b` the sample at b): the
  /// bracket narrowed to the jump width, and the sample at its right end.
  std::pair<std::pair<double, double>, Sample> locate_jump(double a, double b, double left, Sample at_b);
  void locate_jumps();
  void refine();
  void add(double at, const Sample& s);  ///< a node with its slope (none if already there)

  Function f_;
  double bound_;
  std::function<void()> tick_;
  double lo_ = 0.0, hi_ = 0.0;
  std::map<double, Sample> nodes_;
  std::map<double, double> slopes_;
};

}  // namespace bounce::analysis::detail
