#include "output_folder.h"
#include <algorithm>
#include <cstdlib>
#include <damseis/input/case.h>
#include <fstream>
#include <set>
#include <stdexcept>
#include <system_error>
#include <unistd.h>

namespace damseis::results
{
namespace fs = std::filesystem;

namespace
{
[[noreturn]] void fail(const fs::path& dir, const std::string& problem)
{
  throw input::InputError("--out " + dir.string() + ": " + problem +
                          "; expected a folder that exists or can be created "
                          "and written");
}

/// True if a folder can be made in `p` (a folder): a probe folder is
/// created and removed at once (access() says yes to root everywhere).
bool writable(const fs::path& p)
{
  std::string probe = (p / ".damseis_probe_XXXXXX").string();
  if (::mkdtemp(probe.data()) == nullptr)
    return false;
  ::rmdir(probe.c_str());
  return true;
}

/// Deepest level of files a run writes: OUT/model/checkpoint/file.
constexpr int max_depth = 2;

/// True if `rel` (relative to the output folder) can be a file of a run:
/// at most max_depth folders down, with an extension damseis writes.
/// Nothing else is ever listed or deleted, whatever the manifest says.
bool output_like(const fs::path& rel)
{
  if (rel.empty() || rel.is_absolute())
    return false;
  int depth = -1;
  for (const fs::path& part : rel)
  {
    if (part == ".." || part == ".")
      return false;
    ++depth;
  }
  if (depth > max_depth)
    return false;
  static const std::set<std::string> ext = {".csv", ".json", ".xdmf", ".h5",
                                            ".png", ".md",   ".toml", ".bin",
                                            ".tmp", ".msh"};
  return ext.count(rel.extension().string()) > 0;
}

/// The files of the manifest (relative paths that stay inside `dir`).
std::set<std::string> listed(const fs::path& dir)
{
  std::set<std::string> files;
  std::ifstream in(manifest_path(dir));
  std::string line;
  while (std::getline(in, line))
  {
    if (output_like(fs::path(line)))
      files.insert(line);
  }
  return files;
}
} // namespace

Overwrite parse_overwrite(const std::string& s)
{
  if (s == "clean")
    return Overwrite::clean;
  if (s == "refuse")
    return Overwrite::refuse;
  if (s == "keep")
    return Overwrite::keep;
  throw std::invalid_argument("unknown output.overwrite: " + s);
}

void add_overwrite_key(input::Schema& schema)
{
  schema.string("output.overwrite", "clean", "-",
                "an earlier run's results in the output folder: clean "
                "(delete the files that run wrote, listed in "
                ".damseis_outputs; nothing else), refuse (stop, exit 2) or "
                "keep (leave them)",
                {"clean", "refuse", "keep"});
}

void check_output_folder(const fs::path& dir)
{
  if (dir.empty())
    fail(dir, "is an empty path");
  std::error_code ec;
  const fs::path abs = fs::absolute(dir, ec);
  if (ec)
    fail(dir, "cannot be resolved (" + ec.message() + ")");
  const auto status = fs::status(abs, ec);
  if (fs::exists(status))
  {
    if (!fs::is_directory(status))
      fail(dir, "exists and is not a folder");
    if (!writable(abs))
      fail(dir, "is a folder that cannot be written");
    return;
  }
  // The nearest existing ancestor must be a writable folder.
  fs::path up = abs.parent_path();
  while (!up.empty() && !fs::exists(up, ec))
  {
    if (up == up.parent_path())
      break;
    up = up.parent_path();
  }
  if (!fs::is_directory(up, ec))
    fail(dir, "lies under " + up.string() + ", which is not a folder");
  if (!writable(up))
    fail(dir, "cannot be created: " + up.string() + " cannot be written");
}

fs::path manifest_path(const fs::path& dir)
{
  return dir / ".damseis_outputs";
}

bool holds_earlier_run(const fs::path& dir)
{
  std::error_code ec;
  return fs::exists(manifest_path(dir), ec) ||
         fs::exists(dir / "case_used.toml", ec);
}

std::string prepare_output_folder(const fs::path& dir, Overwrite policy)
{
  if (!holds_earlier_run(dir))
    return "";
  if (policy == Overwrite::refuse)
  {
    throw input::InputError(
        "--out " + dir.string() +
        ": holds the results of an earlier run (output.overwrite = "
        "\"refuse\"); expected another folder, or output.overwrite = "
        "\"clean\" to replace them");
  }
  const auto files = listed(dir);
  if (policy == Overwrite::keep)
  {
    return "output: " + dir.string() + " holds an earlier run's files (" +
           std::to_string(files.size()) +
           " listed); they stay (output.overwrite = \"keep\")";
  }
  if (!fs::exists(manifest_path(dir)))
  {
    return "warning: " + dir.string() +
           " holds results of an earlier damseis run without a list of its "
           "files (written before lists existed): files this run does not "
           "rewrite stay; use a new folder to be sure";
  }
  std::size_t removed = 0;
  std::set<fs::path> folders;
  std::error_code ec;
  for (const std::string& f : files)
  {
    const fs::path p = dir / f;
    if (fs::is_regular_file(fs::symlink_status(p, ec)) && fs::remove(p, ec))
    {
      ++removed;
      for (fs::path q = p.parent_path(); q != dir && !q.empty();
           q = q.parent_path())
        folders.insert(q);
    }
  }
  // Folders the run made and left empty (deepest first).
  std::vector<fs::path> sorted(folders.begin(), folders.end());
  std::sort(sorted.begin(), sorted.end(),
            [](const fs::path& a, const fs::path& b)
            { return a.string().size() > b.string().size(); });
  for (const fs::path& q : sorted)
  {
    if (fs::is_empty(q, ec))
      fs::remove(q, ec);
  }
  fs::remove(manifest_path(dir), ec);
  return "output: removed the " + std::to_string(removed) +
         " files of the earlier run in " + dir.string() +
         " (output.overwrite = \"clean\")";
}

std::vector<std::string> write_manifest(const fs::path& dir,
                                        fs::file_time_type start, bool restart)
{
  std::vector<std::string> older;
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    return older;
  std::set<std::string> files;
  if (restart)
    files = listed(dir);
  const std::string manifest = manifest_path(dir).filename().string();
  for (auto it = fs::recursive_directory_iterator(dir, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
  {
    if (it->is_directory(ec) && !it->is_symlink(ec) && it.depth() < max_depth)
      continue; // look inside
    if (it->is_directory(ec))
    {
      it.disable_recursion_pending();
      continue;
    }
    const fs::path relpath = fs::relative(it->path(), dir, ec);
    const std::string rel = relpath.string();
    if (!it->is_regular_file(ec) || it->is_symlink(ec) ||
        !output_like(relpath) || rel == manifest + ".tmp")
      continue;
    if (it->last_write_time(ec) >= start || files.count(rel))
      files.insert(rel);
    else
      older.push_back(rel);
  }
  const fs::path tmp = manifest_path(dir).string() + ".tmp";
  {
    std::ofstream out(tmp);
    for (const std::string& f : files)
      out << f << "\n";
  }
  fs::rename(tmp, manifest_path(dir), ec);
  std::sort(older.begin(), older.end());
  return older;
}
} // namespace damseis::results
