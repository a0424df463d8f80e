#include "gravity_dam_analysis.h"
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <damseis/fem/modal.h>
#include <damseis/geometry/tags.h>
#include <damseis/output/field_writer.h>
#include <damseis/output/point_probe.h>
#include <damseis/output/progress.h>
#include <damseis/output/stress_envelope.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/la/petsc.h>
#include <dolfinx/mesh/Mesh.h>
#include <dolfinx/mesh/MeshTags.h>
#include <fstream>
#include <sstream>

namespace damseis::analysis
{
namespace
{
using dolfinx::la::petsc::Matrix;
using dolfinx::la::petsc::Vector;
using nlohmann::json;

/// A new vector with the layout of the columns of A.
Vector column_vector(Mat A)
{
  Vec x;
  MatCreateVecs(A, &x, nullptr);
  VecSet(x, 0.0);
  return Vector(x, false);
}

/// Copies `x` (owned values) into the Function `u` and updates its ghosts.
void to_function(Vec x, dolfinx::fem::Function<double>& u)
{
  const double* a = nullptr;
  VecGetArrayRead(x, &a);
  std::span<double> y = u.x()->mutable_array();
  const auto& map = *u.function_space()->dofmap()->index_map;
  const int bs = u.function_space()->dofmap()->index_map_bs();
  std::copy_n(a, map.size_local() * bs, y.begin());
  VecRestoreArrayRead(x, &a);
  u.x()->scatter_fwd();
}

json extreme_json(const output::Extreme& e, double scale)
{
  return {{"value", e.value * scale}, {"x", e.x[0]}, {"y", e.x[1]}, {"t", e.t}};
}

/// Local cells with the given region tag.
std::vector<std::int32_t> region_cells(const geometry::Model& m, int region)
{
  std::vector<std::int32_t> cells;
  const auto& tags = *m.cell_tags;
  for (std::size_t i = 0; i < tags.indices().size(); ++i)
  {
    if (tags.values()[i] == region)
      cells.push_back(tags.indices()[i]);
  }
  return cells;
}

void write_modes(fem::ElasticModel& fe, const fem::Modes& modes,
                 const std::filesystem::path& file)
{
  dolfinx::fem::Function<double> u(fe.V()), u1(fe.output_space("u_vertex"));
  u1.name = "mode_shape";
  dolfinx::io::XDMFFile xdmf(fe.mesh()->comm(), file, "w");
  xdmf.write_mesh(*fe.mesh());
  for (std::size_t i = 0; i < modes.shapes.size(); ++i)
  {
    to_function(modes.shapes[i], u);
    u1.interpolate(u);
    xdmf.write_function(u1, static_cast<double>(i + 1));
  }
  xdmf.close();
}
} // namespace

json run_gravity_dam_analysis(MPI_Comm comm, const GravityDamConfig& cfg,
                              const std::filesystem::path& out_dir,
                              const std::string& case_text)
{
  const auto wall_start = std::chrono::steady_clock::now();
  auto seconds_since = [](auto t0)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
        .count();
  };
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const bool with_foundation = cfg.section.foundation;

  // Model.
  auto model = geometry::build_gravity_dam(comm, cfg.section);
  std::map<int, fem::Material> materials = {{tags::dam, cfg.concrete}};
  if (with_foundation)
    materials[tags::foundation] = cfg.rock;
  fem::ElasticModel fe(model, cfg.order, materials, cfg.plane);
  if (with_foundation)
    fe.fix({tags::foundation_bottom, tags::foundation_sides});
  else
    fe.fix({tags::dam_base});
  const auto& cell_map = *model.mesh->topology().index_map(2);
  const auto& dof_map = *fe.V()->dofmap()->index_map;
  const std::int64_t n_cells = cell_map.size_global();
  const std::int64_t n_dofs = dof_map.size_global() * 2;
  output::print(comm, "damseis gravity dam: " + std::to_string(n_cells) +
                          " cells, " + std::to_string(n_dofs) + " dofs, P" +
                          std::to_string(cfg.order));

  const bool wet = cfg.reservoir.depth() > 0.0;
  const fem::Reservoir* added =
      cfg.westergaard && wet ? &cfg.reservoir : nullptr;
  Matrix K(fe.assemble_stiffness(), false);
  Matrix M(fe.assemble_mass(added), false);

  // Static stage: dead weight and hydrostatic pressure.
  Vector F(fe.assemble_gravity({0.0, -cfg.gravity, 0.0}), false);
  if (wet)
  {
    Vector H(fe.assemble_hydrostatic(cfg.reservoir), false);
    VecAXPY(F.vec(), 1.0, H.vec());
  }
  Vector u_static = column_vector(K.mat());
  {
    fem::DirectSolver solver(comm, cfg.factorization);
    solver.factorize(K.mat());
    solver.solve(F.vec(), u_static.vec());
  }

