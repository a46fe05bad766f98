// make_model(): validation of Params and the mass properties of the rigid bodies.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/rotation.hpp"
#include "fowtsim/flexbody/axial_force.hpp"
#include "fowtsim/flexbody/blade_shapes.hpp"
#include "fowtsim/flexbody/rr_blade.hpp"
#include "fowtsim/flexbody/integrals.hpp"
#include "fowtsim/flexbody/quadrature.hpp"
#include "fowtsim/flexbody/shape_functions.hpp"
#include "fowtsim/flexbody/station_segment.hpp"
#include "fowtsim/multibody/dynamics.hpp"
#include "fowtsim/multibody/model.hpp"
#include "fowtsim/multibody/blade_body.hpp"
#include "fowtsim/multibody/tower_body.hpp"

namespace fowtsim::multibody {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// ∫_a^b μ(s) s^k ds for μ linear from μa at a to μb at b, exactly (k = 0, 1, 2).
double linear_moment(double a, double b, double mu_a, double mu_b, int k) {
  // μ(s) = μa + (μb − μa)(s − a)/(b − a); ∫ s^k μ = μa I_k + slope (I_{k+1} − a I_k).
  auto power_integral = [&](int n) { return (std::pow(b, n + 1) - std::pow(a, n + 1)) / (n + 1); };
  const double slope = (mu_b - mu_a) / (b - a);
  return mu_a * power_integral(k) + slope * (power_integral(k + 1) - a * power_integral(k));
}

// Mass, first and second moments of a piecewise-linear line density over [0, length] about s = 0.
BladeMassMoments line_moments(const std::vector<double>& fraction, const std::vector<double>& density,
                              double scale, double length) {
  BladeMassMoments m;
  for (std::size_t i = 0; i + 1 < fraction.size(); ++i) {
    const double a = fraction[i] * length, b = fraction[i + 1] * length;
    const double mu_a = scale * density[i], mu_b = scale * density[i + 1];
    m.mass_kg += linear_moment(a, b, mu_a, mu_b, 0);
    m.first_moment_kg_m += linear_moment(a, b, mu_a, mu_b, 1);
    m.second_moment_kg_m2 += linear_moment(a, b, mu_a, mu_b, 2);
  }
  return m;
}

// Adds body (mass properties about its own CM, in the same frame) to an accumulated body.
RigidBody combine(const RigidBody& a, const RigidBody& b) {
  RigidBody c;
  c.mass_kg = a.mass_kg + b.mass_kg;
  if (c.mass_kg <= 0.0) return c;
  c.cm_m = (a.mass_kg * a.cm_m + b.mass_kg * b.cm_m) / c.mass_kg;
  // Parallel-axis theorem: I_C = I_cm + m (|d|² 1 − d dᵀ).
  auto shifted = [&](const RigidBody& x) {
    const Vec3 d = x.cm_m - c.cm_m;
    return Mat3(x.inertia_kg_m2 + x.mass_kg * (d.squaredNorm() * Mat3::Identity() - d * d.transpose()));
  };
  c.inertia_kg_m2 = shifted(a) + shifted(b);
  return c;
}

RigidBody point_mass(double mass, const Vec3& at) { return RigidBody{mass, at, Mat3::Zero()}; }

class Problems {
 public:
  void require(bool ok, const std::string& key, double value, const std::string& expected) {
    if (!ok) out_ << "\n  structure." << key << " = " << value << ": expected " << expected;
  }
  void add(const std::string& text) { out_ << "\n  " << text; }
  void throw_if_any() const {
    const std::string s = out_.str();
    if (!s.empty()) {
      throw InputError({"multibody", std::nullopt, "structure", "fix the listed keys of the deck"},
                       "invalid multibody parameters:" + s);
    }
  }

