// Slurm options of a sweep (issue 27): the spec's `slurm:` section — account, QOS, memory, extra
// #SBATCH lines and set-up lines — in the job script, the command line's values over the spec's,
// and bad lines stopped at their spec line.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "fowtsim/io/deck.hpp"
#include "fowtsim/testing/skip.hpp"
#include "sweep/case_files.hpp"
#include "sweep/slurm_job.hpp"
#include "sweep/sweep_spec.hpp"

using namespace fowtsim;
using namespace fowtsim::driver::sweep;

namespace {

std::filesystem::path write_spec(const std::string& test, const std::string& slurm_section) {
  const std::filesystem::path dir = testing::scratch_dir(test);
  const std::filesystem::path path = dir / "spec.yaml";
  std::ofstream(path) << "sweep:\n  name: " << test << "\n  base_deck: "
                      << (testing::source_dir() / "inputs/oc3_hywind/turbine_ntm_12mps_irregular.yaml").string()
                      << "\n  output_dir: " << (dir / "out").string() << "\n" << slurm_section
                      << "load_cases:\n  - name: steady\n";
  return path;
}

std::string script_of(const SweepSpec& spec, const SlurmOptions& command_line) {
  const SlurmJob job = write_slurm_job(spec.name, SweepLayout{spec.output_dir}, {"steady"}, "/usr/bin/fowtsim",
                                       merge_slurm_options(spec.slurm, command_line));
  std::ifstream in(job.script);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TEST_CASE("sweep --slurm: the spec's account, QOS, memory, sbatch and set-up lines reach the job script", "[unit][sweep]") {
  const SweepSpec spec = read_sweep_spec(write_spec("slurm_options", R"(slurm:
  partition: short
  account: wind-loads
  qos: normal
  mem: 2G
  sbatch_lines: [--constraint=avx2, --exclusive]
  setup_lines: ["module load hdf5", "export OMP_NUM_THREADS=1"]
)"));
  const std::string script = script_of(spec, {});
  for (const char* line : {"#SBATCH --partition=short\n", "#SBATCH --account=wind-loads\n", "#SBATCH --qos=normal\n",
                           "#SBATCH --mem=2G\n", "#SBATCH --constraint=avx2\n", "#SBATCH --exclusive\n",
                           "\nmodule load hdf5\n", "\nexport OMP_NUM_THREADS=1\n"})
    CHECK_THAT(script, Catch::Contains(line));
  // sbatch reads #SBATCH lines only before the first command: every one precedes the set-up.
  CHECK(script.rfind("#SBATCH") < script.find("module load hdf5"));
  // The set-up runs before the first case.
  CHECK(script.find("export OMP_NUM_THREADS=1") < script.find("run \"$root/decks/"));

  SECTION("the command line's values win; its extra lines come after the spec's") {
    SlurmOptions command_line;
    command_line.account = std::string("other");
    command_line.memory = std::string("4G");
    const std::string overridden = script_of(spec, command_line);
    CHECK_THAT(overridden, Catch::Contains("#SBATCH --account=other\n"));
    CHECK_THAT(overridden, Catch::Contains("#SBATCH --mem=4G\n"));
    CHECK_THAT(overridden, !Catch::Contains("wind-loads"));
    CHECK_THAT(overridden, Catch::Contains("#SBATCH --qos=normal\n"));  // not given: the spec's
  }
}

TEST_CASE("sweep --slurm: a script without a slurm section names no account, QOS or memory", "[unit][sweep]") {
  const std::string script = script_of(read_sweep_spec(write_spec("slurm_plain", "")), {});
  CHECK_THAT(script, !Catch::Contains("--account"));
  CHECK_THAT(script, !Catch::Contains("--qos"));
  CHECK_THAT(script, !Catch::Contains("--mem"));
}

TEST_CASE("sweep specs: a bad Slurm line stops at its spec line", "[unit][sweep]") {
  const std::filesystem::path path = write_spec("slurm_bad", R"(slurm:
  sbatch_lines: [constraint=avx2]
  setup_lines: ["module load hdf5\nrm -rf x"]
)");
  std::string message;
  try {
    read_sweep_spec(path);
  } catch (const io::DeckError& e) {
    message = e.what();
  }
  CHECK_THAT(message, Catch::Contains("spec.yaml:6") && Catch::Contains("slurm.sbatch_lines[0]") && Catch::Contains("starting with -"));
  CHECK_THAT(message, Catch::Contains("slurm.setup_lines[0]") && Catch::Contains("one shell line per item"));
}
