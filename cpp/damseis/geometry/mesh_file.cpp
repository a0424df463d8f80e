#include "mesh_file.h"
#include "gmsh_session.h"
#include "root_status.h"
#include <algorithm>
#include <damseis/linalg/all_gather.h>
#include <dolfinx/fem/CoordinateElement.h>
#include <dolfinx/io/XDMFFile.h>
#include <dolfinx/mesh/Mesh.h>
#include <dolfinx/mesh/MeshTags.h>
#include <gmsh.h>
#include <numeric>
#include <set>
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

namespace
{
/// The groups of a tag array: one per value found on any rank.
void add_groups(MPI_Comm comm, const dolfinx::mesh::MeshTags<std::int32_t>& t,
                std::map<std::string, PhysicalGroup>& groups)
{
  std::set<std::int32_t> local(t.values().begin(), t.values().end());
  const std::vector<std::int32_t> all = linalg::all_gather(
      comm, std::vector<std::int32_t>(local.begin(), local.end()));
  for (std::int32_t v : all)
    groups[std::to_string(t.dim()) + ":" + std::to_string(v)] = {t.dim(), v};
}

/// An XDMF mesh with its tags, read in parallel.
MeshFile read_xdmf(MPI_Comm comm, const std::filesystem::path& file,
                   const XdmfGrids& grids)
{
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw std::runtime_error(file.string() + ": no such mesh file");
  MeshFile out;
  std::string problem;
  try
  {
    dolfinx::io::XDMFFile xdmf(comm, file, "r");
    const auto [type, degree] = xdmf.read_cell_type(grids.mesh);
    if (degree != 1 || (type != dolfinx::mesh::CellType::triangle &&
                        type != dolfinx::mesh::CellType::tetrahedron))
      throw std::runtime_error("the mesh is not of linear triangles or "
                               "tetrahedra");
    const dolfinx::fem::CoordinateElement element(type, 1);
    auto mesh = std::make_shared<dolfinx::mesh::Mesh>(xdmf.read_mesh(
        element, dolfinx::mesh::GhostMode::shared_facet, grids.mesh));
    out.tdim = mesh->topology().dim();
    if (mesh->geometry().dim() != out.tdim)
      throw std::runtime_error(
          "a mesh of triangles needs 2 coordinates per node (z = 0 dropped)");
    mesh->topology_mutable().create_entities(out.tdim - 1);
    mesh->topology_mutable().create_connectivity(out.tdim - 1, out.tdim);
    out.model.mesh = mesh;
    out.model.cell_tags =
        std::make_shared<dolfinx::mesh::MeshTags<std::int32_t>>(
            xdmf.read_meshtags(mesh, grids.cell_tags));
    out.model.facet_tags =
        std::make_shared<dolfinx::mesh::MeshTags<std::int32_t>>(
            xdmf.read_meshtags(mesh, grids.facet_tags));
    if (out.model.cell_tags->dim() != out.tdim ||
        out.model.facet_tags->dim() != out.tdim - 1)
      throw std::runtime_error("the grids \"" + grids.cell_tags + "\" and \"" +
                               grids.facet_tags +
                               "\" must tag cells and facets");
  }
  catch (const std::exception& e)
  {
    problem = e.what();
  }
  // The same outcome on every rank.
  int ok = problem.empty() ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &ok, 1, MPI_INT, MPI_MIN, comm);
  if (!ok)
    throw std::runtime_error(
        file.string() + ": cannot read it as an XDMF mesh with grids \"" +
        grids.mesh + "\", \"" + grids.cell_tags + "\", \"" + grids.facet_tags +
        "\"" +
        (problem.empty() ? std::string()
                         : " (" + problem.substr(0, 160) + ")"));
  add_groups(comm, *out.model.cell_tags, out.groups);
  add_groups(comm, *out.model.facet_tags, out.groups);
  return out;
}
} // namespace

MeshFile read_mesh_file(MPI_Comm comm, const std::filesystem::path& file,
                        const XdmfGrids& grids)
{
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (ext == ".xdmf")
    return read_xdmf(comm, file, grids);
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
