#include "recorders.h"
#include <damseis/engine/checkpoint.h>
#include <damseis/fem/group_loads.h>
#include <damseis/geometry/tagged.h>
#include <damseis/linalg/petsc_vectors.h>
#include <dolfinx/fem/utils.h>
#include <fstream>

namespace damseis::analysis
{
namespace
{
std::vector<double> copy_of(std::span<const double> x)
{
  return std::vector<double>(x.begin(), x.end());
}

/// Per step, item, quantity (u, v, a, absolute a) and component: the
/// largest norm over the steps of each item's quantity.
std::vector<std::array<double, 4>> state_peaks(const std::vector<double>& hist,
                                               std::size_t items, int dim)
{
  std::vector<std::array<double, 4>> peaks(items, {0, 0, 0, 0});
  const std::size_t row = items * 4 * dim;
  for (std::size_t k = 0; k < hist.size() / row; ++k)
    for (std::size_t p = 0; p < items; ++p)
      for (int q = 0; q < 4; ++q)
      {
        double norm2 = 0.0;
        for (int c = 0; c < dim; ++c)
        {
          const double v = hist[k * row + (p * 4 + q) * dim + c];
          norm2 += v * v;
        }
        peaks[p][q] = std::max(peaks[p][q], std::sqrt(norm2));
      }
  return peaks;
}

/// The table of such histories (rank 0): t, then per item the columns
/// <name>_u<x>_m, _v<x>_m_per_s, _a<x>_m_per_s2, _a<x>_abs_m_per_s2.
void write_state_table(MPI_Comm comm, const std::filesystem::path& file,
                       double dt, const std::vector<std::string>& names,
                       int dim, const std::vector<double>& hist)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank != 0)
    return;
  const char* axis = "xyz";
  const char* quantity[4] = {"u", "v", "a", "a"};
  const char* unit[4] = {"m", "m_per_s", "m_per_s2", "abs_m_per_s2"};
  std::ofstream out(file);
  out << "t_s";
  for (const auto& name : names)
    for (int q = 0; q < 4; ++q)
      for (int c = 0; c < dim; ++c)
        out << "," << name << "_" << quantity[q] << axis[c] << "_" << unit[q];
  out << "\n";
  out.precision(10);
  const std::size_t row = names.size() * 4 * dim;
  for (std::size_t k = 0; k < hist.size() / row; ++k)
  {
    out << k * dt;
    for (std::size_t j = 0; j < row; ++j)
      out << "," << hist[k * row + j];
    out << "\n";
  }
}
} // namespace

FullDisplacement::FullDisplacement(const engine::Stepper& stepper, Mat tie)
    : _stepper(stepper), _tie(tie)
{
  if (_tie)
  {
    _u = linalg::row_vector(_tie);
    _work = linalg::row_vector(_tie);
  }
}

void FullDisplacement::record(int, double)
{
  if (_tie)
    MatMult(_tie, _stepper.u(), _u.vec());
}

Vec FullDisplacement::vec() const
{
  return _tie ? _u.vec() : _stepper.u();
}

Vec FullDisplacement::full(Vec x) const
{
  if (!_tie)
    return x;
  MatMult(_tie, x, _work.vec());
  return _work.vec();
}

StressRecorder::StressRecorder(results::StressEnvelope envelope,
                               std::function<std::span<const double>()> stress)
    : _envelope(std::move(envelope)), _stress(std::move(stress))
{
}

void StressRecorder::record(int, double t)
{
  _last = _stress();
  const std::size_t owned =
      _envelope.max_principal().size() * _envelope.components();
  _envelope.update(_last.first(owned), t);
}

void StressRecorder::save(engine::Arrays& arrays) const
{
  arrays["env_max"] = copy_of(_envelope.max_principal());
  arrays["env_t_max"] = copy_of(_envelope.max_times());
  arrays["env_min"] = copy_of(_envelope.min_principal());
  arrays["env_t_min"] = copy_of(_envelope.min_times());
}

void StressRecorder::restore(const engine::CheckpointData& d)
{
  using engine::checkpoint_array;
  _envelope.restore(
      checkpoint_array(d, "env_max"), checkpoint_array(d, "env_t_max"),
      checkpoint_array(d, "env_min"), checkpoint_array(d, "env_t_min"));
}

