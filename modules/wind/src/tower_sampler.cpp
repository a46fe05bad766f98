#include "fowtsim/wind/tower_sampler.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

#include "fowtsim/core/error.hpp"
#include "fowtsim/wind/coherent_sampler.hpp"

namespace fowtsim::wind {

int turbsim_tower_point_count(double z_bottom_m, double dz_m) {
  constexpr double tolerance = 1e-4;  // TurbSim's Tolerance [m]: the lowest point stays above the ground
  if (!(dz_m > 0.0) || !(z_bottom_m > tolerance)) return 0;
  const int below = static_cast<int>(std::floor((z_bottom_m - tolerance) / dz_m));  // NTwrPts
  return below < 1 ? 0 : below + 1;                                                  // NTwrIndx
}

struct TowerSampler::Impl {
  int ny, nz, n_tower;
  double dy, dz;
  bool on_grid;                 // odd ny: tower point 0 is the grid's bottom-centre point
  std::vector<int> depth;       // depth index k of each drawn tower point (z = z_bottom − k dz)
  // Symmetric basis: vector s = (row iz, lateral index m) with one or two members.
  int n_sym_row = 0;            // basis vectors per row
  std::vector<int> member_a, member_b;  // grid iy of the members (member_b = −1: single member)
  std::vector<double> weight;           // 1 (single) or 1/√2 (pair)
  double r_min = 0.0;           // smallest distance of a drawn tower point to any other point [m]

  Method method = Method::independent;
  double max_dropped = 0.0;
  Eigen::MatrixXd table;        // grid coherence by (|Δiy|, |Δiz|)
  Eigen::MatrixXd c_ss, c_ts, c_tt, w, k, s, root;
  Eigen::LLT<Eigen::MatrixXd> llt;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen;
  std::vector<std::complex<double>> x_sym;

