#include "mesh_file.h"
#include "gmsh_session.h"
#include "root_status.h"
#include <gmsh.h>
#include <sstream>
#include <stdexcept>

namespace damseis::geometry
{
namespace
{
/// The groups, one per line ("dim tag name"), as rank 0 sends them.
std::string group_lines(const std::map<std::string, PhysicalGroup>& groups)
{
  std::ostringstream out;
  for (const auto& [name, g] : groups)
    out << g.dim << ' ' << g.tag << ' ' << name << '\n';
  return out.str();
}

std::map<std::string, PhysicalGroup> parse_group_lines(const std::string& text)
{
  std::map<std::string, PhysicalGroup> groups;
  std::istringstream in(text);
  PhysicalGroup g;
  std::string name;
  // "dim tag name": one space before the name, which is kept as it is.
  while (in >> g.dim >> g.tag && in.get() == ' ' && std::getline(in, name))
    groups[name] = g;
  return groups;
}

/// Rank 0: opens the file in gmsh and lists its physical groups.
std::map<std::string, PhysicalGroup>
open_file(const std::filesystem::path& file)
{
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw std::runtime_error(file.string() + ": no such mesh file");
  try
  {
    gmsh::open(file.string());
  }
  catch (const std::exception& e)
  {
    throw std::runtime_error(file.string() + ": gmsh cannot read it (" +
                             e.what() + ")");
  }
  catch (...)
  {
    throw std::runtime_error(file.string() + ": gmsh cannot read it");
  }
  gmsh::vectorpair tags;
  gmsh::model::getPhysicalGroups(tags);
  std::map<std::string, PhysicalGroup> groups;
  for (const auto& [dim, tag] : tags)
  {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    if (name.empty())
      name = std::to_string(dim) + ":" + std::to_string(tag);
    if (groups.count(name))
      throw std::runtime_error(file.string() +
                               ": two physical groups named \"" + name + "\"");
    groups[name] = {dim, tag};
  }
  return groups;
}

} // namespace

MeshFile read_mesh_file(MPI_Comm comm, const std::filesystem::path& file)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  MeshFile out;
  // gmsh lives on rank 0 from opening the file to the end of the
  // distribution (model_from_gmsh reads the open model there).
  std::unique_ptr<GmshSession> session;
  std::string groups;
  on_root(comm,
          [&]
          {
            session = std::make_unique<GmshSession>(false);
            out.groups = open_file(file);
            for (const auto& [name, g] : out.groups)
              out.tdim = std::max(out.tdim, g.dim);
            if (out.tdim < 2)
              throw std::runtime_error(
                  file.string() +
                  ": no physical group of dimension 2 or 3 (the cells of the "
                  "model are those of physical groups)");
            groups = group_lines(out.groups);
          },
          {"", file.string() + ": gmsh failed while reading it"});
  groups = broadcast_from_root(comm, groups);
  MPI_Bcast(&out.tdim, 1, MPI_INT, 0, comm);
  // Every rank (rank 0 too) holds the groups parsed from the same text.
  out.groups = parse_group_lines(groups);
  out.model = model_from_gmsh(comm, out.tdim);
  return out;
}
} // namespace damseis::geometry