PointHistories::PointHistories(const dolfinx::fem::FunctionSpace& V,
                               const std::array<double, 3>& crest_point,
                               const std::array<double, 3>& base_point,
                               int steps, const FullDisplacement& u)
    : _crest(V, crest_point), _base(V, base_point),
      _dim(V.dofmap()->index_map_bs()), _u(u),
      _hist(2 * _dim * (steps + 1), 0.0)
{
}

void PointHistories::record(int k, double)
{
  const auto c = _crest.value(_u.vec()), b = _base.value(_u.vec());
  for (int i = 0; i < _dim; ++i)
  {
    _hist[2 * _dim * k + i] = c[i];
    _hist[2 * _dim * k + _dim + i] = b[i];
  }
}

void PointHistories::save(engine::Arrays& arrays) const
{
  arrays["history"] = _hist;
}

void PointHistories::restore(const engine::CheckpointData& d)
{
  _hist = engine::checkpoint_array(d, "history", _hist.size());
}

const std::vector<double>& PointHistories::reduce(MPI_Comm comm)
{
  results::reduce_history(comm, _hist);
  return _hist;
}

PointStates::PointStates(const dolfinx::fem::FunctionSpace& V,
                         const std::vector<NamedPoint>& points, int steps,
                         const engine::Stepper& stepper,
                         const FullDisplacement& full,
                         std::function<double(int, int)> ground, Vec static_u)
    : _dim(V.dofmap()->index_map_bs()), _stepper(stepper), _full(full),
      _ground(std::move(ground))
{
  for (const auto& [name, x] : points)
  {
    _names.push_back(name);
    _probes.emplace_back(V, x);
    _static.push_back(static_u ? _probes.back().value(static_u)
                               : std::array<double, 3>{0, 0, 0});
  }
  _hist.assign((steps + 1) * _probes.size() * 4 * _dim, 0.0);
}

void PointStates::record(int k, double)
{
  const std::size_t n = _probes.size();
  if (n == 0)
    return;
  const std::array<Vec, 3> states = {_stepper.u(), _stepper.v(), _stepper.a()};
  for (int q = 0; q < 3; ++q)
  {
    const Vec x = _full.full(states[q]);
    for (std::size_t p = 0; p < n; ++p)
    {
      const auto value = _probes[p].value(x);
      for (int c = 0; c < _dim; ++c)
      {
        double* row = &_hist[((k * n + p) * 4) * _dim];
        row[q * _dim + c] = value[c] - (q == 0 ? _static[p][c] : 0.0);
        // The absolute acceleration: the owners' shares (summed).
        if (q == 2)
          row[3 * _dim + c] = value[c] + _probes[p].share() * _ground(k, c);
      }
    }
  }
}

void PointStates::save(engine::Arrays& arrays) const
{
  arrays["point_states"] = _hist;
}

void PointStates::restore(const engine::CheckpointData& d)
{
  if (_probes.empty())
    return;
  _hist = engine::checkpoint_array(d, "point_states", _hist.size());
}

nlohmann::json PointStates::write_csv(MPI_Comm comm, double dt,
                                      const std::filesystem::path& file)
{
  nlohmann::json peaks = nlohmann::json::object();
  if (_probes.empty())
    return peaks;
  results::reduce_history(comm, _hist);
  const auto peak = state_peaks(_hist, _probes.size(), _dim);
  for (std::size_t p = 0; p < _probes.size(); ++p)
  {
    const auto& node = _probes[p].node();
    peaks[_names[p]] = {{"node", {node[0], node[1], node[2]}},
                        {"max_displacement_m", peak[p][0]},
                        {"max_velocity_m_per_s", peak[p][1]},
                        {"max_acceleration_m_per_s2", peak[p][2]},
                        {"max_absolute_acceleration_m_per_s2", peak[p][3]}};
  }
  write_state_table(comm, file, dt, _names, _dim, _hist);
  return peaks;
}

