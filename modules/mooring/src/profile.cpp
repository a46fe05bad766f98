#include "fowtsim/mooring/profile.hpp"

#include <fmt/format.h>

#include "fowtsim/core/error.hpp"
#include "line_solution.hpp"

namespace fowtsim::mooring {

std::vector<LineNode> line_profile(const MooringParams& p, const QuasiStaticMooring::Input& u,
                                   const QuasiStaticMooring::State& s, std::size_t index, std::size_t node_count) {
  if (index >= p.lines.size() || node_count < 2) {
    throw InputError({"mooring", std::nullopt, "line_profile", "index < number of lines, node_count ≥ 2"},
                     fmt::format("line_profile: index {} of {} lines, node_count {}", index, p.lines.size(),
                                 node_count));
  }
  detail::check_pose(u.platform, u.time_s);
  const detail::LineGeometry g = detail::line_geometry(p, index, u.platform);
  const detail::SolvedLine solved = detail::solve_line(p, index, g, s.lines[index], u.time_s);
  const LineParams& line = p.lines[index];
  std::vector<LineNode> nodes(node_count);
  for (std::size_t k = 0; k < node_count; ++k) {
    LineNode& n = nodes[k];
    n.arc_length_m = line.unstretched_length_m * static_cast<double>(k) / static_cast<double>(node_count - 1);
    if (p.model == LineModel::taut) {
      n.position_m = line.anchor_m + g.chord_m * (n.arc_length_m / line.unstretched_length_m);
      n.tension_N = solved.output.fairlead_tension_N;
    } else {
      const CatenaryLine cat = catenary_line(p, index);
      const Eigen::Vector2d xz = catenary_point(cat, solved.catenary, n.arc_length_m);
      n.position_m = line.anchor_m + xz.x() * g.horizontal_unit + xz.y() * Vec3::UnitZ();
      n.tension_N = catenary_tension(cat, solved.catenary, n.arc_length_m);
    }
  }
  return nodes;
}

}  // namespace fowtsim::mooring
