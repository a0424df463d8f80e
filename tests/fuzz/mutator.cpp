#include "mutator.h"
#include <cstring>
#include <limits>
#include <stdexcept>

namespace damseis::fuzz
{
const std::vector<std::string>& extreme_literals()
{
  static const std::vector<std::string> literals = {
      "0",
      "-0.0",
      "1",
      "-1",
      "0.5",
      "2",
      "1e308",
      "-1e308",
      "1.7976931348623157e308",
      "5e-324",
      "1e-300",
      "1e300",
      "1e-12",
      "1e-7",
      "1e7",
      "1e10",
      "1e200",
      "nan",
      "inf",
      "-inf",
      "+inf",
      "0.49999999999999994",
      "2147483647",
      "2147483648",
      "-2147483649",
      "9223372036854775807",
      "-9223372036854775808",
      "99999999999999999999",
      "0x7fffffff",
      "1_000",
      "3.",
      ".5",
      "1e",
      "--1",
      "\"\"",
      "\"x\"",
      "\"/dev/null\"",
      "\"/\"",
      "\".\"",
      "\"no_such_file.at2\"",
      "\"../../data/records/elcentro_1940_ns.at2\"",
      "\"\\u0000\"",
      "true",
      "false",
      "[]",
      "[0]",
      "[1, 3]",
      "[1e308, -1e308]",
      "[nan]",
      "[\"a\", 1]",
      "[[1]]",
      "{}",
      "{ a = 1 }",
      "1979-05-27",
      "'''x'''"};
  return literals;
}

Mutator::Mutator(std::uint64_t seed, std::vector<std::string> seeds,
                 std::vector<std::string> dictionary,
                 std::vector<std::string> keys, bool binary)
    : rng_(seed), seeds_(std::move(seeds)), dictionary_(std::move(dictionary)),
      keys_(std::move(keys)), binary_(binary)
{
  if (seeds_.empty())
    throw std::invalid_argument("Mutator: no seed inputs");
  if (dictionary_.empty())
    dictionary_ = extreme_literals();
}

std::size_t Mutator::below(std::size_t n)
{
  return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_);
}

std::string Mutator::next()
{
  std::string s = seeds_[below(seeds_.size())];
  const std::size_t count = 1 + below(8);
  for (std::size_t i = 0; i < count; ++i)
  {
    mutate_once(s);
    if (s.size() > max_size)
      s.resize(max_size);
  }
  return s;
}

void Mutator::mutate_once(std::string& s)
{
  static const char special[] = {'\0', '\n', '\r',   '\t',   ' ',   '=', '[',
                                 ']',  '"',  '\'',   '.',    '#',   ',', '-',
                                 'e',  '\\', '\x7f', '\xff', '\xc3'};
  const std::size_t n = s.size();
  switch (below(binary_ ? 8 : 12))
  {
  case 0: // flip a bit
    if (n > 0)
      s[below(n)] ^= static_cast<char>(1u << below(8));
    break;
  case 1: // a special or random byte
    if (n > 0)
      s[below(n)] = below(2) ? special[below(sizeof special)]
                             : static_cast<char>(below(256));
    break;
  case 2: // delete a range (sometimes to the end: truncation)
    if (n > 0)
    {
      const std::size_t at = below(n);
      s.erase(at, below(2) ? n - at : 1 + below(16));
    }
    break;
  case 3: // insert random bytes
  {
    std::string bytes(1 + below(8), '\0');
    for (char& c : bytes)
      c = static_cast<char>(below(256));
    s.insert(below(n + 1), bytes);
    break;
  }
  case 4: // copy a range elsewhere
    if (n > 0)
    {
      const std::size_t at = below(n);
      const std::string part = s.substr(at, 1 + below(64));
      s.insert(below(n + 1), part);
    }
    break;
  case 5: // splice with another seed
  {
    const std::string& other = seeds_[below(seeds_.size())];
    s = s.substr(0, below(n + 1)) + other.substr(below(other.size() + 1));
    break;
  }
  case 6: // repeat a range many times
    if (n > 0)
    {
      const std::size_t at = below(n);
      const std::string part = s.substr(at, 1 + below(32));
      std::string many;
      for (std::size_t k = 0, r = 2 + below(2000); k < r; ++k)
        many += part;
      s.insert(at, many);
    }
    break;
  case 7:
    if (binary_)
      set_field(s);
    else
      s.insert(below(n + 1), dictionary_[below(dictionary_.size())]);
    break;
  case 8:
  case 9:
    swap_number(s);
    break;
  case 10:
    set_key(s);
    break;
  default:
    nest_deeply(s);
  }
}