PointStresses::PointStresses(MPI_Comm comm,
                             const std::vector<PointStates::NamedPoint>& points,
                             int steps, const StressRecorder& stresses)
    : _nc(stresses.envelope().components()), _stresses(stresses)
{
  const auto& env = stresses.envelope();
  const std::int32_t owned =
      static_cast<std::int32_t>(env.max_principal().size());
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  for (const auto& [name, x] : points)
  {
    struct
    {
      double d;
      int rank;
    } mine{HUGE_VAL, rank}, best;
    std::int32_t arg = -1;
    for (std::int32_t i = 0; i < owned; ++i)
    {
      const auto& p = env.point(i);
      const double d = std::hypot(p[0] - x[0], p[1] - x[1], p[2] - x[2]);
      if (d < mine.d)
      {
        mine.d = d;
        arg = i;
      }
    }
    MPI_Allreduce(&mine, &best, 1, MPI_DOUBLE_INT, MPI_MINLOC, comm);
    std::array<double, 3> where = {0, 0, 0};
    if (best.rank == rank && arg >= 0)
      where = env.point(arg);
    MPI_Bcast(where.data(), 3, MPI_DOUBLE, best.rank, comm);
    _names.push_back(name);
    _local.push_back(best.rank == rank ? arg : -1);
    _where.push_back(where);
  }
  _hist.assign((steps + 1) * _names.size() * _nc, 0.0);
}

void PointStresses::record(int k, double)
{
  const auto s = _stresses.stress();
  for (std::size_t p = 0; p < _names.size(); ++p)
  {
    if (_local[p] < 0)
      continue;
    for (int c = 0; c < _nc; ++c)
      _hist[(k * _names.size() + p) * _nc + c] = s[_local[p] * _nc + c];
  }
}

void PointStresses::save(engine::Arrays& arrays) const
{
  if (!_names.empty())
    arrays["point_stresses"] = _hist;
}

void PointStresses::restore(const engine::CheckpointData& d)
{
  if (!_names.empty())
    _hist = engine::checkpoint_array(d, "point_stresses", _hist.size());
}

nlohmann::json PointStresses::write_csv(MPI_Comm comm, double dt,
                                        const std::filesystem::path& file)
{
  nlohmann::json out = nlohmann::json::object();
  const std::size_t n = _names.size();
  if (n == 0)
    return out;
  results::reduce_history(comm, _hist);
  const char* names2[3] = {"sxx", "syy", "sxy"};
  const char* names3[6] = {"sxx", "syy", "szz", "sxy", "syz", "sxz"};
  const char** comp = _nc == 3 ? names2 : names3;
  const std::size_t row = n * _nc;
  const std::size_t steps = _hist.size() / row;
  for (std::size_t p = 0; p < n; ++p)
  {
    nlohmann::json peaks = nlohmann::json::object();
    for (int c = 0; c < _nc; ++c)
    {
      double hi = -HUGE_VAL, lo = HUGE_VAL;
      for (std::size_t k = 0; k < steps; ++k)
      {
        hi = std::max(hi, _hist[k * row + p * _nc + c]);
        lo = std::min(lo, _hist[k * row + p * _nc + c]);
      }
      peaks[comp[c]] = {{"max_mpa", 1e-6 * hi}, {"min_mpa", 1e-6 * lo}};
    }
    out[_names[p]] = {
        {"stress_point", {_where[p][0], _where[p][1], _where[p][2]}},
        {"components", peaks}};
  }
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank != 0)
    return out;
  std::ofstream f(file);
  f << "t_s";
  for (std::size_t p = 0; p < n; ++p)
    for (int c = 0; c < _nc; ++c)
      f << "," << _names[p] << "_" << comp[c] << "_mpa";
  f << "\n";
  f.precision(10);
  for (std::size_t k = 0; k < steps; ++k)
  {
    f << k * dt;
    for (std::size_t j = 0; j < row; ++j)
      f << "," << 1e-6 * _hist[k * row + j];
    f << "\n";
  }
  return out;
}

