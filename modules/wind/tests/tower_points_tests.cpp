// TurbSim's tower points in generated fields (issue 16, "Our files in OpenFAST"): layout, exact joint
// covariance with the grid, one-point statistics and coherence over seeds, the grid left unchanged,
// and the .bts round trip.
#include <catch2/catch.hpp>

#include "series_support.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstring>
#include <filesystem>
#include <vector>

#include "fowtsim/io/turbsim_bts.hpp"
#include "fowtsim/wind/coherent_sampler.hpp"
#include "fowtsim/wind/full_field.hpp"
#include "fowtsim/wind/iec_turbulence.hpp"
#include "fowtsim/wind/tower_sampler.hpp"
#include "fowtsim/wind/turbulence_generator.hpp"

using namespace fowtsim;
using namespace fowtsim::wind;
using Complex = std::complex<double>;
using test_support::dft;
using test_support::series_at;

namespace {

// Grid ny × 3 at 10 m spacing around a 40 m hub: z_bottom = 30 m, so INT(29.9999/10) + 1 = 3 tower
// points at 30, 20, 10 m.
WindParams tower_case(int ny, std::uint64_t seed) {
  WindParams p;
  p.model = WindModel::turbulent;
  p.speed_m_s = 10.0;
  p.reference_height_m = 40.0;
  p.turbulence.category = TurbulenceCategory::A;
  p.turbulence.ny = ny;
  p.turbulence.nz = 3;
  p.turbulence.width_m = 10.0 * (ny - 1);
  p.turbulence.height_m = 20.0;
  p.turbulence.dt_s = 0.25;
  p.turbulence.duration_s = 600.0;
  p.turbulence.seed = seed;
  return p;
}

// Joint covariance of [grid; drawn tower] realised by sampler + tower sampler, from unit inputs.
Eigen::MatrixXcd joint_covariance(CoherentSampler& grid, TowerSampler& tower) {
  const std::size_t ng = grid.point_count(), nt = tower.draws(), gd = grid.draws();
  Eigen::MatrixXcd cov = Eigen::MatrixXcd::Zero(ng + nt, ng + nt);
  std::vector<Complex> xi(gd), eta(nt), xg(ng), xt(nt);
  for (std::size_t l = 0; l < gd + nt; ++l) {
    std::fill(xi.begin(), xi.end(), Complex(0.0, 0.0));
    std::fill(eta.begin(), eta.end(), Complex(0.0, 0.0));
    if (l < gd) xi[l] = 1.0;
    else eta[l - gd] = 1.0;
    grid.sample(xi, xg);
    tower.sample(xg, eta, xt);
    Eigen::VectorXcd v(ng + nt);
    for (std::size_t j = 0; j < ng; ++j) v[j] = xg[j];
    for (std::size_t j = 0; j < nt; ++j) v[ng + j] = xt[j];
    cov += v * v.adjoint();
  }
  return cov;
}

// Largest |realised − IEC| over the blocks: [0] grid–grid, [1] tower–grid, [2] tower–tower.
std::array<double, 3> covariance_errors(int ny, int nz, double dy, double dz, int n_tower, double a) {
  CoherentSampler grid(ny, nz, dy, dz);
  TowerSampler tower(ny, nz, dy, dz, n_tower);
  const bool exact = grid.prepare(a) != CoherentSampler::Method::independent;
  tower.prepare(a, exact);
  const Eigen::MatrixXcd cov = joint_covariance(grid, tower);
  const int ng = ny * nz, first = tower.first_on_grid() ? 1 : 0;
  auto position = [&](int j, double& y, double& z) {
    if (j < ng) y = (j % ny - 0.5 * (ny - 1)) * dy, z = (j / ny) * dz;
    else y = 0.0, z = -(first + j - ng) * dz;
  };
  std::array<double, 3> worst{0, 0, 0};
  for (int j = 0; j < cov.rows(); ++j)
    for (int k = 0; k < cov.cols(); ++k) {
      double yj, zj, yk, zk;
      position(j, yj, zj);
      position(k, yk, zk);
      const double err = std::abs(cov(j, k) - std::exp(-a * std::hypot(yj - yk, zj - zk)));
      const int block = (j < ng && k < ng) ? 0 : (j >= ng && k >= ng) ? 2 : 1;
      worst[block] = std::max(worst[block], err);
    }
  return worst;
}



std::vector<double> tower_series(const FullField& f, int k, int c) {
  std::vector<double> s(f.nt);
  for (int it = 0; it < f.nt; ++it) s[it] = f.tower[(static_cast<std::size_t>(it) * f.n_tower + k) * 3 + c];
  return s;
}

}  // namespace