// Replaces a number (a run of digits with its sign, point and exponent) by
// an extreme literal.
void Mutator::swap_number(std::string& s)
{
  const std::size_t n = s.size();
  if (n == 0)
    return;
  auto in_number = [&](std::size_t i)
  {
    const char c = s[i];
    return (c >= '0' && c <= '9') || c == '.' || c == 'e' || c == 'E' ||
           c == '+' || c == '-';
  };
  std::size_t at = below(n);
  while (at < n && !(s[at] >= '0' && s[at] <= '9'))
    ++at;
  if (at == n)
    return;
  std::size_t begin = at, end = at;
  while (begin > 0 && in_number(begin - 1))
    --begin;
  while (end < n && in_number(end))
    ++end;
  const auto& literals = extreme_literals();
  s.replace(begin, end - begin, literals[below(literals.size())]);
}

// Sets the value of a known key ("leaf = value" at the start of a line) to
// an extreme literal.
void Mutator::set_key(std::string& s)
{
  if (keys_.empty())
    return swap_number(s);
  const std::string& key = keys_[below(keys_.size())];
  const auto& literals = extreme_literals();
  const std::string value = literals[below(literals.size())];
  for (std::size_t at = s.find(key); at != std::string::npos;
       at = s.find(key, at + 1))
  {
    if (at > 0 && s[at - 1] != '\n')
      continue;
    std::size_t eq = at + key.size();
    while (eq < s.size() && s[eq] == ' ')
      ++eq;
    if (eq == s.size() || s[eq] != '=')
      continue;
    const std::size_t end = s.find('\n', eq);
    s.replace(eq + 1, end == std::string::npos ? end : end - eq - 1,
              " " + value);
    return;
  }
  s += "\n" + key + " = " + value + "\n";
}

// Overwrites an aligned 8-byte field with an extreme integer or double.
void Mutator::set_field(std::string& s)
{
  if (s.size() < 8)
    return;
  static const std::int64_t integers[] = {
      0,
      1,
      -1,
      2,
      1000,
      1001,
      std::int64_t(1) << 31,
      std::int64_t(1) << 40,
      std::numeric_limits<std::int64_t>::max(),
      std::numeric_limits<std::int64_t>::min()};
  static const double reals[] = {std::numeric_limits<double>::quiet_NaN(),
                                 std::numeric_limits<double>::infinity(),
                                 -std::numeric_limits<double>::infinity(),
                                 std::numeric_limits<double>::max(),
                                 std::numeric_limits<double>::denorm_min(),
                                 -0.0};
  const std::size_t at = below(s.size() / 8) * 8;
  char bytes[8];
  if (below(2))
    std::memcpy(bytes, &integers[below(std::size(integers))], 8);
  else
    std::memcpy(bytes, &reals[below(std::size(reals))], 8);
  s.replace(at, 8, bytes, 8);
}

// A table header, dotted key, inline table or array nested up to 60,000
// levels deep (recursive parsers overflow the stack on these).
void Mutator::nest_deeply(std::string& s)
{
  const std::size_t depth = below(2) ? 1 + below(64) : 1 + below(60000);
  std::string text;
  switch (below(4))
  {
  case 0: // [a.a.a...]
    text = "\n[";
    for (std::size_t i = 0; i < depth; ++i)
      text += "a.";
    text += "a]\n";
    break;
  case 1: // a.a.a... = 1
    text = "\n";
    for (std::size_t i = 0; i < depth; ++i)
      text += "a.";
    text += "a = 1\n";
    break;
  case 2: // x = [[[...]]]
    text = "\nx = " + std::string(depth, '[') + std::string(depth, ']') + "\n";
    break;
  default: // x = {a={a=...}}
    text = "\nx = ";
    for (std::size_t i = 0; i < depth; ++i)
      text += "{a=";
    text += "1" + std::string(depth, '}') + "\n";
  }
  s.insert(below(s.size() + 1), text);
}
} // namespace damseis::fuzz
