// Seeded random mutation of inputs (the fuzzing harness's input source):
// byte-level changes for any format, plus text-aware ones (numbers swapped
// for extreme values, dictionary tokens, values of known keys, deep
// nesting) and binary-aware ones (8-byte fields set to extreme integers or
// doubles). The same seed gives the same sequence of inputs.
#pragma once

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace damseis::fuzz
{
class Mutator
{
public:
  /// `seeds`: valid inputs to start from (at least one). `dictionary`:
  /// tokens of the format (keys, table headers, literals). `keys`: leaf
  /// names of "key = value" lines whose values are swapped for extreme
  /// literals. `binary`: the input is binary (no text-aware mutations).
  Mutator(std::uint64_t seed, std::vector<std::string> seeds,
          std::vector<std::string> dictionary, std::vector<std::string> keys,
          bool binary);

  /// The next input: a seed with one to eight mutations, at most
  /// `max_size` bytes (except for the deep-nesting mutation).
  std::string next();

  static constexpr std::size_t max_size = 1 << 17;

private:
  std::size_t below(std::size_t n); ///< uniform in [0, n), n > 0
  void mutate_once(std::string& s);
  void swap_number(std::string& s);
  void set_key(std::string& s);
  void set_field(std::string& s);
  void nest_deeply(std::string& s);

  std::mt19937_64 rng_;
  std::vector<std::string> seeds_, dictionary_, keys_;
  bool binary_;
};

/// Literals of extreme, degenerate and wrong-typed values (numbers, strings,
/// booleans, arrays, tables), as they would be written in a TOML file.
const std::vector<std::string>& extreme_literals();
} // namespace damseis::fuzz
