// dam_model: the seismic (or general dynamic) analysis of your own mesh.
//   build/bin/dam_model --case FILE [--out DIR] [--set key=value ...]
// The case file names a gmsh .msh file and maps its physical groups to
// roles: material regions, supports, the reservoir's wetted faces, joints,
// loaded faces, output faces (README "Your own dam"; --help lists the keys).
// With no arguments it runs demos/dam_model/section_2d.toml.
#include <damseis/analysis/dam_model_analysis.h>
#include <damseis/analysis/demo_main.h>

using namespace damseis::analysis;

nlohmann::json analyse(MPI_Comm comm, const DamModelConfig& config,
                       const std::filesystem::path& out_dir,
                       const std::string& case_text)
{
  // 1. Model: the mesh (read and checked with the case), materials per
  //    region, supports fixed, joints tied, tractions, body forces and the
  //    initial velocity.
  DamModel model = dam_model(comm, config);
  auto analysis =
      dam_model_seismic_analysis(model, config, {out_dir, case_text});
  // 2. Modes with and without the reservoir's added mass; Rayleigh damping.
  analysis->modal_stage();
  // 3. Static stage: dead weight, water, body forces.
  analysis->static_stage();
  // 4. Time history under the ground motion and the tractions.
  analysis->time_history();
  // 5. Results: crest history, point histories, stress envelopes and face
  //    tables, fields (XDMF), summary.json.
  return dam_model_results(comm, config, model, analysis->results(), out_dir);
}

int main(int argc, char** argv)
{
  return demo_main(argc, argv, "dam_model",
                   DAMSEIS_SOURCE_DIR "/demos/dam_model/section_2d.toml",
                   dam_model_schema, read_dam_model_config, analyse);
}