 private:
  std::ostringstream out_;
};

void validate(const Params& p) {
  Problems e;
  auto finite_nonneg = [&](double v, const std::string& key) {
    e.require(std::isfinite(v) && v >= 0.0, key, v, "a finite number >= 0");
  };
  auto finite = [&](double v, const std::string& key) {
    e.require(std::isfinite(v), key, v, "a finite number");
  };
  auto finite_vec = [&](const Vec3& v, const std::string& key) {
    for (int i = 0; i < 3; ++i) finite(v[i], key + "[" + std::to_string(i) + "]");
  };
  e.require(std::isfinite(p.gravity_m_s2) && p.gravity_m_s2 >= 0.0, "gravity_m_s2", p.gravity_m_s2, ">= 0");
  e.require(std::isfinite(p.max_step_s) && p.max_step_s > 0.0, "max_step_s", p.max_step_s, "> 0");
  // Platform
  finite_nonneg(p.platform.mass_kg, "platform.mass_kg");
  finite_vec(p.platform.cm_m, "platform.cm_m");
  finite_nonneg(p.platform.roll_inertia_kg_m2, "platform.roll_inertia_kg_m2");
  finite_nonneg(p.platform.pitch_inertia_kg_m2, "platform.pitch_inertia_kg_m2");
  finite_nonneg(p.platform.yaw_inertia_kg_m2, "platform.yaw_inertia_kg_m2");
  finite(p.platform.xy_inertia_kg_m2, "platform.xy_inertia_kg_m2");
  finite(p.platform.yz_inertia_kg_m2, "platform.yz_inertia_kg_m2");
  finite(p.platform.xz_inertia_kg_m2, "platform.xz_inertia_kg_m2");
  finite(p.platform.reference_height_m, "platform.reference_height_m");
  // Tower
  finite(p.tower.base_height_m, "tower.base_height_m");
  e.require(std::isfinite(p.tower.top_height_m) && p.tower.top_height_m > p.tower.base_height_m,
            "tower.top_height_m", p.tower.top_height_m, "> tower.base_height_m");
  finite_nonneg(p.tower.mass_density_scale, "tower.mass_density_scale");
  const auto& gauges = p.tower.gauge_heights_m;
  if (gauges.size() > static_cast<std::size_t>(kMaxTowerGauges))
    e.add("structure.tower.gauge_heights_m: expected at most " + std::to_string(kMaxTowerGauges) +
          " gauges (ElastoDyn's NTwGages ≤ 9: TwHt1 … TwHt9), got " + std::to_string(gauges.size()));
  for (std::size_t i = 0; i < gauges.size(); ++i)
    e.require(std::isfinite(gauges[i]) && gauges[i] >= 0.0 && gauges[i] < p.tower.top_height_m - p.tower.base_height_m,
              "tower.gauge_heights_m[" + std::to_string(i) + "]", gauges[i],
              "a height above the tower base, 0 ≤ h < top_height_m − base_height_m (the yaw bearing's loads are YawBr*)");
  const auto& f = p.tower.station_fraction;
  if (f.size() < 2 || f.size() != p.tower.mass_density_kg_m.size()) {
    e.add("structure.tower.station_fraction / mass_density_kg_m: expected two equally long lists "
          "of at least 2 entries (got " + std::to_string(f.size()) + " and " +
          std::to_string(p.tower.mass_density_kg_m.size()) + ")");
  } else {
    e.require(f.front() == 0.0, "tower.station_fraction[0]", f.front(), "0");
    e.require(f.back() == 1.0, "tower.station_fraction[last]", f.back(), "1");
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (i > 0) e.require(f[i] > f[i - 1], "tower.station_fraction[" + std::to_string(i) + "]", f[i], "strictly increasing");
      finite_nonneg(p.tower.mass_density_kg_m[i], "tower.mass_density_kg_m[" + std::to_string(i) + "]");
    }
  }
  if (p.tower.flexible) {
    const std::size_t n = p.tower.station_fraction.size();
    auto stiffness = [&](const std::vector<double>& ei, const std::string& key) {
      if (ei.size() != n) {
        e.add("structure.tower." + key + ": expected one value per station (" + std::to_string(n) + "), got " +
              std::to_string(ei.size()));
        return;
      }
      for (std::size_t i = 0; i < n; ++i)
        e.require(std::isfinite(ei[i]) && ei[i] > 0.0, "tower." + key + "[" + std::to_string(i) + "]", ei[i], "> 0");
    };
    stiffness(p.tower.fore_aft_stiffness_N_m2, "fore_aft_stiffness_N_m2");
    stiffness(p.tower.side_side_stiffness_N_m2, "side_side_stiffness_N_m2");
    const std::size_t modes = p.tower.fore_aft_mode_shapes.size() + p.tower.side_side_mode_shapes.size();
    if (modes == 0 || modes > static_cast<std::size_t>(kMaxTowerModes))
      e.add("structure.tower.fore_aft_mode_shapes / side_side_mode_shapes: expected 1 … " +
            std::to_string(kMaxTowerModes) + " modes in all with a flexible tower, got " + std::to_string(modes));
    auto shapes = [&](const std::vector<std::vector<double>>& c, const std::vector<double>& damping,
                      const std::string& key, const std::string& damping_key) {
      for (std::size_t j = 0; j < c.size(); ++j) {
        if (c[j].size() != 5) {
          e.add("structure.tower." + key + "[" + std::to_string(j) + "]: expected 5 coefficients (x^2 … x^6)");
          continue;
        }
        double sum = 0.0;
        for (double cj : c[j]) sum += cj;
        e.require(std::abs(sum - 1.0) <= 1e-3, "tower." + key + "[" + std::to_string(j) + "] (sum)", sum,
                  "coefficients adding up to 1 within 0.001 (ElastoDyn's rule)");
      }
      if (!damping.empty() && damping.size() != c.size())
        e.add("structure.tower." + damping_key + ": expected one value per mode or none");
      for (std::size_t j = 0; j < damping.size(); ++j)
        finite_nonneg(damping[j], "tower." + damping_key + "[" + std::to_string(j) + "]");
    };
    shapes(p.tower.fore_aft_mode_shapes, p.tower.fore_aft_damping_percent, "fore_aft_mode_shapes",
           "fore_aft_damping_percent");
    shapes(p.tower.side_side_mode_shapes, p.tower.side_side_damping_percent, "side_side_mode_shapes",
           "side_side_damping_percent");
  }
  // Nacelle
  finite_nonneg(p.nacelle.mass_kg, "nacelle.mass_kg");
  finite_vec(p.nacelle.cm_m, "nacelle.cm_m");
  finite_vec(p.nacelle.imu_m, "nacelle.imu_m");
  finite_nonneg(p.nacelle.yaw_bearing_mass_kg, "nacelle.yaw_bearing_mass_kg");
  finite(p.nacelle.tower_to_shaft_m, "nacelle.tower_to_shaft_m");
  finite(p.nacelle.overhang_m, "nacelle.overhang_m");
  e.require(std::isfinite(p.nacelle.shaft_tilt_deg) && std::abs(p.nacelle.shaft_tilt_deg) < 90.0,
            "nacelle.shaft_tilt_deg", p.nacelle.shaft_tilt_deg, "|tilt| < 90");
  const double own = p.nacelle.mass_kg * p.nacelle.cm_m.head<2>().squaredNorm();
  e.require(std::isfinite(p.nacelle.yaw_inertia_kg_m2) && p.nacelle.yaw_inertia_kg_m2 >= own,
            "nacelle.yaw_inertia_kg_m2", p.nacelle.yaw_inertia_kg_m2,
            ">= mass · (cm_x² + cm_y²) = " + std::to_string(own) +
                " (it is about the yaw axis; less would be a negative inertia about the CM)");
  // Rotor
  const auto& r = p.rotor;
  e.require(r.blade_count >= 1 && r.blade_count <= kMaxBlades, "rotor.blade_count", r.blade_count, "1, 2 or 3");
  finite_nonneg(r.hub_mass_kg, "rotor.hub_mass_kg");
  finite_nonneg(r.hub_inertia_kg_m2, "rotor.hub_inertia_kg_m2");
  finite(r.hub_cm_m, "rotor.hub_cm_m");
  finite_nonneg(r.hub_radius_m, "rotor.hub_radius_m");
  e.require(std::isfinite(r.tip_radius_m) && r.tip_radius_m > r.hub_radius_m, "rotor.tip_radius_m",
            r.tip_radius_m, "> rotor.hub_radius_m");
  e.require(std::isfinite(r.precone_deg) && std::abs(r.precone_deg) < 90.0, "rotor.precone_deg",
            r.precone_deg, "|precone| < 90");
  finite_nonneg(r.blade_mass_kg, "rotor.blade_mass_kg");
  finite_nonneg(r.blade_first_mass_moment_kg_m, "rotor.blade_first_mass_moment_kg_m");
  finite_nonneg(r.blade_second_mass_moment_kg_m2, "rotor.blade_second_mass_moment_kg_m2");
  // Cauchy–Schwarz: (∫ m r)² ≤ ∫ m · ∫ m r² for any non-negative distribution.
  e.require(r.blade_first_mass_moment_kg_m * r.blade_first_mass_moment_kg_m <=
                r.blade_mass_kg * r.blade_second_mass_moment_kg_m2 * (1.0 + 1e-12),
            "rotor.blade_first_mass_moment_kg_m", r.blade_first_mass_moment_kg_m,
            "first² <= mass · second moment (a real mass distribution)");
  if (!r.rayleigh_ritz_blade && !r.blade_gauge_fractions.empty())
    e.add("structure.rotor.rayleigh_ritz_blade_gauges: needs structure.rotor.rayleigh_ritz_blade_file (Rayleigh-Ritz blades)");
  if (r.rayleigh_ritz_blade) {
    const flexbody::ElastoDynBlade& b = *r.rayleigh_ritz_blade;
    if (r.flexible_blades)
      e.add("structure.rotor.rayleigh_ritz_blade_file: Rayleigh-Ritz blades and flexible (MBBT) blades — the `blades` section — "
            "together; expected one blade model");
    e.require(std::abs(b.hub_radius - r.hub_radius_m) <= 1e-9 * r.tip_radius_m, "rotor.rayleigh_ritz_blade.hub_radius_m",
              b.hub_radius, "= rotor.hub_radius_m (" + std::to_string(r.hub_radius_m) + ")");
    e.require(std::abs(b.tip_radius - r.tip_radius_m) <= 1e-9 * r.tip_radius_m, "rotor.rayleigh_ritz_blade.tip_radius_m",
              b.tip_radius, "= rotor.tip_radius_m (" + std::to_string(r.tip_radius_m) + ")");
    e.require(r.rayleigh_ritz_blade_nodes >= 1, "rotor.rayleigh_ritz_blade_nodes", r.rayleigh_ritz_blade_nodes, ">= 1");
    e.require(r.blade_station_spans_m.size() < static_cast<std::size_t>(kMaxBladeStations), "rotor.blade_station_spans_m",
              static_cast<double>(r.blade_station_spans_m.size()), "fewer than " + std::to_string(kMaxBladeStations) + " stations");
    e.require(r.blade_gauge_fractions.size() <= static_cast<std::size_t>(kMaxBladeGauges), "rotor.rayleigh_ritz_blade_gauges",
              static_cast<double>(r.blade_gauge_fractions.size()), "at most " + std::to_string(kMaxBladeGauges) + " gauges");
    for (std::size_t i = 0; i < r.blade_gauge_fractions.size(); ++i)
      e.require(r.blade_gauge_fractions[i] >= 0.0 && r.blade_gauge_fractions[i] < 1.0,
                "rotor.rayleigh_ritz_blade_gauges[" + std::to_string(i) + "]", r.blade_gauge_fractions[i], "0 <= x/L < 1");
    const double length = r.tip_radius_m - r.hub_radius_m;
    for (std::size_t i = 0; i < r.blade_station_spans_m.size(); ++i) {
      const double x = r.blade_station_spans_m[i];
      e.require(x >= 0.0 && x <= length && (i == 0 || x >= r.blade_station_spans_m[i - 1]),
                "rotor.blade_station_spans_m[" + std::to_string(i) + "] (the aero node spans)", x,
                "ascending within 0 … the blade length " + std::to_string(length));
    }
  }
  // Drivetrain
  const auto& d = p.drivetrain;
  e.require(std::isfinite(d.gearbox_ratio) && d.gearbox_ratio > 0.0, "drivetrain.gearbox_ratio", d.gearbox_ratio, "> 0");
  finite_nonneg(d.generator_inertia_kg_m2, "drivetrain.generator_inertia_kg_m2");
  finite_nonneg(d.torsional_stiffness_N_m_rad, "drivetrain.torsional_stiffness_N_m_rad");
  finite_nonneg(d.torsional_damping_N_m_s_rad, "drivetrain.torsional_damping_N_m_s_rad");
  if (d.torsional_flexibility) {
    e.require(d.generator_inertia_kg_m2 > 0.0, "drivetrain.generator_inertia_kg_m2",
              d.generator_inertia_kg_m2, "> 0 with torsional_flexibility (the generator azimuth is a DOF)");
  }
  // Initial conditions
  const auto& ic = p.initial_conditions;
  finite_vec(ic.platform_position_m, "initial_conditions.platform_position_m");
  finite_vec(ic.platform_angles_deg, "initial_conditions.platform_angles_deg");
  finite_vec(ic.platform_velocity_m_s, "initial_conditions.platform_velocity_m_s");
  finite_vec(ic.platform_angular_velocity_deg_s, "initial_conditions.platform_angular_velocity_deg_s");
  finite(ic.azimuth_deg, "initial_conditions.azimuth_deg");
  finite(ic.rotor_speed_rpm, "initial_conditions.rotor_speed_rpm");
  finite(ic.nacelle_yaw_deg, "initial_conditions.nacelle_yaw_deg");
  finite(ic.tower_top_deflection_m[0], "initial_conditions.tower_top_deflection_m[0]");
  finite(ic.tower_top_deflection_m[1], "initial_conditions.tower_top_deflection_m[1]");
  if (!p.tower.flexible && (ic.tower_top_deflection_m[0] != 0.0 || ic.tower_top_deflection_m[1] != 0.0))
    e.add("structure.initial_conditions.tower_top_deflection_m: needs structure.tower.flexible: true");
  e.throw_if_any();
}

