#include "arch_dam_analysis.h"
#include "linear_seismic.h"
#include <damseis/fem/tied_dofs.h>
#include <damseis/geometry/arch_mesh.h>
#include <damseis/geometry/tags.h>
#include <damseis/results/progress.h>
#include <dolfinx/la/petsc.h>

namespace damseis::analysis
{
nlohmann::json run_arch_dam_analysis(MPI_Comm comm, const ArchDamConfig& cfg,
                                     const std::filesystem::path& out_dir,
                                     const std::string& case_text)
{
  auto arch = geometry::build_arch_dam(comm, cfg.geometry);
  results::print(
      comm, "arch dam mesh: " + std::to_string(arch.num_cells) + " cells (" +
                std::to_string(arch.num_dam_cells) + " in the dam), " +
                std::to_string(arch.joints.size()) + " joints, built in " +
                std::to_string(arch.total_seconds) + " s");
  fem::ElasticModel fe(
      arch.model, cfg.order,
      {{tags::dam, cfg.concrete}, {tags::foundation, cfg.rock}});
  // Massless foundation fixed on its far boundaries.
  fe.fix({tags::foundation_bottom, tags::foundation_sides,
          tags::foundation_upstream, tags::foundation_downstream});

  std::vector<std::pair<int, int>> joint_tags;
  for (const auto& j : arch.joints)
    joint_tags.emplace_back(j.tag_side1, j.tag_side2);
  dolfinx::la::petsc::Matrix tie(
      joint_tags.empty()
          ? nullptr
          : fem::tie_prolongation(*fe.V(), *arch.model.facet_tags, joint_tags),
      false);

  nlohmann::json summary =
      run_linear_seismic(fe, cfg.seismic, out_dir, case_text, tie.mat());
  summary["analysis"] = "arch dam, linear elastic, massless foundation";
  summary["joints"] = {{"count", arch.joints.size()},
                       {"model", "bonded"},
                       {"pairs", [&]
                        {
                          std::size_t n = 0;
                          for (const auto& j : arch.joints)
                            n += j.size();
                          return n;
                        }()}};
  summary["mesh_seconds"] = arch.total_seconds;
  write_summary_and_plots(comm, summary, out_dir, cfg.seismic.plots,
                          "plot_arch_dam.py");
  return summary;
}
} // namespace damseis::analysis
