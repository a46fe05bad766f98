#pragma once
// The computations behind the wind verification checks (DESIGN.md §8 tier 2), shared by the module
// tests and `fowtsim verify wind`: the coherence the sampler realises, the small turbulent field
// of the generator's statistics, one grid point's statistics, and a field against a recorded
// velocity history. The reference values and their sources stay with the callers.
#include <array>
#include <cstdint>
#include <vector>

#include "fowtsim/core/types.hpp"
#include "fowtsim/core/wind_grid.hpp"
#include "fowtsim/wind/coherent_sampler.hpp"
#include "fowtsim/wind/params.hpp"
#include "fowtsim/wind/wind_field.hpp"

namespace fowtsim::wind::verification {

// Largest |E[X Xᴴ]_jk − exp(−a r_jk)| of the covariance the prepared sampler realises, built from
// unit vectors ξ = e_l as Σ_l X(e_l) X(e_l)ᴴ, on the sampler's ny-wide grid of spacings dy, dz.
double sampler_coherence_error(CoherentSampler& sampler, int ny, double dy_m, double dz_m, double decay_per_m);

// The generator's statistics case: IEC Kaimal NTM class A, 10 m/s at 90 m, a 4 × 3 grid of 20 m
// spacing, 600 s at 4 Hz, seed `seed`.
WindParams small_turbulent_field(std::uint64_t seed);

struct PointStatistics {
  std::array<double, 3> mean_m_s{};   // mean of u, v, w over the record [m/s]
  std::array<double, 3> sigma_m_s{};  // standard deviation (1/N) of u, v, w [m/s]
};
// Statistics of grid point (iy, iz) over all nt samples of `grid`.
PointStatistics grid_point_statistics(const WindGrid& grid, int iy, int iz);

// The IEC 61400-1 events of the wind field against the standard's formulas, transcribed in
// verification.cpp independently of iec_events.cpp: NREL 5MW (D = 126 m, hub 90 m), class I B,
// power law 0.2 at V_hub = 12 m/s (ECD: 10 m/s), the event from 5 s, `direction_deg` of yaw
// misalignment underneath. Largest |v − v_IEC| / V_hub over the hub and the rotor disk's top,
// bottom, left and right and 401 times over 0–30 s.
double iec_event_worst_deviation(WindEventType type, int sign, double direction_deg);

// The turbulent EWM at V_hub = 40 m/s (V_1 of class I), 3 × 3 grid of 20 m, 600 s at 4 Hz, over
// seeds 1…seeds: the hub u variance averaged over the seeds, its standard error (from the seeds'
// spread), the record's target σ and the IEC σ1 = 0.11 V_hub the generator was given.
struct EwmHubSigma {
  double mean_variance_m2_s2 = 0.0;
  double standard_error_m2_s2 = 0.0;
  double record_sigma_m_s = 0.0;
  double iec_sigma_m_s = 0.0;
};
EwmHubSigma ewm_hub_sigma(int seeds);

// Largest |field velocity − reference| per component at the fixed inertial point `point_m` over the
// sample times `time_s`; reference[c] holds component c at those times [m/s]. Throws InputError
// when a reference column is not as long as the times.
std::array<double, 3> max_velocity_deviation(const WindField& field, const Vec3& point_m, const std::vector<double>& time_s,
                                             const std::array<std::vector<double>, 3>& reference);

}  // namespace fowtsim::wind::verification
