// Koyna dam: seismic analysis of a gravity-dam section, linear or with HTC
// concrete (koyna_table1.toml: the three concrete models of Table 1).
//   build/bin/koyna [--case FILE] [--out DIR] [--set key=value ...]
// With no arguments it runs demos/koyna/koyna.toml; --help lists the keys.
//
// The phases of the analysis are below; to build a study of your own, copy
// this file and change a phase (another model, extra loads, other outputs).
#include <damseis/analysis/demo_main.h>
#include <damseis/analysis/gravity_dam_analysis.h>

using namespace damseis::analysis;

nlohmann::json analyse(MPI_Comm comm, const GravityDamConfig& config,
                       const RunFolder& folder)
{
  // 1. Model: the section (and its massless foundation block) meshed by
  //    gmsh, materials per region, supports, the silt and uplift loads.
  GravityDamModel model = gravity_dam_model(comm, config, folder.dir);
  auto analysis = gravity_dam_seismic_analysis(model, config, folder);
  // 2. Modes with and without the reservoir's added mass (Westergaard);
  //    Rayleigh damping fitted to two of them.
  analysis->modal_stage();
  // 3. Static stage: dead weight, water, silt and uplift (in load
  //    increments with Newton for nonlinear concrete).
  analysis->static_stage();
  // 4. Time history under the ground motion (HHT; checkpoints, restart).
  analysis->time_history();
  // 5. Results: crest history, stress envelopes and face tables, fields
  //    (XDMF), summary.json and plots.
  return gravity_dam_results(comm, config, analysis->results(), folder.dir);
}

int main(int argc, char** argv)
{
  return demo_main(
      argc, argv, "koyna", DAMSEIS_SOURCE_DIR "/demos/koyna/koyna.toml",
      gravity_dam_schema, read_gravity_dam_config,
      [](MPI_Comm comm, const GravityDamConfig& config,
         const std::filesystem::path& out_dir, const std::string& case_text) {
        return run_gravity_dam_study(comm, config, out_dir, case_text, analyse);
      });
}
