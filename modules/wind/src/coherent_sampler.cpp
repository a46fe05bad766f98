#include "fowtsim/wind/coherent_sampler.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "fowtsim/core/error.hpp"
#include "fowtsim/core/fft.hpp"

namespace fowtsim::wind {
namespace {

// Smallest m >= n whose prime factors are 2, 3 and 5 (fast FFTW sizes).
int fft_friendly(int n) {
  for (int m = std::max(n, 1);; ++m) {
    int r = m;
    for (int p : {2, 3, 5}) while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

}  // namespace

struct CoherentSampler::Impl {
  int ny, nz;
  double dy, dz;
  int my, mz;                       // embedding sizes
  std::optional<ForwardComplexFft2d> fft;  // My·Mz values, z slow
  std::vector<double> root_lambda;  // sqrt(λ / (My Mz)) of the prepared embedding
  // |r_j − r_k| and exp(−a |r_j − r_k|) by offset (|Δiy|, |Δiz|), Δiy ≤ My/2, Δiz ≤ Mz/2 (which
  // covers the grid's offsets, ≤ ny − 1 and nz − 1): one exp per distinct distance, not per pair.
  int table_ny = 0, table_nz = 0;   // My/2 + 1, Mz/2 + 1
  std::vector<double> distance_table, coherence_table;  // [Δiz · table_ny + Δiy] [m], [-]
  // The dense case in the basis of the grid's two mirror symmetries (y → −y, z → −z about the
  // grid's centre): C commutes with both reflections, so with the orthonormal basis Q of the
  // four parity classes (even/odd in y, even/odd in z) QᵀCQ is block-diagonal, four blocks B of
  // about n/4 each. X = Q blockdiag(L) ξ with B = L Lᵀ has covariance Q QᵀCQ Qᵀ = C exactly, for
  // 1/16 of a Cholesky of C (n = 961: four factorisations of 225–256 against one of 961).
  struct SymmetryBlock {
    // Basis vectors of the class: each has 1, 2 or 4 nonzeros (point index, weight ±1/√2 …).
    std::vector<std::array<std::pair<int, double>, 4>> columns;
    std::vector<int> nonzeros;  // per column
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> cholesky;  // L of QᵀCQ's block
  };
  std::array<SymmetryBlock, 4> blocks;
  Method method = Method::independent;
  double max_dropped = 0.0;

  double distance(int diy, int diz) const { return std::hypot(diy * dy, diz * dz); }
  double coherence(int diy, int diz) const {
    return coherence_table[static_cast<std::size_t>(std::abs(diz)) * table_ny + std::abs(diy)];
  }
};

CoherentSampler::CoherentSampler(int ny, int nz, double dy_m, double dz_m) : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.ny = ny;
  s.nz = nz;
  s.dy = dy_m;
  s.dz = dz_m;
  s.my = fft_friendly(2 * (ny - 1));
  s.mz = fft_friendly(2 * (nz - 1));
  s.fft.emplace(s.mz, s.my);
  s.root_lambda.assign(static_cast<std::size_t>(s.my) * s.mz, 0.0);
  s.table_ny = s.my / 2 + 1;
  s.table_nz = s.mz / 2 + 1;
  s.distance_table.resize(static_cast<std::size_t>(s.table_ny) * s.table_nz);
  s.coherence_table.resize(s.distance_table.size());
  for (int diz = 0; diz < s.table_nz; ++diz)
    for (int diy = 0; diy < s.table_ny; ++diy)
      s.distance_table[static_cast<std::size_t>(diz) * s.table_ny + diy] = s.distance(diy, diz);
  // One-dimensional parity basis of m points: even vectors (e_p + e_{m−1−p})/√2, and e_p alone at
  // the centre of an odd m; odd vectors (e_p − e_{m−1−p})/√2.
  const auto parity_basis = [](int m, bool odd) {
    std::vector<std::vector<std::pair<int, double>>> basis;
    for (int p = 0; p < m - 1 - p; ++p)
      basis.push_back({{p, std::numbers::sqrt2 / 2}, {m - 1 - p, (odd ? -1.0 : 1.0) * std::numbers::sqrt2 / 2}});
    if (!odd && m % 2 == 1) basis.push_back({{m / 2, 1.0}});
    return basis;
  };
  for (int k = 0; k < 4; ++k) {
    Impl::SymmetryBlock& block = s.blocks[k];
    for (const auto& vz : parity_basis(nz, k / 2 == 1))
      for (const auto& vy : parity_basis(ny, k % 2 == 1)) {
        std::array<std::pair<int, double>, 4> column{};
        int count = 0;
        for (const auto& [iz, wz] : vz)
          for (const auto& [iy, wy] : vy) column[count++] = {iz * ny + iy, wz * wy};
        block.columns.push_back(column);
        block.nonzeros.push_back(count);
      }
  }
}

CoherentSampler::~CoherentSampler() = default;

std::size_t CoherentSampler::point_count() const { return static_cast<std::size_t>(impl_->ny) * impl_->nz; }
std::size_t CoherentSampler::embedding_size() const { return static_cast<std::size_t>(impl_->my) * impl_->mz; }
double CoherentSampler::max_dropped_coherence() const { return impl_->max_dropped; }

CoherentSampler::Method CoherentSampler::prepare(double a) {
  Impl& s = *impl_;
  const double nearest = std::exp(-a * std::min(s.dy, s.dz));
  if (nearest < independence_threshold) {
    s.max_dropped = std::max(s.max_dropped, nearest);
    return s.method = Method::independent;
  }
  // The same values as exp(−a · distance) pair by pair (hypot is even in each argument).
  for (std::size_t k = 0; k < s.distance_table.size(); ++k) s.coherence_table[k] = std::exp(-a * s.distance_table[k]);
  // First row of the block-circulant embedding (periodic distances), then its eigenvalues.
  std::complex<double>* buffer = s.fft->data();
  for (int iz = 0; iz < s.mz; ++iz) {
    const int diz = std::min(iz, s.mz - iz);
    for (int iy = 0; iy < s.my; ++iy) {
      const int diy = std::min(iy, s.my - iy);
      buffer[static_cast<std::size_t>(iz) * s.my + iy] = {s.coherence(diy, diz), 0.0};
    }
  }
  s.fft->execute();
  const std::size_t m = embedding_size();
  double lambda_max = 0.0, lambda_min = 0.0;
  for (std::size_t k = 0; k < m; ++k) {
    lambda_max = std::max(lambda_max, buffer[k].real());
    lambda_min = std::min(lambda_min, buffer[k].real());
  }
  // Negative eigenvalues beyond round-off: the embedding is not a covariance; use the dense way.
  if (lambda_min >= -1e-12 * lambda_max) {
    for (std::size_t k = 0; k < m; ++k)
      s.root_lambda[k] = std::sqrt(std::max(buffer[k].real(), 0.0) / static_cast<double>(m));
    return s.method = Method::embedding;
  }
  for (Impl::SymmetryBlock& block : s.blocks) {
    const int m = static_cast<int>(block.columns.size());
    // QᵀCQ restricted to the class. C q_k lies in q_k's class (C commutes with the reflections), so
    // q_jᵀ C q_k = (C q_k)[p] / q_j[p] at any point p of q_j: its first.
    Eigen::MatrixXd b(m, m);
    for (int j = 0; j < m; ++j) {
      const auto [pj, wj] = block.columns[j][0];
      for (int k = 0; k <= j; ++k) {
        double sum = 0.0;
        for (int v = 0; v < block.nonzeros[k]; ++v) {
          const auto [pk, wk] = block.columns[k][v];
          sum += wk * s.coherence(pj % s.ny - pk % s.ny, pj / s.ny - pk / s.ny);
        }
        b(j, k) = b(k, j) = sum / wj;
      }
    }
    Eigen::LLT<Eigen::MatrixXd> llt(b);
    if (llt.info() != Eigen::Success)
      throw NumericalError(ErrorContext{"wind.turbulence", std::nullopt, "coherence matrix",
                                        "check grid spacing and mean wind speed"},
                           "Cholesky factorisation of the u-coherence matrix failed");
    block.cholesky = llt.matrixL();
  }
  return s.method = Method::dense;
}

std::size_t CoherentSampler::draws() const {
  return impl_->method == Method::embedding ? embedding_size() : point_count();
}

void CoherentSampler::sample(std::span<const std::complex<double>> xi, std::span<std::complex<double>> out) {
  Impl& s = *impl_;
  const std::size_t n = point_count();
  if (xi.size() != draws() || out.size() != n)
    throw InputError(ErrorContext{"wind.turbulence", std::nullopt, "xi/out", ""},
                     "CoherentSampler::sample: xi.size() != draws() or out.size() != point_count()");
  switch (s.method) {
    case Method::independent:
      std::copy(xi.begin(), xi.end(), out.begin());
      return;
    case Method::embedding: {
      std::complex<double>* buffer = s.fft->data();
      for (std::size_t k = 0; k < embedding_size(); ++k)
        buffer[k] = {s.root_lambda[k] * xi[k].real(), s.root_lambda[k] * xi[k].imag()};
      s.fft->execute();
      for (int iz = 0; iz < s.nz; ++iz)
        for (int iy = 0; iy < s.ny; ++iy)
          out[static_cast<std::size_t>(iz) * s.ny + iy] = buffer[static_cast<std::size_t>(iz) * s.my + iy];
      return;
    }
    case Method::dense: {
      // X = Q blockdiag(L) ξ: ξ taken block by block in class order, each L lower triangular.
      std::fill(out.begin(), out.end(), std::complex<double>{});
      std::size_t offset = 0;
      for (const Impl::SymmetryBlock& block : s.blocks) {
        const std::size_t m = block.columns.size();
        for (std::size_t j = 0; j < m; ++j) {
          const double* row = block.cholesky.data() + j * m;
          double re = 0.0, im = 0.0;
          for (std::size_t k = 0; k <= j; ++k) {
            re += row[k] * xi[offset + k].real();
            im += row[k] * xi[offset + k].imag();
          }
          for (int u = 0; u < block.nonzeros[j]; ++u) {
            const auto [point, weight] = block.columns[j][u];
            out[point] += std::complex<double>{weight * re, weight * im};
          }
        }
        offset += m;
      }
      return;
    }
  }
}

}  // namespace fowtsim::wind
