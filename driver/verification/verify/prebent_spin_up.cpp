#include "verify/prebent_spin_up.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fowtsim/beam/beam_outputs.hpp"
#include "fowtsim/beam/benchmarks.hpp"
#include "fowtsim/beam/solvers.hpp"
#include "fowtsim/core/rotation_vector.hpp"
#include "fowtsim/flexbody/hub_spin.hpp"
#include "verify/kane_spin_up.hpp"

namespace fowtsim::driver {
namespace {

constexpr double kEnd = 30.0;     // 15 s spin-up + 15 s at Ω_s [s]
constexpr double kSample = 0.02;  // common output grid [s]

// The Sec. 5.4 beam on a curved reference line [x, 0, z₀(x)] in the hub frame f. Built by
// ReferenceLine::parametric in BeamDyn's coordinates (line along z, so its frame rule applies) and
// turned into f by the cyclic permutation of rotating_benchmarks.hpp, local (1, 2, 3) = f's
// (y, z, x) at the root: local 1 is the edge direction, 3 the tangent.
beam::BeamDefinition prebent_beam(const flexbody::PrebentBeam& b) {
  const double k = std::numbers::pi / (2.0 * b.length);
  const beam::ReferenceLine bd = beam::ReferenceLine::parametric(
      [&b, k](double x) { return Vec3(0.0, b.prebend_tip * (1.0 - std::cos(k * x)), x); }, [](double) { return 0.0; },
      0.0, b.length);
  Mat3 to_f;
  to_f << Vec3::UnitY(), Vec3::UnitZ(), Vec3::UnitX();
  const beam::ReferenceLine line(bd.length_m(), [bd, to_f](double s) {
    const beam::LinePoint p = bd.at(s);
    return beam::LinePoint{to_f * p.position_m, to_f * p.frame};
  });
  const Vec6 stiffness = (Vec6() << 1e7, 1e7, 2e7, b.bending_stiffness, b.bending_stiffness, b.torsion_stiffness).finished();
  const Vec3 inertia(0.0, 0.0, b.polar_inertia);
  return beam::BeamDefinition{line,
                              {beam::benchmarks::uniform_station(0.0, stiffness, b.mass_per_length, inertia),
                               beam::benchmarks::uniform_station(1.0, stiffness, b.mass_per_length, inertia)}};
}

void record(const beam::BeamModel& model, const beam::BeamState& state, flexbody::PrebentTipHistory& h) {
  const beam::BeamOutputs out = beam::beam_outputs(model, state);
  // The tip moves rigidly with the last node: its rotation from the reference is R_N R0_Nᵀ; the
  // twist is its rotation vector along the undeformed tangent (equal to the RR's φ to first order).
  const beam::NodeModel& tip = model.nodes.back();
  const Vec3 rotation = rotation_vector(state.orientation.back() * tip.orientation.transpose());
  h.edge.push_back(out.tip_displacement_m.y());
  h.flap.push_back(out.tip_position_m.z());
  h.torsion.push_back(rotation.dot(tip.orientation.col(2)));
}

flexbody::PrebentTipHistory mbbt_tips(const flexbody::PrebentBeam& b, const flexbody::HubSpin& hub) {
  const beam::BeamModel model = beam::discretise(prebent_beam(b), 30);
  flexbody::PrebentTipHistory h;
  mbbt_spin_up(model, hub, kEnd, kSample, [&](const beam::BeamState& state) { record(model, state, h); });
  return h;
}

}  // namespace

PrebentSpinUp prebent_spin_up_histories() {
  const flexbody::PrebentBeam b{};  // the seed's Sec. 5.2/5.4 values (prebent_spinning_beam.hpp)
  const flexbody::HubSpin hub = flexbody::kane_spin_up(6.0, 15.0);
  return {mbbt_tips(b, hub), flexbody::prebent_spin_up_history(flexbody::PrebentSpinningBeam(b, 3, 3, 3), hub, kEnd,
                                                               kSample, 1e-3)};
}

PrebentComparison compare(const PrebentSpinUp& h) {
  const auto& m = h.mbbt;
  const auto& r = h.rr;
  const auto lo = [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); };
  const auto hi = [](const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); };
  return {rms_over_max(r.edge, m.edge), m.flap.back(),     r.flap.back(), max_abs_difference(r.flap, m.flap),
          lo(m.torsion),                lo(r.torsion),     hi(m.torsion), hi(r.torsion),
          rms_over_max(r.torsion, m.torsion)};
}

}  // namespace fowtsim::driver
