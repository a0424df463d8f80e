#include "run_outputs.h"
#include <chrono>
#include <cmath>
#include <damseis/geometry/mesh_estimate.h>
#include <damseis/geometry/tagged.h>
#include <damseis/results/gather.h>
#include <damseis/results/progress.h>
#include <damseis/results/singular_points.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/mesh/Mesh.h>
#include <dolfinx/mesh/MeshTags.h>
#include <fstream>
#include <sstream>

namespace damseis::analysis
{
using nlohmann::json;

double coordinate(double x)
{
  return std::round(x * 1e6) / 1e6 + 0.0;
}

double instant(double t)
{
  return std::round(t * 1e9) / 1e9 + 0.0;
}

json extreme_json(const results::Extreme& e, int dim)
{
  json j = {{"value", e.value * 1e-6},
            {"x", coordinate(e.x[0])},
            {"y", coordinate(e.x[1])}};
  if (dim == 3)
    j["z"] = coordinate(e.x[2]);
  j["t"] = instant(e.t);
  return j;
}

std::vector<std::int32_t> region_cells(const geometry::Model& m, int region)
{
  return region_cells(m, std::vector<int>{region});
}

std::vector<std::int32_t> region_cells(const geometry::Model& m,
                                       const std::vector<int>& regions)
{
  return geometry::tagged_entities(*m.cell_tags, regions);
}

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
      .count();
}

void write_face_csv(MPI_Comm comm, const results::StressEnvelope& env,
                    std::span<const std::int32_t> points,
                    std::span<const std::array<double, 3>> singular,
                    const std::filesystem::path& file,
                    std::span<const std::int8_t> joint_sides,
                    std::span<const std::int64_t> cells)
{
  // The columns of every rank's rows: a rank without points on this face
  // has empty spans, and rank 0 writes the header.
  int columns[2] = {!joint_sides.empty(), !cells.empty()};
  MPI_Allreduce(MPI_IN_PLACE, columns, 2, MPI_INT, MPI_MAX, comm);
  const bool sides = columns[0], with_cells = columns[1];
  std::vector<double> local;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const std::int32_t p = points[i];
    const auto& x = env.point(p);
    local.insert(local.end(),
                 {x[0], x[1], x[2], env.max_principal()[p] * 1e-6,
                  env.max_times()[p], env.min_principal()[p] * 1e-6,
                  env.min_times()[p], results::distance_to(x, singular)});
    if (sides)
      local.push_back(joint_sides[i]);
    if (with_cells)
      local.push_back(static_cast<double>(cells[i]));
  }
  write_rows_csv(comm, local, 8 + sides + with_cells,
                 std::string("x_m,y_m,z_m,max_principal_mpa,t_max_s,"
                             "min_principal_mpa,t_min_s,"
                             "distance_to_singular_m") +
                     (sides ? ",joint_side" : "") + (with_cells ? ",cell" : ""),
                 file);
}

void write_rows_csv(MPI_Comm comm, const std::vector<double>& local,
                    int columns, const std::string& header,
                    const std::filesystem::path& file)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const std::vector<double> all = results::gather_to_root(comm, local);
  if (rank != 0)
    return;
  std::ofstream csv(file);
  csv << header << "\n";
  csv.precision(8);
  for (std::size_t i = 0; i < all.size(); i += columns)
  {
    for (int k = 0; k < columns; ++k)
      csv << all[i + k] << (k < columns - 1 ? "," : "\n");
  }
}

void print_model_line(fem::ElasticModel& fe, const std::string& suffix)
{
  const auto model = fe.model();
  MPI_Comm comm = model.mesh->comm();
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  const int dim = fe.dim();
  const std::int64_t n_cells =
      model.mesh->topology().index_map(dim)->size_global();
  const std::int64_t n_dofs = fe.V()->dofmap()->index_map->size_global() * dim;
  results::print(comm, "damseis: " + std::to_string(n_cells) + " cells, " +
                           std::to_string(n_dofs) + " dofs, P" +
                           std::to_string(fe.degree()) + ", " +
                           std::to_string(ranks) + " rank(s)" + suffix);
}

