/// @file case.h
/// Case files: the TOML input of every damseis demo.
///
/// A demo declares the keys it understands in a Schema (dotted path, type,
/// default, unit, description, bounds), then loads a case file with
/// Case::load, which applies command-line overrides (`--set key=value`) and
/// validates everything. Any problem in the user's input is reported as an
/// InputError whose message is ONE line naming the file, the key and what is
/// expected; the demo's main catches it, prints it and exits with code 2.
/// Mistakes of the programmer (asking for an undeclared key, an invalid
/// schema default) throw std::logic_error instead.
///
/// Example:
/// @code
///   Schema schema;
///   schema.real("material.E", "30e9", "Pa", "Young's modulus").above(0);
///   schema.real("material.nu", "0.2", "-", "Poisson's ratio")
///       .between_exclusive(-1, 0.5);
///   schema.string("output.stress", "\"seismic\"", "-", "Stress to save",
///                 {"static", "seismic", "total"});
///   schema.integer_array("damping.modes", "[1, 3]", "-",
///                        "Modes given the target damping ratio")
///       .at_least(1);
///   Case c = Case::load(schema, "koyna.toml", {"material.E=31.027e9"});
///   double E = c.real("material.E");
/// @endcode
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace damseis::input
{

/// Invalid user input (case file, --set override, command line). The message
/// is a single line meant to be printed as is; the program then exits with
/// code 2.
class InputError : public std::runtime_error
{
public:
  /// The message is made printable_line(message).
  explicit InputError(const std::string& message);
};

/// `text` as one printable line: line breaks shown as "\n", other control
/// characters as spaces, and any word (a run without spaces, e.g. a key or
/// a path the user typed) longer than 200 characters cut to its first 120
/// and last 40 around "...(N characters)...".
std::string printable_line(std::string_view text);

/// Type of the value of a key.
enum class Type
{
  boolean,       ///< TOML boolean: true / false
  integer,       ///< TOML integer
  real,          ///< TOML float; an integer literal is accepted too
  string,        ///< TOML string; a bare word is accepted in --set
  real_array,    ///< array of numbers (integer literals accepted)
  integer_array, ///< array of integers
  string_array   ///< array of strings (e.g. names of mesh groups)
};

/// Short name of a type as shown by --help: "bool", "int", "real", "string",
/// "real[]", "int[]", "string[]".
std::string type_name(Type type);

/// One key of a case file.
struct Key
{
  /// Dotted path, e.g. "material.E" (table "material", key "E"). Every
  /// component is a TOML bare key: letters, digits, '_' and '-'.
  std::string path;
  Type type;
  /// Default as a TOML literal, e.g. "30e9", "\"plane_strain\"", "[1, 3]",
  /// "true". (A bare word is accepted for string keys, as in --set.)
  std::string default_value;
  /// Unit: "Pa", "m", "s", "g", "-" (dimensionless or not a quantity), ...
  std::string unit;
  /// One-line description shown by --help.
  std::string help;
  /// Bounds for numbers and for each element of arrays (optional).
  std::optional<double> min, max;
  /// If true the bound itself is not allowed (min < v instead of min <= v).
  bool min_exclusive = false, max_exclusive = false;
  /// Allowed values of a string key (empty: anything).
  std::vector<std::string> choices;

  /// The constraints in words, e.g. "E > 0", "-1 < nu < 0.5",
  /// "modes[i] >= 1", "one of \"a\", \"b\""; empty if there are none.
  std::string constraint_text() const;
};

/// Sets the bounds of a Key just added to a Schema; the calls chain:
/// @code schema.real("material.nu", "0.2", "-", "Poisson's ratio")
///           .between_exclusive(-1, 0.5); @endcode
/// Bounds apply to numbers and to each element of arrays; setting one on a
/// boolean or string key throws std::logic_error. A KeyBuilder refers into
/// the schema: use it right away, before adding the next key.
class KeyBuilder
{
public:
  explicit KeyBuilder(Key& key) : _key(&key) {}
  /// value > x
  KeyBuilder& above(double x);
  /// value < x
  KeyBuilder& below(double x);
  /// value >= x
  KeyBuilder& at_least(double x);
  /// value <= x
  KeyBuilder& at_most(double x);
  /// a <= value <= b
  KeyBuilder& between(double a, double b);
  /// a < value < b
  KeyBuilder& between_exclusive(double a, double b);
  /// The key being built.
  Key& key() const { return *_key; }

private:
  KeyBuilder& bound(bool lower, double x, bool exclusive);
  Key* _key;
};

/// The keys a program understands, in declaration order.
///
/// Adding a key with a malformed path, a path already declared (or one that
/// is a table of another key, e.g. "material" next to "material.E") or a
/// default that does not parse as the key's type throws std::logic_error.
/// Bounds of defaults are checked by validate() (called by Case::load).
class Schema
{
public:
  /// A real number (a TOML float; integer literals accepted).
  KeyBuilder real(const std::string& path, const std::string& default_value,
                  const std::string& unit, const std::string& help);
  /// A TOML integer.
  KeyBuilder integer(const std::string& path, const std::string& default_value,
                     const std::string& unit, const std::string& help);
  /// A TOML boolean ("true" / "false").
  KeyBuilder boolean(const std::string& path, const std::string& default_value,
                     const std::string& unit, const std::string& help);
  /// A string; if `choices` is not empty the value must be one of them.
  KeyBuilder string(const std::string& path, const std::string& default_value,
                    const std::string& unit, const std::string& help,
                    std::vector<std::string> choices = {});
  /// An array of real numbers, e.g. "[0.5, 1.0]" (bounds apply per element).
  KeyBuilder real_array(const std::string& path,
                        const std::string& default_value,
                        const std::string& unit, const std::string& help);
  /// An array of integers, e.g. "[1, 3]" (bounds apply per element).
  KeyBuilder integer_array(const std::string& path,
                           const std::string& default_value,
                           const std::string& unit, const std::string& help);

  /// An array of strings, e.g. "[\"dam\", \"rock\"]" (in --set also
  /// dam,rock).
  KeyBuilder string_array(const std::string& path,
                          const std::string& default_value,
                          const std::string& unit, const std::string& help);
  /// All keys, in declaration order.
  const std::vector<Key>& keys() const { return _keys; }
  /// The key with this dotted path, or nullptr.
  const Key* find(const std::string& path) const;
  /// Changes the default of an existing key (a demo's own default for a
  /// shared key); std::logic_error if the key does not exist.
  void set_default(const std::string& path, const std::string& value);
  /// Checks every default against its key's type, bounds and choices (and
  /// that bounds/choices suit the type); throws std::logic_error otherwise.
  void validate() const;
  /// Human-readable table of all keys (key, type, default, unit, description
  /// with constraints), grouped by TOML table; ends with a newline.
  std::string help_text() const;

private:
  KeyBuilder add(const std::string& path, Type type,
                 const std::string& default_value, const std::string& unit,
                 const std::string& help);
  std::vector<Key> _keys;
};

/// A loaded and validated case: every key of the schema with its final value
/// (file value, overridden by --set, or the default).
class Case
{
public:
  /// Reads `file` (TOML), applies `overrides` ("key=value" strings, the value
  /// parsed as a TOML value; bare words accepted for string keys; for array
  /// keys the brackets may be omitted: "damping.modes=1,3"), validates: every
  /// key known, every type right (an integer literal is accepted for a real
  /// key), finite numbers, bounds/choices respected. Missing keys take their
  /// defaults. Bounds are checked on the final values, so --set can repair a
  /// file value. Throws InputError with a single-line message, e.g.
  /// "koyna.toml: material.nu = 0.7 is out of range; expected -1 < nu < 0.5".
  /// Throws std::logic_error if the schema itself is invalid.
  static Case load(const Schema& schema, const std::filesystem::path& file,
                   const std::vector<std::string>& overrides = {});

  /// Values. Asking for an undeclared key or with the wrong type is a
  /// programming error: std::logic_error.
  bool boolean(const std::string& key) const;
  std::int64_t integer(const std::string& key) const;
  double real(const std::string& key) const;
  std::string string(const std::string& key) const;
  std::vector<double> reals(const std::string& key) const;
  std::vector<std::int64_t> integers(const std::string& key) const;
  std::vector<std::string> strings(const std::string& key) const;

  /// A string key holding a path, resolved relative to the directory of the
  /// case file (absolute paths are kept; an empty string gives an empty
  /// path, i.e. "none"). to_toml() writes the keys read this way as
  /// absolute paths.
  std::filesystem::path path(const std::string& key) const;

  /// True if the key was given in the file or by --set (not defaulted).
  bool is_set(const std::string& key) const;

  /// Number of keys the case file itself gives (0: an empty file, every
  /// value a default or an override).
  std::size_t keys_in_file() const { return _keys_in_file; }

  /// The case file, as given to load().
  const std::filesystem::path& file() const { return _file; }

  /// For cross-key checks done by the caller: throws InputError
  /// "<file>: <key>: <problem>; expected <expected>" (made one line).
  [[noreturn]] void fail(const std::string& key, const std::string& problem,
                         const std::string& expected) const;

  /// The effective case (all keys with their final values, unit and
  /// description as comments; a header names the case file and the --set
  /// overrides) as TOML text, to be saved with the results. The keys left
  /// to their defaults are written commented out,
  /// "# key = value  # [unit] help (default)", and the keys read by path()
  /// as absolute paths, so that loading it again, from anywhere, gives the
  /// same values, given and defaulted alike (a default may depend on
  /// other keys).
  std::string to_toml() const;

private:
  using Value =
      std::variant<bool, std::int64_t, double, std::string, std::vector<double>,
                   std::vector<std::int64_t>, std::vector<std::string>>;
  struct Entry
  {
    Value value;
    bool set = false;
  };
  const Entry& entry(const std::string& key, Type type) const;

  std::filesystem::path _file;
  std::vector<std::string> _overrides;
  std::size_t _keys_in_file = 0;
  std::vector<Key> _keys;
  std::map<std::string, Entry> _values;
  /// The keys read by path() (to_toml writes them absolute).
  mutable std::set<std::string> _path_keys;
};

} // namespace damseis::input