GroupStates::GroupStates(
    const fem::ElasticModel& fe,
    const std::vector<SeismicSettings::HistoryGroup>& groups, int steps,
    const engine::Stepper& stepper, const FullDisplacement& full,
    std::function<double(int, int)> ground, Vec static_u)
    : _dim(fe.V()->dofmap()->index_map_bs()), _comm(fe.mesh()->comm()),
      _stepper(stepper), _full(full), _ground(std::move(ground))
{
  const std::size_t owned =
      static_cast<std::size_t>(fe.V()->dofmap()->index_map->size_local()) *
      _dim;
  _total.assign(groups.size() * _dim, 0.0);
  for (std::size_t g = 0; g < groups.size(); ++g)
  {
    const auto entities =
        geometry::tagged_entities(*groups[g].tags, {groups[g].tag});
    dolfinx::la::petsc::Vector w(
        fem::group_weights(fe, groups[g].tags->dim(), entities), false);
    const double* a = nullptr;
    VecGetArrayRead(w.vec(), &a);
    _weights.emplace_back(a, a + owned);
    VecRestoreArrayRead(w.vec(), &a);
    for (std::size_t i = 0; i < owned; ++i)
      _total[g * _dim + i % _dim] += _weights[g][i];
    _names.push_back(groups[g].name);
  }
  MPI_Allreduce(MPI_IN_PLACE, _total.data(), static_cast<int>(_total.size()),
                MPI_DOUBLE, MPI_SUM, _comm);
  _static.assign(_weights.size() * _dim, 0.0);
  if (static_u)
  {
    local_sums(static_u, _static);
    MPI_Allreduce(MPI_IN_PLACE, _static.data(),
                  static_cast<int>(_static.size()), MPI_DOUBLE, MPI_SUM, _comm);
  }
  _hist.assign((steps + 1) * _weights.size() * 4 * _dim, 0.0);
}

void GroupStates::local_sums(Vec x, std::vector<double>& out) const
{
  const double* a = nullptr;
  VecGetArrayRead(x, &a);
  for (std::size_t g = 0; g < _weights.size(); ++g)
  {
    const std::vector<double>& w = _weights[g];
    for (std::size_t i = 0; i < w.size(); ++i)
      out[g * _dim + i % _dim] += w[i] * a[i];
  }
  VecRestoreArrayRead(x, &a);
}

void GroupStates::record(int k, double)
{
  const std::size_t n = _weights.size();
  if (n == 0)
    return;
  // u, v, a weighted sums over the groups' owned dofs, one reduction.
  std::vector<double> sums(3 * n * _dim, 0.0), part(n * _dim);
  const std::array<Vec, 3> states = {_stepper.u(), _stepper.v(), _stepper.a()};
  for (int q = 0; q < 3; ++q)
  {
    std::fill(part.begin(), part.end(), 0.0);
    local_sums(_full.full(states[q]), part);
    std::copy(part.begin(), part.end(), sums.begin() + q * n * _dim);
  }
  MPI_Allreduce(MPI_IN_PLACE, sums.data(), static_cast<int>(sums.size()),
                MPI_DOUBLE, MPI_SUM, _comm);
  for (std::size_t g = 0; g < n; ++g)
  {
    double* row = &_hist[((k * n + g) * 4) * _dim];
    for (int c = 0; c < _dim; ++c)
    {
      const double total = _total[g * _dim + c];
      const double w = total != 0.0 ? 1.0 / total : 0.0;
      row[c] = w * (sums[g * _dim + c] - _static[g * _dim + c]);
      row[_dim + c] = w * sums[(n + g) * _dim + c];
      row[2 * _dim + c] = w * sums[(2 * n + g) * _dim + c];
      row[3 * _dim + c] = row[2 * _dim + c] + _ground(k, c);
    }
  }
}

void GroupStates::save(engine::Arrays& arrays) const
{
  if (!_weights.empty())
    arrays["group_states"] = _hist;
}

void GroupStates::restore(const engine::CheckpointData& d)
{
  if (!_weights.empty())
    _hist = engine::checkpoint_array(d, "group_states", _hist.size());
}