// The tower's shape integrals from quadrature points along it (x from the tower base) and the
// yaw-bearing point mass at the top.
ShapeIntegrals tower_inertia(const Model& m, const FlexibleTower& t, const std::vector<flexbody::QuadraturePoint>& points,
                             double yaw_bearing_mass_kg) {
  ShapeIntegrals in;
  auto add = [&](double mass, double x) {
    std::array<Vec3, kMaxBodyModes> phi{};
    for (int j = 0; j < t.mode_count; ++j) phi[j] = t.shape[j].value(x) * t.direction_b[j];
    in.add_point(mass, m.tower_base_b + Vec3(0.0, 0.0, x), phi, t.mode_count);
  };
  for (const flexbody::QuadraturePoint& q : points) add(q.w * q.m, q.x);
  add(yaw_bearing_mass_kg, m.tower_top_b.z() - m.tower_base_b.z());
  return in;
}

// The tower gauges: for each, the shape integrals of the mass above it, from the model's 8-point
// Gauss rule on the piece [h, L] of the station table (flexbody::segment, whose x starts at h: shifted
// back to the tower's heights), and the yaw-bearing mass. EI is not used by the mass integrals; the
// rigid tower's table carries 1 N·m² (quadrature_points requires EI > 0).
void make_tower_gauges(const Params& p, Model& m) {
  const TowerParams& tp = p.tower;
  const double length = tp.top_height_m - tp.base_height_m;
  flexbody::BeamStations table;
  for (std::size_t i = 0; i < tp.station_fraction.size(); ++i) {
    table.x.push_back(tp.station_fraction[i] * length);
    table.m.push_back(tp.mass_density_scale * tp.mass_density_kg_m[i]);
    table.EI.push_back(1.0);
  }
  const flexbody::QuadratureRule station_rule{flexbody::QuadratureRule::Kind::GaussLegendre, 1, 8};
  m.tower_gauge_count = static_cast<int>(tp.gauge_heights_m.size());
  for (int k = 0; k < m.tower_gauge_count; ++k) {
    const double h = tp.gauge_heights_m[static_cast<std::size_t>(k)];
    std::vector<flexbody::QuadraturePoint> points = flexbody::quadrature_points(flexbody::segment(table, h, length), station_rule);
    for (flexbody::QuadraturePoint& q : points) q.x += h;
    m.tower_gauges[k] = {h, tower_inertia(m, m.flexible_tower, points, p.nacelle.yaw_bearing_mass_kg)};
  }
}