// Intent: the tower column has TurbSim's layout (TSsubs.f90 CreateGrid: INT((Zbottom − Tolerance)/dz)
// + 1 points from the grid bottom down, none if no point fits): the OC3 field (z_bottom 17.5 m,
// dz 145/30 m) has 4, as the header of TurbSim's 90m_12mps_twr.bts says; point 0 of an odd-ny grid is
// the grid's bottom-centre point, bit for bit.
TEST_CASE("generated tower points follow TurbSim's layout", "[unit][wind][turbulence]") {
  CHECK(turbsim_tower_point_count(17.5, 145.0 / 30.0) == 4);     // TurbSim's OC3 file: 4 tower points
  CHECK(turbsim_tower_point_count(30.0, 10.0) == 3);             // 30, 20, 10 m (0 m is the ground: excluded)
  CHECK(turbsim_tower_point_count(30.00005, 10.0) == 3);         // within TurbSim's Tolerance of the ground
  CHECK(turbsim_tower_point_count(9.0, 10.0) == 0);              // no point fits: TurbSim writes none
  const GeneratedTurbulence odd = generate_turbulence(tower_case(5, 3));
  REQUIRE(odd.field.n_tower == 3);
  REQUIRE(odd.field.tower.size() == static_cast<std::size_t>(odd.field.nt) * 3 * 3);
  for (int c = 0; c < 3; ++c) {
    const std::vector<double> bottom = series_at(odd.field, 2, 0, c), first = tower_series(odd.field, 0, c);
    CHECK(bottom == first);  // exact copy: the same point
  }
  const GeneratedTurbulence even = generate_turbulence(tower_case(4, 3));
  CHECK(even.field.n_tower == 3);  // point 0 drawn at (0, z_bottom), between the two centre columns
  CHECK(even.stats.tower_conditional_frequencies + even.stats.tower_independent_frequencies == even.stats.frequencies);
  validate(odd.field);
  validate(even.field);
}

// Intent: the grid is generated exactly as without tower points (same draws, its own stream for
// the tower), so same seed → bit-identical grid, and the field read below the grid is the tower's.
TEST_CASE("adding tower points leaves the grid bit-identical", "[unit][wind][turbulence]") {
  WindParams with = tower_case(5, 11), without = tower_case(5, 11);
  without.turbulence.tower_points = false;
  const GeneratedTurbulence a = generate_turbulence(with), b = generate_turbulence(without);
  CHECK(b.field.n_tower == 0);
  CHECK(b.field.tower.empty());
  REQUIRE(a.field.grid.size() == b.field.grid.size());
  CHECK(std::memcmp(a.field.grid.data(), b.field.grid.data(), a.field.grid.size() * sizeof(float)) == 0);
  // Tower point 1 (z = 20 m) through the full-field lookup at t = 0 (x = 0, periodic: sample 0).
  const Vec3 v = full_field_velocity(a.field, Vec3(0.0, 0.0, 20.0), 0.0);
  CHECK(v.x() == Approx(a.field.tower[1 * 3 + 0]).margin(1e-6));  // float storage, exact interpolation weight
}

// Intent: the joint covariance of grid and tower amplitudes realised by the two samplers equals the
// IEC coherence matrix of all points: exactly (round-off, 1e-12) when the grid is drawn by embedding
// or dense Cholesky (odd and even ny); when the grid's own coherences are dropped (< 1e-4), tower–grid
// and tower–tower stay exact and only the grid's dropped 1e-4 remain.
TEST_CASE("tower amplitudes are jointly coherent with the grid", "[verification][wind][turbulence]") {
  for (int ny : {5, 4}) {
    INFO("ny = " << ny);
    for (double a : {0.5, 0.05, 0.002}) {  // embedding (0.5, 0.05) and dense (0.002) on a 6-point-wide grid
      INFO("a = " << a);
      const auto err = covariance_errors(ny, 4, 4.0, 5.0, 3, a);
      CHECK(err[0] < 1e-12);
      CHECK(err[1] < 1e-12);
      CHECK(err[2] < 1e-12);
    }
    // a = 2.5: grid independent (exp(−2.5·4) = 4.5e-5); even ny: the tower's point 0 is 2 m from its
    // neighbours (exp(−5) = 6.7e-3), so it is still drawn given the grid.
    const auto err = covariance_errors(ny, 4, 4.0, 5.0, 3, 2.5);
    CHECK(err[0] < CoherentSampler::independence_threshold);
    CHECK(err[1] < (ny % 2 ? CoherentSampler::independence_threshold : 1e-12));
    CHECK(err[2] < CoherentSampler::independence_threshold);
  }
}

