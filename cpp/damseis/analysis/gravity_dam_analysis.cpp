#include "gravity_dam_analysis.h"
#include "linear_seismic.h"
#include <damseis/geometry/tags.h>

namespace damseis::analysis
{
nlohmann::json run_gravity_dam_analysis(MPI_Comm comm,
                                        const GravityDamConfig& cfg,
                                        const std::filesystem::path& out_dir,
                                        const std::string& case_text)
{
  const bool foundation = cfg.section.foundation;
  std::map<int, fem::Material> materials = {{tags::dam, cfg.concrete}};
  if (foundation)
    materials[tags::foundation] = cfg.rock;
  fem::ElasticModel fe(geometry::build_gravity_dam(comm, cfg.section),
                       cfg.order, materials, cfg.plane);
  if (foundation)
    fe.fix({tags::foundation_bottom, tags::foundation_sides});
  else
    fe.fix({tags::dam_base});

  nlohmann::json summary =
      run_linear_seismic(fe, cfg.seismic, out_dir, case_text);
  summary["analysis"] = "gravity dam section, linear elastic";
  summary["plane"] = cfg.plane == fem::PlaneMode::plane_stress ? "plane_stress"
                                                               : "plane_strain";
  summary["base"] = foundation ? "massless foundation" : "rigid";
  write_summary_and_plots(comm, summary, out_dir, cfg.seismic.plots,
                          "plot_gravity_dam.py");
  return summary;
}
} // namespace damseis::analysis
