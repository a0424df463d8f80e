// Models from the user's mesh files (geometry/mesh_file): a gmsh file
// written here with named physical groups is read back on every rank
// count with its cells, groups and tags; the area of a polygon and the
// length of a tagged edge are exact for straight-sided triangles. Bad
// files give one error, the same on every rank.
#include "fem_test_support.h"
#include <cmath>
#include <damseis/fem/elastic_model.h>
#include <damseis/geometry/gmsh_session.h>
#include <damseis/geometry/gravity_dam.h>
#include <damseis/geometry/mesh_file.h>
#include <damseis/geometry/tags.h>
#include <damseis/linalg/modal.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/io/XDMFFile.h>
#include <dolfinx/mesh/utils.h>
#include <filesystem>
#include <fstream>
#include <gmsh.h>
#include <gtest/gtest.h>
#include <mpi.h>

using namespace damseis::geometry;
using damseis::geometry::GravityDamSection;

namespace
{
using damseis::test::global_sum;

/// A temporary folder every rank agrees on (made by rank 0).
std::filesystem::path shared_folder(const std::string& name)
{
  const auto dir =
      std::filesystem::temp_directory_path() / ("damseis_mesh_file_" + name);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
  {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
  }
  MPI_Barrier(MPI_COMM_WORLD);
  return dir;
}

/// Rank 0 writes a 70 m x 100 m rectangle meshed with triangles: surface
/// group "dam" (tag 7), curve groups "base" (y = 0, tag 3) and
/// "upstream" (x = 0, tag 4); returns the number of triangles.
std::int64_t write_rectangle(const std::filesystem::path& file)
{
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  std::int64_t cells = 0;
  if (rank == 0)
  {
    const GmshSession session(false);
    gmsh::model::add("rectangle");
    const int s = gmsh::model::occ::addRectangle(0, 0, 0, 70, 100);
    gmsh::model::occ::synchronize();
    gmsh::vectorpair edges;
    gmsh::model::getBoundary({{2, s}}, edges, false, false, false);
    int base = -1, upstream = -1;
    for (const auto& [dim, tag] : edges)
    {
      double x = 0, y = 0, z = 0;
      gmsh::model::occ::getCenterOfMass(dim, tag, x, y, z);
      if (std::abs(y) < 1e-9)
        base = tag;
      if (std::abs(x) < 1e-9)
        upstream = tag;
    }
    gmsh::model::addPhysicalGroup(2, {s}, 7);
    gmsh::model::setPhysicalName(2, 7, "dam");
    gmsh::model::addPhysicalGroup(1, {base}, 3);
    gmsh::model::setPhysicalName(1, 3, "base");
    gmsh::model::addPhysicalGroup(1, {upstream}, 4);
    gmsh::model::setPhysicalName(1, 4, "upstream");
    gmsh::option::setNumber("Mesh.MeshSizeMax", 10.0);
    gmsh::model::mesh::generate(2);
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> tags, nodes;
    gmsh::model::mesh::getElements(types, tags, nodes, 2, -1);
    for (const auto& t : tags)
      cells += static_cast<std::int64_t>(t.size());
    gmsh::write(file.string());
  }
  MPI_Bcast(&cells, 1, MPI_INT64_T, 0, MPI_COMM_WORLD);
  return cells;
}

/// Error message of read_mesh_file on `file` ("" if it reads).
std::string read_error(const std::filesystem::path& file)
{
  try
  {
    read_mesh_file(MPI_COMM_WORLD, file);
  }
  catch (const std::runtime_error& e)
  {
    return e.what();
  }
  return "";
}
} // namespace