// Intent: over many seeds, the tower points carry the one-point statistics and the coherence the
// grid points carry. σ_u at each tower height against the record target σ² = Σ S(f_m) Δf (the IEC
// Kaimal spectrum is the same at every height; the IEC σ itself is larger by the band the record
// lacks, see generator_tests.cpp): each record's variance is Σ_m S_m Δf |X_m|² with E|X_m|² = 1 and
// Var|X_m|² ≤ 1 (|X|² of a linear combination of unit phasors: E|X|⁴ ≤ 2 (E|X|²)²), so the mean over
// K seeds of the variance has standard deviation ≤ sqrt(Σ_m (S_m Δf)² / K); bound 4 of them. The mean
// over the record is U(z) = V_hub (z/z_hub)^α exactly (no m = 0 term) up to float storage.
// Co-coherence per octave band: tower point 1 with the grid point above it (tower point 0 = grid
// bottom centre, r = 10 m), tower 1 with tower 2 (r = 10 m), tower 2 with the grid bottom centre
// (r = 20 m); even ny: the drawn point 0 with its grid neighbour (r = 5 m). Bound 4 (1 − γ²)/sqrt(2K)
// as for the grid (Bendat & Piersol §9.2.3).
TEST_CASE("tower points have the IEC spectra, intensity, mean profile and coherence",
          "[verification][wind][turbulence]") {
  const int seeds = 150;
  for (int ny : {5, 4}) {
    INFO("ny = " << ny);
    const WindParams p0 = tower_case(ny, 1);
    const KaimalModel kaimal = kaimal_model(p0.turbulence, p0.speed_m_s, p0.reference_height_m);
    const int n = static_cast<int>(std::llround(p0.turbulence.duration_s / p0.turbulence.dt_s));
    const double dt = p0.turbulence.dt_s, df = 1.0 / (n * dt);
    const int top = n / 2 - 1;
    double target_var = 0.0, spread = 0.0;
    for (int m = 1; m <= top; ++m) {
      const double s = kaimal.spectrum(0, m * df) * df;
      target_var += s, spread += s * s;
    }
    std::vector<int> band_start;
    for (int b = 4; b <= top; b *= 2) band_start.push_back(b);
    const std::size_t bands = band_start.size();
    auto band_end = [&](std::size_t i) { return std::min(2 * band_start[i], top + 1); };

    // Pairs (a, b): index ≥ 0 a tower point, −1 the grid point (centre or, even ny, right of centre) of row 0.
    struct Pair {
      int a, b;
      double r;
    };
    const std::vector<Pair> pairs = ny % 2 ? std::vector<Pair>{{1, -1, 10.0}, {1, 2, 10.0}, {2, -1, 20.0}}
                                           : std::vector<Pair>{{0, -1, 5.0}, {1, -1, std::hypot(5.0, 10.0)}, {1, 2, 10.0}};
    std::vector<std::vector<double>> cross(pairs.size(), std::vector<double>(bands)), auto_a = cross, auto_b = cross;
    std::vector<double> var_sum(3, 0.0), mean_err(3, 0.0);
    std::vector<double> heights(3);
    for (int seed = 1; seed <= seeds; ++seed) {
      const GeneratedTurbulence g = generate_turbulence(tower_case(ny, static_cast<std::uint64_t>(seed)));
      const FullField& f = g.field;
      REQUIRE(f.n_tower == 3);
      std::vector<std::vector<Complex>> tower_dft(3);
      for (int k = 0; k < 3; ++k) {
        std::vector<double> s = tower_series(f, k, 0);
        double mean = 0.0;
        for (double v : s) mean += v / n;
        heights[k] = f.z_bottom_m - k * f.dz_m;
        const double u = p0.speed_m_s * std::pow(heights[k] / p0.reference_height_m, p0.shear_exponent);
        mean_err[k] = std::max(mean_err[k], std::abs(mean - u));
        double var = 0.0;
        for (double& v : s) v -= mean, var += v * v / n;
        var_sum[k] += var;
        tower_dft[k] = dft(s);
      }
      const std::vector<Complex> grid_dft = dft(series_at(f, ny / 2, 0, 0));  // odd: centre; even: right of centre
      for (std::size_t q = 0; q < pairs.size(); ++q) {
        const std::vector<Complex>& xa = tower_dft[pairs[q].a];
        const std::vector<Complex>& xb = pairs[q].b < 0 ? grid_dft : tower_dft[pairs[q].b];
        for (std::size_t i = 0; i < bands; ++i)
          for (int m = band_start[i]; m < band_end(i); ++m) {
            cross[q][i] += (xa[m] * std::conj(xb[m])).real();
            auto_a[q][i] += std::norm(xa[m]);
            auto_b[q][i] += std::norm(xb[m]);
          }
      }
    }
    const double bound = 4.0 * std::sqrt(spread / seeds);  // on the seed-mean variance [m²/s²], see above
    for (int k = (ny % 2 ? 1 : 0); k < 3; ++k) {
      const double var = var_sum[k] / seeds;
      INFO("tower point " << k << " at z = " << heights[k] << " m: σ_u " << std::sqrt(var) << " m/s, record target "
                          << std::sqrt(target_var) << " m/s, IEC " << kaimal.component[0].sigma_m_s << " m/s; |Δσ²| "
                          << std::abs(var - target_var) << " vs bound " << bound << " m²/s²");
      CHECK(std::abs(var - target_var) < bound);
      CHECK(mean_err[k] < 1e-4);  // float32 storage of ~10 m/s plus the float sum of 2400 samples
    }
    for (std::size_t q = 0; q < pairs.size(); ++q)
      for (std::size_t i = 0; i < bands; ++i) {
        double target = 0.0, weight = 0.0;
        for (int m = band_start[i]; m < band_end(i); ++m) {
          target += kaimal.spectrum(0, m * df) * std::exp(-kaimal.coherence_decay_per_m(m * df) * pairs[q].r);
          weight += kaimal.spectrum(0, m * df);
        }
        target /= weight;
        const double estimate = cross[q][i] / std::sqrt(auto_a[q][i] * auto_b[q][i]);
        const double samples = static_cast<double>(seeds) * (band_end(i) - band_start[i]);
        const double tolerance = 4.0 * (1.0 - target * target) / std::sqrt(2.0 * samples);
        INFO("pair " << pairs[q].a << "–" << pairs[q].b << ", r = " << pairs[q].r << " m, band from " << band_start[i] * df
                     << " Hz: co-coherence " << estimate << " vs IEC " << target << ", tolerance " << tolerance);
        CHECK(std::abs(estimate - target) < tolerance);
      }
  }
}

