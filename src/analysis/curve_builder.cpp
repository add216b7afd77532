#include "curve_builder.hpp"

#include <cmath>
#include <deque>

#include "bisect.hpp"
#include "bounce/core/error.hpp"

namespace bounce::analysis::detail {

namespace {

// Jumps are located to this width (in the logarithmic variable).
constexpr double jump_width = 1e-11;
// Step of the finite differences that give the node slopes: small enough for a
// truncation of ~1e-9, large enough that evaluation noise (~1e-10) stays ~1e-6.
constexpr double slope_step = 1e-4;
constexpr std::size_t max_nodes = 200000;

// Cubic Hermite on [x0, x1] (the same formula as nt_hermite of the C99 core).
double hermite(double x0, double f0, double d0, double x1, double f1, double d1, double x) {
  const double h = x1 - x0, t = (x - x0) / h, t2 = t * t, t3 = t2 * t;
  return (2 * t3 - 3 * t2 + 1) * f0 + (t3 - 2 * t2 + t) * h * d0 + (-2 * t3 + 3 * t2) * f1 + (t3 - t2) * h * d1;
}

}  // namespace

CurveBuilder::CurveBuilder(Function f, double bound, std::function<void()> tick)
    : f_(std::move(f)), bound_(bound), tick_(std::move(tick)) {}

Sample CurveBuilder::eval(double at) {
  if (tick_) tick_();
  return f_(at);
}

// A second-order difference inside the node's piece.
double CurveBuilder::slope(double at, const Sample& s) {
  const double h = slope_step;
  const bool left_ok = at - h >= lo_ - 1e-12, right_ok = at + h <= hi_ + 1e-12;
  Sample plus{0, 0}, minus{0, 0};
  if (left_ok) minus = eval(at - h);
  if (right_ok) plus = eval(at + h);
  const bool left = left_ok && minus.label == s.label, right = right_ok && plus.label == s.label;
  if (left && right) return (plus.value - minus.value) / (2 * h);
  if (right) {
    const Sample plus2 = eval(at + 2 * h);
    return (-3 * s.value + 4 * plus.value - plus2.value) / (2 * h);
  }
  if (left) {
    const Sample minus2 = eval(at - 2 * h);
    return (3 * s.value - 4 * minus.value + minus2.value) / (2 * h);
  }
  return 0.0;  // a one-node piece (a jump bracket too narrow to differentiate)
}

std::pair<std::pair<double, double>, Sample> CurveBuilder::locate_jump(double a, double b, double left, Sample at_b) {
  Sample right = at_b;
  const auto bracket = bisect(
      a, b,
      [&](double mid) {
        const Sample s = eval(mid);
        if (s.label == left) return true;
        right = s;
        return false;
      },
      [](double x, double y) { return 0.5 * (x + y); }, [](double x, double y) { return y - x <= jump_width; });
  return {bracket, right};
}

// Every jump between neighbours of the first grid, located to jump_width.
void CurveBuilder::locate_jumps() {
  for (bool again = true; again;) {
    again = false;
    for (auto it = nodes_.begin(); std::next(it) != nodes_.end(); ++it) {
      const auto next = std::next(it);
      if (it->second.label == next->second.label || next->first - it->first <= jump_width) continue;
      const auto [bracket, right] = locate_jump(it->first, next->first, it->second.label, next->second);
      nodes_.emplace(bracket.first, eval(bracket.first));
      nodes_.emplace(bracket.second, right);
      again = true;
      break;
    }
    if (nodes_.size() > max_nodes) throw NumericalError("table: too many jumps to locate");
  }
}

void CurveBuilder::add(double at, const Sample& s) {
  if (nodes_.emplace(at, s).second) slopes_[at] = slope(at, s);
}

// Halves every interval inside a piece until Hermite predicts its midpoint within bound/4;
// a jump that the first grid missed is located and both sides refined.
void CurveBuilder::refine() {
  std::deque<std::pair<double, double>> queue;
  for (auto it = nodes_.begin(); std::next(it) != nodes_.end(); ++it) {
    if (it->second.label == std::next(it)->second.label) queue.emplace_back(it->first, std::next(it)->first);
  }
  while (!queue.empty()) {
    const auto [a, b] = queue.front();
    queue.pop_front();
    if (b - a <= 2 * jump_width) continue;
    const double mid = 0.5 * (a + b);
    const Sample s = eval(mid);
    const Sample& sa = nodes_.at(a);
    if (s.label != sa.label) {
      const auto [bracket, right] = locate_jump(a, mid, sa.label, s);
      const Sample at_lo = eval(bracket.first);
      add(bracket.first, at_lo);
      add(bracket.second, right);
      add(mid, s);
      queue.emplace_back(a, bracket.first);
      queue.emplace_back(bracket.second, mid);
      queue.emplace_back(mid, b);
      continue;
    }
    const double guess = hermite(a, sa.value, slopes_.at(a), b, nodes_.at(b).value, slopes_.at(b), mid);
    if (std::abs(guess - s.value) > 0.25 * bound_) {
      add(mid, s);
      queue.emplace_back(a, mid);
      queue.emplace_back(mid, b);
    }
    if (nodes_.size() > max_nodes) throw NumericalError("table: the refinement does not converge (max nodes)");
  }
}

PiecewiseCubic CurveBuilder::build(double lo, double hi, int initial) {
  lo_ = lo;
  hi_ = hi;
  nodes_.clear();
  slopes_.clear();
  for (int i = 0; i <= initial; ++i) {
    const double at = lo + (hi - lo) * i / initial;
    if (!nodes_.count(at)) nodes_.emplace(at, eval(at));
  }
  locate_jumps();
  for (const auto& [at, s] : nodes_) slopes_[at] = slope(at, s);
  refine();
  PiecewiseCubic c;
  for (const auto& [at, s] : nodes_) {
    c.x.push_back(at);
    c.f.push_back(s.value);
    c.slope.push_back(slopes_.at(at));
    c.label.push_back(s.label);
  }
  return c;
}

}  // namespace bounce::analysis::detail