// The flexible tower: shapes, stiffness and softening integrals (flexbody), and its mass integrals
// on Gauss points (exact for the polynomial shapes: m linear × φ_i φ_j of degree 13 ≤ 2·8 − 1)
// with the yaw-bearing mass.
FlexibleTower make_flexible_tower(const Params& p, const Model& m, double top_mass_kg) {
  using namespace fowtsim::flexbody;
  FlexibleTower t;
  const TowerParams& tp = p.tower;
  const double length = tp.top_height_m - tp.base_height_m;
  const int n_fa = static_cast<int>(tp.fore_aft_mode_shapes.size());
  const int n_ss = static_cast<int>(tp.side_side_mode_shapes.size());
  t.mode_count = n_fa + n_ss;
  t.fore_aft_count = n_fa;
  auto table = [&](const std::vector<double>& ei) {
    BeamStations b;
    for (std::size_t i = 0; i < tp.station_fraction.size(); ++i) {
      b.x.push_back(tp.station_fraction[i] * length);
      b.m.push_back(tp.mass_density_scale * tp.mass_density_kg_m[i]);
      b.EI.push_back(ei[i]);
    }
    return b;
  };
  const BeamStations fa = table(tp.fore_aft_stiffness_N_m2), ss = table(tp.side_side_stiffness_N_m2);
  std::vector<ShapeFunction> fa_shapes, ss_shapes;
  auto coefficients = [](const std::vector<double>& c) { return std::array<double, 5>{c[0], c[1], c[2], c[3], c[4]}; };
  for (const auto& c : tp.fore_aft_mode_shapes) fa_shapes.push_back(polynomial_shape(coefficients(c), length));
  for (const auto& c : tp.side_side_mode_shapes) ss_shapes.push_back(polynomial_shape(coefficients(c), length));
  const QuadratureRule station_rule{QuadratureRule::Kind::GaussLegendre, 1, 8};
  const std::vector<QuadraturePoint> points = quadrature_points(fa, station_rule);
  // Per direction: K_q, K^T per unit g (self-weight + top mass), M_q; block-diagonal in all.
  auto block = [&](const BeamStations& b, const std::vector<ShapeFunction>& shapes, int offset) {
    if (shapes.empty()) return;
    const int n = static_cast<int>(shapes.size());
    const SampledBody body = sample(quadrature_points(b), shapes);
    const AxialForce self = self_weight_axial_force(b, 1.0);
    const AxialForce top = top_mass_axial_force(top_mass_kg, 1.0);
    const AxialForce both = [self, top](double x) { return self(x) + top(x); };
    t.stiffness.block(offset, offset, n, n) = generalized_stiffness(body);
    t.geometric_stiffness_per_g.block(offset, offset, n, n) = geometric_stiffness(body, both);
    t.generalized_mass.block(offset, offset, n, n) = generalized_mass(body);
  };
  block(fa, fa_shapes, 0);
  block(ss, ss_shapes, n_fa);
  for (int j = 0; j < t.mode_count; ++j) {
    const bool fore_aft = j < n_fa;
    const ShapeFunction& shape = fore_aft ? fa_shapes[j] : ss_shapes[j - n_fa];
    t.direction_b[j] = fore_aft ? Vec3::UnitX() : Vec3::UnitY();
    const auto& c = fore_aft ? tp.fore_aft_mode_shapes[j] : tp.side_side_mode_shapes[j - n_fa];
    const double sum = c[0] + c[1] + c[2] + c[3] + c[4];  // normalised as polynomial_shape does
    t.shape[j] = {{c[0] / sum, c[1] / sum, c[2] / sum, c[3] / sum, c[4] / sum}, length};
    const ShapeValue top = shape(length);
    t.top_shape[j] = top.u;
    t.top_slope[j] = top.nu;
  }
  // ElastoDyn's damping: C(:, l) = (ζ_l/100) K(:, l) / (π f_l), f_l the mode's own frequency
  // without the top mass, sqrt(K_ll / M_ll) / 2π (ElastoDyn Coeff: CTFA, CTSS).
  for (int l = 0; l < t.mode_count; ++l) {
    const bool fore_aft = l < n_fa;
    const auto& pct = fore_aft ? tp.fore_aft_damping_percent : tp.side_side_damping_percent;
    const int index = fore_aft ? l : l - n_fa;
    const double zeta = pct.empty() ? 0.0 : 0.01 * pct[index];
    const double omega = std::sqrt(t.stiffness(l, l) / t.generalized_mass(l, l));
    t.damping.col(l) = zeta * t.stiffness.col(l) * 2.0 / omega;
  }
  t.inertia = tower_inertia(m, t, points, p.nacelle.yaw_bearing_mass_kg);
  t.top_mass_kg = top_mass_kg;
  return t;
}

