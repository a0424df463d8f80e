// The bytes of a checkpoint: the per-rank state file and the checkpoint.json
// that points to it. Pure functions on strings (no files, no MPI), so that
// damaged checkpoints can be tested and fuzzed without a model;
// engine/checkpoint does the collective reading and writing.
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace damseis::checkpoint
{
/// What a checkpoint holds: the step reached and the rank's arrays.
struct CheckpointData
{
  int step = 0;
  std::map<std::string, std::vector<double>> arrays;
};

/// checkpoint.json: the step of the rank files and how many ranks wrote them.
struct Meta
{
  int step = 0;
  int ranks = 1;
};

/// Largest step and rank count a checkpoint.json may name (the case reader
/// allows at most 1e7 steps).
inline constexpr int max_step = 10'000'000;
inline constexpr int max_ranks = 1'000'000;
/// Largest number of arrays in a rank file.
inline constexpr std::int64_t max_arrays = 1000;

/// A fingerprint of the rank's part of the model (e.g. its dof
/// coordinates), to refuse a checkpoint from another mesh or partition.
std::uint64_t fingerprint(std::span<const double> values);

/// A fingerprint of the effective case (Case::to_toml text, the default
/// keys' commented lines included) without what a restart may change:
/// comments and the [run], [output] and [solver] tables. A checkpoint of a
/// case with another material, geometry, load or time step is refused.
std::uint64_t case_fingerprint(const std::string& case_text);

/// The text of checkpoint.json.
std::string encode_meta(const Meta& meta);
/// Parses checkpoint.json. Throws input::InputError naming `file` (and
/// saying how to start over) unless it is a JSON object whose "step" is an
/// integer in [0, max_step] and "ranks" an integer in [1, max_ranks].
Meta decode_meta(std::string_view text, const std::string& file);

/// The bytes of a rank file: magic, `print`, step, then each array as
/// (name length, name, value count, values), native byte order.
std::string encode_rank(const CheckpointData& data, std::uint64_t print);

/// How a rank file compares with the run that wants to resume from it.
enum class RankFile
{
  ok,       ///< decoded: every size consistent, every value finite
  mismatch, ///< another model, partition or case (magic/print/step differ)
  damaged   ///< truncated, inconsistent sizes, trailing bytes or non-finite
};

/// Decodes a rank file written by encode_rank for step `step` and model
/// fingerprint `print` into `out` (cleared first). Sizes read from the bytes
/// are checked against what is left of them, so damaged bytes cannot ask
/// for a huge allocation.
RankFile decode_rank(std::string_view bytes, std::uint64_t print, int step,
                     CheckpointData& out);
} // namespace damseis::checkpoint
