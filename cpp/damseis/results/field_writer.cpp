#include "field_writer.h"
#include "principal.h"
#include <algorithm>
#include <cmath>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/mesh/Mesh.h>
#include <dolfinx/mesh/MeshTags.h>
#include <limits>

namespace damseis::results
{
namespace
{
using Function = dolfinx::fem::Function<double>;

std::int32_t owned_cells(const dolfinx::mesh::Mesh& mesh)
{
  return mesh.topology().index_map(mesh.topology().dim())->size_local();
}

/// Column `j` of a row-major array with `n` columns, times `scale`.
std::vector<double> column(const std::vector<double>& a, int n, int j,
                           double scale)
{
  std::vector<double> c(a.size() / n);
  for (std::size_t i = 0; i < c.size(); ++i)
    c[i] = scale * a[i * n + j];
  return c;
}
} // namespace

std::vector<double> cell_average(const dolfinx::fem::FunctionSpace& S,
                                 std::span<const double> s, int num_cells)
{
  const int nc = S.dofmap()->index_map_bs();
  std::vector<double> out(static_cast<std::size_t>(num_cells) * nc, 0.0);
  for (int c = 0; c < num_cells; ++c)
  {
    auto dofs = S.dofmap()->cell_dofs(c);
    for (std::int32_t d : dofs)
    {
      for (int k = 0; k < nc; ++k)
        out[c * nc + k] += s[d * nc + k] / dofs.size();
    }
  }
  return out;
}

std::vector<double> cell_max_scalar(const dolfinx::fem::FunctionSpace& S,
                                    std::span<const double> v, int num_cells)
{
  std::vector<double> out(num_cells, -std::numeric_limits<double>::infinity());
  for (int c = 0; c < num_cells; ++c)
  {
    for (std::int32_t d : S.dofmap()->cell_dofs(c))
      out[c] = std::max(out[c], v[d]);
  }
  return out;
}

std::vector<std::string> stress_component_names(int tdim)
{
  if (tdim == 2)
    return {"sigma_xx_MPa", "sigma_yy_MPa", "sigma_xy_MPa"};
  return {"sigma_xx_MPa", "sigma_yy_MPa", "sigma_zz_MPa",
          "sigma_xy_MPa", "sigma_yz_MPa", "sigma_xz_MPa"};
}

FieldWriter::FieldWriter(
    fem::ElasticModel& model, const std::filesystem::path& file,
    std::shared_ptr<const dolfinx::fem::FunctionSpace> stress_space,
    const std::vector<std::string>& extra)
    : _model(model), _S(stress_space ? stress_space : model.S()),
      _file(model.mesh(), file), _extra(extra)
{
  _u = std::make_shared<Function>(model.output_space("u_vertex"));
  const auto mesh = model.mesh();
  _region.assign(owned_cells(*mesh), 0.0);
  const auto& tags = *model.model().cell_tags;
  for (std::size_t i = 0; i < tags.indices().size(); ++i)
  {
    if (tags.indices()[i] < static_cast<std::int32_t>(_region.size()))
      _region[tags.indices()[i]] = tags.values()[i];
  }
}

void FieldWriter::write(const Function& u, std::span<const double> s, double t,
                        const std::vector<std::span<const double>>& extra)
{
  _u->interpolate(u);
  auto mesh = _model.mesh();
  const int tdim = mesh->topology().dim();
  const std::int32_t n = owned_cells(*mesh);
  const int nc = tdim == 2 ? 3 : 6;
  const std::vector<double> avg = cell_average(*_S, s, n);
  std::vector<double> p1(n), p3(n);
  for (std::int32_t c = 0; c < n; ++c)
  {
    const auto [hi, lo] = principal_extremes(avg.data() + c * nc, nc);
    p1[c] = 1e-6 * hi;
    p3[c] = 1e-6 * lo;
  }
  _file.point_field("displacement_m", *_u);
  const auto names = stress_component_names(tdim);
  for (int j = 0; j < nc; ++j)
    _file.cell_field(names[j], column(avg, nc, j, 1e-6));
  _file.cell_field("sigma1_MPa", p1);
  _file.cell_field("sigma3_MPa", p3);
  for (std::size_t i = 0; i < _extra.size() && i < extra.size(); ++i)
    _file.cell_field(_extra[i], cell_max_scalar(*_S, extra[i], n));
  _file.cell_field("region", _region);
  _file.write(t);
}

void write_envelopes(
    fem::ElasticModel& model, const StressEnvelope& env,
    std::span<const std::int32_t> region_cells,
    const std::filesystem::path& file,
    std::shared_ptr<const dolfinx::fem::FunctionSpace> stress_space,
    bool vertex_points, const std::vector<PointScalar>& extra)
{
  auto mesh = model.mesh();
  const std::int32_t n = owned_cells(*mesh);
  const auto& S = stress_space ? *stress_space : *model.S();
  const auto P1 = model.output_space("s_vertex");
  const double inf = std::numeric_limits<double>::infinity();

  // Cells: extremes over their points and when; vertices: extremes over
  // the points at the vertex (or of the cell, for interior points).
  std::vector<double> cmax(n, -inf), cmin(n, inf), tmax(n, 0.0), tmin(n, 0.0);
  Function vmax(P1), vmin(P1);
  std::span<double> bmax = vmax.x()->mutable_array();
  std::span<double> bmin = vmin.x()->mutable_array();
  std::fill(bmax.begin(), bmax.end(), -inf);
  std::fill(bmin.begin(), bmin.end(), inf);
  const auto emax = env.max_principal(), emin = env.min_principal();
  const auto et_max = env.max_times(), et_min = env.min_times();
  for (std::int32_t c : region_cells)
  {
    if (c >= n)
      continue;
    auto pts = S.dofmap()->cell_dofs(c);
    auto verts = P1->dofmap()->cell_dofs(c);
    for (std::size_t i = 0; i < pts.size(); ++i)
    {
      const double hi = emax[pts[i]], lo = emin[pts[i]];
      if (hi > cmax[c])
      {
        cmax[c] = hi;
        tmax[c] = et_max[pts[i]];
      }
      if (lo < cmin[c])
      {
        cmin[c] = lo;
        tmin[c] = et_min[pts[i]];
      }
      for (std::size_t k = 0; k < verts.size(); ++k)
      {
        if (vertex_points && pts.size() == verts.size() && k != i)
          continue;
        bmax[verts[k]] = std::max(bmax[verts[k]], hi);
        bmin[verts[k]] = std::min(bmin[verts[k]], lo);
      }
    }
  }
  vmax.x()->scatter_rev([](double a, double b) { return std::max(a, b); });
  vmin.x()->scatter_rev([](double a, double b) { return std::min(a, b); });
  vmax.x()->scatter_fwd();
  vmin.x()->scatter_fwd();
  for (double& v : bmax)
    v *= 1e-6;
  for (double& v : bmin)
    v *= 1e-6;
  for (std::int32_t c = 0; c < n; ++c)
  {
    cmax[c] *= 1e-6;
    cmin[c] *= 1e-6;
  }

  XdmfWriter xdmf(mesh, file, region_cells, false);
  xdmf.cell_field("max_principal_MPa", cmax);
  xdmf.cell_field("t_max_principal_s", tmax);
  xdmf.cell_field("min_principal_MPa", cmin);
  xdmf.cell_field("t_min_principal_s", tmin);
  xdmf.point_field("max_principal_vertex_MPa", vmax);
  xdmf.point_field("min_principal_vertex_MPa", vmin);
  for (const PointScalar& e : extra)
    xdmf.cell_field(e.name, cell_max_scalar(S, e.values, n));
  xdmf.write();
}
} // namespace damseis::results
