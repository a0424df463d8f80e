#include "checkpoint.h"
#include <damseis/input/case.h>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace damseis::engine
{
namespace
{
std::filesystem::path rank_file(const std::filesystem::path& dir, int rank,
                                int step)
{
  return dir / ("rank" + std::to_string(rank) + "_step" + std::to_string(step) +
                ".bin");
}

/// The whole file, or nothing if it cannot be read.
std::optional<std::string> contents(const std::filesystem::path& file)
{
  std::ifstream in(file, std::ios::binary);
  if (!in)
    return std::nullopt;
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad())
    return std::nullopt;
  return std::move(bytes).str();
}

/// The worst status over the ranks (ok < mismatch < damaged).
checkpoint::RankFile worst(MPI_Comm comm, checkpoint::RankFile mine)
{
  int code = static_cast<int>(mine), all = 0;
  MPI_Allreduce(&code, &all, 1, MPI_INT, MPI_MAX, comm);
  return static_cast<checkpoint::RankFile>(all);
}
} // namespace

void write_checkpoint(MPI_Comm comm, const std::filesystem::path& dir,
                      const CheckpointData& data, std::uint64_t print)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  std::filesystem::create_directories(dir);
  {
    const std::string bytes = checkpoint::encode_rank(data, print);
    std::ofstream out(rank_file(dir, rank, data.step), std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out)
      throw std::runtime_error("cannot write checkpoint in " + dir.string());
  }
  MPI_Barrier(comm);
  if (rank == 0)
  {
    // Point to the new files, then drop the older ones.
    int previous = -1;
    if (const auto meta = contents(dir / "checkpoint.json"))
    {
      try
      {
        previous = checkpoint::decode_meta(*meta, "").step;
      }
      catch (const input::InputError&)
      {
      }
    }
    const auto tmp = dir / "checkpoint.json.tmp";
    std::ofstream(tmp) << checkpoint::encode_meta({data.step, size});
    std::filesystem::rename(tmp, dir / "checkpoint.json");
    if (previous >= 0 && previous != data.step)
    {
      for (int r = 0; r < size; ++r)
        std::filesystem::remove(rank_file(dir, r, previous));
    }
  }
  MPI_Barrier(comm);
}

std::optional<CheckpointData> read_checkpoint(MPI_Comm comm,
                                              const std::filesystem::path& dir,
                                              std::uint64_t print)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  // Every rank reads the same checkpoint.json, so all throw or none.
  const auto meta_text = contents(dir / "checkpoint.json");
  if (!meta_text)
    return std::nullopt;
  const auto meta =
      checkpoint::decode_meta(*meta_text, (dir / "checkpoint.json").string());
  if (meta.ranks != size)
  {
    throw input::InputError(
        "the checkpoint in " + dir.string() + " was written by " +
        std::to_string(meta.ranks) +
        " MPI ranks; restart with the same number of ranks");
  }
  CheckpointData data;
  auto status = checkpoint::RankFile::mismatch;
  if (const auto bytes = contents(rank_file(dir, rank, meta.step)))
    status = checkpoint::decode_rank(*bytes, print, meta.step, data);
  switch (worst(comm, status))
  {
  case checkpoint::RankFile::ok:
    return data;
  case checkpoint::RankFile::mismatch:
    throw input::InputError(
        "the checkpoint in " + dir.string() +
        " does not match this run (the mesh, the partition, the output points "
        "(crest, base, history) or a case value "
        "other than run.*, output.* and solver.* changed) or is damaged; "
        "restart with the case it was written with, or remove it to start "
        "over");
  case checkpoint::RankFile::damaged:
  default:
    throw input::InputError("truncated or damaged checkpoint in " +
                            dir.string() +
                            "; remove it (or set run.restart = false) to "
                            "start over");
  }
}

const std::vector<double>& checkpoint_array(const CheckpointData& data,
                                            const std::string& name,
                                            std::size_t size)
{
  const auto it = data.arrays.find(name);
  if (it == data.arrays.end())
    throw std::runtime_error("no array " + name);
  if (size != 0 && it->second.size() != size)
    throw std::runtime_error("array " + name + " has " +
                             std::to_string(it->second.size()) +
                             " values, expected " + std::to_string(size));
  return it->second;
}

void restore_collectively(MPI_Comm comm, const std::filesystem::path& dir,
                          const std::function<void()>& restore)
{
  std::string what;
  try
  {
    restore();
  }
  catch (const std::exception& e)
  {
    what = e.what();
  }
  int ok = what.empty() ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &ok, 1, MPI_INT, MPI_MIN, comm);
  if (!ok)
  {
    throw input::InputError(
        "the checkpoint in " + dir.string() + " does not fit this run (" +
        (what.empty() ? std::string("on another rank") : what.substr(0, 120)) +
        "); remove it (or set run.restart = false) to start over");
  }
}
} // namespace damseis::engine