  double y_of(int iy) const { return (iy - 0.5 * (ny - 1)) * dy; }
  int basis_count() const { return nz * n_sym_row; }
};

TowerSampler::TowerSampler(int ny, int nz, double dy_m, double dz_m, int n_tower) : impl_(std::make_unique<Impl>()) {
  Impl& p = *impl_;
  if (ny < 2 || nz < 2 || n_tower < 0 || !(dy_m > 0.0) || !(dz_m > 0.0))
    throw InputError(ErrorContext{"wind.turbulence", std::nullopt, "tower points", ""},
                     "TowerSampler needs ny, nz >= 2, positive spacings and n_tower >= 0");
  p.ny = ny;
  p.nz = nz;
  p.dy = dy_m;
  p.dz = dz_m;
  p.n_tower = n_tower;
  p.on_grid = ny % 2 == 1;
  for (int k = p.on_grid ? 1 : 0; k < n_tower; ++k) p.depth.push_back(k);
  // Symmetric basis of one row (orthonormal): odd ny: the centre, then (c+m, c−m)/√2; even ny:
  // (h+m, h−1−m)/√2.
  if (p.on_grid) {
    const int c = (ny - 1) / 2;
    p.n_sym_row = c + 1;
    p.member_a.push_back(c), p.member_b.push_back(-1), p.weight.push_back(1.0);
    for (int m = 1; m <= c; ++m)
      p.member_a.push_back(c + m), p.member_b.push_back(c - m), p.weight.push_back(std::sqrt(0.5));
  } else {
    const int h = ny / 2;
    p.n_sym_row = h;
    for (int m = 0; m < h; ++m)
      p.member_a.push_back(h + m), p.member_b.push_back(h - 1 - m), p.weight.push_back(std::sqrt(0.5));
  }
  const std::size_t nd = p.depth.size();
  const int ns = p.basis_count();
  // Nearest neighbour of a drawn tower point: the point dz above it, or (even ny, point 0) the two
  // centre grid points dy/2 to either side.
  p.r_min = p.on_grid ? dz_m : std::min(0.5 * dy_m, dz_m);
  p.table.resize(ny, nz);
  p.c_ss.resize(ns, ns);
  p.c_ts.resize(static_cast<Eigen::Index>(nd), ns);
  p.c_tt.resize(static_cast<Eigen::Index>(nd), static_cast<Eigen::Index>(nd));
  p.k.resize(static_cast<Eigen::Index>(nd), ns);
  p.root.resize(static_cast<Eigen::Index>(nd), static_cast<Eigen::Index>(nd));
  p.x_sym.resize(static_cast<std::size_t>(ns));
}

TowerSampler::~TowerSampler() = default;

bool TowerSampler::first_on_grid() const { return impl_->on_grid && impl_->n_tower > 0; }
std::size_t TowerSampler::first_grid_index() const { return static_cast<std::size_t>((impl_->ny - 1) / 2); }
std::size_t TowerSampler::draws() const { return impl_->depth.size(); }
double TowerSampler::max_dropped_coherence() const { return impl_->max_dropped; }

TowerSampler::Method TowerSampler::prepare(double a, bool grid_exact) {
  Impl& p = *impl_;
  const Eigen::Index nd = static_cast<Eigen::Index>(p.depth.size());
  if (nd == 0) return p.method = Method::independent;
  const double nearest = std::exp(-a * p.r_min);
  if (nearest < CoherentSampler::independence_threshold) {
    p.max_dropped = std::max(p.max_dropped, nearest);
    return p.method = Method::independent;
  }
  const int ns = p.basis_count(), per_row = p.n_sym_row;
  // Tower–basis coherences C_ts = C_tg Q_s and tower–tower C_tt.
  for (Eigen::Index t = 0; t < nd; ++t) {
    for (int s = 0; s < ns; ++s) {
      const int iz = s / per_row, m = s % per_row;
      const double y = p.y_of(p.member_a[m]);
      const double value = std::exp(-a * std::hypot(y, (iz + p.depth[t]) * p.dz));
      p.c_ts(t, s) = (p.member_b[m] < 0 ? 1.0 : 2.0) * p.weight[m] * value;  // both members at the same |y|
    }
    for (Eigen::Index u = 0; u < nd; ++u) p.c_tt(t, u) = std::exp(-a * std::abs(p.depth[t] - p.depth[u]) * p.dz);
  }
  if (grid_exact) {
    for (int diz = 0; diz < p.nz; ++diz)
      for (int diy = 0; diy < p.ny; ++diy) p.table(diy, diz) = std::exp(-a * std::hypot(diy * p.dy, diz * p.dz));
    // C_ss = Q_sᵀ C_gg Q_s, lower triangle (LLT reads only that).
    for (int s = 0; s < ns; ++s) {
      const int iz = s / per_row, m = s % per_row;
      for (int r = 0; r <= s; ++r) {
        const int jz = r / per_row, n = r % per_row;
        const int diz = std::abs(iz - jz);
        auto coh = [&](int iy, int jy) { return p.table(std::abs(iy - jy), diz); };
        double sum = coh(p.member_a[m], p.member_a[n]);
        if (p.member_b[n] >= 0) sum += coh(p.member_a[m], p.member_b[n]);
        if (p.member_b[m] >= 0) {
          sum += coh(p.member_b[m], p.member_a[n]);
          if (p.member_b[n] >= 0) sum += coh(p.member_b[m], p.member_b[n]);
        }
        p.c_ss(s, r) = p.weight[m] * p.weight[n] * sum;
      }
    }
    p.llt.compute(p.c_ss);
    if (p.llt.info() != Eigen::Success)
      throw NumericalError(ErrorContext{"wind.turbulence", std::nullopt, "tower coherence matrix",
                                        "check grid spacing and mean wind speed"},
                           "Cholesky factorisation of the grid's symmetric coherence block failed");
    p.w = p.llt.solve(p.c_ts.transpose());  // C_ss⁻¹ C_st
    p.k = p.w.transpose();
    p.s = p.c_tt - p.c_ts * p.w;
  } else {
    p.k = p.c_ts;  // realised grid covariance I
    p.s = p.c_tt - p.c_ts * p.c_ts.transpose();
  }
  p.eigen.compute(p.s);
  const Eigen::VectorXd lambda = p.eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  p.root = p.eigen.eigenvectors() * lambda.asDiagonal();
  return p.method = Method::conditional;
}

void TowerSampler::sample(std::span<const std::complex<double>> grid_x, std::span<const std::complex<double>> eta,
                          std::span<std::complex<double>> out) {
  Impl& p = *impl_;
  const std::size_t nd = p.depth.size();
  if (grid_x.size() != static_cast<std::size_t>(p.ny) * p.nz || eta.size() != nd || out.size() != nd)
    throw InputError(ErrorContext{"wind.turbulence", std::nullopt, "grid_x/eta/out", ""},
                     "TowerSampler::sample: grid_x.size() != ny*nz or eta/out.size() != draws()");
  if (p.method == Method::independent) {
    std::copy(eta.begin(), eta.end(), out.begin());
    return;
  }
  const int ns = p.basis_count(), per_row = p.n_sym_row;
  for (int s = 0; s < ns; ++s) {
    const std::size_t row = static_cast<std::size_t>(s / per_row) * p.ny;
    const int m = s % per_row;
    std::complex<double> v = grid_x[row + p.member_a[m]];
    if (p.member_b[m] >= 0) v += grid_x[row + p.member_b[m]];
    p.x_sym[s] = p.weight[m] * v;
  }
  for (std::size_t t = 0; t < nd; ++t) {
    std::complex<double> v = 0.0;
    for (int s = 0; s < ns; ++s) v += p.k(static_cast<Eigen::Index>(t), s) * p.x_sym[s];
    for (std::size_t u = 0; u < nd; ++u) v += p.root(static_cast<Eigen::Index>(t), static_cast<Eigen::Index>(u)) * eta[u];
    out[t] = v;
  }
}

}  // namespace fowtsim::wind