json write_crest_history(MPI_Comm comm, const std::vector<double>& hist,
                         int dim, int steps, double dt,
                         const std::array<double, 3>& crest_static,
                         const std::array<double, 3>& base_static,
                         bool history_is_total,
                         const std::filesystem::path& file)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const char* axis = "xyz";
  std::array<double, 3> peak = {0, 0, 0}, peak_t = {0, 0, 0};
  double peak_h = 0.0, peak_h_t = 0.0;
  std::ofstream csv;
  if (rank == 0)
  {
    csv.open(file);
    csv << "t_s";
    for (int i = 0; i < dim; ++i)
      csv << ",u" << axis[i] << "_m";
    for (int i = 0; i < dim; ++i)
      csv << ",u" << axis[i] << "_total_m";
    csv << "\n";
    csv.precision(10);
  }
  std::array<double, 3> rel_static = {0, 0, 0};
  for (int i = 0; i < dim; ++i)
    rel_static[i] = crest_static[i] - base_static[i];
  for (int k = 0; k <= steps; ++k)
  {
    std::array<double, 3> u = {0, 0, 0};
    double horizontal = 0.0;
    for (int i = 0; i < dim; ++i)
    {
      u[i] = hist[2 * dim * k + i] - hist[2 * dim * k + dim + i];
      if (history_is_total)
        u[i] -= rel_static[i];
      if (std::abs(u[i]) > std::abs(peak[i]))
      {
        peak[i] = u[i];
        peak_t[i] = k * dt;
      }
      if (i < dim - 1)
        horizontal += u[i] * u[i];
    }
    horizontal = std::sqrt(horizontal);
    if (dim == 2)
      horizontal = u[0];
    if (std::abs(horizontal) > std::abs(peak_h))
    {
      peak_h = horizontal;
      peak_h_t = k * dt;
    }
    if (rank == 0)
    {
      csv << k * dt;
      for (int i = 0; i < dim; ++i)
        csv << "," << u[i];
      for (int i = 0; i < dim; ++i)
        csv << "," << u[i] + rel_static[i];
      csv << "\n";
    }
  }
  json by_component = json::object(), statics = json::array();
  for (int i = 0; i < dim; ++i)
  {
    by_component[std::string(1, axis[i])] = {{"value", peak[i]},
                                             {"t", instant(peak_t[i])}};
    statics.push_back(rel_static[i]);
  }
  return {{"crest_static_m", statics},
          {"crest_displacement_max_m",
           {{"value", peak_h}, {"t", instant(peak_h_t)}}},
          {"crest_displacement_max_by_component_m", by_component}};
}

json away_from_singular(MPI_Comm comm, const SeismicSettings& s,
                        const results::StressEnvelope& env, int dim,
                        const std::vector<std::int32_t>* subset)
{
  const std::vector<std::int32_t> pts =
      results::points_away_from(env, subset ? *subset : env.region_points(),
                                s.singular_points, s.singular_radius);
  json j = {{"radius_m", s.singular_radius},
            {"max_principal_tension_mpa",
             extreme_json(env.max_tension(comm, pts), dim)},
            {"max_principal_compression_mpa",
             extreme_json(env.max_compression(comm, pts), dim)}};
  if (!subset)
  {
    j["method"] =
        "extremes over the stress points farther than radius_m "
        "(output.singular_radius) from every singular point (" +
        s.singular_where +
        "), where the elastic stress is unbounded and grows with mesh "
        "refinement; the stress at a fixed distance from them converges";
    json where = json::array();
    if (s.singular_points.size() <= 20)
    {
      for (const auto& p : s.singular_points)
      {
        json q = json::array();
        for (int i = 0; i < dim; ++i)
          q.push_back(coordinate(p[i]));
        where.push_back(q);
      }
      j["singular_points"] = where;
    }
    j["singular_point_count"] = s.singular_points.size();
  }
  return j;
}

json seismic_summary(MPI_Comm comm, const fem::ElasticModel& fe,
                     const SeismicSettings& s, const ModalResult& modal,
                     bool added_mass, const std::array<double, 3>& crest_node,
                     const results::StressEnvelope& envelope, const json& faces,
                     const std::string& solver, const RunTimes& t)
{
  const int dim = fe.dim();
  int ranks = 1;
  MPI_Comm_size(comm, &ranks);
  const char* axis = "xyz";
  json motion = json::object();
  for (int i = 0; i < dim; ++i)
  {
    motion[std::string(1, axis[i])] = {
        {"record", s.motion[i].record},
        {"description", s.motion[i].description},
        {"peak_g", s.motion[i].active ? s.motion[i].peak_g : 0.0}};
  }
  // Components driven by one record file are one fully correlated signal
  // (only one real record ships so far): say so.
  for (int i = 0; i < dim; ++i)
  {
    std::string shared;
    for (int j = 0; j < dim; ++j)
    {
      if (j != i and s.motion[i].active and s.motion[j].active and
          s.motion[i].record == s.motion[j].record)
        shared += axis[j];
    }
    if (!shared.empty())
    {
      motion[std::string(1, axis[i])]["same_record_as"] = shared;
      motion["note"] = "several components are scaled copies of one record "
                       "(fully correlated input), not independent motions";
    }
  }
  const int steps_run = std::max(1, s.steps - t.restarted_from_step);
  return {
      {"n_cells", fe.mesh()->topology().index_map(dim)->size_global()},
      {"n_dofs", fe.V()->dofmap()->index_map->size_global() * dim},
      {"mesh_order", fe.degree()},
      {"steps", s.steps},
      {"dt_s", s.scheme.dt},
      {"frequencies_hz", modal.modes.frequencies_hz},
      {"frequencies_dry_hz", modal.dry_hz},
      {"mode_shapes",
       "modes.xdmf: one field per mode (mode_01_<f>_Hz), mass-normalised "
       "(phi^T M phi = 1 kg, M the mass of the modal analysis)"},
      {"added_mass", added_mass},
      {"damping",
       {{"ratio", s.damping_ratio},
        {"f1_hz", modal.f1},
        {"f2_hz", modal.f2},
        {"a_mass", modal.damping.a_mass},
        {"b_stiffness", modal.damping.b_stiffness}}},
      {"stress", s.stress_total ? "total" : "seismic"},
      {"crest_point",
       [&]
       {
         std::vector<double> x;
         for (int i = 0; i < dim; ++i)
           x.push_back(coordinate(crest_node[i]));
         return x;
       }()},
      {"max_principal_tension_mpa",
       extreme_json(envelope.max_tension(comm), dim)},
      {"max_principal_compression_mpa",
       extreme_json(envelope.max_compression(comm), dim)},
      {"away_from_singular_points",
       away_from_singular(comm, s, envelope, dim, nullptr)},
      {"faces", faces},
      {"ground_motion", motion},
      {"solver", solver},
      {"setup_and_static_seconds", t.setup_and_static},
      {"modal_seconds", t.modal},
      {"factorization_seconds", t.factorization},
      {"time_loop_seconds", t.loop},
      {"seconds_per_step", t.loop / steps_run},
      {"restarted_from_step", t.restarted_from_step},
      {"mpi_ranks", ranks},
  };
}

