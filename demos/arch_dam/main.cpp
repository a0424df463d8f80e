// Arch dam: seismic analysis of a 3D arch dam in its canyon, on a
// massless foundation or on rock with mass and a viscous-spring boundary,
// with bonded or contact contraction joints.
//   build/bin/arch_dam [--case FILE] [--out DIR] [--set key=value ...]
// With no arguments it runs demos/arch_dam/arch_dam.toml (the paper's 102 m
// dam); presets of other dams are in demos/arch_dam/presets/; --help lists
// the keys. material.model runs the HTC concrete (elastic, plastic or
// viscoplastic) instead of the linear engine.
//
// The phases of the analysis are below; to build a study of your own, copy
// this file and change a phase. study.joints repeats the analysis for
// several sets of active joints (the paper's Tables 2-5), study.table1 for
// the three concrete models at several reservoir levels (Table 1).
#include <damseis/analysis/arch_dam_analysis.h>
#include <damseis/analysis/demo_main.h>
#include <damseis/analysis/foundation_study.h>
#include <damseis/analysis/joint_study.h>
#include <damseis/results/progress.h>

using namespace damseis::analysis;

nlohmann::json analyse(MPI_Comm comm, const ArchDamConfig& config,
                       const std::filesystem::path& out_dir,
                       const std::string& case_text)
{
  // 1. Model: dam, canyon and foundation block meshed by gmsh (OCC), the
  //    joints split and tied, the foundation fixed on its far boundaries
  //    (massless) or held by a viscous-spring boundary (with mass).
  ArchDamModel model = arch_dam_model(comm, config);
  auto analysis = arch_dam_seismic_analysis(model, {out_dir, case_text});
  // 2. Modes with and without the reservoir's added mass (Westergaard);
  //    Rayleigh damping fitted to two of them.
  analysis->modal_stage();
  // 3. Static stage: dead weight and water.
  analysis->static_stage();
  // 4. Time history under the three-component ground motion.
  analysis->time_history();
  // 5. Results: crest history, face envelopes of the principal stresses,
  //    fields (XDMF), summary.json, plots and pictures of the mesh.
  return arch_dam_results(comm, config, model, analysis->results(), out_dir);
}

// A foundation study (study.foundation): the analysis above on massless
// rock and on rock with mass and a viscous-spring boundary (and Liao's
// boundary if the case has foundation.boundary = "mtf"), for each ratio
// E_f / E_d (the paper's Figs. 22-27).
nlohmann::json foundation_study(MPI_Comm comm, const ArchDamConfig& config,
                                const std::filesystem::path& out_dir,
                                const std::string& case_text)
{
  std::vector<FoundationBoundary> models = {FoundationBoundary::viscous_spring};
  if (config.boundary == FoundationBoundary::transmitting)
    models.push_back(FoundationBoundary::transmitting);
  return run_foundation_study(
      comm, config.foundation_ratios, out_dir, "foundation_study",
      [&](double ratio, FoundationBoundary boundary,
          const std::vector<double>& damping_hz,
          const std::filesystem::path& dir)
      {
        ArchDamConfig c =
            with_foundation(config, ratio * config.concrete.E, boundary);
        c.foundation_ratios.clear();
        if (!damping_hz.empty())
          c.seismic.damping_frequencies_hz = damping_hz;
        return analyse(comm, c, dir, case_text);
      },
      {}, models);
}

// The paper's section I study (study.table1): the analysis above with the
// elastic, plastic and viscoplastic concrete at each reservoir level.
nlohmann::json table1_study(MPI_Comm comm, const ArchDamConfig& config,
                            const std::filesystem::path& out_dir,
                            const std::string& case_text)
{
  return run_arch_table1_study(
      comm, config, out_dir,
      [&](const ArchDamConfig& c, const std::filesystem::path& dir)
      { return analyse(comm, c, dir, case_text); });
}

// A joint study (study.joints): the analysis above once per set of active
// joints, each into its subfolder, then the comparison tables.
nlohmann::json study(MPI_Comm comm, const ArchDamConfig& config,
                     const std::filesystem::path& out_dir,
                     const std::string& case_text)
{
  if (!config.foundation_ratios.empty())
    return foundation_study(comm, config, out_dir, case_text);
  if (config.table1)
    return table1_study(comm, config, out_dir, case_text);
  if (config.study_joints.empty())
    return analyse(comm, config, out_dir, case_text);
  std::vector<JointStudyRun> runs;
  for (const std::string& set : config.study_joints)
  {
    const std::string folder = joint_study_folder(set);
    damseis::results::print(comm, "== " + folder + " ==");
    runs.push_back({set, analyse(comm, joint_study_case(config, set),
                                 out_dir / folder, case_text)});
  }
  write_joint_study(comm, runs, candidate_labels(config), out_dir,
                    config.seismic.plots);
  return runs.back().summary;
}

int main(int argc, char** argv)
{
  return demo_main(argc, argv, "arch_dam",
                   DAMSEIS_SOURCE_DIR "/demos/arch_dam/arch_dam.toml",
                   arch_dam_schema, read_arch_dam_config, study);
}
