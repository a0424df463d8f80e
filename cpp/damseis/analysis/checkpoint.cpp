#include "checkpoint.h"
#include <cmath>
#include <cstring>
#include <damseis/case/case.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
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

std::uint64_t case_fingerprint(const std::string& case_text)
{
  std::istringstream in(case_text);
  std::string line, table, kept;
  while (std::getline(in, line))
  {
    if (line.empty() || line[0] == '#')
      continue;
    if (line[0] == '[')
    {
      table = line;
      continue;
    }
    if (table == "[run]" || table == "[output]" || table == "[solver]")
      continue;
    const auto comment = line.find("  # ");
    kept += table + line.substr(0, comment) + "\n";
  }
  kept.resize((kept.size() + 7) / 8 * 8, ' ');
  return fingerprint(std::span<const double>(
      reinterpret_cast<const double*>(kept.data()), kept.size() / 8));
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
  nlohmann::json info;
  try
  {
    info = nlohmann::json::parse(meta);
    if (!info.at("ranks").is_number_integer() ||
        !info.at("step").is_number_integer() || info.at("step").get<int>() < 0)
      throw std::runtime_error("step and ranks are not integers");
  }
  catch (const std::exception& e)
  {
    throw input::InputError((dir / "checkpoint.json").string() + ": damaged (" +
                            std::string(e.what()).substr(0, 80) + "); remove " +
                            dir.string() +
                            " (or set run.restart = false) to start over");
  }
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
    throw input::InputError(
        "the checkpoint in " + dir.string() +
        " does not match this run (the mesh, the partition or a case value "
        "other than run.*, output.* and solver.* changed) or is damaged; "
        "restart with the case it was written with, or remove it to start "
        "over");
  }
  // Sizes read from the file are checked against what is left of it, so a
  // damaged file cannot ask for a huge allocation.
  std::error_code ec;
  const auto file_size = static_cast<std::int64_t>(
      std::filesystem::file_size(rank_file(dir, rank, data.step), ec));
  auto left = [&] { return file_size - static_cast<std::int64_t>(in.tellg()); };
  const auto n = get<std::int64_t>(in);
  bool sizes_ok = in && n >= 0 && n <= 1000;
  for (std::int64_t i = 0; sizes_ok && i < n; ++i)
  {
    const auto length = get<std::int64_t>(in);
    sizes_ok = in && length >= 0 && length <= left();
    if (!sizes_ok)
      break;
    std::string name(static_cast<std::size_t>(length), ' ');
    in.read(name.data(), static_cast<std::streamsize>(name.size()));
    const auto count = get<std::int64_t>(in);
    sizes_ok = in && count >= 0 &&
               count <= left() / static_cast<std::int64_t>(sizeof(double));
    if (!sizes_ok)
      break;
    std::vector<double> values(static_cast<std::size_t>(count));
    in.read(reinterpret_cast<char*>(values.data()),
            static_cast<std::streamsize>(values.size() * sizeof(double)));
    data.arrays.emplace(std::move(name), std::move(values));
  }
  // Every value finite (a damaged payload must not reach the results).
  bool finite = sizes_ok;
  for (const auto& [name, values] : data.arrays)
  {
    for (double v : values)
      finite = finite && std::isfinite(v);
  }
  int read_ok = in && finite ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &read_ok, 1, MPI_INT, MPI_MIN, comm);
  if (!read_ok)
    throw input::InputError("truncated or damaged checkpoint in " +
                            dir.string() +
                            "; remove it (or set run.restart = false) to "
                            "start over");
  return data;
}
} // namespace damseis::analysis
