// Checkpoints of a time history: named arrays per rank, so a stopped run can
// resume with the same number of ranks. The file format is
// checkpoint/checkpoint_file; this part writes and reads it collectively.
#pragma once

#include <damseis/checkpoint/checkpoint_file.h>
#include <filesystem>
#include <functional>
#include <mpi.h>
#include <optional>
#include <string>
#include <vector>

namespace damseis::engine
{
using checkpoint::case_fingerprint;
using checkpoint::CheckpointData;
using checkpoint::fingerprint;

/// Writes `data` into `dir` (collective): one file per rank, then
/// `checkpoint.json` on rank 0 once every rank has finished, so a run
/// stopped while writing leaves the previous checkpoint valid.
void write_checkpoint(MPI_Comm comm, const std::filesystem::path& dir,
                      const CheckpointData& data, std::uint64_t print);

/// Reads the checkpoint in `dir` (collective). Returns nothing if there is
/// none; throws input::InputError (one line, the same on every rank) if it
/// was written by a different number of ranks, for a different model or
/// case (fingerprint mismatch), or is damaged.
std::optional<CheckpointData> read_checkpoint(MPI_Comm comm,
                                              const std::filesystem::path& dir,
                                              std::uint64_t print);

/// The array `name` of a checkpoint with `size` values (0: any size);
/// std::runtime_error otherwise.
const std::vector<double>& checkpoint_array(const CheckpointData& data,
                                            const std::string& name,
                                            std::size_t size = 0);
/// Runs `restore` (reading a checkpoint into the run) on every rank; a
/// failure on any rank (a missing or mis-sized array) becomes
/// input::InputError on all of them. Collective.
void restore_collectively(MPI_Comm comm, const std::filesystem::path& dir,
                          const std::function<void()>& restore);
} // namespace damseis::engine
