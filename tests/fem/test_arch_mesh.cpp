// Tests of the 3D arch-dam geometry (damseis/geometry/arch_*, joints):
// reference integrals, meshed volume and face areas, tags, joints with
// duplicated nodes. Run serial and on 2 MPI ranks (coarse meshes).
//
// References:
//  - ArchGeometry.CylinderAnalytic: a circular arch of constant thickness
//    between vertical walls x = +-X is a vertical cylindrical shell cut by
//    two planes; per unit height its area is F(Ru) - F(Rd) with
//    F(r) = X sqrt(r^2 - X^2) + r^2 asin(X / r), its faces 2 r asin(X / r)
//    (elementary geometry). The quadrature of ArchDamGeometry must agree to
//    1e-9.
//  - ArchMesh.*: the meshed volume and face areas against the independent
//    quadrature of the parametric shape (Gauss-Legendre over elevation and
//    arch angle, Green's theorem for the sections). The tolerance is the
//    chordal error of P1 facets on the curved faces: a triangle of size h
//    on a surface of curvature radius rho deviates by at most
//    h^2 / (8 rho); summed over the curved faces this bounds the volume
//    error, and (h / rho)^2 / 8 bounds the relative area error. gmsh edges
//    reach about 1.5 x the target size, so h = 1.5 mesh.size, and rho is
//    the smallest face radius of the dam (ArchDamGeometry::min_face_radius).
//    The test also checks that the error decreases under refinement.
//  - Joints: pairs coincide (distance < 1e-9), normals are unit and
//    perpendicular to the joint plane (algorithms.md 2.1), side-1 and
//    side-2 facet areas are equal, the pair count equals the number of
//    distinct side-2 vertices off the interface in the distributed mesh.
#include <damseis/geometry/arch_case.h>
#include <damseis/geometry/arch_dam.h>
#include <damseis/geometry/arch_mesh.h>
#include <damseis/geometry/joints.h>
#include <damseis/geometry/tags.h>
#include <damseis/input/case.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include <dolfinx/common/IndexMap.h>
#include <dolfinx/mesh/Geometry.h>
#include <dolfinx/mesh/Topology.h>
#include <dolfinx/mesh/utils.h>
#include <gtest/gtest.h>
#include <mpi.h>

namespace
{
using namespace damseis::geometry;
namespace tags = damseis::tags;
namespace input = damseis::input;

const std::filesystem::path presets =
    std::filesystem::path(DAMSEIS_SOURCE_DIR) / "demos/arch_dam/presets";

void metric(const std::string& s)
{
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank == 0)
    std::cout << "[   metric ] " << s << std::endl;
}

