#include "joint_recorder.h"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <tuple>

namespace damseis::joint
{
namespace
{
constexpr int step_columns = 8;

/// The largest of `value` over the pairs of joint j that are on `face`
/// (all pairs if face is null), with its pair index (-1: none).
std::pair<double, int> largest(const PairSet& pairs, std::size_t j,
                               const std::vector<double>& value,
                               const PairFace* face)
{
  std::pair<double, int> best{0.0, -1};
  for (std::size_t i = 0; i < pairs.size(); ++i)
  {
    if (pairs.joint[i] != static_cast<int>(j))
      continue;
    if (face && !std::binary_search(face->blocks.begin(), face->blocks.end(),
                                    pairs.block1[i]))
      continue;
    if (best.second < 0 || value[i] > best.first)
      best = {value[i], static_cast<int>(i)};
  }
  return best;
}

std::string cm(double metres)
{
  char s[32];
  std::snprintf(s, sizeof s, "%.4f", 100.0 * metres);
  return s;
}

/// The pairs with histories and their names: the pair nearest to each of
/// `points` ("<joint>_p<k>"), or with no points the top pair of each joint
/// ("<joint>_top").
std::pair<std::vector<int>, std::vector<std::string>>
history_pairs(const PairSet& pairs,
              const std::vector<std::array<double, 3>>& points)
{
  std::vector<int> index;
  std::vector<std::string> name;
  // The pair of `among` (a predicate) that minimises `cost`, or -1.
  auto best_pair = [&](auto among, auto cost)
  {
    int best = -1;
    for (std::size_t i = 0; i < pairs.size(); ++i)
    {
      if (among(i) && (best < 0 || cost(i) < cost(best)))
        best = static_cast<int>(i);
    }
    return best;
  };
  if (points.empty())
  {
    for (std::size_t j = 0; j < pairs.joints.size(); ++j)
    {
      const int top = best_pair(
          [&](std::size_t i) { return pairs.joint[i] == static_cast<int>(j); },
          [&](std::size_t i) { return -pairs.x[i][2]; });
      if (top >= 0)
      {
        index.push_back(top);
        name.push_back(pairs.joints[j].label + "_top");
      }
    }
  }
  for (std::size_t k = 0; k < points.size(); ++k)
  {
    const auto& q = points[k];
    const int nearest = best_pair([](std::size_t) { return true; },
                                  [&](std::size_t i)
                                  {
                                    return std::hypot(pairs.x[i][0] - q[0],
                                                      pairs.x[i][1] - q[1],
                                                      pairs.x[i][2] - q[2]);
                                  });
    index.push_back(nearest);
    name.push_back(pairs.joints[pairs.joint[nearest]].label + "_p" +
                   std::to_string(k + 1));
  }
  return {index, name};
}
} // namespace

JointRecorder::JointRecorder(const ContactRun& stepper,
                             Eigen::VectorXd w_static,
                             const std::vector<std::array<double, 3>>& points)
    : _stepper(stepper), _w_static(std::move(w_static))
{
  const PairSet& pairs = stepper.contact().pairs();
  const std::size_t n = pairs.size();
  std::tie(_probe, _probe_name) = history_pairs(pairs, points);
  _open.assign(n, 0.0);
  _t_open.assign(n, 0.0);
  _slide.assign(n, 0.0);
  _t_slide.assign(n, 0.0);
}

void JointRecorder::record(int, double t)
{
  const CondensedContact& c = _stepper.contact();
  const Eigen::VectorXd& w = c.relative_displacement();
  int open = 0, sliding = 0;
  double widest = 0.0;
  for (std::size_t i = 0; i < _open.size(); ++i)
  {
    const double gap = std::max(c.gap(i), 0.0);
    const double slide =
        (w.segment<2>(3 * i + 1) - _w_static.segment<2>(3 * i + 1)).norm();
    // A new largest value (by more than round-off: the time is when the
    // plateau is reached).
    if (gap > _open[i] * (1.0 + 1e-9) + 1e-15)
    {
      _open[i] = gap;
      _t_open[i] = t;
    }
    if (slide > _slide[i] * (1.0 + 1e-9) + 1e-15)
    {
      _slide[i] = slide;
      _t_slide[i] = t;
    }
    open += c.states()[i] == contact::PairState::open;
    sliding += c.states()[i] == contact::PairState::slip;
    widest = std::max(widest, gap);
  }
  _histories.push_back(t);
  for (int i : _probe)
  {
    _histories.push_back(std::max(c.gap(i), 0.0));
    _histories.push_back(
        (w.segment<2>(3 * i + 1) - _w_static.segment<2>(3 * i + 1)).norm());
  }
  const ContactTotals& last = _stepper.last_step();
  _steps.insert(_steps.end(),
                {t, static_cast<double>(open), static_cast<double>(sliding),
                 widest, static_cast<double>(last.ncp_iterations),
                 static_cast<double>(last.line_search_steps),
                 static_cast<double>(last.state_changes),
                 static_cast<double>(last.impacts)});
}

void JointRecorder::save(engine::Arrays& arrays) const
{
  arrays["joint_open"] = _open;
  arrays["joint_t_open"] = _t_open;
  arrays["joint_slide"] = _slide;
  arrays["joint_t_slide"] = _t_slide;
  arrays["joint_steps"] = _steps;
  arrays["joint_histories"] = _histories;
}

void JointRecorder::restore(const engine::CheckpointData& data)
{
  const std::size_t n = _open.size();
  _open = engine::checkpoint_array(data, "joint_open", n);
  _t_open = engine::checkpoint_array(data, "joint_t_open", n);
  _slide = engine::checkpoint_array(data, "joint_slide", n);
  _t_slide = engine::checkpoint_array(data, "joint_t_slide", n);
  _steps = engine::checkpoint_array(data, "joint_steps");
  _histories = engine::checkpoint_array(data, "joint_histories");
  if (_steps.size() % step_columns != 0 ||
      _histories.size() % (1 + 2 * _probe.size()) != 0)
    throw std::runtime_error("checkpoint array joint_steps or "
                             "joint_histories is damaged");
}

void JointRecorder::write_histories(const std::filesystem::path& file) const
{
  std::ofstream h(file);
  h << "t_s";
  for (const auto& name : _probe_name)
    h << "," << name << "_opening_cm," << name << "_sliding_cm";
  h << "\n";
  const std::size_t columns = 1 + 2 * _probe.size();
  for (std::size_t k = 0; k < _histories.size(); k += columns)
  {
    h << _histories[k];
    for (std::size_t c = 1; c < columns; ++c)
      h << "," << 100.0 * _histories[k + c];
    h << "\n";
  }
}

nlohmann::json JointRecorder::write(MPI_Comm comm,
                                    const std::filesystem::path& dir,
                                    const std::vector<PairFace>& faces) const
{
  const PairSet& pairs = _stepper.contact().pairs();
  nlohmann::json table = nlohmann::json::array();
  for (std::size_t j = 0; j < pairs.joints.size(); ++j)
  {
    nlohmann::json row = {{"joint", pairs.joints[j].label}};
    auto entry = [&](const std::string& key, const std::vector<double>& value,
                     const std::vector<double>& time, const PairFace* face)
    {
      const auto [v, i] = largest(pairs, j, value, face);
      if (i < 0)
        return;
      row[key] = {{"cm", 100.0 * v}, {"t_s", time[i]}, {"x", pairs.x[i]}};
    };
    entry("opening", _open, _t_open, nullptr);
    entry("sliding", _slide, _t_slide, nullptr);
    for (const PairFace& f : faces)
    {
      entry("opening_" + f.name, _open, _t_open, &f);
      entry("sliding_" + f.name, _slide, _t_slide, &f);
    }
    table.push_back(row);
  }
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0)
  {
    std::ofstream p(dir / "joint_pairs.csv");
    p << "joint,x,y,z,max_opening_cm,t_opening_s,max_sliding_cm,"
         "t_sliding_s\n";
    for (std::size_t i = 0; i < pairs.size(); ++i)
    {
      p << pairs.joints[pairs.joint[i]].label << "," << pairs.x[i][0] << ","
        << pairs.x[i][1] << "," << pairs.x[i][2] << "," << 100.0 * _open[i]
        << "," << _t_open[i] << "," << 100.0 * _slide[i] << "," << _t_slide[i]
        << "\n";
    }
    std::ofstream s(dir / "joint_steps.csv");
    s << "t_s,pairs_open,pairs_sliding,widest_opening_cm,ncp_iterations,"
         "line_search_steps,state_changes,impacts\n";
    for (std::size_t k = 0; k < _steps.size(); k += step_columns)
    {
      s << _steps[k] << "," << _steps[k + 1] << "," << _steps[k + 2] << ","
        << 100.0 * _steps[k + 3];
      for (int j = 4; j < step_columns; ++j)
        s << "," << _steps[k + j];
      s << "\n";
    }
    write_histories(dir / "joint_histories.csv");
    // The tables: joints as rows; opening and sliding, overall and per face.
    std::vector<std::string> columns = {"opening"};
    for (const PairFace& f : faces)
      columns.push_back("opening_" + f.name);
    columns.push_back("sliding");
    for (const PairFace& f : faces)
      columns.push_back("sliding_" + f.name);
    std::ofstream csv(dir / "joint_table.csv"), md(dir / "joint_table.md");
    csv << "joint";
    md << "| joint |";
    for (const auto& c : columns)
    {
      csv << "," << c << "_cm";
      md << " max " << c << " [cm] |";
    }
    csv << "\n";
    md << "\n|---|";
    for (std::size_t k = 0; k < columns.size(); ++k)
      md << "---|";
    md << "\n";
    for (const auto& row : table)
    {
      csv << row["joint"].get<std::string>();
      md << "| " << row["joint"].get<std::string>() << " |";
      for (const auto& c : columns)
      {
        const std::string v =
            row.contains(c) ? cm(row[c]["cm"].get<double>() / 100.0) : "-";
        csv << "," << v;
        md << " " << v << " |";
      }
      csv << "\n";
      md << "\n";
    }
  }
  double widest = 0.0, slide = 0.0;
  for (std::size_t i = 0; i < pairs.size(); ++i)
  {
    widest = std::max(widest, _open[i]);
    slide = std::max(slide, _slide[i]);
  }
  nlohmann::json probes = nlohmann::json::array();
  for (std::size_t k = 0; k < _probe.size(); ++k)
    probes.push_back({{"name", _probe_name[k]}, {"x", pairs.x[_probe[k]]}});
  const ContactTotals& t = _stepper.contact().totals();
  return {{"model", "contact"},
          {"pairs", pairs.size()},
          {"pairs_condensed_on_relative_displacement",
           _stepper.contact().relative_pairs()},
          {"max_opening_cm", 100.0 * widest},
          {"max_sliding_cm", 100.0 * slide},
          {"table", table},
          {"history_pairs", probes},
          {"ncp_iterations", t.ncp_iterations},
          {"line_search_steps", t.line_search_steps},
          {"gradient_steps", t.gradient_steps},
          {"state_changes", t.state_changes},
          {"impacts", t.impacts},
          {"bonds_broken", t.bonds_broken},
          {"seconds",
           {{"bulk_solve", t.seconds_bulk},
            {"contact_solve", t.seconds_contact},
            {"impact_correction", t.seconds_impact},
            {"flexibility_setup", t.seconds_setup}}}};
}

