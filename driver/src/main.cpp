#include <fmt/format.h>
#include "coupling/coupling_study.hpp"
using namespace fowtsim::driver;
int main() {
  auto p = study_problem();
  for (auto mode : {CouplingMode::single_rate, CouplingMode::multi_rate, CouplingMode::predictor_corrector}) {
    for (int n : {1, 4, 16}) {
      if (mode == CouplingMode::single_rate && n != 1) continue;
      auto row = measure_order(p, mode, n, 0.2, 6, 20.0);
      for (auto& s : row.samples) fmt::print("{:20} n={:2} dT={:.5f} eX={:.3e} eq={:.3e} {}\n", to_string(mode), n, s.dt_coupling_s, s.slow_error, s.fast_error, s.finite);
      fmt::print("  order X {:.2f} q {:.2f}\n", row.slow_order, row.fast_order);
      auto st = measure_stability(p, mode, n, 0.01, 5.0, 200.0);
      fmt::print("  stable up to {:.4f} first unstable {:.4f}\n", st.largest_stable_dt_s, st.first_unstable_dt_s);
    }
  }
}
