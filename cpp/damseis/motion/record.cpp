/// @file record.cpp
/// Ground-motion record reading, resampling, scaling and baseline correction.
#include "record.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string_view>
#include <system_error>

namespace damseis::motion
{

namespace
{

/// Throws a RecordError "<file>: <message>".
[[noreturn]] void fail(const std::filesystem::path& file,
                       const std::string& message)
{
  throw RecordError(file.string() + ": " + message);
}

/// Formats a number for error messages (shortest round-trip form).
std::string fmt(double x)
{
  std::ostringstream s;
  s.precision(10);
  s << x;
  return s.str();
}

/// Quotes (and shortens) a piece of file content for an error message.
/// A safe excerpt for an error message: at most 40 bytes, other than
/// printable ASCII as \xNN.
std::string quote(std::string_view text)
{
  constexpr std::size_t max_length = 40;
  std::string quoted = "\"";
  for (std::size_t i = 0; i < text.size() && i < max_length; ++i)
  {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f && c != '"' && c != '\\')
      quoted.push_back(static_cast<char>(c));
    else
    {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", c);
      quoted.append(hex);
    }
  }
  if (text.size() > max_length)
    quoted.append("...");
  quoted.push_back('"');
  return quoted;
}

/// Refuses a file that is not text (a NUL byte, or many bytes that are
/// neither printable nor whitespace, in its first 4 KiB).
void require_text(const std::filesystem::path& file)
{
  std::ifstream in(file, std::ios::binary);
  char buffer[4096];
  in.read(buffer, sizeof buffer);
  const std::streamsize n = in.gcount();
  std::size_t odd = 0;
  for (std::streamsize i = 0; i < n; ++i)
  {
    const auto c = static_cast<unsigned char>(buffer[i]);
    if (c == 0)
    {
      fail(file, "is not a text file (a NUL byte at offset " +
                     std::to_string(i) +
                     "); expected a PEER .at2 file or one/two numeric "
                     "columns of text");
    }
    if (c < 0x20 && c != '\n' && c != '\r' && c != '\t' && c != '\f' &&
        c != '\v')
      ++odd;
  }
  if (n > 0 && odd * 10 > static_cast<std::size_t>(n))
    fail(file, "is not a text file (" + std::to_string(odd) +
                   " control bytes in its first " + std::to_string(n) +
                   "); expected a PEER .at2 file or one/two numeric columns "
                   "of text");
}

/// Removes leading and trailing whitespace.
std::string_view trim(std::string_view s)
{
  const auto is_space = [](char c)
  { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!s.empty() && is_space(s.front()))
    s.remove_prefix(1);
  while (!s.empty() && is_space(s.back()))
    s.remove_suffix(1);
  return s;
}

/// Splits @p s at whitespace.
std::vector<std::string_view> split_whitespace(std::string_view s)
{
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < s.size())
  {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i])))
      ++i;
    const std::size_t start = i;
    while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i])))
      ++i;
    if (i > start)
      tokens.push_back(s.substr(start, i - start));
  }
  return tokens;
}

/// Parses a number at the start of @p s (optional '+', Fortran 'D'
/// exponent accepted). Returns the number of characters consumed, or 0 if
/// @p s does not start with a finite number.
std::size_t parse_prefix(std::string_view s, double& value)
{
  std::string text(s);
  std::size_t skip = 0;
  if (!text.empty() && text.front() == '+')
    skip = 1;
  for (char& c : text)
    if (c == 'D' || c == 'd')
      c = 'E';
  const char* begin = text.data() + skip;
  const char* end = text.data() + text.size();
  if (begin != end && (*begin == '+' || *begin == '-') && skip == 1)
    return 0; // "+-1" or "++1"
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || !std::isfinite(value))
    return 0;
  return static_cast<std::size_t>(ptr - text.data());
}

/// Parses a whole token as a finite number.
bool parse_number(std::string_view token, double& value)
{
  return !token.empty() && parse_prefix(token, value) == token.size();
}

/// Splits a Fortran fixed-format token at each '-' that follows a digit
/// ("-0.00128-0.00133" -> "-0.00128", "-0.00133"); exponents such as
/// "1.0E-03" are left alone.
std::vector<std::string_view> split_glued(std::string_view token)
{
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  for (std::size_t i = 1; i < token.size(); ++i)
  {
    if (token[i] == '-' &&
        std::isdigit(static_cast<unsigned char>(token[i - 1])))
    {
      parts.push_back(token.substr(start, i - start));
      start = i;
    }
  }
  parts.push_back(token.substr(start));
  return parts;
}

