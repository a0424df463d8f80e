// Tests of the gravity-dam section builder and the gmsh -> DOLFINx
// conversion (damseis/geometry). Run serial and on 2 MPI ranks.
//
// References: the Koyna non-overflow section (heel (0,0), toe (70,0),
// neck (19.25,66.5), downstream crest corner (14.8,103), upstream crest
// corner (0,103)) has area, by trapezoids,
//   (70 + 19.25)/2 * 66.5 + (19.25 + 14.8)/2 * (103 - 66.5)
//   = 2967.5625 + 621.4125 = 3588.975 m^2,
// an upstream face of 103 m, a base of 70 m, a crest of 14.8 m and a
// downstream face of sqrt(50.75^2 + 66.5^2) + sqrt(4.45^2 + 36.5^2) m.
// A straight-sided polygon is meshed exactly by P1 triangles, so areas
// and lengths must agree to round-off.
#include <damseis/geometry/gmsh_mesh.h>
#include <damseis/geometry/gravity_dam.h>
#include <damseis/geometry/tags.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <stdexcept>
#include <vector>

#include <dolfinx/common/IndexMap.h>
#include <dolfinx/mesh/Geometry.h>
#include <dolfinx/mesh/Topology.h>
#include <dolfinx/mesh/utils.h>
#include <gmsh.h>
#include <gtest/gtest.h>
#include <mpi.h>

