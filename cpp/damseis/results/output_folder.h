// The output folder of a run: checked before any work, cleared of an
// earlier run's files, and listed at the end.
//
// Every run ends by writing OUT/.damseis_outputs, the files it wrote
// (relative paths). A new run in the same folder (not a restart) reads that
// list first and, by `output.overwrite`:
//  - "clean" (default): deletes exactly those files (and folders they leave
//    empty), so no stale result (dam_points.csv of an earlier nonlinear
//    run, a plot titled with another model) sits beside new ones; files of
//    the user's own are never touched;
//  - "refuse": stops with exit code 2 if the folder holds an earlier run;
//  - "keep": leaves them, and the end of the run names the files it did not
//    write.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace damseis::input
{
class Schema;
}

namespace damseis::results
{
/// What a new run does with an earlier run's files in its folder.
enum class Overwrite
{
  clean,
  refuse,
  keep
};
/// "clean", "refuse" or "keep" (std::invalid_argument otherwise).
Overwrite parse_overwrite(const std::string& s);

/// Declares the case key output.overwrite (every demo has it).
void add_overwrite_key(input::Schema& schema);

/// Throws input::InputError (one line, naming `--out`) if `dir` cannot be a
/// run's output folder: an empty path, an existing file (or device), a path
/// under a file, or a place that cannot be written. Creates nothing.
void check_output_folder(const std::filesystem::path& dir);

/// The manifest of a run's files in `dir`.
std::filesystem::path manifest_path(const std::filesystem::path& dir);

/// True if `dir` holds the results of an earlier damseis run (a manifest,
/// or a case_used.toml written before manifests existed).
bool holds_earlier_run(const std::filesystem::path& dir);

/// Before a new (not restarted) run, on rank 0: applies `policy` to an
/// earlier run's files in `dir` (see above) and returns a line for the log
/// (empty if there was nothing to do). Throws input::InputError for
/// "refuse".
std::string prepare_output_folder(const std::filesystem::path& dir,
                                  Overwrite policy);

/// After a run, on rank 0: lists in the manifest every file under `dir`
/// that looks like an output (an extension damseis writes: csv, json,
/// xdmf, h5, png, md, toml, bin; at most two folders down) and was modified
/// since `start` (the files of this run; after a restart the files of the
/// earlier part are kept in the list); returns the output-like files that
/// are older (not written by this run), relative to `dir`. Only such files
/// are ever listed or deleted.
std::vector<std::string> write_manifest(const std::filesystem::path& dir,
                                        std::filesystem::file_time_type start,
                                        bool restart);
} // namespace damseis::results
