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

// Largest |field velocity − reference| per component at the fixed inertial point `point_m` over the
// sample times `time_s`; reference[c] holds component c at those times [m/s]. Throws InputError
// when a reference column is not as long as the times.
std::array<double, 3> max_velocity_deviation(const WindField& field, const Vec3& point_m, const std::vector<double>& time_s,
                                             const std::array<std::vector<double>, 3>& reference);

}  // namespace fowtsim::wind::verification
