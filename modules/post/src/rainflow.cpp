#include "fowtsim/post/rainflow.hpp"

#include <cmath>

#include "fowtsim/core/error.hpp"

namespace fowtsim::post {

std::vector<double> turning_points(std::span<const double> values) {
  std::vector<double> points;
  if (values.empty()) return points;
  points.reserve(values.size() / 2 + 2);
  for (const double v : values) {
    if (std::isnan(v)) throw InputError({"post.rainflow", std::nullopt, "values", ""}, "rainflow counting of a series holding NaN");
    if (!points.empty() && v == points.back()) continue;  // plateau: one point
    // Still rising (or falling) after the last two points: the last one was no turning point.
    if (points.size() >= 2 && (points.back() - points[points.size() - 2]) * (v - points.back()) > 0.0) {
      points.back() = v;
    } else {
      points.push_back(v);
    }
  }
  return points;
}

std::vector<RainflowCycle> rainflow_cycles(std::span<const double> values, ResidueCounting residue) {
  const std::vector<double> points = turning_points(values);
  std::vector<RainflowCycle> cycles;
  cycles.reserve(points.size());
  std::vector<double> stack;
  stack.reserve(points.size());
  for (const double point : points) {
    stack.push_back(point);
    // Four-point test on the top of the stack, repeated while it closes cycles (ASTM §5.4.4.4).
    while (stack.size() >= 4) {
      const std::size_t n = stack.size();
      const double a = stack[n - 4], b = stack[n - 3], c = stack[n - 2], d = stack[n - 1];
      const double inner = std::abs(b - c);
      if (inner > std::abs(a - b) || inner > std::abs(c - d)) break;
      cycles.push_back({inner, 0.5 * (b + c), 1.0});
      stack.erase(stack.end() - 3, stack.end() - 1);  // drop b and c, keep d
    }
  }
  const double residue_count = residue == ResidueCounting::half_cycles ? 0.5 : 1.0;
  for (std::size_t i = 1; i < stack.size(); ++i)
    cycles.push_back({std::abs(stack[i] - stack[i - 1]), 0.5 * (stack[i] + stack[i - 1]), residue_count});
  return cycles;
}

}  // namespace fowtsim::post
