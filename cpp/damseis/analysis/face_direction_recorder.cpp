#include "face_direction_recorder.h"
#include "run_outputs.h"
#include <damseis/results/face_directions.h>
#include <damseis/results/singular_points.h>

namespace damseis::analysis
{
FaceDirectionRecorder::FaceDirectionRecorder(
    const dolfinx::fem::FunctionSpace& S,
    const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags,
    const SeismicSettings& s,
    const std::vector<std::vector<std::int32_t>>& points,
    const StressRecorder& stresses)
    : _stresses(stresses)
{
  for (std::size_t i = 0; i < s.faces.size(); ++i)
  {
    _names.push_back(s.faces[i].first);
    _envelopes.emplace_back(points[i],
                            results::arch_cantilever_directions(
                                S, facet_tags, s.faces[i].second, points[i]));
  }
}

void FaceDirectionRecorder::record(int, double t)
{
  for (auto& e : _envelopes)
    e.update(_stresses.stress(), t);
}

void FaceDirectionRecorder::save(engine::Arrays& arrays) const
{
  for (std::size_t i = 0; i < _names.size(); ++i)
    arrays["arch_cantilever_" + _names[i]] = _envelopes[i].state();
}

void FaceDirectionRecorder::restore(const engine::CheckpointData& data)
{
  for (std::size_t i = 0; i < _names.size(); ++i)
    _envelopes[i].restore(
        engine::checkpoint_array(data, "arch_cantilever_" + _names[i]));
}

nlohmann::json FaceDirectionRecorder::write(
    MPI_Comm comm, const SeismicSettings& s, const std::filesystem::path& dir,
    const std::vector<std::vector<std::int8_t>>& joint_sides) const
{
  const bool sides = !joint_sides.empty();
  const results::StressEnvelope& env = _stresses.envelope();
  nlohmann::json out = nlohmann::json::object();
  for (std::size_t f = 0; f < _names.size(); ++f)
  {
    const results::DirectionEnvelope& e = _envelopes[f];
    const auto& pts = e.points();
    std::vector<double> rows;
    // Per direction: values, times and coordinates by point, for the
    // extremes away from the singular points.
    std::vector<std::array<double, 3>> x;
    std::vector<std::int32_t> away;
    for (std::size_t i = 0; i < pts.size(); ++i)
    {
      const auto& xi = env.point(pts[i]);
      x.push_back(xi);
      const double dist = results::distance_to(xi, s.singular_points);
      if (dist >= s.singular_radius) // as results::points_away_from
        away.push_back(static_cast<std::int32_t>(i));
      rows.insert(rows.end(), {xi[0], xi[1], xi[2]});
      for (int d = 0; d < 2; ++d)
      {
        const std::size_t k = 2 * i + d;
        rows.insert(rows.end(), {e.max()[k] * 1e-6, e.max_times()[k],
                                 e.min()[k] * 1e-6, e.min_times()[k]});
      }
      rows.push_back(dist);
      if (sides) // the points are those of the face (the constructor's)
        rows.push_back(joint_sides[f].at(i));
    }
    write_rows_csv(comm, rows, sides ? 13 : 12,
                   std::string("x_m,y_m,z_m,arch_max_mpa,t_arch_max_s,"
                               "arch_min_mpa,t_arch_min_s,cantilever_max_mpa,"
                               "t_cantilever_max_s,cantilever_min_mpa,"
                               "t_cantilever_min_s,distance_to_singular_m") +
                       (sides ? ",joint_side" : ""),
                   dir / ("face_" + _names[f] + "_arch_cantilever.csv"));
    nlohmann::json face;
    for (int d = 0; d < 2; ++d)
    {
      std::vector<double> vmax, tmax, vmin, tmin;
      for (std::size_t i = 0; i < pts.size(); ++i)
      {
        vmax.push_back(e.max()[2 * i + d]);
        tmax.push_back(e.max_times()[2 * i + d]);
        vmin.push_back(e.min()[2 * i + d]);
        tmin.push_back(e.min_times()[2 * i + d]);
      }
      const std::string name = d == 0 ? "arch" : "cantilever";
      face[name + "_tension_mpa"] = extreme_json(
          results::global_extreme(comm, vmax, tmax, x, away, 1.0), 3);
      face[name + "_compression_mpa"] = extreme_json(
          results::global_extreme(comm, vmin, tmin, x, away, -1.0), 3);
    }
    out[_names[f]] = face;
  }
  return out;
}
} // namespace damseis::analysis