TEST(MeshFile, RectangleReadsBackWithItsGroups)
{
  const auto dir = shared_folder("rectangle");
  const auto file = dir / "rectangle.msh";
  const std::int64_t cells = write_rectangle(file);
  const MeshFile m = read_mesh_file(MPI_COMM_WORLD, file);
  EXPECT_EQ(m.tdim, 2);
  ASSERT_EQ(m.groups.size(), 3u);
  EXPECT_EQ(m.groups.at("dam").dim, 2);
  EXPECT_EQ(m.groups.at("dam").tag, 7);
  EXPECT_EQ(m.groups.at("base").tag, 3);
  EXPECT_EQ(m.groups.at("upstream").dim, 1);
  const auto cell_map = m.model.mesh->topology().index_map(2);
  EXPECT_EQ(cell_map->size_global(), cells);

  // Area of the owned cells (every one tagged 7): 7000 m2 exactly.
  const auto& dofs = m.model.mesh->geometry().dofmap();
  auto x = m.model.mesh->geometry().x();
  double area = 0;
  for (std::int32_t c = 0; c < cell_map->size_local(); ++c)
  {
    auto d = dofs.links(c);
    const double* p = &x[3 * d[0]];
    const double* q = &x[3 * d[1]];
    const double* r = &x[3 * d[2]];
    area += 0.5 * std::abs((q[0] - p[0]) * (r[1] - p[1]) -
                           (q[1] - p[1]) * (r[0] - p[0]));
  }
  EXPECT_NEAR(global_sum(area), 7000.0, 1e-9 * 7000.0);
  std::int64_t tagged = 0;
  for (std::int32_t v : m.model.cell_tags->values())
    tagged += v == 7;
  EXPECT_GE(tagged, cell_map->size_local());

  // Lengths of the tagged edges: base 70 m, upstream 100 m (owned facets).
  const auto facet_map = m.model.mesh->topology().index_map(1);
  for (const auto& [tag, length] : {std::pair{3, 70.0}, std::pair{4, 100.0}})
  {
    std::vector<std::int32_t> facets;
    const auto& idx = m.model.facet_tags->indices();
    const auto& val = m.model.facet_tags->values();
    for (std::size_t i = 0; i < idx.size(); ++i)
      if (val[i] == tag && idx[i] < facet_map->size_local())
        facets.push_back(idx[i]);
    const auto g =
        dolfinx::mesh::entities_to_geometry(*m.model.mesh, 1, facets, false);
    double l = 0;
    for (std::size_t i = 0; i < facets.size(); ++i)
    {
      const double* p = &x[3 * g[2 * i]];
      const double* q = &x[3 * g[2 * i + 1]];
      l += std::hypot(q[0] - p[0], q[1] - p[1]);
    }
    EXPECT_NEAR(global_sum(l), length, 1e-9 * length) << "tag " << tag;
  }
}

TEST(MeshFile, BadFilesGiveOneErrorOnEveryRank)
{
  const auto dir = shared_folder("bad");
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
  {
    std::ofstream(dir / "garbage.msh") << "$MeshFormat\nnot a mesh\n";
    // A mesh with only a curve group: no cells.
    const GmshSession session(false);
    const int l =
        gmsh::model::occ::addLine(gmsh::model::occ::addPoint(0, 0, 0),
                                  gmsh::model::occ::addPoint(1, 0, 0));
    gmsh::model::occ::synchronize();
    gmsh::model::addPhysicalGroup(1, {l}, 1);
    gmsh::model::mesh::generate(1);
    gmsh::write((dir / "line.msh").string());
  }
  MPI_Barrier(MPI_COMM_WORLD);
  EXPECT_NE(read_error(dir / "missing.msh").find("no such mesh file"),
            std::string::npos);
  EXPECT_NE(read_error(dir / "garbage.msh").find("gmsh cannot read it"),
            std::string::npos)
      << read_error(dir / "garbage.msh");
  EXPECT_NE(read_error(dir / "line.msh").find("no physical group of dimension"),
            std::string::npos);
}

namespace
{
/// The three lowest frequencies [Hz] of a gravity-dam model (P2, dam
/// fixed at its base, the foundation massless).
std::vector<double> frequencies(const Model& m)
{
  using damseis::fem::ElasticModel;
  using damseis::fem::Material;
  namespace tags = damseis::tags;
  ElasticModel fe(m, 2,
                  std::map<int, Material>{{tags::dam, {31.03e9, 0.2, 2643}},
                                          {tags::foundation, {31e9, 0.2, 0}}});
  fe.fix({tags::foundation_bottom, tags::foundation_sides});
  Mat K = fe.assemble_stiffness(), M = fe.assemble_mass(nullptr);
  const auto modes = damseis::linalg::solve_modes(K, M, 3);
  MatDestroy(&K);
  MatDestroy(&M);
  return modes.frequencies_hz;
}
} // namespace