  // Modal analysis, with and without the added mass.
  fem::Modes modes = fem::solve_modes(K.mat(), M.mat(), cfg.modes);
  std::vector<double> dry_hz = modes.frequencies_hz;
  if (added)
  {
    Matrix M0(fe.assemble_mass(nullptr), false);
    dry_hz = fem::solve_modes(K.mat(), M0.mat(), cfg.modes).frequencies_hz;
  }
  std::ostringstream freqs;
  for (double f : modes.frequencies_hz)
    freqs << " " << std::round(f * 1000) / 1000;
  output::print(comm, "natural frequencies [Hz]:" + freqs.str());

  // Rayleigh damping.
  double f1, f2;
  if (cfg.damping_frequencies_hz.size() == 2)
  {
    f1 = cfg.damping_frequencies_hz[0];
    f2 = cfg.damping_frequencies_hz[1];
  }
  else
  {
    f1 = modes.frequencies_hz[cfg.damping_modes[0] - 1];
    f2 = modes.frequencies_hz[cfg.damping_modes[1] - 1];
  }
  const auto damping =
      dynamics::RayleighDamping::from_ratio(cfg.damping_ratio, f1, f2);

  // Dynamic stage: relative displacement under base acceleration,
  // M a + C v + K u = -M (r_x a_gx + r_y a_gy), started at rest.
  dynamics::LinearNewmark newmark(M.mat(), K.mat(), damping, cfg.scheme,
                                  cfg.factorization);
  Vector rx(fe.influence(0), false), ry(fe.influence(1), false);
  Vector Lx = column_vector(K.mat()), Ly = column_vector(K.mat());
  MatMult(M.mat(), rx.vec(), Lx.vec());
  MatMult(M.mat(), ry.vec(), Ly.vec());
  VecScale(Lx.vec(), -1.0);
  VecScale(Ly.vec(), -1.0);
  const auto& ax = cfg.horizontal.acceleration;
  const auto& ay = cfg.vertical.acceleration;
  Vector f = column_vector(K.mat()), zero = column_vector(K.mat()),
         a0 = column_vector(K.mat());
  VecAXPBYPCZ(f.vec(), ax[0], ay[0], 0.0, Lx.vec(), Ly.vec());
  // Consistent initial relative acceleration at rest: a = -(r_x a_gx + r_y
  // a_gy) satisfies M a = f exactly (also where M is singular).
  VecAXPBYPCZ(a0.vec(), -ax[0], -ay[0], 0.0, rx.vec(), ry.vec());
  newmark.set_state(zero.vec(), zero.vec(), a0.vec(), f.vec());

  // Outputs: everything that can fail on input has been checked by now.
  std::filesystem::create_directories(out_dir);
  if (rank == 0)
    std::ofstream(out_dir / "case_used.toml") << case_text;
  write_modes(fe, modes, out_dir / "modes.xdmf");

  Matrix B(fe.assemble_stress_operator(), false);
  // Stress-point vectors have the row layout of B.
  auto row_vector = [&B]
  {
    Vec x;
    MatCreateVecs(B.mat(), nullptr, &x);
    return Vector(x, false);
  };
  Vector s_static = row_vector(), s_field = row_vector();
  MatMult(B.mat(), u_static.vec(), s_static.vec());
  const auto dam_cells = region_cells(model, tags::dam);
  output::StressEnvelope envelope(*fe.S(), dam_cells);
  output::FieldWriter writer(fe, out_dir / "fields.xdmf");
  dolfinx::fem::Function<double> u_fn(fe.V());
  Vector u_out = column_vector(K.mat());

  output::PointProbe crest(*fe.V(), cfg.crest_point);
  output::PointProbe base(*fe.V(), cfg.base_point);
  const auto crest_static = crest.value_on_all(u_static.vec());
  const auto base_static = base.value_on_all(u_static.vec());
  const int n = cfg.steps;
  const double dt = cfg.scheme.dt;
  std::vector<double> hist(4 * (n + 1), 0.0); // crest x,y and base x,y

  auto record_state = [&](int k, double t, Vec ud)
  {
    MatMult(B.mat(), ud, s_field.vec());
    if (cfg.stress_total)
      VecAXPY(s_field.vec(), 1.0, s_static.vec());
    const double* sa = nullptr;
    PetscInt ns = 0;
    VecGetLocalSize(s_field.vec(), &ns);
    VecGetArrayRead(s_field.vec(), &sa);
    envelope.update(std::span<const double>(sa, ns), t);
    const auto c = crest.value(ud), b = base.value(ud);
    hist[4 * k + 0] = c[0];
    hist[4 * k + 1] = c[1];
    hist[4 * k + 2] = b[0];
    hist[4 * k + 3] = b[1];
    if (k % cfg.output_every == 0)
    {
      VecCopy(ud, u_out.vec());
      if (cfg.stress_total)
        VecAXPY(u_out.vec(), 1.0, u_static.vec());
      to_function(u_out.vec(), u_fn);
      writer.write(u_fn, std::span<const double>(sa, ns), t);
    }
    VecRestoreArrayRead(s_field.vec(), &sa);
  };

