/// @file record.h
/// Ground-motion records: reading (PEER AT2 and plain column files),
/// resampling onto the analysis time grid, scaling and baseline correction.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace damseis::motion
{

/// Thrown for bad record files (and for records that cannot be processed,
/// such as scaling an all-zero record). The message is one line naming the
/// file, what is wrong and what is expected.
class RecordError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/// Units of the acceleration values stored in a record file.
enum class Units
{
  g,       ///< multiples of standard gravity, g = 9.80665 m/s2
  m_per_s2 ///< metres per second squared
};

/// Layout of a record file.
enum class Format
{
  automatic, ///< ".at2" extension (any case) -> at2, otherwise columns
  at2,       ///< PEER NGA AT2 (3 header lines, NPTS/DT line, values)
  columns    ///< plain text, one (a) or two (t, a) columns
};

/// Standard gravity used to convert records given in g, m/s2.
inline constexpr double standard_gravity = 9.80665;

/// Largest sampling step of a record, s (ground motions are sampled at
/// 0.005 to 0.02 s; a larger step means a misread file or a wrong key).
inline constexpr double max_record_dt = 1.0;

/// A uniformly sampled acceleration time history; sample k is at t = k*dt.
struct Record
{
  double dt = 0;                    ///< time step, s
  std::vector<double> acceleration; ///< accelerations, m/s2
  std::string description;          ///< first header line (AT2) or file name

  /// Duration (n-1)*dt in s; 0 for an empty or one-sample record.
  double duration() const;
  /// Peak ground acceleration max|a| in m/s2; 0 for an empty record.
  double peak() const;
};

/// Parses a units name: "g", "m/s2" or "m/s^2".
/// @throws std::invalid_argument for any other string.
Units parse_units(const std::string& name);

/// Parses a format name: "auto", "at2" or "columns".
/// @throws std::invalid_argument for any other string.
Format parse_format(const std::string& name);

/// Reads a ground-motion record and converts it to m/s2.
///
/// Format::automatic picks at2 for a ".at2" extension (any case) and columns
/// otherwise.
///
/// at2 (PEER NGA): three free header lines (the first becomes the
/// description), then a line giving NPTS and DT either in the modern form
/// "NPTS=  1559, DT= .02000 SEC" (case-insensitive, comma and spaces
/// optional) or in the old form "1559    0.0200    NPTS, DT". Then exactly
/// NPTS values, any number per line, separated by whitespace; glued negative
/// numbers from Fortran fixed formats ("-0.00128-0.00133") are split at a
/// '-' that follows a digit. Fortran 'D' exponents are accepted.
///
/// columns: plain text; blank lines and lines starting with '#' or '%' are
/// skipped; values are separated by whitespace or commas. One column holds
/// accelerations sampled at @p dt_for_one_column (must then be > 0). Two
/// columns hold time and acceleration; time must be strictly increasing and
/// uniform (each step within 1e-6*dt of the first step). The first time is
/// taken as t = 0 (the record is shifted), and dt is the mean step.
///
/// @param file   record file
/// @param units  units of the values in the file
/// @param format file layout
/// @param dt_for_one_column time step (s) for one-column files; ignored
///        otherwise
/// @throws RecordError (message names @p file) if the file cannot be opened
///         or its content is malformed, its sampling step is above
///         max_record_dt, or a value overflows when converted to m/s2.
Record read_record(const std::filesystem::path& file, Units units,
                   Format format = Format::automatic,
                   double dt_for_one_column = 0.0);

/// Writes @p r as two columns "time_s acceleration_m_s2" (a '#' header
/// line with its description), 9 significant digits; read_record reads it
/// back (columns, m/s2).
void write_columns(const std::filesystem::path& file, const Record& r);

/// Writes @p r as a PEER-style AT2 file in g: three header lines (the
/// description first), "NPTS= n, DT= dt SEC", then 5 values per line
/// (%15.7E); read_record reads it back (at2, g).
void write_at2(const std::filesystem::path& file, const Record& r);

/// Linearly interpolates @p r onto the uniform grid t_k = k*dt,
/// k = 0..n-1, n = floor(duration/dt + 1e-9) + 1. Beyond the end of the
/// record the value is 0 (quiet after the record).
/// @throws std::invalid_argument if dt <= 0, duration < 0 (or not finite),
///         or the record has more than one sample and r.dt <= 0.
std::vector<double> resample(const Record& r, double dt, double duration);

/// Scales @p a so that max|a| equals @p target_peak exactly (same units as
/// @p a).
/// @throws RecordError if @p a is empty or all zero.
/// @throws std::invalid_argument if target_peak < 0 or not finite.
void scale_to_peak(std::vector<double>& a, double target_peak);

/// Baseline correction: removes from @p a (sampled at @p dt) its
/// least-squares polynomial in time of degree @p order (0: mean, 1: linear
/// trend, 2: quadratic). Records with at most @p order + 1 samples become 0.
/// @throws std::invalid_argument if order is not 0, 1 or 2 or dt <= 0.
void remove_baseline(std::vector<double>& a, double dt, int order);

} // namespace damseis::motion
