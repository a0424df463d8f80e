// The energy balance of a linear time history per step (energy.csv) and
// its summary: kinetic and strain energy, the work of the loads, the
// energy damping dissipated, the work of the joints' contact forces, the
// kinetic energy the impact corrections changed, and the balance error
// (dynamics::EnergyBalance).
#pragma once

#include <damseis/engine/parts.h>
#include <filesystem>
#include <mpi.h>
#include <nlohmann/json.hpp>
#include <vector>

namespace damseis::analysis
{
class EnergyRecorder : public engine::Observer
{
public:
  /// `stepper` must keep an energy balance (Stepper::energy() not null).
  explicit EnergyRecorder(const engine::Stepper& stepper);
  void record(int k, double t) override;
  void save(engine::Arrays& arrays) const override;
  void restore(const engine::CheckpointData& data) override;
  /// energy.csv on rank 0 (kJ) and the summary entry. Collective.
  nlohmann::json write(MPI_Comm comm, const std::filesystem::path& file) const;

private:
  const engine::Stepper& _stepper;
  std::vector<double> _rows; ///< per recorded step: t and the 7 terms
};
} // namespace damseis::analysis
