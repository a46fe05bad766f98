#include "scenes/scene_schema.hpp"

#include "scenes/scene_runner.hpp"

namespace fowtsim::driver {
namespace {

using io::Schema;

Schema toy_simulation_schema() {
  return Schema::map({
      {"t_max_s", Schema::number().unit("s").greater_than(0.0).doc("simulated time")},
      {"dt_coupling_s", Schema::number().unit("s").greater_than(0.0).doc("large (coupling) step ΔT")},
      {"substeps", Schema::integer().at_least(1).at_most(100000).default_value(10)
                       .doc("small steps per large step: Δt = ΔT / substeps")},
      {"coupling", Schema::choice({"multi_rate", "predictor_corrector", "single_rate"})
                       .default_value("multi_rate").doc("how slow and fast subsystems exchange state")},
      {"seed", Schema::integer().at_least(0).default_value(0).doc("random seed (recorded in the output)")},
  });
}

Schema oscillator_schema(const char* what) {
  return Schema::map({
      {"mass_kg", Schema::number().unit("kg").greater_than(0.0).doc(std::string(what) + " mass")},
      {"stiffness_N_m", Schema::number().unit("N_m").greater_than(0.0).doc("spring stiffness")},
      {"damping_N_s_m", Schema::number().unit("N_s_m").at_least(0.0).default_value(0.0).doc("dashpot")},
      {"initial_position_m", Schema::number().unit("m").default_value(0.0).doc("initial displacement")},
      {"divergence_limit_m", Schema::number().unit("m").greater_than(0.0).default_value(1e3)
                                 .doc("|displacement| above this stops the run as divergent")},
  });
}

}  // namespace

Schema scene_schema() {
  return Schema::map({
      {"simulation", toy_simulation_schema().doc("time stepping and coupling")},
      {"output", output_schema().optional().doc("what to write; absent = HDF5, all channels")},
      {"toy_oscillators", Schema::map({
                              {"slow", oscillator_schema("slow (heavy) oscillator")},
                              {"fast", oscillator_schema("fast (light, stiff) oscillator, relative to the slow one")},
                          }).doc("verification scene: coupled oscillators with an exact solution")},
  });
}

}  // namespace fowtsim::driver