/// Reads all lines of @p file (a trailing '\r' is removed from each).
std::vector<std::string> read_lines(const std::filesystem::path& file)
{
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    fail(file, "cannot open: is a directory; expected a ground-motion "
               "record file");
  std::ifstream in(file);
  if (!in)
    fail(file, "cannot open (missing or unreadable); expected a readable "
               "ground-motion record file");
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(in, line))
  {
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    lines.push_back(std::move(line));
  }
  if (in.bad())
    fail(file, "read error; expected a readable ground-motion record file");
  return lines;
}

/// Looks for "<key> = <number>" (case-insensitive, spaces optional) in the
/// upper-cased line @p upper. Returns false if the key with '=' is absent;
/// sets @p ok false if the key is present but no number follows.
bool find_keyed_number(const std::string& upper, std::string_view key,
                       double& value, bool& ok)
{
  for (std::size_t pos = upper.find(key); pos != std::string::npos;
       pos = upper.find(key, pos + 1))
  {
    std::size_t i = pos + key.size();
    while (i < upper.size() && upper[i] == ' ')
      ++i;
    if (i >= upper.size() || upper[i] != '=')
      continue;
    ++i;
    while (i < upper.size() &&
           std::isspace(static_cast<unsigned char>(upper[i])))
      ++i;
    ok = parse_prefix(std::string_view(upper).substr(i), value) > 0;
    return true;
  }
  return false;
}

/// Parses the AT2 NPTS/DT line (4th line) into @p npts and @p dt.
void parse_at2_header(const std::filesystem::path& file,
                      const std::string& line, std::size_t& npts, double& dt)
{
  const std::string expected =
      "expected line 4 as \"NPTS= 1559, DT= .02000 SEC\" or \"1559 0.0200 "
      "NPTS, DT\"";
  std::string upper = line;
  for (char& c : upper)
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (upper.find("NPTS") == std::string::npos)
    fail(file, "line 4 " + quote(trim(line)) + " has no NPTS; " + expected);

  double n = 0;
  bool npts_ok = true, dt_ok = true;
  const bool modern_npts = find_keyed_number(upper, "NPTS", n, npts_ok);
  const bool modern_dt = find_keyed_number(upper, "DT", dt, dt_ok);
  if (modern_npts || modern_dt)
  {
    if (!modern_npts)
      fail(file, "line 4 has DT= but no NPTS=; " + expected);
    if (!modern_dt)
      fail(file, "line 4 has NPTS= but no DT=; " + expected);
    if (!npts_ok)
      fail(file, "line 4: cannot read a number after NPTS=; " + expected);
    if (!dt_ok)
      fail(file, "line 4: cannot read a number after DT=; " + expected);
  }
  else
  {
    // Old form: "1559    0.0200    NPTS, DT".
    const auto tokens = split_whitespace(upper);
    if (tokens.size() < 2 || !parse_number(tokens[0], n) ||
        !parse_number(tokens[1], dt))
      fail(file, "line 4 " + quote(trim(line)) + ": cannot read NPTS and DT; " +
                     expected);
  }
  if (!(n >= 1) || n != std::floor(n) || n > 1e9)
    fail(file, "line 4: NPTS = " + fmt(n) +
                   " is invalid; expected a positive whole number");
  if (!(dt > 0))
    fail(file, "line 4: DT = " + fmt(dt) + " is invalid; expected DT > 0 s");
  npts = static_cast<std::size_t>(n);
}

