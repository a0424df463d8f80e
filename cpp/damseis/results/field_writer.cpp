#include "field_writer.h"
#include "principal.h"
#include <algorithm>
#include <cmath>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/DofMap.h>
#include <dolfinx/mesh/Mesh.h>
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

/// Voigt stress vector (3 or 6 components) -> row-major tensor.
void to_tensor(const double* s, int tdim, double* t)
{
  if (tdim == 2)
  {
    t[0] = s[0];
    t[1] = t[2] = s[2];
    t[3] = s[1];
    return;
  }
  t[0] = s[0];
  t[4] = s[1];
  t[8] = s[2];
  t[1] = t[3] = s[3];
  t[5] = t[7] = s[4];
  t[2] = t[6] = s[5];
}
} // namespace

std::vector<double> cell_average_tensor(const dolfinx::fem::FunctionSpace& S,
                                        std::span<const double> s,
                                        int num_cells, int tdim)
{
  const int nc = S.dofmap()->index_map_bs();
  std::vector<double> avg(nc),
      out(static_cast<std::size_t>(num_cells) * tdim * tdim);
  for (int c = 0; c < num_cells; ++c)
  {
    auto dofs = S.dofmap()->cell_dofs(c);
    std::fill(avg.begin(), avg.end(), 0.0);
    for (std::int32_t d : dofs)
    {
      for (int k = 0; k < nc; ++k)
        avg[k] += s[d * nc + k] / dofs.size();
    }
    to_tensor(avg.data(), tdim, out.data() + c * tdim * tdim);
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

FieldWriter::FieldWriter(
    fem::ElasticModel& model, const std::filesystem::path& file,
    std::shared_ptr<const dolfinx::fem::FunctionSpace> stress_space,
    const std::vector<std::string>& extra)
    : _model(model), _S(stress_space ? stress_space : model.S())
{
  auto mesh = model.mesh();
  _file = std::make_unique<dolfinx::io::XDMFFile>(mesh->comm(), file, "w");
  _file->write_mesh(*mesh);
  _u = std::make_shared<Function>(model.output_space("u_vertex"));
  _sig = std::make_shared<Function>(model.output_space("sig_cell"));
  _pmax = std::make_shared<Function>(model.output_space("s_cell"));
  _pmin = std::make_shared<Function>(model.output_space("s_cell"));
  _u->name = "displacement";
  _sig->name = "stress";
  _pmax->name = "max_principal_stress";
  _pmin->name = "min_principal_stress";
  for (const std::string& name : extra)
  {
    _extra.push_back(std::make_shared<Function>(model.output_space("s_cell")));
    _extra.back()->name = name;
  }
}

FieldWriter::~FieldWriter()
{
  _file->close();
}

void FieldWriter::write(const Function& u, std::span<const double> s, double t,
                        const std::vector<std::span<const double>>& extra)
{
  _u->interpolate(u);
  auto mesh = _model.mesh();
  const int tdim = mesh->topology().dim();
  const std::int32_t n = owned_cells(*mesh);
  const auto& S = *_S;
  std::vector<double> tensors = cell_average_tensor(S, s, n, tdim);
  std::span<double> sig = _sig->x()->mutable_array();
  std::span<double> pmax = _pmax->x()->mutable_array();
  std::span<double> pmin = _pmin->x()->mutable_array();
  const auto& tdofs = *_sig->function_space()->dofmap();
  const auto& sdofs = *_pmax->function_space()->dofmap();
  const int ts = tdim * tdim;
  for (std::int32_t c = 0; c < n; ++c)
  {
    const double* tc = tensors.data() + c * ts;
    std::copy_n(tc, ts, sig.data() + tdofs.cell_dofs(c)[0] * ts);
    std::array<double, 6> v;
    if (tdim == 2)
      v = {tc[0], tc[3], tc[1], 0, 0, 0};
    else
      v = {tc[0], tc[4], tc[8], tc[1], tc[5], tc[2]};
    auto [p1, p3] = principal_extremes(v.data(), tdim == 2 ? 3 : 6);
    pmax[sdofs.cell_dofs(c)[0]] = p1;
    pmin[sdofs.cell_dofs(c)[0]] = p3;
  }
  for (std::size_t i = 0; i < _extra.size() && i < extra.size(); ++i)
  {
    const auto cmax = cell_max_scalar(S, extra[i], n);
    std::span<double> y = _extra[i]->x()->mutable_array();
    const auto& dm = *_extra[i]->function_space()->dofmap();
    for (std::int32_t c = 0; c < n; ++c)
      y[dm.cell_dofs(c)[0]] = cmax[c];
  }
  for (auto& f : {_sig, _pmax, _pmin})
    f->x()->scatter_fwd();
  for (auto& f : _extra)
    f->x()->scatter_fwd();
  for (auto& f : {_u, _sig, _pmax, _pmin})
    _file->write_function(*f, t);
  for (auto& f : _extra)
    _file->write_function(*f, t);
}

void write_envelopes(
    fem::ElasticModel& model, const StressEnvelope& env,
    const std::filesystem::path& file,
    std::shared_ptr<const dolfinx::fem::FunctionSpace> stress_space,
    bool vertex_points, const std::vector<PointScalar>& extra)
{
  auto mesh = model.mesh();
  const std::int32_t n = owned_cells(*mesh);
  const auto& S = stress_space ? *stress_space : *model.S();
  const auto Q = model.output_space("s_cell");
  const auto P1 = model.output_space("s_vertex");
  const double inf = std::numeric_limits<double>::infinity();

  Function cmax(Q), cmin(Q), vmax(P1), vmin(P1);
  cmax.name = "max_principal_envelope";
  cmin.name = "min_principal_envelope";
  vmax.name = "max_principal_envelope_vertex";
  vmin.name = "min_principal_envelope_vertex";
  std::span<double> amax = cmax.x()->mutable_array();
  std::span<double> amin = cmin.x()->mutable_array();
  std::span<double> bmax = vmax.x()->mutable_array();
  std::span<double> bmin = vmin.x()->mutable_array();
  std::fill(bmax.begin(), bmax.end(), -inf);
  std::fill(bmin.begin(), bmin.end(), inf);
  auto emax = env.max_principal();
  auto emin = env.min_principal();
  for (std::int32_t c = 0; c < n; ++c)
  {
    auto pts = S.dofmap()->cell_dofs(c);
    auto verts = P1->dofmap()->cell_dofs(c);
    double cm = -inf, cn = inf;
    for (std::size_t i = 0; i < pts.size(); ++i)
    {
      const double hi = emax[pts[i]], lo = emin[pts[i]];
      cm = std::max(cm, hi);
      cn = std::min(cn, lo);
      // A stress point at a vertex (degree 2) feeds that vertex; a single
      // cell-centre point (degree 1) feeds all vertices of the cell.
      for (std::size_t k = 0; k < verts.size(); ++k)
      {
        if (vertex_points && pts.size() == verts.size() && k != i)
          continue;
        bmax[verts[k]] = std::max(bmax[verts[k]], hi);
        bmin[verts[k]] = std::min(bmin[verts[k]], lo);
      }
    }
    amax[Q->dofmap()->cell_dofs(c)[0]] = cm;
    amin[Q->dofmap()->cell_dofs(c)[0]] = cn;
  }
  vmax.x()->scatter_rev([](double a, double b) { return std::max(a, b); });
  vmin.x()->scatter_rev([](double a, double b) { return std::min(a, b); });
  // Points outside the tracked region are written as NaN (blank in
  // ParaView).
  for (Function* f : {&cmax, &cmin, &vmax, &vmin})
  {
    for (double& v : f->x()->mutable_array())
    {
      if (std::isinf(v))
        v = std::numeric_limits<double>::quiet_NaN();
    }
    f->x()->scatter_fwd();
  }
  std::vector<std::unique_ptr<Function>> more;
  for (const PointScalar& e : extra)
  {
    more.push_back(std::make_unique<Function>(Q));
    more.back()->name = e.name;
    const auto cm = cell_max_scalar(S, e.values, n);
    std::span<double> y = more.back()->x()->mutable_array();
    for (std::int32_t c = 0; c < n; ++c)
      y[Q->dofmap()->cell_dofs(c)[0]] = cm[c];
    more.back()->x()->scatter_fwd();
  }
  dolfinx::io::XDMFFile xdmf(mesh->comm(), file, "w");
  xdmf.write_mesh(*mesh);
  for (Function* f : {&cmax, &cmin, &vmax, &vmin})
    xdmf.write_function(*f, 0.0);
  for (auto& f : more)
    xdmf.write_function(*f, 0.0);
  xdmf.close();
}
} // namespace damseis::results