nlohmann::json write_static_pairs(MPI_Comm comm,
                                  const std::filesystem::path& dir,
                                  const PairSet& pairs,
                                  const StaticContactResult& s)
{
  static const char* state_name[] = {"open", "stick", "slip"};
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  int open = 0;
  std::ofstream out;
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0)
  {
    out.open(dir / "joint_static.csv");
    out << "joint,x,y,z,area_m2,gap_cm,state,bond,P_n_kN,P_a_kN,P_b_kN,"
           "f_x_kN,f_y_kN,f_z_kN\n";
  }
  for (std::size_t i = 0; i < pairs.size(); ++i)
  {
    const Eigen::Vector3d p = s.p.segment<3>(3 * i);
    const Eigen::Vector3d f = pairs.frame[i] * p;
    total += f;
    open += s.states[i] == contact::PairState::open;
    if (rank != 0)
      continue;
    const JointSpec& joint = pairs.joints[pairs.joint[i]];
    const bool bonded = joint.tensile_strength > 0.0 || joint.cohesion > 0.0;
    out << joint.label << "," << pairs.x[i][0] << "," << pairs.x[i][1] << ","
        << pairs.x[i][2] << "," << pairs.area[i] << ","
        << 100.0 * (s.g0[i] + s.w[3 * i]) << ","
        << state_name[static_cast<int>(s.states[i])] << ","
        << (!bonded       ? "none"
            : s.broken[i] ? "broken"
                          : "intact");
    for (double v : {p[0], p[1], p[2], f[0], f[1], f[2]})
      out << "," << v / 1e3;
    out << "\n";
  }
  return {
      {"pairs_open", open},
      {"bonds_broken", std::count(s.broken.begin(), s.broken.end(), 1)},
      {"force_on_side2_kN", {total[0] / 1e3, total[1] / 1e3, total[2] / 1e3}}};
}
} // namespace damseis::joint
