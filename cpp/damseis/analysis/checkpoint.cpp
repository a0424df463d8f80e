#include "checkpoint.h"
#include <cstring>
#include <damseis/case/case.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace damseis::analysis
{
namespace
{
constexpr std::uint64_t magic = 0x74706b6373696d64; // "dmsckpt"

std::filesystem::path rank_file(const std::filesystem::path& dir, int rank,
                                int step)
{
  return dir / ("rank" + std::to_string(rank) + "_step" + std::to_string(step) +
                ".bin");
}

template <typename T>
void put(std::ofstream& out, const T& v)
{
  out.write(reinterpret_cast<const char*>(&v), sizeof(T));
}

template <typename T>
T get(std::ifstream& in)
{
  T v{};
  in.read(reinterpret_cast<char*>(&v), sizeof(T));
  return v;
}
} // namespace

std::uint64_t fingerprint(std::span<const double> values)
{
  // FNV-1a over the bytes.
  std::uint64_t h = 1469598103934665603ull;
  const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
  for (std::size_t i = 0; i < values.size_bytes(); ++i)
  {
    h ^= bytes[i];
    h *= 1099511628211ull;
  }
  return h;
}

void write_checkpoint(MPI_Comm comm, const std::filesystem::path& dir,
                      const CheckpointData& data, std::uint64_t print)
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  std::filesystem::create_directories(dir);
  {
    std::ofstream out(rank_file(dir, rank, data.step), std::ios::binary);
    put(out, magic);
    put(out, print);
    put(out, static_cast<std::int64_t>(data.step));
    put(out, static_cast<std::int64_t>(data.arrays.size()));
    for (const auto& [name, values] : data.arrays)
    {
      put(out, static_cast<std::int64_t>(name.size()));
      out.write(name.data(), static_cast<std::streamsize>(name.size()));
      put(out, static_cast<std::int64_t>(values.size()));
      out.write(reinterpret_cast<const char*>(values.data()),
                static_cast<std::streamsize>(values.size() * sizeof(double)));
    }
    if (!out)
      throw std::runtime_error("cannot write checkpoint in " + dir.string());
  }
  MPI_Barrier(comm);
  if (rank == 0)
  {
    // Point to the new files, then drop the older ones.
    int previous = -1;
    if (std::ifstream meta(dir / "checkpoint.json"); meta)
      previous = nlohmann::json::parse(meta).value("step", -1);
    const auto tmp = dir / "checkpoint.json.tmp";
    std::ofstream(tmp)
        << nlohmann::json{{"step", data.step}, {"ranks", size}}.dump() << "\n";
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
  std::ifstream meta(dir / "checkpoint.json");
  if (!meta)
    return std::nullopt;
  const auto info = nlohmann::json::parse(meta);
  if (info.at("ranks").get<int>() != size)
  {
    throw input::InputError(
        "the checkpoint in " + dir.string() + " was written by " +
        std::to_string(info.at("ranks").get<int>()) +
        " MPI ranks; restart with the same number of ranks");
  }
  CheckpointData data;
  data.step = info.at("step").get<int>();
  std::ifstream in(rank_file(dir, rank, data.step), std::ios::binary);
  int ok = in && get<std::uint64_t>(in) == magic &&
           get<std::uint64_t>(in) == print &&
           get<std::int64_t>(in) == data.step;
  int all_ok = 0;
  MPI_Allreduce(&ok, &all_ok, 1, MPI_INT, MPI_MIN, comm);
  if (!all_ok)
  {
    throw input::InputError("the checkpoint in " + dir.string() +
                            " does not match this model (mesh, order or "
                            "partition changed); remove it to start over");
  }
  const auto n = get<std::int64_t>(in);
  for (std::int64_t i = 0; i < n; ++i)
  {
    std::string name(static_cast<std::size_t>(get<std::int64_t>(in)), ' ');
    in.read(name.data(), static_cast<std::streamsize>(name.size()));
    std::vector<double> values(static_cast<std::size_t>(get<std::int64_t>(in)));
    in.read(reinterpret_cast<char*>(values.data()),
            static_cast<std::streamsize>(values.size() * sizeof(double)));
    data.arrays.emplace(std::move(name), std::move(values));
  }
  int read_ok = in ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &read_ok, 1, MPI_INT, MPI_MIN, comm);
  if (!read_ok)
    throw input::InputError("truncated checkpoint in " + dir.string() +
                            "; remove it (or set run.restart = false) to "
                            "start over");
  return data;
}
} // namespace damseis::analysis
