#include "fowtsim/beam/beam_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation.hpp"
#include "fowtsim/core/rotation_vector.hpp"

namespace fowtsim::beam {
namespace {

[[noreturn]] void fail(const std::string& variable, const std::string& message) {
  throw InputError({"beam", std::nullopt, variable, ""}, message);
}

template <class Get>
Mat6 interpolate_station(const BeamDefinition& def, double eta, Get get) {
  const auto& st = def.stations;
  if (eta <= st.front().eta) return get(st.front());
  if (eta >= st.back().eta) return get(st.back());
  const auto hi = std::upper_bound(st.begin(), st.end(), eta,
                                   [](double e, const Station& s) { return e < s.eta; });
  const auto lo = hi - 1;
  const double w = (eta - lo->eta) / (hi->eta - lo->eta);
  return (1.0 - w) * get(*lo) + w * get(*hi);
}

}  // namespace

void validate(const BeamDefinition& def) {
  if (def.stations.size() < 1) fail("stations", "need at least one station");
  if (def.root_end == EndCondition::free) fail("root_end", "the root is clamped or pinned, not free");
  for (std::size_t i = 0; i < def.stations.size(); ++i) {
    const Station& s = def.stations[i];
    if (i > 0 && !(s.eta > def.stations[i - 1].eta))
      fail("stations[" + std::to_string(i) + "].eta", "eta must increase along the beam");
    if (!s.stiffness.allFinite() || !s.mass.allFinite())
      fail("stations[" + std::to_string(i) + "]", "stiffness and mass must be finite");
    if (s.mass(0, 0) < 0.0)
      fail("stations[" + std::to_string(i) + "].mass", "mass per length must be ≥ 0");
  }
  if ((def.stiffness_damping.array() < 0.0).any() || def.mass_damping_1_s < 0.0)
    fail("damping", "damping coefficients must be ≥ 0");
}

namespace {

// Segment inertia about its node, in the node's local frame: 4 sub-intervals × 3-point Gauss
// (exact for cubic variation per sub-interval; property tables vary linearly between stations).
void integrate_segment(const BeamDefinition& def, double s0, double s1, NodeModel& node) {
  static constexpr std::array<double, 3> kX{-0.7745966692414834, 0.0, 0.7745966692414834};
  static constexpr std::array<double, 3> kW{5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  constexpr int kSub = 4;
  const double length = def.line.length_m();
  const Mat3 rt = node.orientation.transpose();
  double mass = 0.0;
  Vec3 first = Vec3::Zero(), arm = Vec3::Zero();
  Mat3 inertia = Mat3::Zero();
  const double h = (s1 - s0) / kSub;
  for (int k = 0; k < kSub; ++k)
    for (int g = 0; g < 3; ++g) {
      const double s = s0 + h * (k + 0.5 + 0.5 * kX[g]);
      const double w = 0.5 * h * kW[g];
      const LinePoint p = def.line.at(s);
      const Mat6 m6 = mass_at(def, s / length);
      const double m = m6(0, 0);
      const Mat3 r_rel = rt * p.frame;                     // local frame at s, in node frame
      const Vec3 d = rt * (p.position_m - node.position_m);  // reference point − node
      const Vec3 e = m > 0.0 ? Vec3(r_rel * axial(m6.block<3, 3>(3, 0)) / m) : Vec3::Zero();
      mass += w * m;
      first += w * m * (d + e);
      arm += w * d;
      inertia += w * (r_rel * m6.block<3, 3>(3, 3) * r_rel.transpose() +
                      m * (d.squaredNorm() * Mat3::Identity() - d * d.transpose()) +
                      m * (2.0 * d.dot(e) * Mat3::Identity() - d * e.transpose() - e * d.transpose()));
    }
  node.mass_kg = mass;
  node.mass_offset_m = mass > 0.0 ? Vec3(first / mass) : Vec3::Zero();
  node.inertia_kg_m2 = 0.5 * (inertia + inertia.transpose());
  node.load_arm_m = arm / (s1 - s0);
}

}  // namespace

Mat6 stiffness_at(const BeamDefinition& def, double eta) {
  return interpolate_station(def, eta, [](const Station& s) { return s.stiffness; });
}

Mat6 mass_at(const BeamDefinition& def, double eta) {
  return interpolate_station(def, eta, [](const Station& s) { return s.mass; });
}

// A held end section becomes a pin (seed §3.4.3's imaginary segment with θ mirrored equal): it
// joins the node to its ghost, the node's mirror image through the end point with the node's own
// orientation, so the section sits on the end point, carries no moment and keeps it in place.
static void hold_by_pin(SectionModel& sec, const NodeModel& node, const Vec3& end_point) {
  sec.pinned = true;
  sec.alpha = 0.5;
  sec.length_m = 2.0 * (node.position_m - end_point).norm();
  const Vec3 chord = sec.inboard == kRootEnd ? Vec3(node.position_m - end_point) : Vec3(end_point - node.position_m);
  sec.chord_ref = node.orientation.transpose() * (2.0 * chord) / sec.length_m;
  sec.curvature_ref.setZero();
}

BeamModel discretise(const BeamDefinition& def, int segments) {
  if (segments < 1) fail("segments", "need at least one segment, got " + std::to_string(segments));
  validate(def);
  BeamModel model;
  const double length = def.line.length_m();
  const double ds = length / segments;
  model.length_m = length;
  model.mass_damping_1_s = def.mass_damping_1_s;
  const LinePoint root = def.line.at(0.0);
  model.root_position_m = root.position_m;
  model.root_orientation = root.frame;

  model.nodes.resize(segments);
  for (int n = 0; n < segments; ++n) {
    NodeModel& node = model.nodes[n];
    node.s_m = (n + 0.5) * ds;
    node.segment_length_m = ds;
    const LinePoint p = def.line.at(node.s_m);
    node.position_m = p.position_m;
    node.orientation = p.frame;
    integrate_segment(def, n * ds, (n + 1) * ds, node);
  }

  const Mat6 mu = def.stiffness_damping.asDiagonal();
  model.sections.resize(segments);
  for (int j = 0; j < segments; ++j) {
    SectionModel& sec = model.sections[j];
    sec.inboard = j - 1;
    sec.outboard = j;
    const double s_in = j == 0 ? 0.0 : model.nodes[j - 1].s_m;
    const Vec3 x_in = j == 0 ? model.root_position_m : model.nodes[j - 1].position_m;
    const Mat3 r_in = j == 0 ? model.root_orientation : model.nodes[j - 1].orientation;
    const NodeModel& out = model.nodes[j];
    sec.length_m = out.s_m - s_in;
    // Interior sections lie on the segment boundary (eq. 2.54: Δs^{n−1j}/Δs^j); the root section
    // midway between the root and node 0, where its strain is a centred difference.
    const double s_sec = j == 0 ? 0.5 * out.s_m : j * ds;
    sec.alpha = (s_sec - s_in) / sec.length_m;
    const Vec3 psi = rotation_vector(r_in.transpose() * out.orientation);
    const Mat3 r_sec = r_in * rotation_matrix(sec.alpha * psi);
    sec.chord_ref = r_sec.transpose() * (out.position_m - x_in) / sec.length_m;
    sec.curvature_ref = psi / sec.length_m;
    sec.stiffness = stiffness_at(def, s_sec / length);
    sec.damping = mu * sec.stiffness;
  }

  const LinePoint tip = def.line.at(length);
  const NodeModel& last = model.nodes.back();
  if (def.root_end == EndCondition::pinned) hold_by_pin(model.sections.front(), model.nodes.front(), root.position_m);
  if (def.tip_end != EndCondition::free) {
    // The held tip: a section from the last node to the tip frame, midway as at the root, or the
    // pin's mirrored segment.
    SectionModel sec;
    sec.inboard = segments - 1;
    sec.outboard = kTipEnd;
    sec.length_m = length - last.s_m;
    sec.alpha = 0.5;
    const Vec3 psi = rotation_vector(last.orientation.transpose() * tip.frame);
    const Mat3 r_sec = last.orientation * rotation_matrix(0.5 * psi);
    sec.chord_ref = r_sec.transpose() * (tip.position_m - last.position_m) / sec.length_m;
    sec.curvature_ref = psi / sec.length_m;
    sec.stiffness = stiffness_at(def, (length - 0.5 * sec.length_m) / length);
    sec.damping = mu * sec.stiffness;
    if (def.tip_end == EndCondition::pinned) hold_by_pin(sec, last, tip.position_m);
    model.sections.push_back(sec);
  }
  model.tip_position_m = tip.position_m;
  model.tip_orientation = tip.frame;
  model.tip_arm_m = last.orientation.transpose() * (tip.position_m - last.position_m);
  return model;
}

}  // namespace fowtsim::beam