  output::print(comm, "time history: " + std::to_string(n) + " steps of " +
                          std::to_string(dt) + " s, factorisation " +
                          newmark.solver().name());
  record_state(0, 0.0, newmark.u());
  output::Progress progress(comm, n);
  const auto loop_start = std::chrono::steady_clock::now();
  for (int k = 1; k <= n; ++k)
  {
    VecAXPBYPCZ(f.vec(), ax[k], ay[k], 0.0, Lx.vec(), Ly.vec());
    newmark.step(f.vec());
    record_state(k, k * dt, newmark.u());
    progress.report(k, k * dt);
  }
  const double loop_seconds = seconds_since(loop_start);
  output::reduce_history(comm, hist);

  // Crest history relative to the base point.
  double crest_max = 0.0, crest_max_t = 0.0;
  if (rank == 0)
  {
    std::ofstream csv(out_dir / "crest.csv");
    csv << "t_s,ux_m,uy_m,ux_total_m,uy_total_m\n";
    csv.precision(10);
    const double sx = crest_static[0] - base_static[0];
    const double sy = crest_static[1] - base_static[1];
    for (int k = 0; k <= n; ++k)
    {
      const double ux = hist[4 * k] - hist[4 * k + 2];
      const double uy = hist[4 * k + 1] - hist[4 * k + 3];
      csv << k * dt << "," << ux << "," << uy << "," << ux + sx << ","
          << uy + sy << "\n";
      if (std::abs(ux) > std::abs(crest_max))
      {
        crest_max = ux;
        crest_max_t = k * dt;
      }
    }
  }
  MPI_Bcast(&crest_max, 1, MPI_DOUBLE, 0, comm);
  MPI_Bcast(&crest_max_t, 1, MPI_DOUBLE, 0, comm);

  output::write_envelopes(fe, envelope, out_dir / "envelopes.xdmf");
  const auto tension = envelope.max_tension(comm);
  const auto compression = envelope.max_compression(comm);

  json summary = {
      {"analysis", "gravity dam, linear elastic"},
      {"n_cells", n_cells},
      {"n_dofs", n_dofs},
      {"mesh_order", cfg.order},
      {"steps", n},
      {"dt_s", dt},
      {"frequencies_hz", modes.frequencies_hz},
      {"frequencies_dry_hz", dry_hz},
      {"added_mass", added != nullptr},
      {"damping",
       {{"ratio", cfg.damping_ratio},
        {"f1_hz", f1},
        {"f2_hz", f2},
        {"a_mass", damping.a_mass},
        {"b_stiffness", damping.b_stiffness}}},
      {"stress", cfg.stress_total ? "total" : "seismic"},
      {"crest_point", {crest.node()[0], crest.node()[1]}},
      {"crest_static_m",
       {crest_static[0] - base_static[0], crest_static[1] - base_static[1]}},
      {"crest_displacement_max_m", {{"value", crest_max}, {"t", crest_max_t}}},
      {"max_principal_tension_mpa", extreme_json(tension, 1e-6)},
      {"max_principal_compression_mpa", extreme_json(compression, 1e-6)},
      {"ground_motion",
       {{"horizontal",
         {{"record", cfg.horizontal.record},
          {"peak_g", cfg.horizontal.active ? cfg.horizontal.peak_g : 0.0}}},
        {"vertical",
         {{"record", cfg.vertical.record},
          {"peak_g", cfg.vertical.active ? cfg.vertical.peak_g : 0.0}}}}},
      {"solver", newmark.solver().name()},
      {"factorization_seconds", newmark.solver().factor_seconds()},
      {"time_loop_seconds", loop_seconds},
      {"seconds_per_step", loop_seconds / n},
      {"mpi_ranks",
       [&]
       {
         int s;
         MPI_Comm_size(comm, &s);
         return s;
       }()},
  };
  summary["wall_seconds"] = seconds_since(wall_start);
  if (rank == 0)
  {
    std::ofstream(out_dir / "summary.json") << summary.dump(2) << "\n";
    if (cfg.plots)
    {
      const std::string cmd =
          std::string(DAMSEIS_PYTHON) + " " + DAMSEIS_SOURCE_DIR +
          "/scripts/plot_gravity_dam.py \"" + out_dir.string() + "\"";
      if (std::system(cmd.c_str()) != 0)
        std::fprintf(stderr, "warning: plotting failed: %s\n", cmd.c_str());
    }
  }
  output::print(comm, "max tension " + std::to_string(tension.value * 1e-6) +
                          " MPa, max compression " +
                          std::to_string(compression.value * 1e-6) +
                          " MPa, max crest displacement " +
                          std::to_string(crest_max * 100) + " cm");
  return summary;
}
} // namespace damseis::analysis