namespace
{
using damseis::geometry::GravityDamSection;
using damseis::geometry::Model;
namespace tags = damseis::tags;

constexpr double koyna_area = 3588.975;

/// Relative tolerance for areas and lengths.
constexpr double rtol = 1e-10;

/// Tag of each local (owned + ghost) entity of dimension `dim`; -1 if
/// untagged.
std::vector<std::int32_t>
entity_tags(const Model& m, const dolfinx::mesh::MeshTags<std::int32_t>& mt)
{
  auto map = m.mesh->topology().index_map(mt.dim());
  std::vector<std::int32_t> t(map->size_local() + map->num_ghosts(), -1);
  for (std::size_t i = 0; i < mt.indices().size(); ++i)
    t[mt.indices()[i]] = mt.values()[i];
  return t;
}

/// Sum over all ranks of MPI_COMM_WORLD.
std::int64_t global_sum(std::int64_t v)
{
  std::int64_t g = 0;
  MPI_Allreduce(&v, &g, 1, MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
  return g;
}

/// Area of the owned cells with tag `tag`, summed over all ranks of the
/// mesh communicator.
double tagged_area(const Model& m, int tag)
{
  const auto& mesh = *m.mesh;
  const int tdim = mesh.topology().dim();
  const std::int32_t num_owned = mesh.topology().index_map(tdim)->size_local();
  const auto t = entity_tags(m, *m.cell_tags);
  const auto& dofmap = mesh.geometry().dofmap();
  auto x = mesh.geometry().x();
  double area = 0;
  for (std::int32_t c = 0; c < num_owned; ++c)
  {
    if (t[c] != tag)
      continue;
    auto d = dofmap.links(c);
    const double* p0 = &x[3 * d[0]];
    const double* p1 = &x[3 * d[1]];
    const double* p2 = &x[3 * d[2]];
    area += 0.5 * std::abs((p1[0] - p0[0]) * (p2[1] - p0[1]) -
                           (p1[1] - p0[1]) * (p2[0] - p0[0]));
  }
  double g = 0;
  MPI_Allreduce(&area, &g, 1, MPI_DOUBLE, MPI_SUM, mesh.comm());
  return g;
}

/// Owned facets (index < size_local) with tag `tag`.
std::vector<std::int32_t> owned_tagged_facets(const Model& m, int tag)
{
  const int fdim = m.mesh->topology().dim() - 1;
  const std::int32_t num_owned =
      m.mesh->topology().index_map(fdim)->size_local();
  std::vector<std::int32_t> f;
  for (std::size_t i = 0; i < m.facet_tags->indices().size(); ++i)
  {
    const std::int32_t e = m.facet_tags->indices()[i];
    if (e < num_owned and m.facet_tags->values()[i] == tag)
      f.push_back(e);
  }
  return f;
}

/// Length of the owned facets with tag `tag`, summed over all ranks.
double tagged_length(const Model& m, int tag)
{
  const auto facets = owned_tagged_facets(m, tag);
  const auto g = dolfinx::mesh::entities_to_geometry(*m.mesh, 1, facets, false);
  auto x = m.mesh->geometry().x();
  double len = 0;
  for (std::size_t i = 0; i < facets.size(); ++i)
  {
    const double* a = &x[3 * g[2 * i]];
    const double* b = &x[3 * g[2 * i + 1]];
    len += std::hypot(b[0] - a[0], b[1] - a[1]);
  }
  double glob = 0;
  MPI_Allreduce(&len, &glob, 1, MPI_DOUBLE, MPI_SUM, m.mesh->comm());
  return glob;
}

/// Global number of cells carrying each tag (owned cells only).
std::map<int, std::int64_t> tag_counts(const Model& m)
{
  const int tdim = m.mesh->topology().dim();
  const auto num_owned = m.mesh->topology().index_map(tdim)->size_local();
  const auto t = entity_tags(m, *m.cell_tags);
  std::int64_t local[3] = {0, 0, 0};
  for (std::int32_t c = 0; c < num_owned; ++c)
    local[std::clamp(t[c], 0, 2)] += 1; // 0: untagged (or negative)
  std::int64_t global[3];
  MPI_Allreduce(local, global, 3, MPI_INT64_T, MPI_SUM, m.mesh->comm());
  return {
      {0, global[0]}, {tags::dam, global[1]}, {tags::foundation, global[2]}};
}

GravityDamSection koyna(double h)
{
  GravityDamSection s;
  s.mesh_size = h;
  return s;
}

GravityDamSection koyna_with_foundation(double h)
{
  GravityDamSection s = koyna(h);
  s.foundation = true;
  s.foundation_width = 300;
  s.foundation_depth = 100;
  return s;
}

/// Models built once per test suite (collectively on MPI_COMM_WORLD)
/// and released before MPI is finalised.
class GravityDamMesh : public ::testing::Test
{
protected:
  static void SetUpTestSuite()
  {
    koyna_ = new Model(
        damseis::geometry::build_gravity_dam(MPI_COMM_WORLD, koyna(4.0)));
    foundation_ = new Model(damseis::geometry::build_gravity_dam(
        MPI_COMM_WORLD, koyna_with_foundation(4.0)));
  }
  static void TearDownTestSuite()
  {
    delete koyna_;
    delete foundation_;
    koyna_ = foundation_ = nullptr;
  }
  static const Model& koyna_model() { return *koyna_; }
  static const Model& foundation_model() { return *foundation_; }

private:
  static Model* koyna_;
  static Model* foundation_;
};
Model* GravityDamMesh::koyna_ = nullptr;
Model* GravityDamMesh::foundation_ = nullptr;
} // namespace

TEST(GravityDamSectionInput, SectionAreaKoyna)
{
  // Hand value (trapezoids), see the header comment
  EXPECT_NEAR(damseis::geometry::section_area(koyna(2.0)), koyna_area,
              1e-12 * koyna_area);
  // A rectangle 10 x 20 (neck on the downstream vertical)
  GravityDamSection r;
  r.heel_x = 5, r.toe_x = 15, r.base_y = -3;
  r.neck_x = 15, r.neck_y = 7, r.crest_down_x = 15, r.crest_y = 17;
  EXPECT_NEAR(damseis::geometry::section_area(r), 200.0, 1e-12 * 200);
}

TEST_F(GravityDamMesh, KoynaDamAreaEqualsPolygonArea)
{
  const Model& m = koyna_model();
  ASSERT_EQ(m.mesh->geometry().dim(), 2);
  ASSERT_EQ(m.mesh->topology().dim(), 2);
  const double exact = damseis::geometry::section_area(koyna(4.0));
  EXPECT_NEAR(tagged_area(m, tags::dam), exact, rtol * exact);
  // Every owned cell is tagged dam
  const auto counts = tag_counts(m);
  EXPECT_EQ(counts.at(0), 0);
  EXPECT_EQ(counts.at(tags::foundation), 0);
  EXPECT_EQ(counts.at(tags::dam),
            m.mesh->topology().index_map(2)->size_global());
}

TEST_F(GravityDamMesh, KoynaFacetLengths)
{
  const Model& m = koyna_model();
  const double down =
      std::hypot(70 - 19.25, 66.5) + std::hypot(19.25 - 14.8, 103 - 66.5);
  EXPECT_NEAR(tagged_length(m, tags::upstream_face), 103.0, rtol * 103);
  EXPECT_NEAR(tagged_length(m, tags::dam_base), 70.0, rtol * 70);
  EXPECT_NEAR(tagged_length(m, tags::crest), 14.8, rtol * 14.8);
  EXPECT_NEAR(tagged_length(m, tags::downstream_face), down, rtol * down);
  for (int t : {5, 6, 7, 8})
    EXPECT_EQ(tagged_length(m, t), 0.0) << "tag " << t;

  // Every owned exterior facet is tagged, and only exterior facets are
  const auto& topology = m.mesh->topology();
  const auto ext = dolfinx::mesh::exterior_facet_indices(topology);
  const auto ft = entity_tags(m, *m.facet_tags);
  std::int64_t untagged = 0, tagged_owned = 0;
  for (std::int32_t f : ext)
    untagged += ft[f] < 0;
  for (std::int32_t f = 0; f < topology.index_map(1)->size_local(); ++f)
    tagged_owned += ft[f] >= 0;
  EXPECT_EQ(global_sum(untagged), 0);
  EXPECT_EQ(global_sum(tagged_owned), global_sum(std::int64_t(ext.size())));
}

TEST_F(GravityDamMesh, WaterLevelNodeOnUpstreamFace)
{
  const Model& m = koyna_model();
  const double wl = koyna(4.0).water_level;
  auto x = m.mesh->geometry().x();
  int found = 0;
  for (std::size_t i = 0; i < x.size() / 3; ++i)
    found |= std::abs(x[3 * i]) < 1e-12 and std::abs(x[3 * i + 1] - wl) < 1e-12;
  int any = 0;
  MPI_Allreduce(&found, &any, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  EXPECT_EQ(any, 1);
}

TEST_F(GravityDamMesh, FoundationAreasAndBoundaries)
{
  const Model& m = foundation_model();
  const double dam = damseis::geometry::section_area(koyna(4.0));
  EXPECT_NEAR(tagged_area(m, tags::dam), dam, rtol * dam);
  EXPECT_NEAR(tagged_area(m, tags::foundation), 300.0 * 100.0, rtol * 3e4);

  EXPECT_NEAR(tagged_length(m, tags::foundation_bottom), 300.0, rtol * 300);
  EXPECT_NEAR(tagged_length(m, tags::foundation_sides), 200.0, rtol * 200);
  const double floor = tagged_length(m, tags::reservoir_floor);
  const double top_down = tagged_length(m, tags::foundation_top_downstream);
  const double base = tagged_length(m, tags::dam_base);
  EXPECT_NEAR(floor, 115.0, rtol * 115);
  EXPECT_NEAR(top_down, 115.0, rtol * 115);
  EXPECT_NEAR(base, 70.0, rtol * 70);
  EXPECT_NEAR(floor + top_down + base, 300.0, rtol * 300);
  EXPECT_NEAR(tagged_length(m, tags::upstream_face), 103.0, rtol * 103);

  // All local cells (owned and ghost) carry a region tag
  const auto ct = entity_tags(m, *m.cell_tags);
  EXPECT_TRUE(std::all_of(ct.begin(), ct.end(),
                          [](auto t) { return t == 1 or t == 2; }));
}

TEST_F(GravityDamMesh, FoundationInterfaceIsConforming)
{
  const Model& m = foundation_model();
  const auto& topology = m.mesh->topology();
  auto f_to_c = topology.connectivity(1, 2);
  ASSERT_TRUE(f_to_c);
  const auto ct = entity_tags(m, *m.cell_tags);
  const auto base = owned_tagged_facets(m, tags::dam_base);
  std::int64_t bad = 0;
  for (std::int32_t f : base)
  {
    auto cells = f_to_c->links(f);
    if (cells.size() != 2)
    {
      ++bad;
      continue;
    }
    const int a = ct[cells[0]], b = ct[cells[1]];
    bad += !((a == tags::dam and b == tags::foundation) or
             (a == tags::foundation and b == tags::dam));
  }
  EXPECT_EQ(global_sum(bad), 0);
  EXPECT_GT(global_sum(std::int64_t(base.size())), 0);
  // The base facets are interior: none is an exterior facet
  const auto ext = dolfinx::mesh::exterior_facet_indices(topology);
  const auto ft = entity_tags(m, *m.facet_tags);
  std::int64_t ext_base = 0;
  for (std::int32_t f : ext)
    ext_base += ft[f] == tags::dam_base;
  EXPECT_EQ(global_sum(ext_base), 0);
}

TEST_F(GravityDamMesh, FoundationIsGradedAwayFromTheDam)
{
  // The default far size is 2.5 x mesh_size: the foundation has fewer
  // cells per unit area than the dam, but is refined near the base.
  const Model& m = foundation_model();
  const auto counts = tag_counts(m);
  const double dam_density = counts.at(tags::dam) / koyna_area;
  const double fnd_density = counts.at(tags::foundation) / 3e4;
  EXPECT_LT(fnd_density, dam_density);
  EXPECT_GT(fnd_density, dam_density / (2.5 * 2.5));
  EXPECT_EQ(counts.at(0), 0);
}

TEST_F(GravityDamMesh, CellCountsIndependentOfRanks)
{
  // Same section on this communicator and on each rank alone
  for (const GravityDamSection& s : {koyna(4.0), koyna_with_foundation(4.0)})
  {
    const Model serial = damseis::geometry::build_gravity_dam(MPI_COMM_SELF, s);
    const Model& parallel = s.foundation ? foundation_model() : koyna_model();
    const auto cs = tag_counts(serial), cp = tag_counts(parallel);
    EXPECT_EQ(cs, cp);
    EXPECT_EQ(serial.mesh->topology().index_map(2)->size_global(),
              parallel.mesh->topology().index_map(2)->size_global());
    EXPECT_EQ(serial.mesh->topology().index_map(0)->size_global(),
              parallel.mesh->topology().index_map(0)->size_global());
    EXPECT_EQ(serial.mesh->topology().index_map(1)->size_global(),
              parallel.mesh->topology().index_map(1)->size_global());
    // Number of facets carrying each boundary tag
    for (int t = 1; t <= 8; ++t)
    {
      const std::int64_t ns = owned_tagged_facets(serial, t).size();
      const std::int64_t np = owned_tagged_facets(parallel, t).size();
      EXPECT_EQ(ns, global_sum(np)) << "facet tag " << t;
    }
  }
}

// Output points are refused when far from the model (issue 16, class 11).
// Koyna: heel (0, 0), toe (70, 0), neck (19.25, 66.5), crest corners
// (14.8, 103), (0, 103); foundation 300 x 100 centred at x = 35. Distances
// by hand.
TEST(GravityDamSectionInput, DistanceFromModel)
{
  using damseis::geometry::distance_from_model;
  const GravityDamSection s = koyna(4.0), f = koyna_with_foundation(4.0);
  EXPECT_EQ(distance_from_model(s, 35, 20), 0.0);
  EXPECT_EQ(distance_from_model(s, 0, 103), 0.0);
  EXPECT_EQ(distance_from_model(s, 18, 66.5), 0.0); // left of the neck
  EXPECT_NEAR(distance_from_model(s, -10, 50), 10, 1e-12);
  EXPECT_NEAR(distance_from_model(s, 35, -5), 5, 1e-12);
  EXPECT_EQ(distance_from_model(f, 35, -5), 0.0);
  EXPECT_NEAR(distance_from_model(f, 200, -50), 15, 1e-12);
  EXPECT_NEAR(distance_from_model(s, 14.8 + 20.2, 110), std::hypot(20.2, 7),
              1e-12);
  // Beside the reflex neck: nearest to the toe-neck face, |e x (p - toe)|
  // / |e| = |(-50.75)(70) - (66.5)(-30)| / hypot(50.75, 66.5).
  EXPECT_NEAR(distance_from_model(s, 40, 70), 1557.5 / std::hypot(50.75, 66.5),
              1e-12);
}

TEST(GravityDamSectionInput, BadInputThrows)
{
  using damseis::geometry::build_gravity_dam;
  auto throws = [](GravityDamSection s) {
    EXPECT_THROW(build_gravity_dam(MPI_COMM_WORLD, s), std::invalid_argument);
  };
  {
    GravityDamSection s = koyna(0.0);
    throws(s);
    s.mesh_size = -1;
    throws(s);
    s.mesh_size = std::nan("");
    throws(s);
  }
  {
    GravityDamSection s = koyna_with_foundation(4.0);
    s.foundation_width = 60; // narrower than the 70 m base
    throws(s);
    s.foundation_width = 70; // must exceed the base
    throws(s);
  }
  {
    GravityDamSection s = koyna_with_foundation(4.0);
    s.foundation_depth = 0;
    throws(s);
    s.foundation_depth = 100;
    s.foundation_mesh_size = -1;
    throws(s);
  }
  {
    GravityDamSection s = koyna(4.0);
    s.crest_y = 60; // below the neck
    throws(s);
    EXPECT_THROW(damseis::geometry::section_area(s), std::invalid_argument);
  }
  {
    GravityDamSection s = koyna(4.0);
    s.toe_x = -10; // toe upstream of the heel
    throws(s);
  }
  {
    GravityDamSection s = koyna(4.0);
    s.crest_down_x = 0; // zero crest width
    throws(s);
  }
}

TEST_F(GravityDamMesh, WaterLevelOutsideTheFaceAddsNoNode)
{
  GravityDamSection s = koyna(8.0);
  s.water_level = 120; // above the crest: no extra node, same geometry
  const Model m = damseis::geometry::build_gravity_dam(MPI_COMM_WORLD, s);
  EXPECT_NEAR(tagged_length(m, tags::upstream_face), 103.0, rtol * 103);
  EXPECT_NEAR(tagged_area(m, tags::dam), koyna_area, rtol * koyna_area);
}

namespace
{
/// gmsh session on rank 0 only, finalised even if a test fails.
struct RootGmsh
{
  bool root;
  explicit RootGmsh(MPI_Comm comm)
  {
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    root = rank == 0;
    if (root)
    {
      gmsh::initialize(0, nullptr, false);
      gmsh::option::setNumber("General.Terminal", 0);
    }
  }
  ~RootGmsh()
  {
    if (root)
      gmsh::finalize();
  }
};
} // namespace

TEST(ModelFromGmsh, UnitCubeTetrahedra)
{
  // Reference: unit cube volume 1, bottom face (z = 0) area 1, the other
  // five faces area 5.
  RootGmsh session(MPI_COMM_WORLD);
  if (session.root)
  {
    gmsh::model::add("cube");
    const int v = gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
    gmsh::model::occ::synchronize();
    gmsh::model::addPhysicalGroup(3, {v}, 7);
    gmsh::vectorpair faces;
    gmsh::model::getBoundary({{3, v}}, faces, false, false, false);
    std::vector<int> bottom, others;
    for (const auto& [dim, tag] : faces)
    {
      double cx, cy, cz;
      gmsh::model::occ::getCenterOfMass(dim, tag, cx, cy, cz);
      (std::abs(cz) < 1e-12 ? bottom : others).push_back(tag);
    }
    gmsh::model::addPhysicalGroup(2, bottom, 11);
    gmsh::model::addPhysicalGroup(2, others, 12);
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.3);
    gmsh::model::mesh::generate(3);
  }
  const Model m = damseis::geometry::model_from_gmsh(MPI_COMM_WORLD, 3);
  ASSERT_EQ(m.mesh->topology().dim(), 3);
  ASSERT_EQ(m.mesh->geometry().dim(), 3);
  auto x = m.mesh->geometry().x();
  auto sub = [&](std::int32_t i, std::int32_t j, int k)
  { return x[3 * i + k] - x[3 * j + k]; };

  // Volume of owned cells tagged 7
  const auto ct = entity_tags(m, *m.cell_tags);
  const auto& dofmap = m.mesh->geometry().dofmap();
  double vol = 0;
  for (std::int32_t c = 0; c < m.mesh->topology().index_map(3)->size_local();
       ++c)
  {
    if (ct[c] != 7)
      continue;
    auto d = dofmap.links(c);
    double a[3], b[3], e[3];
    for (int k = 0; k < 3; ++k)
      a[k] = sub(d[1], d[0], k), b[k] = sub(d[2], d[0], k),
      e[k] = sub(d[3], d[0], k);
    vol += std::abs(a[0] * (b[1] * e[2] - b[2] * e[1]) -
                    a[1] * (b[0] * e[2] - b[2] * e[0]) +
                    a[2] * (b[0] * e[1] - b[1] * e[0])) /
           6;
  }
  double vol_g = 0;
  MPI_Allreduce(&vol, &vol_g, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_NEAR(vol_g, 1.0, 1e-12);

  // Areas of owned facets tagged 11 and 12
  for (auto [tag, ref] : {std::pair{11, 1.0}, std::pair{12, 5.0}})
  {
    const auto facets = owned_tagged_facets(m, tag);
    const auto g =
        dolfinx::mesh::entities_to_geometry(*m.mesh, 2, facets, false);
    double area = 0;
    for (std::size_t i = 0; i < facets.size(); ++i)
    {
      double a[3], b[3];
      for (int k = 0; k < 3; ++k)
        a[k] = sub(g[3 * i + 1], g[3 * i], k),
        b[k] = sub(g[3 * i + 2], g[3 * i], k);
      area += 0.5 * std::sqrt(std::pow(a[1] * b[2] - a[2] * b[1], 2) +
                              std::pow(a[2] * b[0] - a[0] * b[2], 2) +
                              std::pow(a[0] * b[1] - a[1] * b[0], 2));
    }
    double area_g = 0;
    MPI_Allreduce(&area, &area_g, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    EXPECT_NEAR(area_g, ref, 1e-12) << "facet tag " << tag;
  }
}

TEST(ModelFromGmsh, QuadrilateralsAreRejectedOnAllRanks)
{
  RootGmsh session(MPI_COMM_WORLD);
  if (session.root)
  {
    gmsh::model::add("quads");
    const int s = gmsh::model::occ::addRectangle(0, 0, 0, 1, 1);
    gmsh::model::occ::synchronize();
    gmsh::model::addPhysicalGroup(2, {s}, 1);
    gmsh::option::setNumber("Mesh.RecombineAll", 1);
    gmsh::option::setNumber("Mesh.MeshSizeMax", 0.25);
    gmsh::model::mesh::generate(2);
  }
  EXPECT_THROW(damseis::geometry::model_from_gmsh(MPI_COMM_WORLD, 2),
               std::runtime_error);
}
