#include "concrete_outputs.h"
#include "run_outputs.h"
#include <cmath>
#include <damseis/results/progress.h>
#include <damseis/results/singular_points.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/mesh/Mesh.h>
#include <sstream>

namespace damseis::analysis
{
using nlohmann::json;

/// Largest value over the flagged owned points of all ranks, with where and
/// when.
results::Extreme scalar_extreme(MPI_Comm comm, const ScalarEnvelope& e,
                                std::span<const double> coords,
                                const std::vector<std::int8_t>& flag)
{
  struct
  {
    double v;
    int rank;
  } local{-HUGE_VAL, 0}, global;
  MPI_Comm_rank(comm, &local.rank);
  std::size_t arg = 0;
  for (std::size_t i = 0; i < e.max.size(); ++i)
  {
    if (flag[i] && e.max[i] > local.v)
    {
      local.v = e.max[i];
      arg = i;
    }
  }
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm);
  std::array<double, 4> data = {0, 0, 0, 0};
  if (local.rank == global.rank && !e.max.empty())
    data = {coords[3 * arg], coords[3 * arg + 1], coords[3 * arg + 2],
            e.t[arg]};
  MPI_Bcast(data.data(), 4, MPI_DOUBLE, global.rank, comm);
  return {global.v, {data[0], data[1], data[2]}, data[3]};
}

/// Global number of cells of the regions.
std::int64_t region_cell_count(MPI_Comm comm, const geometry::Model& model,
                               const std::vector<int>& regions)
{
  const std::int32_t owned = model.mesh->topology()
                                 .index_map(model.mesh->topology().dim())
                                 ->size_local();
  std::int64_t n = 0;
  for (std::int32_t c : region_cells(model, regions))
    n += c < owned ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &n, 1, MPI_INT64_T, MPI_SUM, comm);
  return n;
}

/// The snap-back limit of the cell size, E Gf / (s ft^2) [m], s the
/// snap-back safety factor (1.25; material/README.md).
double concrete_characteristic_length(const ConcreteSettings& c)
{
  const auto& p = c.params;
  return p.E * p.Gf / (p.snap_back_safety * p.ft0 * p.ft0);
}

/// dam_points.csv on rank 0: one row per owned dam point of every rank.
void write_dam_points(MPI_Comm comm, int dim,
                      const results::StressEnvelope& env,
                      const std::vector<std::int8_t>& in_dam,
                      const std::vector<const std::vector<double>*>& columns,
                      const std::filesystem::path& file)
{
  const int nc = dim + 2 + static_cast<int>(columns.size());
  std::vector<double> local;
  for (std::size_t i = 0; i < in_dam.size(); ++i)
  {
    if (!in_dam[i])
      continue;
    const auto& x = env.point(static_cast<std::int32_t>(i));
    local.insert(local.end(), x.begin(), x.begin() + dim);
    local.insert(local.end(), {env.max_principal()[i] * 1e-6,
                               env.min_principal()[i] * 1e-6});
    for (const auto* c : columns)
      local.push_back((*c)[i]);
  }
  // The vertical stress is sigma_yy in 2D, sigma_zz in 3D.
  const std::string v = dim == 2 ? "syy" : "szz";
  write_rows_csv(comm, local, nc,
                 std::string(dim == 2 ? "x_m,y_m," : "x_m,y_m,z_m,") +
                     "max_principal_mpa,min_principal_mpa,kappa_t,kappa_c,"
                     "max_strain_rate_per_s,t_max_strain_rate_s,"
                     "max_kappa_t_rate_per_s,max_" +
                     v + "_mpa,min_" + v + "_mpa",
                 file);
}

/// {"value", "x", "y"(, "z")(, "t")} of a scalar extreme, scaled.
json scalar_json(const results::Extreme& e, double scale, bool with_time,
                 int dim)
{
  json j = {{"value", scale * e.value},
            {"x", coordinate(e.x[0])},
            {"y", coordinate(e.x[1])}};
  if (dim == 3)
    j["z"] = coordinate(e.x[2]);
  if (with_time)
    j["t"] = instant(e.t);
  return j;
}

/// summary.json "concrete": the material of the run.
json concrete_json(const ConcreteSettings& c, const fem::ConcreteModel& cm,
                   int degree)
{
  const auto& p = c.params;
  json j = {
      {"model", to_string(c.kind)},
      {"E_pa", p.E},
      {"fc_mpa", p.fc0 * 1e-6},
      {"ft_mpa", p.ft0 * 1e-6},
      {"Gf_n_per_m", p.Gf},
      {"static_E_pa", c.static_E},
      {"static_fc_mpa", c.static_fc * 1e-6},
      {"static_ft_mpa", c.static_ft * 1e-6},
      {"factor_E", c.applied.E},
      {"factor_strength", c.applied.strength},
      {"material_bins", cm.material_count()},
      {"material_integration", c.implex ? "implex" : "implicit"},
      {"characteristic_length_m", concrete_characteristic_length(c)},
      {"tension_softening", to_string(c.params.tension_softening)},
      {"cells_with_reduced_tensile_strength", cm.cells_with_reduced_strength()},
      {"cells_with_raised_tensile_energy",
       cm.cells_with_raised_tensile_energy()},
      // Energy Gf per unit crack area whatever the mesh: P1 cells no
      // larger than the snap-back limit.
      {"crack_band_exact",
       degree == 1 &&
           p.tension_softening == material::TensionSoftening::crack_band &&
           cm.cells_with_reduced_strength() == 0 &&
           cm.cells_with_raised_tensile_energy() == 0}};
  if (cm.cells_with_reduced_strength() > 0)
  {
    const auto ft_low = cm.reduced_tensile_strength_range();
    j["reduced_tensile_strength_mpa"] = {{"min", ft_low[0] * 1e-6},
                                         {"max", ft_low[1] * 1e-6}};
  }
  return j;
}

