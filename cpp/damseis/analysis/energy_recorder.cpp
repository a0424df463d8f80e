#include "energy_recorder.h"
#include <algorithm>
#include <cmath>
#include <damseis/engine/checkpoint.h>
#include <fstream>
#include <stdexcept>

namespace damseis::analysis
{
namespace
{
constexpr std::size_t columns = 8;
} // namespace

EnergyRecorder::EnergyRecorder(const engine::Stepper& stepper)
    : _stepper(stepper)
{
  if (!stepper.energy())
    throw std::invalid_argument("EnergyRecorder: the stepper keeps no energy "
                                "balance");
}

void EnergyRecorder::record(int k, double t)
{
  const dynamics::EnergyBalance& e = *_stepper.energy();
  _rows.resize(static_cast<std::size_t>(k) * columns);
  _rows.insert(_rows.end(), {t, e.kinetic - e.kinetic0, e.strain - e.strain0,
                             e.external_work, e.damping, e.constraint_work,
                             e.impact, e.error()});
}

void EnergyRecorder::save(engine::Arrays& arrays) const
{
  arrays["energy_history"] = _rows;
}

void EnergyRecorder::restore(const engine::CheckpointData& data)
{
  _rows = engine::checkpoint_array(data, "energy_history");
  if (_rows.size() % columns != 0)
    throw std::runtime_error("checkpoint array energy_history is damaged");
}

nlohmann::json EnergyRecorder::write(MPI_Comm comm,
                                     const std::filesystem::path& file) const
{
  // The scale of the error: the largest energy term of the run.
  double scale = 0.0, worst = 0.0, kinetic = 0.0;
  for (std::size_t k = 0; k < _rows.size(); k += columns)
  {
    for (std::size_t j = 1; j < columns - 1; ++j)
      scale = std::max(scale, std::abs(_rows[k + j]));
    worst = std::max(worst, std::abs(_rows[k + columns - 1]));
    kinetic = std::max(kinetic, _rows[k + 1]);
  }
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  if (rank == 0)
  {
    std::ofstream f(file);
    f << "t_s,kinetic_change_kj,strain_change_kj,load_work_kj,damping_kj,"
         "joint_work_kj,impact_kj,balance_error_kj\n";
    f.precision(10);
    for (std::size_t k = 0; k < _rows.size(); k += columns)
    {
      f << _rows[k];
      for (std::size_t j = 1; j < columns; ++j)
        f << "," << 1e-3 * _rows[k + j];
      f << "\n";
    }
  }
  if (_rows.empty())
    return nlohmann::json::object();
  const double* last = &_rows[_rows.size() - columns];
  return {
      {"note", "changes since the start [J]: kinetic + strain + damping "
               "= load work + joint work + impact corrections + error"},
      {"max_kinetic_change_j", kinetic},
      {"load_work_j", last[3]},
      {"damping_j", last[4]},
      {"joint_work_j", last[5]},
      {"impact_corrections_j", last[6]},
      {"balance_error_j", last[7]},
      {"largest_balance_error_j", worst},
      {"largest_balance_error_relative", scale > 0.0 ? worst / scale : 0.0}};
}
} // namespace damseis::analysis