// The Koyna section with its foundation, written by the builder
// (build_gravity_dam's mesh_file) and read back: the same groups by name
// and tag, the same cells, and the same three lowest frequencies (the
// same matrices up to the numbering of the nodes: 1e-9 relative).
TEST(MeshFile, KoynaSectionExportReadsBackTheSameModel)
{
  namespace tags = damseis::tags;
  const auto dir = shared_folder("koyna");
  const auto file = dir / "koyna.msh";
  GravityDamSection s;
  s.mesh_size = 8.0;
  s.foundation = true;
  s.foundation_width = 300.0; // the koyna case's foundation block
  s.foundation_depth = 100.0;
  const Model built = build_gravity_dam(MPI_COMM_WORLD, s, false, file);
  const MeshFile read = read_mesh_file(MPI_COMM_WORLD, file);
  EXPECT_EQ(read.tdim, 2);
  EXPECT_EQ(read.groups.at("dam").tag, int(tags::dam));
  EXPECT_EQ(read.groups.at("foundation").tag, int(tags::foundation));
  EXPECT_EQ(read.groups.at("dam_base").tag, int(tags::dam_base));
  EXPECT_EQ(read.groups.at("upstream_face").dim, 1);
  EXPECT_EQ(read.groups.at("foundation_sides").tag,
            int(tags::foundation_sides));
  EXPECT_EQ(read.model.mesh->topology().index_map(2)->size_global(),
            built.mesh->topology().index_map(2)->size_global());
  const auto f_built = frequencies(built), f_read = frequencies(read.model);
  ASSERT_EQ(f_built.size(), 3u);
  ASSERT_EQ(f_read.size(), 3u);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(f_read[i], f_built[i], 1e-9 * f_built[i]) << "mode " << i + 1;
}

namespace
{
/// The Koyna section with its foundation (8 m mesh) written as DOLFINx
/// writes meshes (XDMF: the mesh, cell tags and facet tags) and read back
/// as the user's mesh: the same groups (named "<dim>:<tag>") and the same
/// natural frequencies (1e-9: the same model, another dof numbering).
TEST(MeshFile, XdmfReadsBackTheSameModel)
{
  namespace tags = damseis::tags;
  const auto dir = shared_folder("koyna_xdmf");
  const auto file = dir / "koyna.xdmf";
  GravityDamSection s;
  s.mesh_size = 8.0;
  s.foundation = true;
  s.foundation_width = 300.0;
  s.foundation_depth = 100.0;
  const Model built = build_gravity_dam(MPI_COMM_WORLD, s);
  {
    dolfinx::io::XDMFFile xdmf(MPI_COMM_WORLD, file, "w");
    xdmf.write_mesh(*built.mesh);
    const std::string geometry = "/Xdmf/Domain/Grid[@Name='mesh']/Geometry";
    auto cells = *built.cell_tags;
    cells.name = "cell_tags";
    xdmf.write_meshtags(cells, geometry);
    auto facets = *built.facet_tags;
    facets.name = "facet_tags";
    xdmf.write_meshtags(facets, geometry);
  }
  const MeshFile read = read_mesh_file(MPI_COMM_WORLD, file);
  EXPECT_EQ(read.tdim, 2);
  EXPECT_EQ(read.groups.at("2:" + std::to_string(tags::dam)).dim, 2);
  EXPECT_EQ(read.groups.at("1:" + std::to_string(tags::dam_base)).dim, 1);
  EXPECT_EQ(read.model.mesh->topology().index_map(2)->size_global(),
            built.mesh->topology().index_map(2)->size_global());
  const auto f_built = frequencies(built), f_read = frequencies(read.model);
  ASSERT_EQ(f_read.size(), 3u);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(f_read[i], f_built[i], 1e-9 * f_built[i]) << "mode " << i + 1;
  // A wrong grid name: one error, on every rank.
  EXPECT_THROW(read_mesh_file(MPI_COMM_WORLD, file, {"mesh", "nothere"}),
               std::runtime_error);
}
} // namespace