void print_summary_line(MPI_Comm comm, const json& summary,
                        const std::string& extra)
{
  results::print(
      comm,
      "max tension " +
          std::to_string(
              summary["max_principal_tension_mpa"]["value"].get<double>()) +
          " MPa, max compression " +
          std::to_string(
              summary["max_principal_compression_mpa"]["value"].get<double>()) +
          " MPa, max crest displacement " +
          std::to_string(
              summary["crest_displacement_max_m"]["value"].get<double>() *
              100) +
          " cm" + extra);
  const auto& away = summary["away_from_singular_points"];
  std::ostringstream line;
  line.precision(4);
  line << "  farther than " << away["radius_m"].get<double>()
       << " m from the singular points: max tension "
       << away["max_principal_tension_mpa"]["value"].get<double>()
       << " MPa, max compression "
       << away["max_principal_compression_mpa"]["value"].get<double>()
       << " MPa";
  results::print(comm, line.str());
}

json write_faces(MPI_Comm comm, const SeismicSettings& s,
                 const results::StressEnvelope& env,
                 const std::vector<std::vector<std::int32_t>>& pts, int dim,
                 const std::filesystem::path& out_dir,
                 const std::vector<std::vector<std::int8_t>>& joint_sides,
                 const std::vector<std::vector<std::int64_t>>& cells)
{
  json faces = json::object();
  for (std::size_t i = 0; i < s.faces.size(); ++i)
  {
    const std::string& name = s.faces[i].first;
    write_face_csv(comm, env, pts[i], s.singular_points,
                   out_dir / ("face_" + name + ".csv"),
                   joint_sides.empty() ? std::span<const std::int8_t>()
                                       : joint_sides[i],
                   cells.empty() ? std::span<const std::int64_t>() : cells[i]);
    json away = away_from_singular(comm, s, env, dim, &pts[i]);
    away.erase("radius_m");
    faces[name] = {{"max_principal_tension_mpa",
                    extreme_json(env.max_tension(comm, pts[i]), dim)},
                   {"max_principal_compression_mpa",
                    extreme_json(env.max_compression(comm, pts[i]), dim)},
                   {"away_from_singular_points", away}};
  }
  return faces;
}

void print_size_estimate(MPI_Comm comm, double cells, int dim, int order,
                         int steps)
{
  const auto e = geometry::estimate_size(cells, dim, order);
  // The linear time history; nonlinear steps cost several of these.
  const double seconds = 1e-3 * e.ms_per_step * steps;
  std::ostringstream history;
  history.precision(2);
  if (seconds < 120)
    history << seconds << " s";
  else if (seconds < 7200)
    history << seconds / 60 << " min";
  else
    history << seconds / 3600 << " h";
  results::print(comm,
                 "size estimate before meshing: " + geometry::describe(e) +
                     " (" + std::to_string(steps) + " steps: about " +
                     history.str() + " if linear)");
  const double available = geometry::machine_memory_gb();
  if (available > 0.0 && e.memory_gb > 0.8 * available)
  {
    std::ostringstream w;
    w.precision(3);
    w << "the estimated memory (" << e.memory_gb
      << " GB) is above 80% of this machine's " << available
      << " GB: the run may swap or be killed; a larger mesh.size reduces it";
    results::warn(comm, w.str());
  }
}
} // namespace damseis::analysis