// The Rayleigh–Ritz blades: ElastoDyn's twisted shapes on its own midpoint rule (BldNodes; so the
// mass moments equal its summary file's), K with its tuners, the centrifugal G per Ω² and its
// damping (flexbody/rr_blade.hpp); the shapes again at the stations where loads act.
RayleighRitzBlades make_rr_blades(const RotorParams& r) {
  using namespace fowtsim::flexbody;
  const ElastoDynBlade& blade = *r.rayleigh_ritz_blade;
  RayleighRitzBlades out;
  out.mode_count = kBladeShapes;
  out.length_m = blade.length();
  BladeRule rule;
  rule.kind = BladeRule::Kind::ElastoDynNodes;
  rule.elastodyn_nodes = r.rayleigh_ritz_blade_nodes;
  const SampledBlade sampled = sample_blade(blade, rule);
  auto shape_at = [](Eigen::Index k, const Eigen::MatrixXd& flap, const Eigen::MatrixXd& edge) {
    std::array<Vec3, kMaxBodyModes> phi{};
    for (int j = 0; j < kBladeShapes; ++j) phi[j] = Vec3(flap(k, j), edge(k, j), 0.0);
    return phi;
  };
  for (std::size_t k = 0; k < sampled.points.size(); ++k) {
    const BladePoint& p = sampled.points[k];
    const auto i = static_cast<Eigen::Index>(k);
    out.inertia.add_point(p.w * p.m, Vec3(0.0, 0.0, p.x), shape_at(i, sampled.u_flap, sampled.u_edge), kBladeShapes);
  }
  const RrBladeMatrices matrices = rr_blade_matrices(blade, sampled);
  out.stiffness = matrices.stiffness;
  out.centrifugal_stiffness = matrices.centrifugal;
  out.damping = elastodyn_damping(blade, matrices);
  // Shapes and slopes at given spans.
  auto stations_at = [&](const std::vector<double>& spans) {
    BladeRule at;
    at.kind = BladeRule::Kind::Spans;
    at.spans = spans;
    const SampledBlade sampled_at = sample_blade(blade, at);
    std::vector<BladeStation> list(spans.size());
    for (std::size_t k = 0; k < spans.size(); ++k) {
      const auto i = static_cast<Eigen::Index>(k);
      list[k] = {spans[k], shape_at(i, sampled_at.u_flap, sampled_at.u_edge),
                 shape_at(i, sampled_at.nu_flap, sampled_at.nu_edge), sampled_at.points[k].twist};
    }
    return list;
  };
  std::vector<double> spans = r.blade_station_spans_m;
  spans.push_back(blade.length());
  const std::vector<BladeStation> stations = stations_at(spans);
  out.station_count = static_cast<int>(stations.size());
  std::copy(stations.begin(), stations.end(), out.stations.begin());
  // Gauges: the mass beyond x_g on the same midpoint rule as the body's integrals (so a gauge at the
  // root carries exactly the blade's mass): each element's part beyond x_g at that part's middle.
  out.gauge_count = static_cast<int>(r.blade_gauge_fractions.size());
  for (int g = 0; g < out.gauge_count; ++g) {
    const double x_g = r.blade_gauge_fractions[static_cast<std::size_t>(g)] * blade.length();
    const double h = blade.length() / r.rayleigh_ritz_blade_nodes;
    std::vector<double> at{x_g}, mass;
    for (const BladePoint& p : sampled.points) {
      const double start = std::max(p.x - 0.5 * h, x_g), end = p.x + 0.5 * h;
      if (end <= start) continue;
      at.push_back(0.5 * (start + end));
      mass.push_back(p.m * (end - start));  // the element's mass per length, as the body's rule takes it
    }
    const std::vector<BladeStation> points = stations_at(at);
    out.gauges[g].station = points[0];
    for (std::size_t k = 1; k < points.size(); ++k)
      out.gauges[g].outboard.add_point(mass[k - 1], Vec3(0.0, 0.0, points[k].span_m), points[k].shape, kBladeShapes);
  }
  return out;
}

}  // namespace

