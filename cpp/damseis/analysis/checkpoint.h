// Checkpoints of a time history: named arrays per rank, so a stopped run can
// resume with the same number of ranks.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <mpi.h>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace damseis::analysis
{
/// What a checkpoint holds: the step reached and the rank's arrays.
struct CheckpointData
{
  int step = 0;
  std::map<std::string, std::vector<double>> arrays;
};

/// A fingerprint of the rank's part of the model (e.g. its dof
/// coordinates), to refuse a checkpoint from another mesh or partition.
std::uint64_t fingerprint(std::span<const double> values);

/// A fingerprint of the effective case (Case::to_toml text) without what a
/// restart may change: comments and the [run], [output] and [solver]
/// tables. A checkpoint of a case with another material, geometry, load or
/// time step is refused.
std::uint64_t case_fingerprint(const std::string& case_text);

/// Writes `data` into `dir` (collective): one file per rank, then
/// `checkpoint.json` on rank 0 once every rank has finished, so a run
/// stopped while writing leaves the previous checkpoint valid.
void write_checkpoint(MPI_Comm comm, const std::filesystem::path& dir,
                      const CheckpointData& data, std::uint64_t print);

/// Reads the checkpoint in `dir` (collective). Returns nothing if there is
/// none; throws input::InputError if it was written by a different number of
/// ranks or for a different model (fingerprint mismatch).
std::optional<CheckpointData> read_checkpoint(MPI_Comm comm,
                                              const std::filesystem::path& dir,
                                              std::uint64_t print);
} // namespace damseis::analysis