/// summary.json "newton": the Newton work of the static stage and of every
/// step of the time history (restored at a restart).
json newton_json(const dynamics::NewtonSettings& newton,
                 const StaticStageReport& st, const NewtonTotals& nt, int steps)
{
  return {{"rtol", newton.rtol},
          {"extrapolated_predictor", newton.extrapolated_predictor},
          {"static_iterations", st.iterations},
          {"static_cuts", st.cuts},
          {"iterations", nt.iterations},
          {"iterations_per_step", nt.iterations / steps},
          {"max_iterations_in_a_step", nt.max_iterations_in_a_step},
          {"tangent_factorizations", nt.tangent_factorizations},
          {"krylov_iterations", nt.krylov_iterations},
          {"substepped_point_updates", nt.substepped},
          {"return_maps", nt.return_maps},
          {"local_newton_iterations", nt.local_iterations},
          // In-run throughput of the points that left the elastic fast path
          // (plane stress: all return maps of a point's sigma_zz iteration and
          // its tangent), per core.
          {"returned_points", nt.returned_points},
          {"returned_points_per_core_second",
           nt.return_map_seconds > 0.0
               ? nt.returned_points / nt.return_map_seconds
               : 0.0},
          {"seconds",
           {{"residual", nt.seconds_residual},
            {"tangent_assembly", nt.seconds_tangent},
            {"factorization", nt.seconds_factorization},
            {"direction_solves", nt.seconds_solve},
            {"return_maps_core_seconds", nt.return_map_seconds}}},
          {"step_cuts", nt.cuts},
          {"max_inelastic_points", nt.max_inelastic_points}};
}

/// Says where the crack band is not exact (material/README.md, README
/// "softening studies"): P2 elements, cells above the snap-back limit.
void print_crack_band_notes(MPI_Comm comm, const fem::ElasticModel& fe,
                            const fem::ConcreteModel& cm,
                            const ConcreteSettings& concrete,
                            const std::vector<int>& regions)
{
  if (concrete.params.tension_softening == material::TensionSoftening::none)
  {
    results::print(comm, "note: concrete.tension_softening = \"none\": the "
                         "concrete is perfectly plastic in tension (no "
                         "softening, no crack band)");
    return;
  }
  if (fe.degree() > 1)
  {
    results::print(comm,
                   "note: P" + std::to_string(fe.degree()) +
                       " elements: the crack band (energy Gf per unit crack "
                       "area) is exact for P1 only (a P2 cell can localise in "
                       "part of its points: 0.75 Gf in the crack-band test); "
                       "use mesh.order = 1 for softening studies");
  }
  // "note: N of M dam cells are larger than ... (snap-back limit ...): "
  auto large_cells = [&](std::int64_t n)
  {
    std::ostringstream note;
    note.precision(3);
    note << "note: " << n << " of "
         << region_cell_count(comm, fe.model(), regions)
         << " dam cells are larger than E Gf / ("
         << concrete.params.snap_back_safety
         << " ft^2) = " << concrete_characteristic_length(concrete)
         << " m (snap-back limit of the softening): ";
    return note.str();
  };
  if (cm.cells_with_raised_tensile_energy() > 0)
  {
    std::ostringstream note;
    note.precision(3);
    note << large_cells(cm.cells_with_raised_tensile_energy())
         << "their tensile strength is kept (concrete.tension_softening = "
            "\"crack_band_keep_strength\") and a crack in a cell of size h "
            "dissipates "
         << concrete.params.snap_back_safety << " ft^2 h / E per unit area, "
         << "more than Gf = " << concrete.params.Gf << " N/m";
    results::print(comm, note.str());
  }
  if (cm.cells_with_reduced_strength() == 0)
    return;
  const auto ft_low = cm.reduced_tensile_strength_range();
  std::ostringstream note;
  note.precision(3);
  note << large_cells(cm.cells_with_reduced_strength())
       << "their tensile strength is lowered from "
       << concrete.params.ft0 * 1e-6 << " to " << ft_low[0] * 1e-6 << ".."
       << ft_low[1] * 1e-6
       << " MPa (the crack band is not honoured there; summary.json "
          "concrete.cells_with_reduced_tensile_strength); refine the mesh "
          "where the concrete cracks, or see concrete.tension_softening";
  results::print(comm, note.str());
}
} // namespace damseis::analysis
