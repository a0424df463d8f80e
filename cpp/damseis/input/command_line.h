/// @file command_line.h
/// The command line shared by every demo:
///   <demo> [--case FILE] [--out DIR] [--set key=value ...] [--help]
#pragma once

#include "case.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace damseis::input
{

/// What the command line asks for.
struct CommandLine
{
  /// --case FILE (default: the demo's default case file).
  std::filesystem::path case_file;
  /// --out DIR (default: "out/<demo>").
  std::filesystem::path out_dir;
  /// Every --set key=value, in order (passed to Case::load, which checks
  /// them; the last one of a key wins).
  std::vector<std::string> overrides;
};

/// Parses the command line of demo `demo`. `--help` (or `-h`) prints the
/// usage and schema.help_text() on standard output and returns std::nullopt
/// (the caller exits with code 0). Unknown options, missing option values or
/// stray arguments throw InputError (one line). Several values may follow
/// one --set (`--set a=1 b=2`), and --set may be repeated.
std::optional<CommandLine>
parse_command_line(int argc, char** argv, const std::string& demo,
                   const std::filesystem::path& default_case,
                   const Schema& schema);

} // namespace damseis::input
