#include "scenes/screening_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "decks/deck_helpers.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/waves/dispersion.hpp"
#include "fowtsim/waves/spectrum.hpp"
#include "fowtsim/wind/iec_turbulence.hpp"

namespace fowtsim::driver {
namespace {

constexpr double kPi = std::numbers::pi;

// cosh(k(z + h))/sinh(kh) and sinh(k(z + h))/sinh(kh) for z ≤ 0, written with decaying exponentials
// so that deep water (kh ≫ 1, where both tend to e^{kz}) does not overflow.
void depth_factors(double k, double z, double depth_m, double& c, double& s) {
  if (!std::isfinite(depth_m)) {
    c = s = std::exp(k * z);
    return;
  }
  const double denominator = 1.0 - std::exp(-2.0 * k * depth_m);
  c = (std::exp(k * z) + std::exp(-k * (z + 2.0 * depth_m))) / denominator;
  s = (std::exp(k * z) - std::exp(-k * (z + 2.0 * depth_m))) / denominator;
}

// Airy velocity per unit elevation amplitude Re[e^{iωt}] at the origin (see the header), at p (g).
Eigen::Vector3cd wave_velocity(const Vec3& p, double omega, double k, double heading, double depth_m) {
  double c = 0.0, s = 0.0;
  depth_factors(k, std::min(p.z(), 0.0), depth_m, c, s);
  const std::complex<double> phase = std::exp(std::complex<double>(0.0, -k * (p.x() * std::cos(heading) + p.y() * std::sin(heading))));
  // u = ω cosh/sinh E along the heading, w = iω sinh/sinh E (η = cos ωt at the origin ⇒ w = dη/dt at z = 0)
  return Eigen::Vector3cd(omega * c * std::cos(heading) * phase, omega * c * std::sin(heading) * phase,
                          std::complex<double>(0.0, omega * s) * phase);
}

// Dynamic pressure per unit amplitude, ρ g cosh(k(z + h))/cosh(kh) E.
std::complex<double> dynamic_pressure(const Vec3& p, double k, double heading, double depth_m, double rho, double g) {
  double c = 0.0, s = 0.0;
  depth_factors(k, std::min(p.z(), 0.0), depth_m, c, s);
  const double tanh_kh = std::isfinite(depth_m) ? std::tanh(k * depth_m) : 1.0;
  const std::complex<double> phase = std::exp(std::complex<double>(0.0, -k * (p.x() * std::cos(heading) + p.y() * std::sin(heading))));
  return rho * g * c * tanh_kh * phase;  // cosh(k(z+h))/cosh(kh) = [cosh/sinh] · tanh(kh)
}

}  // namespace

WaveSpectrum::WaveSpectrum(const waves::WaveParams& w) : waves_(w) {
  if (w.model != waves::WaveModel::still && w.model != waves::WaveModel::jonswap && w.model != waves::WaveModel::pierson_moskowitz)
    throw InputError({"screen", std::nullopt, "waves.model", "jonswap, pm or still"},
                     "the frequency-domain screening needs a wave spectrum: waves.model jonswap, pm or still (or no waves)");
  if (w.model == waves::WaveModel::jonswap) {
    gamma_ = w.gamma.value_or(waves::default_peak_shape(w.hs_m, w.tp_s));
    normalisation_ = waves::jonswap_normalisation(gamma_);
  }
}

double WaveSpectrum::at_hz(double f_hz) const {
  const waves::WaveParams& w = waves_;
  if (w.model == waves::WaveModel::still || w.hs_m == 0.0 || f_hz <= 0.0) return 0.0;
  if (f_hz < w.cutoff_low_hz || (w.cutoff_high_hz && f_hz > *w.cutoff_high_hz)) return 0.0;
  const double omega = 2.0 * kPi * f_hz;
  // S(f) = 2π S(ω): the waves module's densities are per rad/s.
  if (w.model == waves::WaveModel::pierson_moskowitz) return 2.0 * kPi * waves::pierson_moskowitz_density(omega, w.hs_m, w.tp_s);
  return 2.0 * kPi * waves::jonswap_density(omega, w.hs_m, w.tp_s, gamma_, normalisation_);
}

RotorEffectiveWind::RotorEffectiveWind(const wind::WindParams& wind, double hub_height_m, double rotor_radius_m) {
  if (wind.model != wind::WindModel::turbulent) return;
  turbulent_ = true;
  const wind::KaimalModel kaimal = wind::kaimal_model(wind.turbulence, wind.speed_m_s, hub_height_m);
  sigma_u_ = kaimal.component[0].sigma_m_s;
  length_u_m_ = kaimal.component[0].length_scale_m;
  speed_m_s_ = wind.speed_m_s;
  coherence_scale_m_ = kaimal.coherence_scale_m;
  // A polar grid of equal-area cells over the disk (ring j holds 8(2j+1) cells), every pair of
  // cells with the weight of their areas, the distances binned at 1/64 of the diameter: the
  // coherence then changes by less than 1 % over a bin up to 1 Hz at 12 m/s.
  constexpr int rings = 8, bins = 64;
  std::vector<Vec3> cells;
  for (int j = 0; j < rings; ++j) {
    const double r = rotor_radius_m * std::sqrt((j + 0.5) / rings);
    const int n = 8 * (2 * j + 1);
    for (int m = 0; m < n; ++m) cells.emplace_back(0.0, r * std::cos(2.0 * kPi * (m + 0.5) / n), r * std::sin(2.0 * kPi * (m + 0.5) / n));
  }
  const double bin_m = 2.0 * rotor_radius_m / bins;
  weight_.assign(bins + 1, 0.0);
  for (const Vec3& a : cells)
    for (const Vec3& b : cells) weight_[static_cast<std::size_t>(std::lround((a - b).norm() / bin_m))] += 1.0;
  const double pairs = static_cast<double>(cells.size() * cells.size());
  for (std::size_t i = 0; i < weight_.size(); ++i) {
    weight_[i] /= pairs;
    distance_m_.push_back(static_cast<double>(i) * bin_m);
  }
}

double RotorEffectiveWind::spectrum_hz(double f_hz) const {
  if (!turbulent_ || f_hz <= 0.0) return 0.0;
  // IEC 61400-1 eq. B.1 (u component) and B.2 (coherence), as the turbulence generator draws them.
  const double x = f_hz * length_u_m_ / speed_m_s_;
  const double point = 4.0 * sigma_u_ * sigma_u_ * length_u_m_ / speed_m_s_ / std::pow(1.0 + 6.0 * x, 5.0 / 3.0);
  const double decay = 12.0 * std::hypot(f_hz / speed_m_s_, 0.12 / coherence_scale_m_);
  double average = 0.0;
  for (std::size_t i = 0; i < weight_.size(); ++i) average += weight_[i] * std::exp(-decay * distance_m_[i]);
  return point * average;
}

PlatformStrips platform_strips(const hydro::Params& hydro) {
  PlatformStrips out;
  for (const hydro::MemberParams& m : hydro.members) {
    const Vec3 a = m.end_a_body_m, b = m.end_b_body_m;
    const double length = (b - a).norm();
    if (length <= 0.0) continue;
    const Vec3 axis = (b - a) / length;
    // The submerged part of the axis (z ≤ 0), cut into the member's strips.
    double s0 = 0.0, s1 = 1.0;
    if (a.z() > 0.0 && b.z() > 0.0) continue;
    if (a.z() > 0.0) s0 = a.z() / (a.z() - b.z());
    if (b.z() > 0.0) s1 = a.z() / (a.z() - b.z());
    const double strip = (s1 - s0) / m.strips;
    for (int i = 0; i < m.strips; ++i) {
      const double s = s0 + (i + 0.5) * strip;
      PlatformStrip st;
      st.centre_m = a + s * (b - a);
      st.axis = axis;
      st.length_m = strip * length;
      st.diameter_m = m.diameter_a_m + s * (m.diameter_b_m - m.diameter_a_m);
      st.cd = m.cd;
      st.ca = m.ca;
      st.area_slope_m = kPi / 2.0 * st.diameter_m * (m.diameter_b_m - m.diameter_a_m) / length;  // d(πD²/4)/dl
      out.strips.push_back(st);
    }
    if (a.z() <= 0.0) out.ends.push_back({a, -axis, kPi / 4.0 * m.diameter_a_m * m.diameter_a_m, m.axial_cp_a});
    if (b.z() <= 0.0) out.ends.push_back({b, axis, kPi / 4.0 * m.diameter_b_m * m.diameter_b_m, m.axial_cp_b});
  }
  // An end plate shared by two members (a joint) is inside the body: pressure on it cancels.
  std::vector<PlatformEnd> kept;
  for (const PlatformEnd& e : out.ends) {
    const bool joint = std::count_if(out.ends.begin(), out.ends.end(), [&](const PlatformEnd& o) {
                         return (o.centre_m - e.centre_m).norm() < 1e-6;
                       }) > 1;
    if (!joint) kept.push_back(e);
  }
  out.ends = kept;
  return out;
}

Vec6c morison_excitation(const PlatformStrips& s, const hydro::Params& hydro, double omega, double heading, double depth_m) {
  const double rho = hydro.water_density_kg_m3, g = hydro.gravity_m_s2;
  const double k = waves::wavenumber(omega, depth_m, g);
  Vec6c f = Vec6c::Zero();
  auto add = [&](const Vec3& at, const Eigen::Vector3cd& force) {
    f.head<3>() += force;
    // r × F written out: Eigen's cross() of complex vectors conjugates its result.
    f[3] += at.y() * force.z() - at.z() * force.y();
    f[4] += at.z() * force.x() - at.x() * force.z();
    f[5] += at.x() * force.y() - at.y() * force.x();
  };
  for (const PlatformStrip& st : s.strips) {
    const Eigen::Vector3cd acceleration = std::complex<double>(0.0, omega) * wave_velocity(st.centre_m, omega, k, heading, depth_m);
    const Eigen::Vector3cd normal = acceleration - st.axis.cast<std::complex<double>>() * st.axis.cast<std::complex<double>>().dot(acceleration);
    const double volume = kPi / 4.0 * st.diameter_m * st.diameter_m * st.length_m;
    add(st.centre_m, rho * (1.0 + st.ca) * volume * normal);
    // A taper's sloping wall: the pressure along the axis, p dA/dl per length (Froude–Krylov).
    if (st.area_slope_m != 0.0)
      add(st.centre_m, dynamic_pressure(st.centre_m, k, heading, depth_m, rho, g) * st.area_slope_m * st.length_m *
                           st.axis.cast<std::complex<double>>());
  }
  for (const PlatformEnd& e : s.ends)
    add(e.centre_m, -e.cp * e.area_m2 * dynamic_pressure(e.centre_m, k, heading, depth_m, rho, g) * e.outward.cast<std::complex<double>>());
  return f;
}

std::vector<Eigen::Vector3cd> strip_wave_velocity(const PlatformStrips& s, double omega, double heading, double depth_m,
                                                 double gravity_m_s2) {
  const double k = waves::wavenumber(omega, depth_m, gravity_m_s2);
  std::vector<Eigen::Vector3cd> out;
  out.reserve(s.strips.size());
  for (const PlatformStrip& st : s.strips) {
    const Eigen::Vector3cd u = wave_velocity(st.centre_m, omega, k, heading, depth_m);
    const Eigen::Vector3cd e = st.axis.cast<std::complex<double>>();
    out.push_back(u - e * e.dot(u));
  }
  return out;
}

void RadiationCoefficients::at(double omega, Mat6& added, Mat6& damping) const {
  const std::vector<double>& w = table.frequencies_rad_s;
  if (w.empty()) {
    added.setZero();
    damping.setZero();
    return;
  }
  // Beyond the table: A(ω) of its nearest end, no damping (the radiation kernel knows B only there).
  if (omega <= w.front() || omega >= w.back()) {
    const std::size_t i = omega <= w.front() ? 0 : w.size() - 1;
    added = table.added_mass[i] - added_mass_infinite;
    damping = omega <= w.front() ? Mat6(table.damping[0] * (omega / w.front())) : Mat6::Zero();
    return;
  }
  const auto upper = static_cast<std::size_t>(std::upper_bound(w.begin(), w.end(), omega) - w.begin());
  const std::size_t lower = upper - 1;
  const double x = (omega - w[lower]) / (w[upper] - w[lower]);
  added = (1.0 - x) * table.added_mass[lower] + x * table.added_mass[upper] - added_mass_infinite;
  damping = (1.0 - x) * table.damping[lower] + x * table.damping[upper];
}

std::optional<RadiationCoefficients> radiation_coefficients(const io::ValidatedDeck& hydro_section, const hydro::Params& hydro) {
  if (!hydro.potential_flow || !hydro_section.has("potential_flow")) return std::nullopt;
  const io::ValidatedDeck flow = hydro_section.section("potential_flow");
  const io::WamitScales scales{hydro.water_density_kg_m3, hydro.gravity_m_s2, flow.number("length_scale_m")};
  RadiationCoefficients r;
  r.table = io::read_wamit_radiation(beside_deck(flow, "wamit_root").string() + ".1", scales);
  r.added_mass_infinite = hydro.potential_flow->radiation.added_mass_infinite_frequency;
  return r;
}

std::optional<io::WamitExcitation> wamit_excitation(const io::ValidatedDeck& hydro_section, const hydro::Params& hydro) {
  if (!hydro_section.has("potential_flow")) return std::nullopt;
  const io::ValidatedDeck flow = hydro_section.section("potential_flow");
  if (!flow.boolean("excitation")) return std::nullopt;
  const io::WamitScales scales{hydro.water_density_kg_m3, hydro.gravity_m_s2, flow.number("length_scale_m")};
  const std::filesystem::path root = beside_deck(flow, "wamit_root");
  try {
    return io::read_wamit_excitation(root.string() + ".3", scales);
  } catch (const InputError& e) {
    throw InputError(e.context(), where(flow, "wamit_root") + ": " + e.message());
  }
}

}  // namespace fowtsim::driver
