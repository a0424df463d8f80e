#include "command_line.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <memory>

namespace damseis::input
{

namespace
{

/// Help layout: the usage line first, then what the program does.
class Formatter : public CLI::Formatter
{
public:
  std::string make_description(const CLI::App*) const override { return ""; }
  std::string make_usage(const CLI::App* app, std::string name) const override
  {
    return "Usage: " + name +
           " [--case FILE] [--out DIR] [--set KEY=VALUE ...]\n\n" +
           app->get_description() + "\n";
  }
};

/// "--set a=1, --set b=x": a real key, a key with choices and an array key
/// of this schema (the first of each), with values of their kind.
std::string set_examples(const Schema& schema)
{
  std::vector<std::string> ex;
  auto first = [&](auto pred) -> const Key*
  {
    for (const Key& k : schema.keys())
    {
      if (pred(k))
        return &k;
    }
    return nullptr;
  };
  if (const Key* k = first([](const Key& k) { return k.type == Type::real; }))
    ex.push_back(k->path + "=" + k->default_value);
  if (const Key* k = first([](const Key& k) { return k.choices.size() >= 2; }))
    ex.push_back(k->path + "=" + k->choices[1]);
  if (const Key* k = first(
          [](const Key& k)
          {
            return (k.type == Type::real_array ||
                    k.type == Type::integer_array) &&
                   k.default_value != "[]";
          }))
  {
    std::string v = k->default_value;
    v.erase(std::remove(v.begin(), v.end(), ' '), v.end());
    ex.push_back(k->path + "=" + v);
  }
  std::string text;
  for (std::size_t i = 0; i < ex.size(); ++i)
    text += (i ? ", --set " : "--set ") + ex[i];
  return text;
}
} // namespace

std::optional<CommandLine>
parse_command_line(int argc, char** argv, const std::string& demo,
                   const std::filesystem::path& default_case,
                   const Schema& schema)
{
  std::string case_file = default_case.string();
  std::string out_dir = (std::filesystem::path("out") / demo).string();
  std::vector<std::string> overrides;

  CLI::App app("Runs the case file FILE (TOML; keys below; any key can be "
               "overridden with --set) and writes the results to DIR.",
               demo);
  app.formatter(std::make_shared<Formatter>());
  app.set_help_flag("-h,--help", "Print this help (options and case keys)");
  app.add_option("--case", case_file, "Case file (TOML)")
      ->type_name("FILE")
      ->capture_default_str();
  app.add_option("--out", out_dir, "Output directory")
      ->type_name("DIR")
      ->capture_default_str();
  app.add_option("--set", overrides,
                 "Override a case key, e.g. " + set_examples(schema) +
                     " (repeatable)")
      ->type_name("KEY=VALUE");

  try
  {
    app.parse(argc, argv);
  }
  catch (const CLI::CallForHelp&)
  {
    std::cout << app.help() << "\n" << schema.help_text() << std::flush;
    return std::nullopt;
  }
  catch (const CLI::ParseError& e)
  {
    std::string message = demo + ": " + e.what() + "; run '" + demo +
                          " --help' for the options and case keys";
    for (char& c : message)
      if (c == '\n' || c == '\r')
        c = ' ';
    throw InputError(message);
  }
  return CommandLine{case_file, out_dir, overrides};
}

} // namespace damseis::input