nlohmann::json GroupStates::write_csv(MPI_Comm comm, double dt,
                                      const std::filesystem::path& file) const
{
  nlohmann::json peaks = nlohmann::json::object();
  if (_weights.empty())
    return peaks;
  const auto peak = state_peaks(_hist, _weights.size(), _dim);
  for (std::size_t g = 0; g < _weights.size(); ++g)
    peaks[_names[g]] = {
        // m3 for cells, m2 for facets (2D: per metre of thickness)
        {"volume_or_area", _total[g * _dim]},
        {"max_mean_displacement_m", peak[g][0]},
        {"max_mean_velocity_m_per_s", peak[g][1]},
        {"max_mean_acceleration_m_per_s2", peak[g][2]},
        {"max_mean_absolute_acceleration_m_per_s2", peak[g][3]}};
  write_state_table(comm, file, dt, _names, _dim, _hist);
  return peaks;
}

NamedHistories::NamedHistories(MPI_Comm comm, const fem::ElasticModel& fe,
                               const SeismicSettings& s,
                               const engine::Stepper& stepper,
                               const FullDisplacement& full,
                               const StressRecorder& stresses, Vec static_u)
    : _s(s),
      _points(
          *fe.V(), s.history_points, s.steps, stepper, full,
          [&s](int k, int c)
          { return s.motion[c].active ? s.motion[c].acceleration[k] : 0.0; },
          static_u),
      _groups(
          fe, s.history_groups, s.steps, stepper, full,
          [&s](int k, int c)
          { return s.motion[c].active ? s.motion[c].acceleration[k] : 0.0; },
          static_u),
      _stresses(comm, s.history_points, s.steps, stresses)
{
}

void NamedHistories::observe(engine::TimeHistory& history)
{
  history.observe(_points);
  history.observe(_groups);
  history.observe(_stresses);
}

void NamedHistories::write(MPI_Comm comm, const std::filesystem::path& dir,
                           nlohmann::json& summary)
{
  const double dt = _s.scheme.dt;
  if (!_s.history_points.empty())
  {
    summary["history_points"] =
        _points.write_csv(comm, dt, dir / "histories.csv");
    summary["history_point_stresses"] =
        _stresses.write_csv(comm, dt, dir / "stress_histories.csv");
  }
  if (!_s.history_groups.empty())
    summary["history_groups"] =
        _groups.write_csv(comm, dt, dir / "group_histories.csv");
}

FaceDisplacementRecorder::FaceDisplacementRecorder(
    const dolfinx::fem::FunctionSpace& V,
    const dolfinx::mesh::MeshTags<std::int32_t>& facet_tags, int tag,
    const results::PointProbe& base, const FullDisplacement& u, Vec reference,
    double base_reference)
    : _envelope(V, facet_tags, tag), _base(base), _u(u), _reference(reference),
      _base_reference(base_reference)
{
}

void FaceDisplacementRecorder::record(int, double)
{
  const Vec u = _u.vec();
  _envelope.update(u, _base.value_on_all(u)[0] - _base_reference, _reference);
}

void FaceDisplacementRecorder::save(engine::Arrays& arrays) const
{
  arrays["face_u"] = _envelope.save();
}

void FaceDisplacementRecorder::restore(const engine::CheckpointData& d)
{
  _envelope.restore(engine::checkpoint_array(d, "face_u"));
}

FieldRecorder::FieldRecorder(fem::ElasticModel& fe,
                             std::filesystem::path out_dir, int every,
                             std::function<Vec()> displacement,
                             const StressRecorder& stresses, Extras extras)
    : _fe(fe), _dir(std::move(out_dir)), _every(every),
      _displacement(std::move(displacement)), _stresses(stresses),
      _extras(std::move(extras)), _u(fe.V())
{
}

void FieldRecorder::begin(int first_step)
{
  const std::string name =
      first_step == 0
          ? std::string("fields.xdmf")
          : "fields_from_step" + std::to_string(first_step) + ".xdmf";
  _writer.emplace(_fe, _dir / name, _extras.stress_space, _extras.names);
}

void FieldRecorder::record(int k, double t)
{
  if (k % _every != 0)
    return;
  linalg::to_function(_displacement(), _u);
  _writer->write(_u, _stresses.stress(), t,
                 _extras.values ? _extras.values()
                                : std::vector<std::span<const double>>{});
}
} // namespace damseis::analysis