BladeMassMoments blade_mass_moments(const std::vector<double>& span_fraction,
                                    const std::vector<double>& mass_density_kg_m,
                                    double mass_density_scale, double blade_length_m) {
  return line_moments(span_fraction, mass_density_kg_m, mass_density_scale, blade_length_m);
}

Model make_model(const Params& params) {
  validate(params);
  Model m;
  m.params = params;
  const auto& p = params;
  const double ref = p.platform.reference_height_m;

  // Platform: ElastoDyn's inertias are about the platform CM; products are −∫xy dm etc.
  RigidBody platform;
  platform.mass_kg = p.platform.mass_kg;
  platform.cm_m = p.platform.cm_m - Vec3(0.0, 0.0, ref);
  platform.inertia_kg_m2 << p.platform.roll_inertia_kg_m2, p.platform.xy_inertia_kg_m2,
      p.platform.xz_inertia_kg_m2, p.platform.xy_inertia_kg_m2, p.platform.pitch_inertia_kg_m2,
      p.platform.yz_inertia_kg_m2, p.platform.xz_inertia_kg_m2, p.platform.yz_inertia_kg_m2,
      p.platform.yaw_inertia_kg_m2;

  // Tower: line mass on z_b; I_xx = I_yy = ∫ μ (z − z_cm)² dz about its CM, I_zz = 0.
  const double length = p.tower.top_height_m - p.tower.base_height_m;
  const BladeMassMoments tm =
      line_moments(p.tower.station_fraction, p.tower.mass_density_kg_m, p.tower.mass_density_scale, length);
  m.tower_base_b = Vec3(0.0, 0.0, p.tower.base_height_m - ref);
  m.tower_top_b = Vec3(0.0, 0.0, p.tower.top_height_m - ref);
  RigidBody tower;
  tower.mass_kg = tm.mass_kg;
  if (tm.mass_kg > 0.0) {
    const double z_cm = tm.first_moment_kg_m / tm.mass_kg;
    tower.cm_m = m.tower_base_b + Vec3(0.0, 0.0, z_cm);
    const double i_cm = tm.second_moment_kg_m2 - tm.mass_kg * z_cm * z_cm;
    tower.inertia_kg_m2.diagonal() << i_cm, i_cm, 0.0;
  } else {
    tower.cm_m = m.tower_base_b;
  }
  m.tower = combine(tower, point_mass(p.nacelle.yaw_bearing_mass_kg, m.tower_top_b));
  m.base = combine(platform, m.tower);

  // Nacelle: NacYIner is about the yaw axis; about its own CM the nacelle keeps only the rest.
  m.nacelle.mass_kg = p.nacelle.mass_kg;
  m.nacelle.cm_m = p.nacelle.cm_m;
  m.nacelle.inertia_kg_m2(2, 2) =
      p.nacelle.yaw_inertia_kg_m2 - p.nacelle.mass_kg * p.nacelle.cm_m.head<2>().squaredNorm();
  m.imu_n = p.nacelle.imu_m;

  // Shaft: x_s = (cos τ, 0, sin τ) in n with τ = ShftTilt, i.e. T_ns = R_y(−τ); the apex is
  // Twr2Shft up the yaw axis then OverHang along x_s (ElastoDyn's geometry).
  const double tilt = p.nacelle.shaft_tilt_deg * kDeg;
  m.shaft_in_nacelle = rotation_y(-tilt);
  m.apex_n = Vec3(0.0, 0.0, p.nacelle.tower_to_shaft_m) + p.nacelle.overhang_m * m.shaft_in_nacelle.col(0);

  // Rotor: hub (axial inertia only, as ElastoDyn's HubIner) + rigid blades as line masses along
  // the preconed pitch axes a_i; a line mass has I = J₂ (1 − a aᵀ) about the apex.
  m.blade_count = p.rotor.blade_count;
  const double cone = p.rotor.precone_deg * kDeg;
  RigidBody rotor{p.rotor.hub_mass_kg, Vec3(p.rotor.hub_cm_m, 0.0, 0.0), Mat3::Zero()};
  rotor.inertia_kg_m2(0, 0) = p.rotor.hub_inertia_kg_m2;
  for (int i = 0; i < m.blade_count; ++i) {
    const double azimuth = 2.0 * std::numbers::pi * i / m.blade_count;
    m.blade_root_orientation_h[i] = rotation_x(azimuth) * rotation_y(cone);
    const Vec3 axis = m.blade_root_orientation_h[i].col(2);
    m.blade_root_h[i] = p.rotor.hub_radius_m * axis;
    if (!p.rotor.flexible_blades && !p.rotor.rayleigh_ritz_blade && p.rotor.blade_mass_kg > 0.0) {
      const double hr = p.rotor.hub_radius_m;
      const double mass = p.rotor.blade_mass_kg;
      const double s1 = p.rotor.blade_first_mass_moment_kg_m + hr * mass;  // about the apex
      const double s2 = p.rotor.blade_second_mass_moment_kg_m2 +
                        2.0 * hr * p.rotor.blade_first_mass_moment_kg_m + hr * hr * mass;
      RigidBody blade;
      blade.mass_kg = mass;
      blade.cm_m = (s1 / mass) * axis;
      // About the CM: J₂,cm = J₂ − m r_cm², then the line formula.
      blade.inertia_kg_m2 = (s2 - s1 * s1 / mass) * (Mat3::Identity() - axis * axis.transpose());
      rotor = combine(rotor, blade);
    }
  }
  m.rotor = rotor;

  m.gearbox_ratio = p.drivetrain.gearbox_ratio;
  m.generator_inertia_kg_m2 = p.drivetrain.generator_inertia_kg_m2;
  m.dof_count = p.drivetrain.torsional_flexibility ? 8 : 7;
  m.generator_dof = p.drivetrain.torsional_flexibility ? kGenerator : kRotor;
  if (p.rotor.rayleigh_ritz_blade) m.rr_blades = make_rr_blades(p.rotor);
  if (p.tower.flexible) {
    // The tower's mass leaves the base body for the stations; the mass above the tower (nacelle,
    // rotor, yaw bearing; ElastoDyn's TwrTpMass) compresses it (geometric stiffness).
    const double top_mass = m.nacelle.mass_kg + m.rotor.mass_kg + m.blade_count * m.rr_blades.inertia.mass_kg +
                            p.nacelle.yaw_bearing_mass_kg;
    m.flexible_tower = make_flexible_tower(p, m, top_mass);
    m.base = platform;
    m.dof_count = kTower + m.flexible_tower.mode_count;
  }
  if (m.rr_blades.mode_count > 0) m.dof_count = kBlade + m.blade_count * kMaxBladeModes;
  make_tower_gauges(p, m);

  for (int i = 0; i < 6; ++i) m.acceleration_given[i] = !p.dofs.platform_free[i];
  if (p.dofs.rotor != RotorSpin::free) {
    m.acceleration_given[kRotor] = true;
    if (m.dof_count > kGenerator) m.acceleration_given[kGenerator] = true;
  }

  // A singular mass matrix (a DOF with no inertia) is an input error, not a run-time NaN. Rows
  // whose acceleration is given are not solved for and need no inertia.
  const State s0 = initial_state(m);
  GeneralisedMatrix mass = generalised_mass(m, s0, Mat6::Zero());
  for (int i = 0; i < m.dof_count; ++i)
    if (m.acceleration_given[i] || !dof_active(m, i)) {
      mass.row(i).setZero();
      mass.col(i).setZero();
      mass(i, i) = mass.diagonal().maxCoeff() + 1.0;
    }
  const Eigen::VectorXd diag = mass.diagonal().head(m.dof_count);
  // Relative to the largest diagonal entry: M mixes kg, kg·m and kg·m² but the test only has to
  // catch an exactly (or numerically) missing inertia.
  const double scale = diag.maxCoeff();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(mass.topLeftCorner(m.dof_count, m.dof_count));
  if (!(eig.eigenvalues().minCoeff() > 1e-12 * scale)) {
    static const char* names[] = {"surge", "sway", "heave", "roll", "pitch", "yaw", "rotor azimuth",
                                  "generator azimuth", "tower mode 1", "tower mode 2", "tower mode 3", "tower mode 4",
                                  "blade 1 flap 1", "blade 1 flap 2", "blade 1 edge 1", "blade 2 flap 1", "blade 2 flap 2",
                                  "blade 2 edge 1", "blade 3 flap 1", "blade 3 flap 2", "blade 3 edge 1"};
    static_assert(sizeof(names) / sizeof(names[0]) == kMaxDofs);
    std::string which;
    for (int i = 0; i < m.dof_count; ++i) {
      if (diag[i] <= 1e-12 * scale) which += std::string(which.empty() ? "" : ", ") + names[i];
    }
    throw InputError({"multibody", std::nullopt, "structure (mass and inertia)",
                      "give the bodies mass and inertia for every free DOF"},
                     "the structure's mass matrix is singular: no mass or inertia for " +
                         (which.empty() ? std::string("a combination of DOFs") : which));
  }
  return m;
}