/// Reads a PEER AT2 file (values in file units).
Record read_at2(const std::filesystem::path& file)
{
  const auto lines = read_lines(file);
  if (lines.size() < 4)
    fail(file, "only " + std::to_string(lines.size()) +
                   " lines; expected an AT2 file with 3 header lines, an "
                   "NPTS/DT line and values");
  Record r;
  r.description = std::string(trim(lines[0]));
  std::size_t npts = 0;
  parse_at2_header(file, lines[3], npts, r.dt);

  // NPTS is checked against the values found below: reserve no more than
  // the lines can hold.
  r.acceleration.reserve(std::min<std::size_t>(npts, 16 * lines.size()));
  std::size_t found = 0;
  for (std::size_t l = 4; l < lines.size(); ++l)
  {
    for (const auto token : split_whitespace(lines[l]))
    {
      for (const auto part : split_glued(token))
      {
        double v = 0;
        if (!parse_number(part, v))
          fail(file, "line " + std::to_string(l + 1) + ": " + quote(part) +
                         " is not a number; expected " + std::to_string(npts) +
                         " acceleration values");
        ++found;
        if (found <= npts)
          r.acceleration.push_back(v);
      }
    }
  }
  if (found != npts)
    fail(file, "found " + std::to_string(found) + " values but NPTS = " +
                   std::to_string(npts) + "; expected exactly NPTS values");
  return r;
}

/// "1 column", "3 columns", ... for error messages.
std::string count_columns(std::size_t n)
{
  return std::to_string(n) + (n == 1 ? " column" : " columns");
}

/// Reads a one- or two-column text file (values in file units).
Record read_columns(const std::filesystem::path& file, double dt_for_one_column)
{
  const auto lines = read_lines(file);
  std::size_t columns = 0;
  std::vector<double> time, value;
  std::vector<std::size_t> line_of; // 1-based line number of each sample
  for (std::size_t l = 0; l < lines.size(); ++l)
  {
    const auto content = trim(lines[l]);
    if (content.empty() || content.front() == '#' || content.front() == '%')
      continue;
    std::string text(content);
    std::replace(text.begin(), text.end(), ',', ' ');
    const auto tokens = split_whitespace(text);
    const std::string where = "line " + std::to_string(l + 1);
    if (columns == 0)
    {
      if (tokens.size() > 2)
        fail(file, where + " has " + count_columns(tokens.size()) +
                       "; expected 1 (acceleration) or 2 (time, "
                       "acceleration)");
      columns = tokens.size();
    }
    else if (tokens.size() != columns)
      fail(file, where + " has " + count_columns(tokens.size()) +
                     " but earlier lines have " + std::to_string(columns) +
                     "; expected the same number of columns on every line");
    double v[2] = {0, 0};
    for (std::size_t c = 0; c < columns; ++c)
      if (!parse_number(tokens[c], v[c]))
        fail(file, where + ": " + quote(tokens[c]) +
                       " is not a number; expected numeric columns (comment "
                       "lines start with '#' or '%')");
    if (columns == 1)
      value.push_back(v[0]);
    else
    {
      time.push_back(v[0]);
      value.push_back(v[1]);
    }
    line_of.push_back(l + 1);
  }

  Record r;
  r.description = file.filename().string();
  if (value.empty())
    fail(file, "no data; expected lines of acceleration or of time and "
               "acceleration");
  if (columns == 1)
  {
    if (!(dt_for_one_column > 0) || !std::isfinite(dt_for_one_column))
      fail(file, "one column of accelerations and no time step; expected "
                 "the case file to give dt > 0 for this record (or a "
                 "two-column time, acceleration file)");
    r.dt = dt_for_one_column;
  }
  else
  {
    const std::size_t n = time.size();
    if (n < 2)
      fail(file, "only one (time, acceleration) row; expected at least two "
                 "to determine the time step");
    const double step0 = time[1] - time[0];
    for (std::size_t k = 1; k < n; ++k)
    {
      const double step = time[k] - time[k - 1];
      const std::string where = "line " + std::to_string(line_of[k]);
      if (!(step > 0))
        fail(file, where + ": time " + fmt(time[k]) +
                       " does not increase (previous " + fmt(time[k - 1]) +
                       "); expected strictly increasing time");
      if (std::abs(step - step0) > 1e-6 * step0)
        fail(file, where + ": time step " + fmt(step) +
                       " differs from the first step " + fmt(step0) +
                       "; expected uniform sampling");
    }
    r.dt = (time[n - 1] - time[0]) / static_cast<double>(n - 1);
  }
  r.acceleration = std::move(value);
  return r;
}

/// True if @p file has the extension ".at2" in any letter case.
bool has_at2_extension(const std::filesystem::path& file)
{
  std::string ext = file.extension().string();
  for (char& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".at2";
}

} // namespace

double Record::duration() const
{
  if (acceleration.size() < 2)
    return 0.0;
  return static_cast<double>(acceleration.size() - 1) * dt;
}