// Intent: the .bts written from a generated field re-reads with its tower points (n_tower, the same
// geometry) and every tower and grid value within the int16 step of the writer (0.5/slope per
// component, plus float32 rounding): what OpenFAST reads is what we generated.
TEST_CASE("a generated field with tower points survives the .bts round trip", "[unit][wind][turbulence]") {
  const GeneratedTurbulence g = generate_turbulence(tower_case(5, 21));
  io::TurbSimField t;
  static_cast<WindGrid&>(t) = g.field;
  t.description = "tower round trip";
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "fowtsim_tower_points_test.bts";
  io::write_turbsim_bts(path, t);
  const io::TurbSimField r = io::read_turbsim_bts(path);
  std::filesystem::remove(path);
  CHECK(r.n_tower == 3);
  CHECK(r.ny == 5);
  CHECK(r.nz == 3);
  CHECK(r.z_bottom_m == Approx(30.0).margin(1e-5));
  CHECK(r.dz_m == Approx(10.0).margin(1e-5));
  REQUIRE(r.tower.size() == g.field.tower.size());
  float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (const auto* values : {&g.field.grid, &g.field.tower})
    for (std::size_t k = 0; k < values->size(); ++k) {
      lo[k % 3] = std::min(lo[k % 3], (*values)[k]);
      hi[k % 3] = std::max(hi[k % 3], (*values)[k]);
    }
  double worst[3] = {0, 0, 0};  // largest error in units of the bound
  for (const auto& [mine, back] : {std::pair{&g.field.grid, &r.grid}, std::pair{&g.field.tower, &r.tower}})
    for (std::size_t k = 0; k < mine->size(); ++k) {
      const auto s = io::int16_scaling(lo[k % 3], hi[k % 3]);
      const double bound = 0.5 / s.slope + std::abs((*mine)[k]) * 0x1.0p-24;
      worst[k % 3] = std::max(worst[k % 3], std::abs((*mine)[k] - (*back)[k]) / bound);
    }
  INFO("worst error / bound: u " << worst[0] << ", v " << worst[1] << ", w " << worst[2]);
  CHECK(worst[0] <= 1.0);
  CHECK(worst[1] <= 1.0);
  CHECK(worst[2] <= 1.0);
}