MassSummary mass_summary(const Model& model) {
  const State s0 = initial_state(model);
  ChainKinematics k;
  chain_kinematics(model, s0, k);
  // Bodies in g at the initial pose, then back into b.
  const Mat3 t_gb = k.base.orientation;
  auto in_b = [&](const RigidBody& body, const Mat3& t_gk, const Vec3& cm_g) {
    RigidBody x;
    x.mass_kg = body.mass_kg;
    x.cm_m = t_gb.transpose() * (cm_g - k.reference.position_m);
    const Mat3 t_bk = t_gb.transpose() * t_gk;
    x.inertia_kg_m2 = t_bk * body.inertia_kg_m2 * t_bk.transpose();
    return x;
  };
  RigidBody all = in_b(model.base, k.base.orientation, k.base_cm.position_m);
  all = combine(all, in_b(model.nacelle, k.nacelle.orientation, k.nacelle_cm.position_m));
  all = combine(all, in_b(model.rotor, k.rotor.orientation, k.rotor_cm.position_m));
  auto add_flexible = [&](const ShapeIntegrals& in, const FlexibleBodyMotion& body) {
    // Its inertia about O, moved to its CM for combine(), in b.
    const FlexibleBodyMassProperties f = flexible_body_mass_properties(in, body);
    const Mat3 t_bk = t_gb.transpose() * body.orientation;
    const Vec3 c = f.first_moment_kg_m / f.mass_kg;  // CM from O in k
    RigidBody x;
    x.mass_kg = f.mass_kg;
    x.cm_m = t_gb.transpose() * (body.origin->position_m - k.reference.position_m) + t_bk * c;
    x.inertia_kg_m2 = t_bk * (f.inertia_kg_m2 - f.mass_kg * (c.squaredNorm() * Mat3::Identity() - c * c.transpose())) * t_bk.transpose();
    all = combine(all, x);
  };
  if (model.flexible_tower.mode_count > 0) add_flexible(model.flexible_tower.inertia, tower_motion(model, s0, k));
  for (int b = 0; b < model.blade_count && model.rr_blades.mode_count > 0; ++b)
    add_flexible(model.rr_blades.inertia, blade_motion(model, s0, k, b));
  MassSummary s;
  s.mass_kg = all.mass_kg;
  s.cm_b_m = all.cm_m;
  const Vec3& d = all.cm_m;
  s.inertia_ref_kg_m2 = all.inertia_kg_m2 + all.mass_kg * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
  return s;
}

}  // namespace fowtsim::multibody