double Record::peak() const
{
  double p = 0;
  for (const double a : acceleration)
    p = std::max(p, std::abs(a));
  return p;
}

Units parse_units(const std::string& name)
{
  if (name == "g")
    return Units::g;
  if (name == "m/s2" || name == "m/s^2")
    return Units::m_per_s2;
  throw std::invalid_argument("unknown acceleration units \"" + name +
                              "\"; expected \"g\" or \"m/s2\"");
}

Format parse_format(const std::string& name)
{
  if (name == "auto")
    return Format::automatic;
  if (name == "at2")
    return Format::at2;
  if (name == "columns")
    return Format::columns;
  throw std::invalid_argument("unknown record format \"" + name +
                              "\"; expected \"auto\", \"at2\" or \"columns\"");
}

Record read_record(const std::filesystem::path& file, Units units,
                   Format format, double dt_for_one_column)
{
  if (format == Format::automatic)
    format = has_at2_extension(file) ? Format::at2 : Format::columns;
  std::error_code ec; // e.g. a name too long for the file system
  if (std::filesystem::is_regular_file(file, ec))
    require_text(file);
  else if (std::filesystem::exists(file, ec) &&
           !std::filesystem::is_directory(file, ec))
    fail(file, "is not a regular file (a device or a pipe); expected a "
               "ground-motion record file");
  Record r = format == Format::at2 ? read_at2(file)
                                   : read_columns(file, dt_for_one_column);
  if (!(r.dt <= max_record_dt))
    fail(file, "sampling step " + fmt(r.dt) +
                   " s is not that of a ground-motion record; expected "
                   "0 < dt <= " +
                   fmt(max_record_dt) + " s");
  if (units == Units::g)
    for (double& a : r.acceleration)
      a *= standard_gravity;
  for (std::size_t k = 0; k < r.acceleration.size(); ++k)
  {
    if (!std::isfinite(r.acceleration[k]))
      fail(file, "value " + std::to_string(k + 1) + " overflows (" +
                     fmt(r.acceleration[k]) +
                     " m/s2 after conversion to SI); expected accelerations "
                     "of a ground motion");
  }
  return r;
}

void write_columns(const std::filesystem::path& file, const Record& r)
{
  std::ofstream out(file);
  out << "# " << r.description << "\n# time_s acceleration_m_s2\n";
  char line[64];
  for (std::size_t k = 0; k < r.acceleration.size(); ++k)
  {
    std::snprintf(line, sizeof line, "%.12g %.9g\n",
                  r.dt * static_cast<double>(k), r.acceleration[k]);
    out << line;
  }
  if (!out)
    throw std::runtime_error("cannot write " + file.string());
}

void write_at2(const std::filesystem::path& file, const Record& r)
{
  std::ofstream out(file);
  out << r.description << "\n"
      << "written by damseis (motion::write_at2)\n"
      << "ACCELERATION TIME SERIES IN UNITS OF G\n";
  char line[96];
  std::snprintf(line, sizeof line, "NPTS= %zu, DT= %.12g SEC\n",
                r.acceleration.size(), r.dt);
  out << line;
  for (std::size_t k = 0; k < r.acceleration.size(); ++k)
  {
    std::snprintf(line, sizeof line, "%15.7E",
                  r.acceleration[k] / standard_gravity);
    out << line
        << ((k + 1) % 5 == 0 || k + 1 == r.acceleration.size() ? "\n" : "");
  }
  if (!out)
    throw std::runtime_error("cannot write " + file.string());
}

