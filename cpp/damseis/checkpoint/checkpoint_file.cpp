#include "checkpoint_file.h"
#include <cmath>
#include <cstring>
#include <damseis/input/case.h>
#include <nlohmann/json.hpp>
#include <sstream>

namespace damseis::checkpoint
{
namespace
{
constexpr std::uint64_t magic = 0x74706b6373696d64; // "dmsckpt"

template <typename T>
void put(std::string& out, const T& v)
{
  out.append(reinterpret_cast<const char*>(&v), sizeof(T));
}

/// Reads values from bytes, remembering whether any read ran past the end.
class Reader
{
public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}
  template <typename T>
  T get()
  {
    T v{};
    if (left() < static_cast<std::int64_t>(sizeof(T)))
    {
      ok_ = false;
      pos_ = bytes_.size();
      return v;
    }
    std::memcpy(&v, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }
  std::string_view take(std::int64_t n)
  {
    const auto part = bytes_.substr(pos_, static_cast<std::size_t>(n));
    pos_ += part.size();
    return part;
  }
  std::int64_t left() const
  {
    return static_cast<std::int64_t>(bytes_.size() - pos_);
  }
  bool ok() const { return ok_; }

private:
  std::string_view bytes_;
  std::size_t pos_ = 0;
  bool ok_ = true;
};

[[noreturn]] void damaged_meta(const std::string& file, const std::string& why)
{
  throw input::InputError(file + ": damaged (" + why.substr(0, 80) +
                          "); remove its folder (or set run.restart = false) "
                          "to start over");
}

int integer_in(const nlohmann::json& info, const char* name, int lo, int hi,
               const std::string& file)
{
  const auto it = info.find(name);
  if (it == info.end() || !it->is_number_integer())
    damaged_meta(file, std::string(name) + " is not an integer");
  const auto v = it->get<std::int64_t>();
  if (v < lo || v > hi)
    damaged_meta(file, std::string(name) + " = " + std::to_string(v) +
                           " is out of range");
  return static_cast<int>(v);
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
    // A default key is written commented out: "# key = value  # ...
    // (default)" (Case::to_toml); its value counts.
    const std::string mark = " (default)";
    if (line.rfind("# ", 0) == 0 && line.size() > mark.size() &&
        line.compare(line.size() - mark.size(), mark.size(), mark) == 0)
      line.erase(0, 2);
    else if (line.empty() || line[0] == '#')
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
  std::vector<double> words(kept.size() / 8);
  std::memcpy(words.data(), kept.data(), kept.size());
  return fingerprint(words);
}

std::string encode_meta(const Meta& meta)
{
  return nlohmann::json{{"step", meta.step}, {"ranks", meta.ranks}}.dump() +
         "\n";
}

Meta decode_meta(std::string_view text, const std::string& file)
{
  nlohmann::json info;
  try
  {
    info = nlohmann::json::parse(text);
  }
  catch (const nlohmann::json::exception& e)
  {
    damaged_meta(file, e.what());
  }
  if (!info.is_object())
    damaged_meta(file, "not a JSON object");
  return {integer_in(info, "step", 0, max_step, file),
          integer_in(info, "ranks", 1, max_ranks, file)};
}

std::string encode_rank(const CheckpointData& data, std::uint64_t print)
{
  std::string out;
  put(out, magic);
  put(out, print);
  put(out, static_cast<std::int64_t>(data.step));
  put(out, static_cast<std::int64_t>(data.arrays.size()));
  for (const auto& [name, values] : data.arrays)
  {
    put(out, static_cast<std::int64_t>(name.size()));
    out += name;
    put(out, static_cast<std::int64_t>(values.size()));
    out.append(reinterpret_cast<const char*>(values.data()),
               values.size() * sizeof(double));
  }
  return out;
}

RankFile decode_rank(std::string_view bytes, std::uint64_t print, int step,
                     CheckpointData& out)
{
  out = CheckpointData{};
  Reader in(bytes);
  if (in.get<std::uint64_t>() != magic || in.get<std::uint64_t>() != print ||
      in.get<std::int64_t>() != step || !in.ok())
    return RankFile::mismatch;
  out.step = step;
  const auto n = in.get<std::int64_t>();
  if (!in.ok() || n < 0 || n > max_arrays)
    return RankFile::damaged;
  for (std::int64_t i = 0; i < n; ++i)
  {
    const auto length = in.get<std::int64_t>();
    if (!in.ok() || length < 0 || length > in.left())
      return RankFile::damaged;
    std::string name(in.take(length));
    const auto count = in.get<std::int64_t>();
    if (!in.ok() || count < 0 ||
        count > in.left() / static_cast<std::int64_t>(sizeof(double)))
      return RankFile::damaged;
    std::vector<double> values(static_cast<std::size_t>(count));
    const auto payload = in.take(count * std::int64_t(sizeof(double)));
    if (count > 0)
      std::memcpy(values.data(), payload.data(), payload.size());
    for (double v : values)
    {
      if (!std::isfinite(v))
        return RankFile::damaged;
    }
    if (!out.arrays.emplace(std::move(name), std::move(values)).second)
      return RankFile::damaged; // the same name twice
  }
  return in.left() == 0 ? RankFile::ok : RankFile::damaged;
}
} // namespace damseis::checkpoint
