#include "run/turbulence_command.hpp"

#include <array>
#include <chrono>

#include <fmt/format.h>

#include "decks/wind_deck.hpp"
#include "fowtsim/core/error.hpp"
#include "fowtsim/io/turbsim_bts.hpp"
#include "fowtsim/wind/turbulence_generator.hpp"
#include "run/output_set.hpp"

namespace fowtsim::driver {

namespace {

io::TurbSimField to_turbsim(const wind::FullField& f, const std::string& description) {
  io::TurbSimField t;
  static_cast<WindGrid&>(t) = f;
  t.description = description;
  return t;
}

}  // namespace

int run_turbulence_command(const std::filesystem::path& deck_path, const std::optional<std::filesystem::path>& base_in, std::FILE* out) {
  // A wind deck, or any deck with a `wind:` section (a turbine deck): only that section is read.
  io::LoadedDeck loaded = io::load_deck(deck_path);
  std::erase_if(loaded.root.entries, [](const io::DeckEntry& e) { return e.key != "wind"; });
  const io::ValidatedDeck deck = io::validate(io::Schema::map({{"wind", wind_schema()}}), std::move(loaded));
  const wind::WindParams params = wind_params(deck.section("wind"));
  if (params.model != wind::WindModel::turbulent)
    throw InputError({"wind", std::nullopt, "wind.model", "turbulent"}, deck_path.string() + ": wind.model must be turbulent to generate a field");
  // -o tb, -o tb.bts and -o tb.h5 all write tb.bts and tb.h5.
  const std::filesystem::path base =
      split_known_extension(base_in.value_or(std::filesystem::path("runs") / deck_path.stem()), {".bts", ".h5"}).first;
  if (base.has_parent_path()) std::filesystem::create_directories(base.parent_path());

  const auto start = std::chrono::steady_clock::now();
  const wind::GeneratedTurbulence g = wind::generate_turbulence(params);
  const double generate_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string description = fmt::format("fowtsim IEC Kaimal {} class {}, {} m/s at {} m, seed {}",
                                              std::array{"NTM", "ETM", "EWM"}[static_cast<int>(params.turbulence.model)],
                                              "ABC"[static_cast<int>(params.turbulence.category)], params.speed_m_s,
                                              params.reference_height_m, params.turbulence.seed);
  const io::TurbSimField field = to_turbsim(g.field, description);
  // Written under temporary names and renamed only when both are complete, as run outputs are: a
  // failed write never leaves a truncated field where a good one was.
  const std::filesystem::path bts = base.string() + ".bts", h5 = base.string() + ".h5";
  const std::filesystem::path bts_running = running_path(bts), h5_running = running_path(h5);
  try {
    io::write_turbsim_bts(bts_running, field);
    io::write_turbsim_hdf5(h5_running, field, params.turbulence.seed);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(bts_running, ignored);
    std::filesystem::remove(h5_running, ignored);
    throw;
  }
  std::filesystem::rename(bts_running, bts);
  std::filesystem::rename(h5_running, h5);

  fmt::print(out, "── fowtsim turbulence ─────────────────────────────────\n");
  fmt::print(out, "  field            {}×{} points, {} steps of {} s ({})\n", g.field.ny, g.field.nz, g.field.nt, g.field.dt_s, description);
  fmt::print(out, "  σ u, v, w        {:.3f}, {:.3f}, {:.3f} m/s (IEC {:.3f}, {:.3f}, {:.3f}; the record's band holds the first)\n",
             g.stats.expected_sigma_m_s[0], g.stats.expected_sigma_m_s[1], g.stats.expected_sigma_m_s[2], g.stats.iec_sigma_m_s[0],
             g.stats.iec_sigma_m_s[1], g.stats.iec_sigma_m_s[2]);
  fmt::print(out, "  frequencies      {} ({} dense Cholesky, {} circulant embedding, {} independent: dropped coherence ≤ {:.1e})\n",
             g.stats.frequencies, g.stats.dense_frequencies, g.stats.embedding_frequencies, g.stats.independent_frequencies,
             g.stats.max_dropped_coherence);
  if (g.field.n_tower > 0)
    fmt::print(out, "  tower points     {} at y = 0, z = {:.2f} … {:.2f} m (TurbSim's column; u drawn given the grid: {} frequencies, {} independent)\n",
               g.field.n_tower, g.field.z_bottom_m, g.field.z_bottom_m - (g.field.n_tower - 1) * g.field.dz_m,
               g.stats.tower_conditional_frequencies, g.stats.tower_independent_frequencies);
  else
    fmt::print(out, "  tower points     none (no TurbSim tower point fits between the grid bottom {:.2f} m and the ground)\n", g.field.z_bottom_m);
  fmt::print(out, "  wall time        {:.2f} s\n  output           {}.bts, {}.h5\n", generate_s, base.string(), base.string());
  return 0;
}

}  // namespace fowtsim::driver