std::vector<double> resample(const Record& r, double dt, double duration)
{
  if (!(dt > 0) || !std::isfinite(dt))
    throw std::invalid_argument("resample: time step dt = " + fmt(dt) +
                                " must be > 0");
  if (!(duration >= 0) || !std::isfinite(duration))
    throw std::invalid_argument("resample: duration = " + fmt(duration) +
                                " must be >= 0");
  const std::size_t m = r.acceleration.size();
  if (m > 1 && !(r.dt > 0))
    throw std::invalid_argument("resample: record time step " + fmt(r.dt) +
                                " must be > 0");

  const auto n = static_cast<std::size_t>(std::floor(duration / dt + 1e-9)) + 1;
  std::vector<double> out(n, 0.0);
  if (m == 0)
    return out;
  const auto& a = r.acceleration;
  const double last = static_cast<double>(m - 1);
  for (std::size_t k = 0; k < n; ++k)
  {
    const double t = static_cast<double>(k) * dt;
    if (m == 1)
    {
      out[k] = (k == 0) ? a[0] : 0.0;
      continue;
    }
    double s = t / r.dt; // position in record samples
    // Snap to a record sample when the grids coincide (up to rounding), so
    // that a resampling at the record's own dt returns the samples exactly.
    if (std::abs(s - std::round(s)) < 1e-9)
      s = std::round(s);
    if (s > last * (1 + 1e-12) + 1e-12)
      break; // quiet after the record
    const std::size_t i =
        std::min(static_cast<std::size_t>(std::floor(s)), m - 2);
    const double w = std::clamp(s - static_cast<double>(i), 0.0, 1.0);
    out[k] = (1 - w) * a[i] + w * a[i + 1];
  }
  return out;
}

void scale_to_peak(std::vector<double>& a, double target_peak)
{
  if (!(target_peak >= 0) || !std::isfinite(target_peak))
    throw std::invalid_argument("scale_to_peak: target peak " +
                                fmt(target_peak) + " must be >= 0");
  double peak = 0;
  for (const double v : a)
    peak = std::max(peak, std::abs(v));
  // A peak below 1e-10 m/s2 (1e-11 g) is a record of zeros and round-off:
  // scaling it would blow noise up by 1e10 or more (and a denormal peak
  // made the factor infinite, -0 x inf = NaN: found by fuzzing).
  if (!(peak > 1e-10))
    throw RecordError("cannot scale a record whose peak is " + fmt(peak) +
                      " m/s2 to peak " + fmt(target_peak) +
                      "; expected a nonzero record");
  for (double& v : a)
  {
    // Samples at the peak are set to the target exactly; the clamp keeps
    // rounding from pushing any other sample above it. (v / peak) * target
    // cannot overflow.
    const double scaled = v / peak * target_peak;
    if (std::abs(v) == peak || std::abs(scaled) > target_peak)
      v = std::copysign(target_peak, v);
    else
      v = scaled;
  }
}

void remove_baseline(std::vector<double>& a, double dt, int order)
{
  if (order < 0 || order > 2)
    throw std::invalid_argument("remove_baseline: order " +
                                std::to_string(order) + " must be 0, 1 or 2");
  if (!(dt > 0))
    throw std::invalid_argument("remove_baseline: dt = " + fmt(dt) +
                                " must be > 0");
  const std::size_t n = a.size();
  if (n == 0)
    return;
  // Polynomials in t = k*dt span the same space as polynomials in the
  // scaled time x in [-1, 1], which is better conditioned. Build an
  // orthonormal basis of {1, x, x^2} over the samples (Gram-Schmidt with
  // re-orthogonalisation) and subtract the projection of a onto it.
  std::vector<double> x(n, 0.0);
  if (n > 1)
    for (std::size_t k = 0; k < n; ++k)
      x[k] = 2.0 * static_cast<double>(k) / static_cast<double>(n - 1) - 1.0;
  const auto dot =
      [n](const std::vector<double>& u, const std::vector<double>& v)
  {
    double s = 0;
    for (std::size_t k = 0; k < n; ++k)
      s += u[k] * v[k];
    return s;
  };
  std::vector<std::vector<double>> basis;
  for (int j = 0; j <= order; ++j)
  {
    std::vector<double> v(n);
    for (std::size_t k = 0; k < n; ++k)
      v[k] = std::pow(x[k], j);
    for (int pass = 0; pass < 2; ++pass)
      for (const auto& q : basis)
      {
        const double c = dot(v, q);
        for (std::size_t k = 0; k < n; ++k)
          v[k] -= c * q[k];
      }
    const double norm = std::sqrt(dot(v, v));
    if (norm <= 1e-10 * std::sqrt(static_cast<double>(n)))
      continue; // too few samples for this degree
    for (double& vk : v)
      vk /= norm;
    basis.push_back(std::move(v));
  }
  for (const auto& q : basis)
  {
    const double c = dot(a, q);
    for (std::size_t k = 0; k < n; ++k)
      a[k] -= c * q[k];
  }
}

} // namespace damseis::motion
