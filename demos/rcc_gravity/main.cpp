// 190 m roller-compacted concrete gravity dam on a massless foundation:
// dead weight, reservoir, silt and uplift, two-component ground motion at
// 0.2 g; rate-independent vs rate-dependent concrete (the paper's Figs. 7-9).
//   build/bin/rcc_gravity [--case FILE] [--out DIR] [--set key=value ...]
// Same keys as koyna (--help); default case demos/rcc_gravity/rcc_gravity.toml.
//
// The phases of the analysis are below (as in demos/koyna/main.cpp).
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
      argc, argv, "rcc_gravity",
      DAMSEIS_SOURCE_DIR "/demos/rcc_gravity/rcc_gravity.toml",
      gravity_dam_schema, read_gravity_dam_config,
      [](MPI_Comm comm, const GravityDamConfig& config,
         const std::filesystem::path& out_dir, const std::string& case_text) {
        return run_gravity_dam_study(comm, config, out_dir, case_text, analyse);
      });
}