double sum(double v)
{
  double g = 0;
  MPI_Allreduce(&v, &g, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  return g;
}

std::int64_t sum(std::int64_t v)
{
  std::int64_t g = 0;
  MPI_Allreduce(&v, &g, 1, MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
  return g;
}

/// A preset with overrides.
ArchDamDefinition preset(const std::string& name,
                         const std::vector<std::string>& overrides)
{
  input::Schema s;
  arch_dam_schema(s);
  return read_arch_dam(input::Case::load(s, presets / name, overrides));
}

/// Tag of every local facet (-1: none).
std::vector<int> facet_tag_array(const Model& m)
{
  auto map = m.mesh->topology().index_map(2);
  std::vector<int> t(map->size_local() + map->num_ghosts(), -1);
  for (std::size_t i = 0; i < m.facet_tags->indices().size(); ++i)
    t[m.facet_tags->indices()[i]] = m.facet_tags->values()[i];
  return t;
}

std::vector<int> cell_tag_array(const Model& m)
{
  auto map = m.mesh->topology().index_map(3);
  std::vector<int> t(map->size_local() + map->num_ghosts(), -1);
  for (std::size_t i = 0; i < m.cell_tags->indices().size(); ++i)
    t[m.cell_tags->indices()[i]] = m.cell_tags->values()[i];
  return t;
}

/// Volume of the owned cells with region `tag` (all ranks).
double region_volume(const Model& m, int tag)
{
  const auto t = cell_tag_array(m);
  const auto n = m.mesh->topology().index_map(3)->size_local();
  const auto& dofs = m.mesh->geometry().dofmap();
  auto x = m.mesh->geometry().x();
  double v = 0;
  for (std::int32_t c = 0; c < n; ++c)
  {
    if (t[c] != tag)
      continue;
    auto d = dofs.links(c);
    auto e = [&](int a, int k) { return x[3 * d[a] + k] - x[3 * d[0] + k]; };
    v += std::abs(e(1, 0) * (e(2, 1) * e(3, 2) - e(2, 2) * e(3, 1)) -
                  e(1, 1) * (e(2, 0) * e(3, 2) - e(2, 2) * e(3, 0)) +
                  e(1, 2) * (e(2, 0) * e(3, 1) - e(2, 1) * e(3, 0))) /
         6;
  }
  return sum(v);
}

/// Area of the owned facets with tag `tag` (all ranks).
double facet_area(const Model& m, int tag)
{
  const auto t = facet_tag_array(m);
  const auto n = m.mesh->topology().index_map(2)->size_local();
  std::vector<std::int32_t> f;
  for (std::int32_t i = 0; i < n; ++i)
    if (t[i] == tag)
      f.push_back(i);
  const auto g = dolfinx::mesh::entities_to_geometry(*m.mesh, 2, f, false);
  auto x = m.mesh->geometry().x();
  double a = 0;
  for (std::size_t i = 0; i < f.size(); ++i)
  {
    const double* p = &x[3 * g[3 * i]];
    const double* q = &x[3 * g[3 * i + 1]];
    const double* r = &x[3 * g[3 * i + 2]];
    const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    const double v[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    a += 0.5 * std::sqrt(std::pow(u[1] * v[2] - u[2] * v[1], 2) +
                         std::pow(u[2] * v[0] - u[0] * v[2], 2) +
                         std::pow(u[0] * v[1] - u[1] * v[0], 2));
  }
  return sum(a);
}

/// Models built once (collectively) and kept for the suite.
struct Models
{
  std::map<std::string, std::shared_ptr<ArchModel>> m;
  std::shared_ptr<ArchModel> get(const std::string& key,
                                 const ArchDamDefinition& d)
  {
    auto it = m.find(key);
    if (it != m.end())
      return it->second;
    auto p = std::make_shared<ArchModel>(build_arch_dam(MPI_COMM_WORLD, d));
    metric(key + ": " + std::to_string(p->num_cells) + " cells (" +
           std::to_string(p->num_dam_cells) + " in the dam), " +
           std::to_string(p->num_nodes) + " nodes, built in " +
           std::to_string(p->total_seconds) + " s (OCC " +
           std::to_string(p->geometry_seconds) + " s, gmsh mesh " +
           std::to_string(p->mesh_seconds) + " s)");
    m[key] = p;
    return p;
  }
};

class ArchMesh : public ::testing::Test
{
protected:
  static void TearDownTestSuite() { models.reset(); }
  static std::shared_ptr<ArchModel> model(const std::string& key,
                                          const ArchDamDefinition& d)
  {
    if (!models)
      models = std::make_unique<Models>();
    return models->get(key, d);
  }
  static std::unique_ptr<Models> models;
};
std::unique_ptr<Models> ArchMesh::models;

ArchDamDefinition paper_v(double h, int joints)
{
  return preset("paper_102m_v.toml",
                {"mesh.size=" + std::to_string(h), "mesh.size_far=60",
                 "joints.count=" + std::to_string(joints)});
}

ArchDamDefinition xiluodu_u(double h, int joints)
{
  return preset("xiluodu_like.toml",
                {"mesh.size=" + std::to_string(h), "mesh.size_far=150",
                 "joints.count=" + std::to_string(joints)});
}

/// Checks of the tags of a model (see the file comment).
void check_tags(const ArchModel& am)
{
  const Model& m = am.model;
  auto& topo = m.mesh->topology();
  const auto ft = facet_tag_array(m);
  const auto ct = cell_tag_array(m);
  auto f2c = topo.connectivity(2, 3);
  ASSERT_TRUE(f2c);
  const std::int32_t nf = topo.index_map(2)->size_local();

  // Every exterior facet is tagged, with a tag of its side
  const std::vector<std::int32_t> ext =
      dolfinx::mesh::exterior_facet_indices(topo);
  std::int64_t untagged = 0, wrong = 0;
  const std::set<int> dam_tags = {tags::upstream_face, tags::upstream_wetted,
                                  tags::downstream_face, tags::crest};
  const std::set<int> rock_tags = {
      tags::foundation_bottom,    tags::foundation_sides,
      tags::reservoir_floor,      tags::foundation_top_downstream,
      tags::foundation_top,       tags::foundation_upstream,
      tags::foundation_downstream};
  for (std::int32_t f : ext)
  {
    if (f >= nf)
      continue;
    const int t = ft[f];
    const int region = ct[f2c->links(f)[0]];
    if (t < 0)
      ++untagged;
    else if (region == tags::dam)
      wrong += !(dam_tags.count(t) or tags::is_joint_tag(t));
    else
      wrong += !rock_tags.count(t);
  }
  EXPECT_EQ(sum(untagged), 0) << "untagged exterior facets";
  EXPECT_EQ(sum(wrong), 0) << "exterior facets with a tag of the other side";

  // Interface facets are shared by a dam cell and a foundation cell
  std::int64_t bad = 0, ninterface = 0;
  for (std::int32_t f = 0; f < nf; ++f)
  {
    if (ft[f] != tags::dam_base)
      continue;
    ++ninterface;
    auto c = f2c->links(f);
    bad += !(c.size() == 2 and std::min(ct[c[0]], ct[c[1]]) == tags::dam and
             std::max(ct[c[0]], ct[c[1]]) == tags::foundation);
  }
  EXPECT_GT(sum(ninterface), 0);
  EXPECT_EQ(sum(bad), 0) << "interface facets not between dam and rock";
  // Each face family exists
  for (int t :
       {int(tags::upstream_face), int(tags::downstream_face), int(tags::crest),
        int(tags::foundation_bottom), int(tags::foundation_sides),
        int(tags::reservoir_floor), int(tags::foundation_top_downstream),
        int(tags::foundation_top), int(tags::foundation_upstream),
        int(tags::foundation_downstream)})
    EXPECT_GT(facet_area(m, t), 0) << "no facet with tag " << t;
}

/// Upstream and downstream face areas of the mesh against the parametric
/// shape: chord error of facets of size he on faces of radius >= rho,
/// relative (he / rho)^2 / 8 (as in VolumeAndFaceAreasConverge).
void check_face_areas(const Model& m, const ArchDamGeometry& g, double he)
{
  const double tolA = std::pow(he / g.min_face_radius(), 2) / 8;
  const double Au = g.face_area(-1), Ad = g.face_area(1);
  const double eu = std::abs(facet_area(m, tags::upstream_face) - Au) / Au;
  const double ed = std::abs(facet_area(m, tags::downstream_face) - Ad) / Ad;
  metric("face areas: relative errors up " + std::to_string(eu) + ", down " +
         std::to_string(ed) + " (tol " + std::to_string(tolA) + ")");
  EXPECT_LT(eu, tolA);
  EXPECT_LT(ed, tolA);
}

/// Checks of the joints of a model.
void check_joints(const ArchModel& am, std::size_t njoints)
{
  const Model& m = am.model;
  const auto& mesh = *m.mesh;
  ASSERT_EQ(am.joints.size(), njoints);
  auto x = mesh.geometry().x();
  const auto ft = facet_tag_array(m);
  auto gmap = mesh.geometry().index_map();
  const std::int32_t nowned = gmap->size_local();
  std::int64_t total_pairs = 0;
  for (std::size_t k = 0; k < am.joints.size(); ++k)
  {
    const JointPairs& j = am.joints[k];
    EXPECT_EQ(j.label, joint_label(int(k))) << "labels A.. in order";
    if (k > 0)
      EXPECT_GT(j.plane_point[0], am.joints[k - 1].plane_point[0])
          << "joints ordered by x";
    EXPECT_GT(j.size(), 3u);
    total_pairs += j.size();
    const auto a = local_geometry_nodes(mesh, j.node1);
    const auto b = local_geometry_nodes(mesh, j.node2);
    double dmax = 0, nerr = 0, perp = 0, off = 0;
    std::int64_t found_a = 0, found_b = 0;
    for (std::size_t i = 0; i < j.size(); ++i)
    {
      const double* n = &j.normal[3 * i];
      nerr = std::max(nerr, std::abs(std::hypot(n[0], n[1], n[2]) - 1));
      // parallel to the plane normal = perpendicular to the joint plane
      const double c = n[0] * j.plane_normal[0] + n[1] * j.plane_normal[1] +
                       n[2] * j.plane_normal[2];
      perp = std::max(perp, 1 - c);
      off = std::max(
          off,
          std::abs((j.x[3 * i] - j.plane_point[0]) * j.plane_normal[0] +
                   (j.x[3 * i + 1] - j.plane_point[1]) * j.plane_normal[1]));
      if (a[i] >= 0 and a[i] < nowned)
        ++found_a;
      if (b[i] >= 0 and b[i] < nowned)
        ++found_b;
      if (a[i] >= 0 and b[i] >= 0)
      {
        const double d = std::hypot(x[3 * a[i]] - x[3 * b[i]],
                                    x[3 * a[i] + 1] - x[3 * b[i] + 1],
                                    x[3 * a[i] + 2] - x[3 * b[i] + 2]);
        dmax = std::max(dmax, d);
      }
      if (a[i] >= 0)
        dmax = std::max(dmax, std::hypot(x[3 * a[i]] - j.x[3 * i],
                                         x[3 * a[i] + 1] - j.x[3 * i + 1],
                                         x[3 * a[i] + 2] - j.x[3 * i + 2]));
    }
    EXPECT_LT(dmax, 1e-9) << "joint " << j.label << ": pair distance";
    EXPECT_LT(nerr, 1e-12) << "joint " << j.label << ": unit normals";
    EXPECT_LT(perp, 1e-9) << "joint " << j.label << ": normal vs plane";
    EXPECT_LT(off, 1e-6) << "joint " << j.label << ": nodes on the plane";
    // Every node of a pair is owned by exactly one rank
    EXPECT_EQ(sum(found_a), std::int64_t(j.size()));
    EXPECT_EQ(sum(found_b), std::int64_t(j.size()));

    // Side areas equal; side-2 vertices off the interface = pairs
    const double a1 = facet_area(m, j.tag_side1);
    const double a2 = facet_area(m, j.tag_side2);
    EXPECT_GT(a1, 0);
    EXPECT_NEAR(a1, a2, 1e-10 * a1) << "joint " << j.label;
    double trib = 0;
    for (double w : j.area)
      trib += w;
    // The interface nodes (bonded, no pair) keep the rest of the area
    EXPECT_LE(trib, a1 * (1 + 1e-12));
    EXPECT_GT(trib, 0.5 * a1);

    // Distinct owned side-2 geometry nodes whose input index is a copy
    std::set<std::int64_t> copies(j.node2.begin(), j.node2.end());
    std::vector<std::int32_t> f2;
    for (std::int32_t f = 0; f < mesh.topology().index_map(2)->size_local();
         ++f)
      if (ft[f] == j.tag_side2)
        f2.push_back(f);
    const auto g = dolfinx::mesh::entities_to_geometry(mesh, 2, f2, false);
    std::set<std::int32_t> side2_nodes;
    for (std::int32_t v : g)
      if (v < nowned and
          copies.count(mesh.geometry().input_global_indices()[v]))
        side2_nodes.insert(v);
    // Nodes on owned facets only: compare with a lower/upper bound
    EXPECT_LE(sum(std::int64_t(side2_nodes.size())), std::int64_t(j.size()));
    metric(std::string("joint ") + j.label + ": " + std::to_string(j.size()) +
           " pairs, area " + std::to_string(a1) + " m2");
  }
  metric("total pairs " + std::to_string(total_pairs));
}
} // namespace

//-----------------------------------------------------------------------------
/// A circular arch of constant thickness T and centre-line radius R
/// between vertical walls x = +-X, height H (the crown's upstream face at
/// y = 0).
static ArchDamDefinition cylinder_dam(double H, double X, double R, double T)
{
  ArchDamDefinition d;
  d.dam.height = H;
  d.dam.levels = {0, H};
  d.dam.crown_upstream_y = {0, 0};
  d.dam.crown_thickness = {T, T};
  d.dam.abutment_thickness = {T, T};
  d.dam.shape = ArchShape::circular;
  d.dam.radius_central = {R, R};
  d.canyon.shape = CanyonShape::points;
  d.canyon.z = {0, H};
  d.canyon.x_left = {-X, -X};
  d.canyon.x_right = {X, X};
  return d;
}

TEST(ArchGeometry, CylinderAnalytic)
{
  const double H = 50, X = 60, R = 100, T = 8;
  const ArchDamGeometry g(cylinder_dam(H, X, R, T));
  auto F = [&](double r)
  { return X * std::sqrt(r * r - X * X) + r * r * std::asin(X / r); };
  const double ru = R + T / 2, rd = R - T / 2;
  EXPECT_NEAR(g.volume(), H * (F(ru) - F(rd)), 1e-9 * H * (F(ru) - F(rd)));
  EXPECT_NEAR(g.face_area(-1), H * 2 * ru * std::asin(X / ru), 1e-6);
  EXPECT_NEAR(g.face_area(1), H * 2 * rd * std::asin(X / rd), 1e-6);
  EXPECT_NEAR(g.crest_area(), F(ru) - F(rd), 1e-7);
  EXPECT_NEAR(g.crest_length(), 2 * R * std::asin(X / R), 1e-9);
}

// Output points are refused when far from the model (issue 16, class 11).
// The cylinder dam of CylinderAnalytic: centre line radius R = 100 about
// (0, 104) (the crown's upstream face at y = 0, T = 8), walls x = -60, 60,
// floor z = 0, foundation box 1 H beyond the rims, below the floor and up
// and downstream. Distances by hand.
TEST(ArchGeometry, DistanceFromModelCylinder)
{
  const double H = 50, X = 60, R = 100, T = 8;
  const ArchDamGeometry g(cylinder_dam(H, X, R, T));
  auto distance = [&](double x, double y, double z) {
    return damseis::geometry::distance_from_model(g, {x, y, z});
  };
  EXPECT_EQ(distance(0, 4, 25), 0.0);          // in the crown
  EXPECT_EQ(distance(70, 0, 25), 0.0);         // in the right bank
  EXPECT_EQ(distance(0, 0, -10), 0.0);         // below the floor
  EXPECT_NEAR(distance(0, -10, 25), 10, 1e-9); // upstream: 114 - 104
  EXPECT_NEAR(distance(0, 20, 40), 12, 1e-9);  // downstream: 96 - 84
  EXPECT_NEAR(distance(0, 40, 25), 25, 1e-9);  // nearer the floor
  // Above the crest at the crown: 30 m above the box, and the box's top
  // there is in the dam (the crest): 30.
  EXPECT_NEAR(distance(0, 4, H + 30), 30, 1e-9);
  // Above the valley's air downstream of the crest (y = 20, z = H + 30):
  // hypot(30, distance at the box top = 96 - 84 = 12).
  EXPECT_NEAR(distance(0, 20, H + 30), std::hypot(30.0, 12.0), 1e-9);
  EXPECT_NEAR(distance(200, 0, 25), 90, 1e-9); // beyond the box x = 110
}

TEST(ArchGeometry, PresetsAndBadInput)
{
  // Crest lengths: paper 310 m; Xiluodu ~680 m; Xiaowan ~900 m (public)
  const ArchDamGeometry p(preset("paper_102m_v.toml", {}));
  EXPECT_NEAR(p.crest_length(), 310.0, 0.5);
  EXPECT_NEAR(p.ring(0).t_c, 24.6, 1e-12);
  EXPECT_NEAR(p.ring(102).t_c, 5.0, 1e-12);
  EXPECT_EQ(p.joint_planes().size(), 13u);
  const ArchDamGeometry x(preset("xiluodu_like.toml", {}));
  EXPECT_NEAR(x.crest_length(), 680.0, 0.01 * 680);
  const ArchDamGeometry w(preset("xiaowan_like.toml", {}));
  EXPECT_NEAR(w.crest_length(), 900.0, 0.01 * 900);
  // Subset of labelled positions
  const auto j3 =
      ArchDamGeometry(preset("paper_102m_v.toml", {"joints.active=DGJ"}))
          .joint_planes();
  ASSERT_EQ(j3.size(), 3u);
  EXPECT_EQ(j3[0].label, 'D');
  EXPECT_EQ(j3[1].label, 'G');
  EXPECT_NEAR(j3[1].point[0], 0, 1e-6); // the crown: symmetric dam
  // Impossible input names the key
  auto fails_on = [](const std::vector<std::string>& o, const std::string& key)
  {
    try
    {
      preset("paper_102m_v.toml", o);
    }
    catch (const input::InputError& e)
    {
      return std::string(e.what()).find(key) != std::string::npos;
    }
    return false;
  };
  EXPECT_TRUE(
      fails_on({"dam.crown_thickness=[20, 10, 5]"}, "dam.crown_thickness"));
  EXPECT_TRUE(fails_on({"dam.levels=[0, 30, 20, 80, 102]"}, "dam.levels"));
  EXPECT_TRUE(fails_on({"joints.active=AZ"}, "joints.active"));
  EXPECT_TRUE(
      fails_on({"dam.radius_lateral=[8, 8, 8, 8, 8]"}, "dam.radius_lateral"));
  EXPECT_TRUE(
      fails_on({"canyon.shape=u", "canyon.u_radius=150"}, "canyon.u_radius"));
}

TEST_F(ArchMesh, VolumeAndFaceAreasConverge)
{
  const ArchDamGeometry g(paper_v(16, 0));
  const double V = g.volume(), Au = g.face_area(-1), Ad = g.face_area(1),
               Ac = g.crest_area();
  const double rho = g.min_face_radius();
  metric("paper dam reference: V = " + std::to_string(V) + " m3, A_up = " +
         std::to_string(Au) + " m2, A_down = " + std::to_string(Ad) +
         " m2, crest = " + std::to_string(Ac) +
         " m2, min face radius = " + std::to_string(rho) + " m");
  double prev[4] = {1e300, 1e300, 1e300, 1e300};
  for (double h : {16.0, 8.0})
  {
    auto am = model("paper V h=" + std::to_string(int(h)) + " 0 joints",
                    paper_v(h, 0));
    const Model& m = am->model;
    const double he = 1.5 * h;
    const double tolV = (Au + Ad) * he * he / (8 * rho);
    const double tolA = std::pow(he / rho, 2) / 8;
    const double eV = std::abs(region_volume(m, tags::dam) - V) / V;
    const double eu = std::abs(facet_area(m, tags::upstream_face) - Au) / Au;
    const double ed = std::abs(facet_area(m, tags::downstream_face) - Ad) / Ad;
    const double ec = std::abs(facet_area(m, tags::crest) - Ac) / Ac;
    metric("h = " + std::to_string(h) + ": relative errors V " +
           std::to_string(eV) + " (tol " + std::to_string(tolV / V) +
           "), A_up " + std::to_string(eu) + ", A_down " + std::to_string(ed) +
           " (tol " + std::to_string(tolA) + "), crest " + std::to_string(ec));
    EXPECT_LT(eV, tolV / V);
    EXPECT_LT(eu, tolA);
    EXPECT_LT(ed, tolA);
    EXPECT_LT(ec, tolA);
    // Decrease under refinement (volume and the two faces)
    EXPECT_LT(eV, prev[0]);
    EXPECT_LT(eu, prev[1]);
    EXPECT_LT(ed, prev[2]);
    prev[0] = eV;
    prev[1] = eu;
    prev[2] = ed;
    prev[3] = ec;
    check_tags(*am);
    EXPECT_TRUE(am->joints.empty());
  }
}

TEST_F(ArchMesh, WaterLineSplitsTheUpstreamFace)
{
  // Reservoir at 70 m on the paper dam (3 joints, h = 16): the mesh follows
  // the water line. The wetted facets (upstream_wetted) lie below it, the
  // dry ones (upstream_face) above it; the wetted area matches the
  // parametric face below 70 m and wetted + dry the whole face (chord-error
  // tolerance as above); volume unchanged.
  const double wl = 70.0, h = 16.0;
  ArchDamDefinition d = paper_v(h, 3);
  d.mesh.water_level = wl;
  auto am = model("paper V h=16 3 joints, water line 70 m", d);
  check_tags(*am);
  check_joints(*am, 3);
  const Model& m = am->model;
  const auto ft = facet_tag_array(m);
  const auto& mesh = *m.mesh;
  const std::int32_t nf = mesh.topology().index_map(2)->size_local();
  std::vector<std::int32_t> wet, dry;
  for (std::int32_t f = 0; f < nf; ++f)
  {
    if (ft[f] == tags::upstream_wetted)
      wet.push_back(f);
    else if (ft[f] == tags::upstream_face)
      dry.push_back(f);
  }
  auto x = mesh.geometry().x();
  double wet_top = -1e300, dry_bottom = 1e300;
  for (const auto& [facets, wetted] : {std::pair{&wet, true}, {&dry, false}})
  {
    const auto g = dolfinx::mesh::entities_to_geometry(mesh, 2, *facets, false);
    for (std::int32_t v : g)
    {
      if (wetted)
        wet_top = std::max(wet_top, x[3 * v + 2]);
      else
        dry_bottom = std::min(dry_bottom, x[3 * v + 2]);
    }
  }
  double top = wet_top, bottom = dry_bottom;
  MPI_Allreduce(&wet_top, &top, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  MPI_Allreduce(&dry_bottom, &bottom, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  EXPECT_NEAR(top, wl, 1e-6) << "highest wetted node on the water line";
  EXPECT_NEAR(bottom, wl, 1e-6) << "lowest dry node on the water line";
  const ArchDamGeometry g(d);
  const double tolA = std::pow(1.5 * h / g.min_face_radius(), 2) / 8;
  const double Aw = g.face_area(-1, wl), Au = g.face_area(-1);
  const double aw = facet_area(m, tags::upstream_wetted);
  const double ad = facet_area(m, tags::upstream_face);
  metric("water line 70 m: wetted area " + std::to_string(aw) +
         " m2 (reference " + std::to_string(Aw) + "), dry " +
         std::to_string(ad) + " m2, whole face reference " +
         std::to_string(Au) + " m2");
  EXPECT_NEAR(aw, Aw, tolA * Aw);
  EXPECT_NEAR(aw + ad, Au, tolA * Au);
  EXPECT_GT(ad, 0.05 * Au);
  EXPECT_NEAR(region_volume(m, tags::dam), g.volume(), 0.02 * g.volume());
}

TEST_F(ArchMesh, VCanyonThreeJoints)
{
  auto am = model("paper V h=16 3 joints", paper_v(16, 3));
  check_tags(*am);
  check_joints(*am, 3);
  // The joints do not change the dam (same volume as without joints)
  auto a0 = model("paper V h=16 0 joints", paper_v(16, 0));
  const double v0 = region_volume(a0->model, tags::dam);
  const double v3 = region_volume(am->model, tags::dam);
  const ArchDamGeometry g(paper_v(16, 0));
  EXPECT_NEAR(v3, g.volume(), 0.02 * g.volume());
  EXPECT_NEAR(v3, v0, 0.02 * v0);
  // write_model runs (collective) and leaves a readable file.
  const auto dir = std::filesystem::temp_directory_path() / "damseis_arch";
  std::filesystem::create_directories(dir);
  write_model(am->model, dir / "paper_v_3_joints.xdmf");
  EXPECT_TRUE(std::filesystem::exists(dir / "paper_v_3_joints.h5"));
}

TEST_F(ArchMesh, VCanyonThirteenJoints)
{
  auto am = model("paper V h=16 13 joints", paper_v(16, 13));
  check_tags(*am);
  check_joints(*am, 13);
  // Symmetric dam, evenly spaced joints: pair counts mirror (A-M, B-L, ...)
  // up to the unstructured mesh; the labels run A ... M with x
  EXPECT_EQ(am->joints.front().label, 'A');
  EXPECT_EQ(am->joints.back().label, 'M');
  EXPECT_NEAR(am->joints[6].plane_point[0], 0.0, 1e-6);
}

TEST_F(ArchMesh, UCanyonThreeJoints)
{
  auto am = model("xiluodu U h=40 3 joints", xiluodu_u(40, 3));
  check_tags(*am);
  check_joints(*am, 3);
  const ArchDamGeometry g(xiluodu_u(40, 3));
  const double V = g.volume();
  const double v = region_volume(am->model, tags::dam);
  metric("xiluodu-like volume: mesh " + std::to_string(v) + " m3, reference " +
         std::to_string(V) + " m3");
  const double he = 1.5 * 40, rho = g.min_face_radius();
  EXPECT_NEAR(v, V, (g.face_area(-1) + g.face_area(1)) * he * he / (8 * rho));
  check_face_areas(am->model, g, he);
}

TEST_F(ArchMesh, XiaowanLikeWideVCanyon)
{
  // The third preset (292 m, parabolic arches, wide V canyon), meshed
  // coarse: tags, joints, volume and face areas against the parametric
  // shape (same tolerances as above).
  const ArchDamDefinition d =
      preset("xiaowan_like.toml",
             {"mesh.size=40", "mesh.size_far=150", "joints.count=3"});
  auto am = model("xiaowan V h=40 3 joints", d);
  check_tags(*am);
  check_joints(*am, 3);
  const ArchDamGeometry g(d);
  const double V = g.volume();
  const double v = region_volume(am->model, tags::dam);
  metric("xiaowan-like: " + std::to_string(am->num_cells) +
         " cells, volume: mesh " + std::to_string(v) + " m3, reference " +
         std::to_string(V) + " m3");
  const double he = 1.5 * 40, rho = g.min_face_radius();
  EXPECT_NEAR(v, V, (g.face_area(-1) + g.face_area(1)) * he * he / (8 * rho));
  check_face_areas(am->model, g, he);
}
