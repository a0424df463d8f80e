// Fuzz targets: the readers of everything a user hands to damseis (case
// files of each demo, ground-motion records, checkpoints), each run on one
// input with the invariants the programs promise checked afterwards.
#pragma once

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace damseis::fuzz
{
/// An input that broke a promise (an exception other than the one-line
/// input error, a message of several lines or with control characters, a
/// non-finite value accepted).
class Finding : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

enum class Outcome
{
  accepted, ///< read (and, where cheap, used) without complaint
  rejected  ///< refused with one clean line
};

struct Target
{
  std::string name;
  std::string help;
  std::vector<std::string> seeds; ///< valid inputs (file contents)
  std::vector<std::string> dictionary;
  std::vector<std::string> keys; ///< leaf key names for value swaps
  bool binary = false;
  /// Runs one input; `scratch` is a private folder the target may write in.
  /// Throws Finding.
  std::function<Outcome(std::string_view, const std::filesystem::path&)> run;
};

/// All targets, with seeds read from the source tree `source_dir`. The
/// scratch folder gets a `data` link to the shipped records so that the
/// demos' case files (which name "../../data/records/...") find them.
std::vector<Target> all_targets(const std::filesystem::path& source_dir,
                                const std::filesystem::path& scratch);
} // namespace damseis::fuzz
