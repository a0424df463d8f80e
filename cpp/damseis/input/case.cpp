#include "case.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <toml++/toml.h>
#include <tuple>

static_assert(TOML_EXCEPTIONS, "damseis expects toml++ built with exceptions");

namespace damseis::input
{

namespace
{

// ---------------------------------------------------------------------------
// Text helpers
// ---------------------------------------------------------------------------

/// Makes a message a single printable line: line breaks become "\n", other
/// control characters become spaces.
std::string one_line(std::string_view text)
{
  std::string out;
  out.reserve(text.size());
  for (char c : text)
  {
    if (c == '\n')
      out += "\\n";
    else if (c == '\r')
      out += "\\r";
    else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      out += ' ';
    else
      out += c;
  }
  return out;
}

[[noreturn]] void throw_input(const std::string& message)
{
  throw InputError(message);
}

[[noreturn]] void throw_logic(const std::string& message)
{
  throw std::logic_error("damseis::input: " + one_line(message));
}

std::string trim(std::string_view text)
{
  const auto* ws = " \t\r\n";
  const auto first = text.find_first_not_of(ws);
  if (first == std::string_view::npos)
    return {};
  const auto last = text.find_last_not_of(ws);
  return std::string(text.substr(first, last - first + 1));
}

std::string lower(std::string text)
{
  for (char& c : text)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

/// Shortest text that reads back as the same double ("0.5", "3e+10", "-1").
std::string number_text(double x)
{
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, result.ptr);
}

/// A double as a TOML float literal (always has a '.' or an exponent).
std::string toml_float(double x)
{
  if (std::isnan(x))
    return "nan";
  if (std::isinf(x))
    return x > 0 ? "inf" : "-inf";
  std::string text = number_text(x);
  if (text.find_first_of(".e") == std::string::npos)
    text += ".0";
  return text;
}

/// A string as a TOML basic string literal, with escapes.
std::string quote(std::string_view text)
{
  std::string out = "\"";
  for (char c : text)
  {
    switch (c)
    {
    case '"':
      out += "\\\"";
      break;
    case '\\':
      out += "\\\\";
      break;
    case '\b':
      out += "\\b";
      break;
    case '\t':
      out += "\\t";
      break;
    case '\n':
      out += "\\n";
      break;
    case '\f':
      out += "\\f";
      break;
    case '\r':
      out += "\\r";
      break;
    default:
      if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      {
        char buffer[8];
        std::snprintf(buffer, sizeof buffer, "\\u%04X",
                      static_cast<unsigned>(static_cast<unsigned char>(c)));
        out += buffer;
      }
      else
        out += c;
    }
  }
  return out + "\"";
}

/// Last component of a dotted path ("material.E" -> "E").
std::string leaf(const std::string& path)
{
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? path : path.substr(dot + 1);
}

/// Table part of a dotted path ("material.E" -> "material", "E" -> "").
std::string table_of(const std::string& path)
{
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? std::string() : path.substr(0, dot);
}

std::size_t levenshtein(const std::string& a, const std::string& b)
{
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
  {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
    {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1,
                         diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

/// The declared key closest to `unknown` (typo, wrong case, or the right key
/// name in the wrong table), or "" if none is close enough.
std::string suggest(const std::vector<Key>& keys, const std::string& unknown)
{
  const std::string unknown_lower = lower(unknown);
  const double threshold =
      std::max(2.0, static_cast<double>(unknown.size()) / 4.0);
  double best_score = threshold + 1;
  std::string best;
  for (const Key& key : keys)
  {
    const std::size_t d = levenshtein(unknown_lower, lower(key.path));
    double score = d == 0 ? 0.5 : static_cast<double>(d);
    if (leaf(key.path) == leaf(unknown))
      score = std::min(score, 1.5);
    if (score < best_score)
    {
      best_score = score;
      best = key.path;
    }
  }
  return best_score <= threshold ? best : std::string();
}

// ---------------------------------------------------------------------------
// Values
// ---------------------------------------------------------------------------

using Value =
    std::variant<bool, std::int64_t, double, std::string, std::vector<double>,
                 std::vector<std::int64_t>, std::vector<std::string>>;

/// A value as a TOML literal.
std::string value_text(const Value& value)
{
  struct Visitor
  {
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(std::int64_t i) const { return std::to_string(i); }
    std::string operator()(double x) const { return toml_float(x); }
    std::string operator()(const std::string& s) const { return quote(s); }
    std::string operator()(const std::vector<double>& v) const
    {
      std::string out = "[";
      for (std::size_t i = 0; i < v.size(); ++i)
        out += (i ? ", " : "") + toml_float(v[i]);
      return out + "]";
    }
    std::string operator()(const std::vector<std::int64_t>& v) const
    {
      std::string out = "[";
      for (std::size_t i = 0; i < v.size(); ++i)
        out += (i ? ", " : "") + std::to_string(v[i]);
      return out + "]";
    }
    std::string operator()(const std::vector<std::string>& v) const
    {
      std::string out = "[";
      for (std::size_t i = 0; i < v.size(); ++i)
        out += (i ? ", " : "") + quote(v[i]);
      return out + "]";
    }
  };
  return std::visit(Visitor{}, value);
}

/// "a float", "an array", ...: the TOML type of a node, for messages.
std::string node_type_text(const toml::node& node)
{
  switch (node.type())
  {
  case toml::node_type::boolean:
    return "a boolean";
  case toml::node_type::integer:
    return "an integer";
  case toml::node_type::floating_point:
    return "a float";
  case toml::node_type::string:
    return "a string";
  case toml::node_type::array:
    return "an array";
  case toml::node_type::table:
    return "a table";
  case toml::node_type::date:
    return "a date";
  case toml::node_type::time:
    return "a time";
  case toml::node_type::date_time:
    return "a date-time";
  default:
    return "an unknown type";
  }
}

/// A node as short one-line TOML-like text, for messages.
std::string node_text(const toml::node& node)
{
  std::string text;
  if (const auto* b = node.as_boolean())
    text = b->get() ? "true" : "false";
  else if (const auto* i = node.as_integer())
    text = std::to_string(i->get());
  else if (const auto* x = node.as_floating_point())
    text = toml_float(x->get());
  else if (const auto* s = node.as_string())
    text = quote(s->get());
  else if (const auto* a = node.as_array())
  {
    text = "[";
    for (std::size_t k = 0; k < a->size(); ++k)
      text += (k ? ", " : "") + node_text(*a->get(k));
    text += "]";
  }
  else if (node.is_table())
    text = "{...}";
  else
  {
    std::ostringstream os;
    node.visit([&](const auto& n) { os << n; });
    text = os.str();
  }
  if (text.size() > 60)
    text = text.substr(0, 56) + " ...";
  return text;
}

/// What a key expects, in words: "a number (Pa)", "an array of integers".
std::string expected_text(const Key& key)
{
  std::string text;
  switch (key.type)
  {
  case Type::boolean:
    return "true or false";
  case Type::integer:
    text = "an integer";
    break;
  case Type::real:
    text = "a number";
    break;
  case Type::string:
    if (!key.choices.empty())
      return key.constraint_text();
    text = "a string";
    break;
  case Type::real_array:
    text = "an array of numbers, e.g. [0.5, 1.0]";
    break;
  case Type::integer_array:
    text = "an array of integers, e.g. [1, 3]";
    break;
  case Type::string_array:
    text = "an array of strings, e.g. [\"dam\", \"rock\"]";
    break;
  }
  if (!key.unit.empty() && key.unit != "-")
    text += " (" + key.unit + ")";
  return text;
}

/// The elements of a TOML array of one type (`as(element)`: the typed
/// node, or null for another type), or the problem with the first other
/// element.
template <typename T, typename As, typename Wrong>
std::variant<Value, std::string> array_of(const toml::array& a, As as,
                                          const Wrong& wrong)
{
  std::vector<T> values;
  for (const toml::node& element : a)
  {
    if (const auto* v = as(element))
      values.push_back(v->get());
    else
      return wrong("has an element that is " + node_type_text(element));
  }
  return Value(std::move(values));
}

/// Converts a TOML node to the value of `key`. On failure returns the
/// problem, e.g. "is a float; expected an integer".
std::variant<Value, std::string> convert(const Key& key, const toml::node& node)
{
  const auto wrong = [&](const std::string& what)
  { return what + "; expected " + expected_text(key); };
  const auto finite = [&](double x) -> std::optional<std::string>
  {
    if (std::isfinite(x))
      return std::nullopt;
    return "is not a finite number; expected " + expected_text(key);
  };
  switch (key.type)
  {
  case Type::boolean:
    if (const auto* b = node.as_boolean())
      return Value(b->get());
    break;
  case Type::integer:
    if (const auto* i = node.as_integer())
      return Value(i->get());
    break;
  case Type::real:
    if (const auto* i = node.as_integer())
      return Value(static_cast<double>(i->get()));
    if (const auto* x = node.as_floating_point())
    {
      if (auto problem = finite(x->get()))
        return *problem;
      return Value(x->get());
    }
    break;
  case Type::string:
    if (const auto* s = node.as_string())
      return Value(s->get());
    break;
  case Type::real_array:
    if (const auto* a = node.as_array())
    {
      std::vector<double> values;
      for (const toml::node& element : *a)
      {
        if (const auto* i = element.as_integer())
          values.push_back(static_cast<double>(i->get()));
        else if (const auto* x = element.as_floating_point())
        {
          if (auto problem = finite(x->get()))
            return "has an element that " + *problem;
          values.push_back(x->get());
        }
        else
          return wrong("has an element that is " + node_type_text(element));
      }
      return Value(std::move(values));
    }
    break;
  case Type::integer_array:
    if (const auto* a = node.as_array())
      return array_of<std::int64_t>(
          *a, [](const toml::node& e) { return e.as_integer(); }, wrong);
    break;
  case Type::string_array:
    if (const auto* a = node.as_array())
      return array_of<std::string>(
          *a, [](const toml::node& e) { return e.as_string(); }, wrong);
    break;
  }
  return wrong("is " + node_type_text(node));
}

/// Checks bounds and choices; returns the problem ("is out of range;
/// expected E > 0") or "" if the value is fine.
std::string check(const Key& key, const Value& value)
{
  const auto in_range = [&](double x)
  {
    if (key.min && (key.min_exclusive ? !(x > *key.min) : !(x >= *key.min)))
      return false;
    if (key.max && (key.max_exclusive ? !(x < *key.max) : !(x <= *key.max)))
      return false;
    return true;
  };
  const std::string out_of_range =
      "is out of range; expected " + key.constraint_text();
  if (const auto* x = std::get_if<double>(&value))
    return in_range(*x) ? "" : out_of_range;
  if (const auto* i = std::get_if<std::int64_t>(&value))
    return in_range(static_cast<double>(*i)) ? "" : out_of_range;
  if (const auto* v = std::get_if<std::vector<double>>(&value))
  {
    for (double x : *v)
      if (!in_range(x))
        return out_of_range;
  }
  if (const auto* v = std::get_if<std::vector<std::int64_t>>(&value))
  {
    for (std::int64_t i : *v)
      if (!in_range(static_cast<double>(i)))
        return out_of_range;
  }
  if (const auto* s = std::get_if<std::string>(&value))
  {
    if (!key.choices.empty() &&
        std::find(key.choices.begin(), key.choices.end(), *s) ==
            key.choices.end())
    {
      std::string problem =
          "is not an allowed value; expected " + key.constraint_text();
      // Suggest a choice differing only by case or a small typo.
      std::size_t best = 3;
      std::string closest;
      for (const auto& choice : key.choices)
      {
        const std::size_t d = levenshtein(lower(*s), lower(choice));
        if (d < best)
        {
          best = d;
          closest = choice;
        }
      }
      if (!closest.empty())
        problem += " (did you mean " + quote(closest) + "?)";
      return problem;
    }
  }
  return "";
}

/// Parses the text of a --set value (or of a schema default) for `key` into
/// a one-entry table {v = ...}; nullopt if it is not a valid TOML value.
/// Bare words are accepted for string keys and brackets may be omitted for
/// array keys.
std::optional<toml::table> parse_literal(const Key& key, const std::string& raw)
{
  std::string text = trim(raw);
  const bool is_array = key.type == Type::real_array ||
                        key.type == Type::integer_array ||
                        key.type == Type::string_array;
  if (is_array && (text.empty() || text.front() != '['))
    text = "[" + text + "]";
  std::optional<toml::table> result;
  try
  {
    toml::table table = toml::parse("v = " + text, std::string_view("--set"));
    if (table.size() == 1 && table.contains("v"))
      result = std::move(table);
  }
  catch (const toml::parse_error&)
  {
  }
  if (key.type == Type::string && (!result || !result->get("v")->is_string()))
  {
    result = toml::table{};
    result->insert("v", text);
  }
  if (key.type == Type::string_array && !result)
  {
    // Bare words: [dam, rock] or dam,rock.
    toml::array words;
    std::string inner = text.substr(1, text.size() - 2), word;
    std::stringstream in(inner);
    while (std::getline(in, word, ','))
    {
      if (!trim(word).empty())
        words.push_back(trim(word));
    }
    result = toml::table{};
    result->insert("v", std::move(words));
  }
  return result;
}

bool is_bare_key(const std::string& component)
{
  return !component.empty() &&
         std::all_of(component.begin(), component.end(),
                     [](char c)
                     {
                       return std::isalnum(static_cast<unsigned char>(c)) ||
                              c == '_' || c == '-';
                     });
}

/// The default of a key as a value; std::logic_error if it is invalid.
Value default_of(const Key& key)
{
  const std::string subject =
      "schema default of " + key.path + " = " + key.default_value;
  auto table = parse_literal(key, key.default_value);
  if (!table)
    throw_logic(subject + " is not a valid TOML value; expected " +
                expected_text(key));
  auto converted = convert(key, *table->get("v"));
  if (const auto* problem = std::get_if<std::string>(&converted))
    throw_logic(subject + " " + *problem);
  return std::get<Value>(converted);
}

} // namespace

// ---------------------------------------------------------------------------
// Type, Key, KeyBuilder
// ---------------------------------------------------------------------------

std::string type_name(Type type)
{
  switch (type)
  {
  case Type::boolean:
    return "bool";
  case Type::integer:
    return "int";
  case Type::real:
    return "real";
  case Type::string:
    return "string";
  case Type::real_array:
    return "real[]";
  case Type::integer_array:
    return "int[]";
  case Type::string_array:
    return "string[]";
  }
  return "?";
}

std::string Key::constraint_text() const
{
  if (!choices.empty())
  {
    std::string text = "one of ";
    for (std::size_t i = 0; i < choices.size(); ++i)
      text += (i ? ", " : "") + quote(choices[i]);
    return text;
  }
  std::string name = leaf(path);
  if (type == Type::real_array || type == Type::integer_array)
    name += "[i]";
  const std::string lo = min_exclusive ? " < " : " <= ";
  const std::string hi = max_exclusive ? " < " : " <= ";
  if (min && max)
    return number_text(*min) + lo + name + hi + number_text(*max);
  if (min)
    return name + (min_exclusive ? " > " : " >= ") + number_text(*min);
  if (max)
    return name + hi + number_text(*max);
  return "";
}

KeyBuilder& KeyBuilder::bound(bool lower_bound, double x, bool exclusive)
{
  if (_key->type == Type::boolean || _key->type == Type::string ||
      _key->type == Type::string_array)
    throw_logic("bounds set on " + type_name(_key->type) + " key " +
                _key->path);
  if (!std::isfinite(x))
    throw_logic("non-finite bound set on key " + _key->path);
  if (lower_bound)
  {
    _key->min = x;
    _key->min_exclusive = exclusive;
  }
  else
  {
    _key->max = x;
    _key->max_exclusive = exclusive;
  }
  return *this;
}

KeyBuilder& KeyBuilder::above(double x)
{
  return bound(true, x, true);
}
KeyBuilder& KeyBuilder::below(double x)
{
  return bound(false, x, true);
}
KeyBuilder& KeyBuilder::at_least(double x)
{
  return bound(true, x, false);
}
KeyBuilder& KeyBuilder::at_most(double x)
{
  return bound(false, x, false);
}

KeyBuilder& KeyBuilder::between(double a, double b)
{
  bound(true, a, false);
  return bound(false, b, false);
}

KeyBuilder& KeyBuilder::between_exclusive(double a, double b)
{
  bound(true, a, true);
  return bound(false, b, true);
}

// ---------------------------------------------------------------------------
// Schema
// ---------------------------------------------------------------------------

KeyBuilder Schema::add(const std::string& path, Type type,
                       const std::string& default_value,
                       const std::string& unit, const std::string& help)
{
  std::size_t start = 0;
  while (true)
  {
    const auto dot = path.find('.', start);
    if (!is_bare_key(path.substr(start, dot - start)))
      throw_logic("invalid key path \"" + path +
                  "\"; expected dot-separated names of letters, digits, "
                  "'_' and '-'");
    if (dot == std::string::npos)
      break;
    start = dot + 1;
  }
  for (const Key& key : _keys)
  {
    if (key.path == path)
      throw_logic("key " + path + " declared twice");
    if (key.path.starts_with(path + ".") || path.starts_with(key.path + "."))
      throw_logic("key " + path + " conflicts with key " + key.path +
                  " (a key cannot also be a table)");
  }
  Key key;
  key.path = path;
  key.type = type;
  key.default_value = default_value;
  key.unit = unit;
  key.help = help;
  default_of(key); // throws std::logic_error if the default does not parse
  _keys.push_back(std::move(key));
  return KeyBuilder(_keys.back());
}

KeyBuilder Schema::real(const std::string& path,
                        const std::string& default_value,
                        const std::string& unit, const std::string& help)
{
  return add(path, Type::real, default_value, unit, help);
}

KeyBuilder Schema::integer(const std::string& path,
                           const std::string& default_value,
                           const std::string& unit, const std::string& help)
{
  return add(path, Type::integer, default_value, unit, help);
}

KeyBuilder Schema::boolean(const std::string& path,
                           const std::string& default_value,
                           const std::string& unit, const std::string& help)
{
  return add(path, Type::boolean, default_value, unit, help);
}

KeyBuilder Schema::string(const std::string& path,
                          const std::string& default_value,
                          const std::string& unit, const std::string& help,
                          std::vector<std::string> choices)
{
  KeyBuilder builder = add(path, Type::string, default_value, unit, help);
  builder.key().choices = std::move(choices);
  return builder;
}

KeyBuilder Schema::real_array(const std::string& path,
                              const std::string& default_value,
                              const std::string& unit, const std::string& help)
{
  return add(path, Type::real_array, default_value, unit, help);
}

KeyBuilder Schema::string_array(const std::string& path,
                                const std::string& default_value,
                                const std::string& unit,
                                const std::string& help)
{
  return add(path, Type::string_array, default_value, unit, help);
}

KeyBuilder Schema::integer_array(const std::string& path,
                                 const std::string& default_value,
                                 const std::string& unit,
                                 const std::string& help)
{
  return add(path, Type::integer_array, default_value, unit, help);
}

const Key* Schema::find(const std::string& path) const
{
  for (const Key& key : _keys)
    if (key.path == path)
      return &key;
  return nullptr;
}

void Schema::set_default(const std::string& path, const std::string& value)
{
  for (Key& key : _keys)
  {
    if (key.path == path)
    {
      key.default_value = value;
      return;
    }
  }
  throw std::logic_error("set_default: unknown key " + path);
}

void Schema::validate() const
{
  for (const Key& key : _keys)
  {
    const bool numeric = key.type != Type::boolean &&
                         key.type != Type::string &&
                         key.type != Type::string_array;
    if (!numeric && (key.min || key.max))
      throw_logic("bounds set on " + type_name(key.type) + " key " + key.path);
    if (key.type != Type::string && !key.choices.empty())
      throw_logic("choices set on " + type_name(key.type) + " key " + key.path);
    if (key.min && key.max && *key.min > *key.max)
      throw_logic("empty range for key " + key.path + ": " +
                  key.constraint_text());
    const Value value = default_of(key);
    const std::string problem = check(key, value);
    if (!problem.empty())
      throw_logic("schema default of " + key.path + " = " + value_text(value) +
                  " " + problem);
  }
}

std::string Schema::help_text() const
{
  struct Row
  {
    std::string key, type, value, unit, help;
  };
  std::vector<std::string> tables;
  for (const Key& key : _keys)
    if (std::find(tables.begin(), tables.end(), table_of(key.path)) ==
        tables.end())
      tables.push_back(table_of(key.path));
  std::stable_partition(tables.begin(), tables.end(),
                        [](const std::string& t) { return t.empty(); });

  std::vector<Row> rows;
  rows.push_back({"KEY", "TYPE", "DEFAULT", "UNIT", "DESCRIPTION"});
  for (const Key& key : _keys)
  {
    std::string value;
    try
    {
      value = value_text(default_of(key));
    }
    catch (const std::logic_error&)
    {
      value = key.default_value;
    }
    std::string help = one_line(key.help);
    const std::string constraint = key.constraint_text();
    if (!constraint.empty())
      help += " [" + constraint + "]";
    rows.push_back({key.path, type_name(key.type), value,
                    key.unit.empty() ? "-" : key.unit, help});
  }
  std::size_t w[4] = {0, 0, 0, 0};
  for (const Row& row : rows)
  {
    w[0] = std::max(w[0], row.key.size());
    w[1] = std::max(w[1], row.type.size());
    w[2] = std::max(w[2], row.value.size());
    w[3] = std::max(w[3], row.unit.size());
  }
  const auto line = [&](const Row& row)
  {
    std::string text = "  ";
    text += row.key + std::string(w[0] + 2 - row.key.size(), ' ');
    text += row.type + std::string(w[1] + 2 - row.type.size(), ' ');
    text += row.value + std::string(w[2] + 2 - row.value.size(), ' ');
    text += row.unit + std::string(w[3] + 2 - row.unit.size(), ' ');
    return text + row.help + "\n";
  };

  std::string text = "Case file keys (TOML; override any with --set "
                     "key=value, e.g. --set material.E=31e9):\n\n";
  text += line(rows[0]);
  for (const std::string& table : tables)
  {
    text += table.empty() ? "(top level)\n" : "[" + table + "]\n";
    for (std::size_t i = 0; i < _keys.size(); ++i)
      if (table_of(_keys[i].path) == table)
        text += line(rows[i + 1]);
  }
  return text;
}

// ---------------------------------------------------------------------------
// Case
// ---------------------------------------------------------------------------

namespace
{

/// A value given in the file or by --set, with the words naming it in
/// messages ("material.nu = 0.7" or "--set material.nu=0.7").
struct Given
{
  Value value;
  std::string subject;
};

/// Visits the leaves of a TOML table in file order, calling
/// `leaf_fn(path, node)` for every node that is a declared key or is not a
/// table leading to declared keys.
template <typename F>
void walk(const toml::table& table, const std::string& prefix,
          const Schema& schema, F&& leaf_fn)
{
  std::vector<std::pair<std::string, const toml::node*>> entries;
  for (auto&& [name, node] : table)
    entries.emplace_back(std::string(name.str()), &node);
  std::stable_sort(entries.begin(), entries.end(),
                   [](const auto& a, const auto& b)
                   {
                     const auto& sa = a.second->source().begin;
                     const auto& sb = b.second->source().begin;
                     return std::tie(sa.line, sa.column) <
                            std::tie(sb.line, sb.column);
                   });
  for (const auto& [name, node] : entries)
  {
    const std::string path = prefix.empty() ? name : prefix + "." + name;
    const auto* sub = node->as_table();
    if (sub && !schema.find(path) && !sub->empty())
      walk(*sub, path, schema, leaf_fn);
    else
      leaf_fn(path, *node);
  }
}

bool is_table_of_keys(const Schema& schema, const std::string& path)
{
  return std::any_of(schema.keys().begin(), schema.keys().end(),
                     [&](const Key& key)
                     { return key.path.starts_with(path + "."); });
}

[[noreturn]] void unknown_key(const std::string& where, const Schema& schema,
                              const std::string& path)
{
  const std::string suggestion = suggest(schema.keys(), path);
  if (suggestion.empty())
    throw_input(where + "unknown key " + path +
                "; expected one of the keys listed by --help");
  throw_input(where + "unknown key " + path + "; did you mean " + suggestion +
              "?");
}

} // namespace

std::string printable_line(std::string_view text)
{
  constexpr std::size_t longest = 200, head = 120, tail = 40;
  const std::string line = one_line(text);
  std::string out;
  std::size_t start = 0;
  while (start < line.size())
  {
    const auto space = line.find(' ', start);
    const auto end = space == std::string::npos ? line.size() : space;
    const std::string_view word(line.data() + start, end - start);
    if (word.size() > longest)
    {
      // Cut between UTF-8 characters, not inside one.
      auto continuation = [&](std::size_t i)
      { return (static_cast<unsigned char>(word[i]) & 0xc0) == 0x80; };
      std::size_t a = head, b = word.size() - tail;
      while (a > 0 && continuation(a))
        --a;
      while (b < word.size() && continuation(b))
        ++b;
      out.append(word.substr(0, a));
      out += "...(" + std::to_string(word.size()) + " characters)...";
      out.append(word.substr(b));
    }
    else
      out.append(word);
    if (end < line.size())
      out += ' ';
    start = end + 1;
  }
  return out;
}

InputError::InputError(const std::string& message)
    : std::runtime_error(printable_line(message))
{
}

Case Case::load(const Schema& schema, const std::filesystem::path& file,
                const std::vector<std::string>& overrides)
{
  schema.validate();
  const std::string name = file.string();

  // Read and parse the file.
  std::error_code ec;
  if (!std::filesystem::exists(file, ec))
    throw_input(name + ": case file not found; expected an existing TOML "
                       "file (--case FILE)");
  if (std::filesystem::is_directory(file, ec))
    throw_input(name + ": is a directory; expected a TOML case file");
  std::ifstream in(file, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  if (!in)
    throw_input(name + ": cannot read the case file; expected a readable "
                       "TOML file");
  // Keys nested far deeper than any damseis key (at most 3 levels) would
  // make the parser (and the document's destructor) recurse until the
  // stack overflows: refuse them before parsing.
  {
    std::istringstream lines(content.str());
    std::string line;
    int number = 0;
    while (std::getline(lines, line))
    {
      ++number;
      const auto start = line.find_first_not_of(" \t");
      if (start == std::string::npos || line[start] == '#')
        continue;
      const auto end =
          line[start] == '[' ? line.find(']', start) : line.find('=', start);
      const auto key = line.substr(
          start, end == std::string::npos ? std::string::npos : end - start);
      const auto depth = std::count(key.begin(), key.end(), '.');
      if (depth > 32)
        throw_input(name + ":" + std::to_string(number) + ": a key nested " +
                    std::to_string(depth + 1) +
                    " levels deep; expected damseis keys such as "
                    "material.E (see --help)");
    }
  }
  toml::table document;
  try
  {
    document = toml::parse(content.str(), std::string_view(name));
  }
  catch (const toml::parse_error& e)
  {
    const auto& at = e.source().begin;
    throw_input(name + ":" + std::to_string(at.line) + ":" +
                std::to_string(at.column) +
                ": malformed TOML: " + std::string(e.description()));
  }

  // Values given in the file.
  std::map<std::string, Given> given;
  const std::string where = name + ": ";
  walk(document, "", schema,
       [&](const std::string& path, const toml::node& node)
       {
         const Key* key = schema.find(path);
         if (!key)
         {
           if (is_table_of_keys(schema, path))
           {
             if (node.is_table())
               return; // an empty table of known keys, e.g. "[output]"
             throw_input(where + path + " = " + node_text(node) + " is " +
                         node_type_text(node) + "; expected a table [" + path +
                         "] of keys");
           }
           unknown_key(where, schema, path);
         }
         std::string subject = path;
         if (!node.is_table() && !node.is_array_of_tables())
           subject += " = " + node_text(node);
         auto converted = convert(*key, node);
         if (const auto* problem = std::get_if<std::string>(&converted))
           throw_input(where + subject + " " + *problem);
         given[path] = {std::get<Value>(std::move(converted)), subject};
       });

  const std::size_t keys_in_file = given.size();

  // Overrides, in order (the last one wins).
  for (const std::string& override_text : overrides)
  {
    const std::string subject = "--set " + override_text;
    const auto eq = override_text.find('=');
    if (eq == std::string::npos)
      throw_input(where + subject + " has no '='; expected --set key=value");
    const std::string path = trim(override_text.substr(0, eq));
    if (path.empty())
      throw_input(where + subject + " has no key; expected --set key=value");
    const Key* key = schema.find(path);
    if (!key)
      unknown_key(where + subject + ": ", schema, path);
    const auto table = parse_literal(*key, override_text.substr(eq + 1));
    if (!table)
      throw_input(where + subject + " is not a valid TOML value; expected " +
                  expected_text(*key));
    auto converted = convert(*key, *table->get("v"));
    if (const auto* problem = std::get_if<std::string>(&converted))
      throw_input(where + subject + " " + *problem);
    given[path] = {std::get<Value>(std::move(converted)), subject};
  }

  // Final values: bounds and choices.
  Case result;
  result._file = file;
  result._overrides = overrides;
  result._keys = schema.keys();
  result._keys_in_file = keys_in_file;
  for (const Key& key : schema.keys())
  {
    const auto it = given.find(key.path);
    if (it == given.end())
    {
      result._values[key.path] = {default_of(key), false};
      continue;
    }
    const std::string problem = check(key, it->second.value);
    if (!problem.empty())
      throw_input(where + it->second.subject + " " + problem);
    result._values[key.path] = {std::move(it->second.value), true};
  }
  return result;
}

const Case::Entry& Case::entry(const std::string& key, Type type) const
{
  const auto it = _values.find(key);
  if (it == _values.end())
    throw_logic("Case: key " + key + " is not in the schema");
  const auto actual = static_cast<Type>(it->second.value.index());
  if (actual != type)
    throw_logic("Case: key " + key + " is a " + type_name(actual) +
                ", asked for as a " + type_name(type));
  return it->second;
}

bool Case::boolean(const std::string& key) const
{
  return std::get<bool>(entry(key, Type::boolean).value);
}

std::int64_t Case::integer(const std::string& key) const
{
  return std::get<std::int64_t>(entry(key, Type::integer).value);
}

double Case::real(const std::string& key) const
{
  return std::get<double>(entry(key, Type::real).value);
}

std::string Case::string(const std::string& key) const
{
  return std::get<std::string>(entry(key, Type::string).value);
}

std::vector<double> Case::reals(const std::string& key) const
{
  return std::get<std::vector<double>>(entry(key, Type::real_array).value);
}

std::vector<std::int64_t> Case::integers(const std::string& key) const
{
  return std::get<std::vector<std::int64_t>>(
      entry(key, Type::integer_array).value);
}

std::vector<std::string> Case::strings(const std::string& key) const
{
  return std::get<std::vector<std::string>>(
      entry(key, Type::string_array).value);
}

std::filesystem::path Case::path(const std::string& key) const
{
  const std::filesystem::path p(string(key));
  if (!p.empty())
    _path_keys.insert(key);
  if (p.empty() || p.is_absolute())
    return p;
  return (_file.parent_path() / p).lexically_normal();
}

bool Case::is_set(const std::string& key) const
{
  const auto it = _values.find(key);
  if (it == _values.end())
    throw_logic("Case: key " + key + " is not in the schema");
  return it->second.set;
}

void Case::fail(const std::string& key, const std::string& problem,
                const std::string& expected) const
{
  throw_input(_file.string() + ": " + key + ": " + problem + "; expected " +
              expected);
}

std::string Case::to_toml() const
{
  std::vector<std::string> tables;
  for (const Key& key : _keys)
    if (std::find(tables.begin(), tables.end(), table_of(key.path)) ==
        tables.end())
      tables.push_back(table_of(key.path));
  // Top-level keys must come before the first [table] header.
  std::stable_partition(tables.begin(), tables.end(),
                        [](const std::string& t) { return t.empty(); });

  std::string text =
      "# Effective damseis case: every key with its final value (file, --set "
      "or default;\n# the defaults commented out, paths made absolute).\n"
      "# Read from " +
      one_line(_file.string()) + "\n";
  for (const std::string& override_text : _overrides)
    text += "# --set " + one_line(override_text) + "\n";
  for (const std::string& table : tables)
  {
    text += table.empty() ? "\n" : "\n[" + table + "]\n";
    for (const Key& key : _keys)
    {
      if (table_of(key.path) != table)
        continue;
      const Entry& e = _values.at(key.path);
      const std::string value =
          _path_keys.count(key.path)
              ? value_text(std::filesystem::absolute(path(key.path))
                               .lexically_normal()
                               .string())
              : value_text(e.value);
      text += (e.set ? "" : "# ") + leaf(key.path) + " = " + value + "  # [" +
              (key.unit.empty() ? "-" : key.unit) + "] " + one_line(key.help) +
              (e.set ? "" : " (default)") + "\n";
    }
  }
  return text;
}

} // namespace damseis::input
