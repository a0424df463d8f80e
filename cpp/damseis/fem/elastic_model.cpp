#include "elastic_model.h"
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/assembler.h>
#include <dolfinx/fem/petsc.h>
#include <dolfinx/fem/utils.h>
#include <dolfinx/la/petsc.h>
#include <dolfinx/mesh/Mesh.h>
#include <dolfinx/mesh/MeshTags.h>
#include <stdexcept>

namespace damseis::fem
{
namespace dfem = dolfinx::fem;

std::shared_ptr<dolfinx::fem::FunctionSpace>
displacement_space(std::shared_ptr<dolfinx::mesh::Mesh> mesh, int degree)
{
  const FormSet& forms = form_set(mesh->topology().dim(), degree);
  return std::make_shared<dolfinx::fem::FunctionSpace>(
      dfem::create_functionspace(forms.space_of_stiffness, "v", mesh));
}

ElasticModel::ElasticModel(geometry::Model model, int degree,
                           const std::map<int, Material>& materials,
                           PlaneMode mode)
    : _model(std::move(model)),
      _forms(form_set(_model.mesh->topology().dim(), degree))
{
  auto mesh = _model.mesh;
  const int tdim = mesh->topology().dim();
  mesh->topology_mutable().create_connectivity(tdim - 1, tdim);
  _V = displacement_space(mesh, degree);
  _S = std::make_shared<FunctionSpace>(
      dfem::create_functionspace(_forms.space_of_stress, "tau", mesh));
  auto Q = std::make_shared<FunctionSpace>(
      dfem::create_functionspace(_forms.space_of_stiffness, "mu", mesh));
  _mu = std::make_shared<Function>(Q);
  _lmbda = std::make_shared<Function>(Q);
  _rho = std::make_shared<Function>(Q);

  // Cell-wise Lame constants and density from the region tags.
  std::span<double> mu = _mu->x()->mutable_array();
  std::span<double> lmbda = _lmbda->x()->mutable_array();
  std::span<double> rho = _rho->x()->mutable_array();
  const auto& tags = *_model.cell_tags;
  const auto& dofmap = *Q->dofmap();
  for (std::size_t i = 0; i < tags.indices().size(); ++i)
  {
    auto it = materials.find(tags.values()[i]);
    if (it == materials.end())
    {
      throw std::invalid_argument("no material given for region tag " +
                                  std::to_string(tags.values()[i]));
    }
    const Material& m = it->second;
    const double G = m.E / (2.0 * (1.0 + m.nu));
    double lam = m.E * m.nu / ((1.0 + m.nu) * (1.0 - 2.0 * m.nu));
    if (tdim == 2 && mode == PlaneMode::plane_stress)
      lam = 2.0 * lam * G / (lam + 2.0 * G);
    const std::int32_t dof = dofmap.cell_dofs(tags.indices()[i])[0];
    mu[dof] = G;
    lmbda[dof] = lam;
    rho[dof] = m.rho;
  }
  for (auto f : {_mu, _lmbda, _rho})
    f->x()->scatter_fwd();
}

std::shared_ptr<const dfem::FunctionSpace>
ElasticModel::output_space(const std::string& name)
{
  auto it = _outputs.find(name);
  if (it != _outputs.end())
    return it->second;
  auto space = std::make_shared<FunctionSpace>(
      dfem::create_functionspace(_forms.space_of_output, name, _model.mesh));
  _outputs.emplace(name, space);
  return space;
}

void ElasticModel::fix(const std::vector<int>& facet_tags)
{
  const auto& ft = *_model.facet_tags;
  std::vector<std::int32_t> facets;
  for (std::size_t i = 0; i < ft.indices().size(); ++i)
  {
    if (std::find(facet_tags.begin(), facet_tags.end(), ft.values()[i]) !=
        facet_tags.end())
    {
      facets.push_back(ft.indices()[i]);
    }
  }
  std::sort(facets.begin(), facets.end());
  const int tdim = _model.mesh->topology().dim();
  auto dofs = dfem::locate_dofs_topological(*_V, tdim - 1, facets, true);
  std::vector<double> zero(dim(), 0.0);
  auto value =
      std::make_shared<dfem::Constant<double>>(std::span<const double>(zero));
  _bcs.push_back(
      std::make_shared<dfem::DirichletBC<double>>(value, std::move(dofs), _V));
}

std::vector<std::int32_t> ElasticModel::fixed_dofs() const
{
  std::vector<std::int32_t> dofs;
  for (const auto& bc : _bcs)
  {
    auto [indices, num_owned] = bc->dof_indices();
    dofs.insert(dofs.end(), indices.begin(), indices.end());
  }
  std::sort(dofs.begin(), dofs.end());
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  return dofs;
}

std::map<std::string, std::shared_ptr<const dfem::Constant<double>>>
ElasticModel::constants(const Reservoir* r,
                        const std::array<double, 3>& g) const
{
  Reservoir none;
  const Reservoir& res = r ? *r : none;
  auto scalar = [](double v)
  { return std::make_shared<const dfem::Constant<double>>(v); };
  std::vector<double> gv(g.begin(), g.begin() + dim());
  return {{"gravity", std::make_shared<const dfem::Constant<double>>(
                          std::span<const double>(gv))},
          {"rho_w", scalar(res.rho_w)},
          {"g_w", scalar(res.g)},
          {"H_w", scalar(res.level)},
          {"H_0", scalar(res.depth())},
          {"floor_on", scalar(res.load_floor ? 1.0 : 0.0)}};
}

std::shared_ptr<dfem::Form<double>> ElasticModel::make_form(
    ufcx_form* form, std::vector<std::shared_ptr<const FunctionSpace>> spaces,
    const Reservoir* reservoir, const std::array<double, 3>& g,
    std::shared_ptr<const Function> u, std::shared_ptr<const Function> rho,
    std::shared_ptr<const Function> mu,
    std::shared_ptr<const Function> lmbda) const
{
  std::map<std::string, std::shared_ptr<const Function>> coefficients = {
      {"mu", mu ? mu : _mu},
      {"lmbda", lmbda ? lmbda : _lmbda},
      {"rho", rho ? rho : _rho}};
  if (u)
    coefficients["u"] = u;
  const std::map<dfem::IntegralType, const dolfinx::mesh::MeshTags<int>*>
      subdomains = {
          {dfem::IntegralType::exterior_facet, _model.facet_tags.get()}};
  return std::make_shared<dfem::Form<double>>(dfem::create_form<double>(
      *form, spaces, coefficients, constants(reservoir, g), subdomains,
      _model.mesh));
}

namespace
{
void finish_matrix(Mat A)
{
  MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY);
}
} // namespace

Mat ElasticModel::assemble_stiffness() const
{
  auto a = make_form(_forms.a_stiffness, {_V, _V});
  Mat A = dfem::petsc::create_matrix(*a, _matrix_type);
  MatZeroEntries(A);
  dfem::assemble_matrix(dolfinx::la::petsc::Matrix::set_block_fn(A, ADD_VALUES),
                        *a, _bcs);
  MatAssemblyBegin(A, MAT_FLUSH_ASSEMBLY);
  MatAssemblyEnd(A, MAT_FLUSH_ASSEMBLY);
  dfem::set_diagonal(dolfinx::la::petsc::Matrix::set_fn(A, INSERT_VALUES), *_V,
                     _bcs, 1.0);
  finish_matrix(A);
  return A;
}

Mat ElasticModel::assemble_mass(const Reservoir* reservoir) const
{
  auto m = make_form(_forms.a_mass, {_V, _V});
  Mat A = dfem::petsc::create_matrix(*m, _matrix_type);
  MatZeroEntries(A);
  auto add = dolfinx::la::petsc::Matrix::set_block_fn(A, ADD_VALUES);
  dfem::assemble_matrix(add, *m, _bcs);
  if (reservoir && reservoir->depth() > 0.0)
  {
    auto ma = make_form(_forms.a_added_mass, {_V, _V}, reservoir);
    dfem::assemble_matrix(add, *ma, _bcs);
  }
  // Keep the diagonal entries of fixed rows in the pattern (value 0) so the
  // matrix can be added to the stiffness with SAME_NONZERO_PATTERN.
  MatAssemblyBegin(A, MAT_FLUSH_ASSEMBLY);
  MatAssemblyEnd(A, MAT_FLUSH_ASSEMBLY);
  dfem::set_diagonal(dolfinx::la::petsc::Matrix::set_fn(A, INSERT_VALUES), *_V,
                     _bcs, 0.0);
  finish_matrix(A);
  return A;
}

Vec ElasticModel::assemble_load(const dfem::Form<double>& L,
                                bool apply_bc) const
{
  const auto& map = *_V->dofmap()->index_map;
  Vec b = dolfinx::la::petsc::create_vector(map, _V->dofmap()->index_map_bs());
  VecSet(b, 0.0);
  dfem::petsc::assemble_vector(b, L);
  VecGhostUpdateBegin(b, ADD_VALUES, SCATTER_REVERSE);
  VecGhostUpdateEnd(b, ADD_VALUES, SCATTER_REVERSE);
  if (apply_bc)
    dfem::petsc::set_bc(b, _bcs, nullptr);
  VecGhostUpdateBegin(b, INSERT_VALUES, SCATTER_FORWARD);
  VecGhostUpdateEnd(b, INSERT_VALUES, SCATTER_FORWARD);
  return b;
}

Vec ElasticModel::assemble_gravity(const std::array<double, 3>& g,
                                   const std::vector<int>& regions) const
{
  if (regions.empty())
    return assemble_load(*make_form(_forms.L_gravity, {_V}, nullptr, g), true);
  // The density on the cells of `regions`, zero elsewhere.
  auto rho = std::make_shared<Function>(_rho->function_space());
  std::span<const double> all = _rho->x()->array();
  std::span<double> some = rho->x()->mutable_array();
  const auto& tags = *_model.cell_tags;
  const auto& dofmap = *_rho->function_space()->dofmap();
  for (std::size_t i = 0; i < tags.indices().size(); ++i)
    if (std::find(regions.begin(), regions.end(), tags.values()[i]) !=
        regions.end())
    {
      const std::int32_t dof = dofmap.cell_dofs(tags.indices()[i])[0];
      some[dof] = all[dof];
    }
  return assemble_load(
      *make_form(_forms.L_gravity, {_V}, nullptr, g, nullptr, rho), true);
}

Vec ElasticModel::assemble_gravity_free(const std::array<double, 3>& g) const
{
  return assemble_load(*make_form(_forms.L_gravity, {_V}, nullptr, g), false);
}

Vec ElasticModel::assemble_hydrostatic(const Reservoir& reservoir) const
{
  return assemble_load(*make_form(_forms.L_hydrostatic, {_V}, &reservoir),
                       true);
}

Vec ElasticModel::assemble_hydrostatic_free(const Reservoir& reservoir) const
{
  return assemble_load(*make_form(_forms.L_hydrostatic, {_V}, &reservoir),
                       false);
}

Vec ElasticModel::assemble_load_form(
    const ufcx_form& form, const std::map<std::string, double>& values,
    const std::map<std::string, std::shared_ptr<const Function>>& coefficients)
    const
{
  std::map<std::string, std::shared_ptr<const dfem::Constant<double>>> c;
  for (const auto& [name, value] : values)
    c[name] = std::make_shared<const dfem::Constant<double>>(value);
  const std::map<dfem::IntegralType, const dolfinx::mesh::MeshTags<int>*>
      subdomains = {
          {dfem::IntegralType::exterior_facet, _model.facet_tags.get()},
          {dfem::IntegralType::interior_facet, _model.facet_tags.get()}};
  auto L = dfem::create_form<double>(form, {_V}, coefficients, c, subdomains,
                                     _model.mesh);
  return assemble_load(L, true);
}

Vec ElasticModel::assemble_group_load(
    const ufcx_form& form, const std::map<std::string, double>& values,
    const dolfinx::mesh::MeshTags<std::int32_t>& group, bool interior,
    bool apply_bc) const
{
  std::map<std::string, std::shared_ptr<const dfem::Constant<double>>> c;
  for (const auto& [name, value] : values)
    c[name] = std::make_shared<const dfem::Constant<double>>(value);
  const auto type = group.dim() == _model.mesh->topology().dim()
                        ? dfem::IntegralType::cell
                    : interior ? dfem::IntegralType::interior_facet
                               : dfem::IntegralType::exterior_facet;
  auto L = dfem::create_form<double>(form, {_V}, {}, c, {{type, &group}},
                                     _model.mesh);
  return assemble_load(L, apply_bc);
}

Vec ElasticModel::assemble_internal_force(const Function& u) const
{
  auto uptr = std::shared_ptr<const Function>(&u, [](const Function*) {});
  return assemble_load(
      *make_form(_forms.L_internal, {_V}, nullptr, {0, 0, 0}, uptr), false);
}

Mat ElasticModel::assemble_stress_operator() const
{
  auto a = make_form(_forms.a_stress, {_S, _V});
  Mat B = dfem::petsc::create_matrix(*a);
  MatZeroEntries(B);
  dfem::assemble_matrix(dolfinx::la::petsc::Matrix::set_block_fn(B, ADD_VALUES),
                        *a, {});
  finish_matrix(B);

  // Lumped weights of the stress points: B <- diag(1/w) B.
  auto L = make_form(_forms.L_stress_weight, {_S});
  const auto& map = *_S->dofmap()->index_map;
  Vec w = dolfinx::la::petsc::create_vector(map, _S->dofmap()->index_map_bs());
  VecSet(w, 0.0);
  dfem::petsc::assemble_vector(w, *L);
  VecGhostUpdateBegin(w, ADD_VALUES, SCATTER_REVERSE);
  VecGhostUpdateEnd(w, ADD_VALUES, SCATTER_REVERSE);
  VecReciprocal(w);
  MatDiagonalScale(B, w, nullptr);
  VecDestroy(&w);
  return B;
}

Vec ElasticModel::influence(int component) const
{
  const auto& map = *_V->dofmap()->index_map;
  const int bs = _V->dofmap()->index_map_bs();
  Vec r = dolfinx::la::petsc::create_vector(map, bs);
  VecSet(r, 0.0);
  double* x = nullptr;
  VecGetArray(r, &x);
  const std::int32_t n = map.size_local();
  for (std::int32_t i = 0; i < n; ++i)
    x[i * bs + component] = 1.0;
  VecRestoreArray(r, &x);
  dfem::petsc::set_bc(r, _bcs, nullptr, 0.0);
  VecGhostUpdateBegin(r, INSERT_VALUES, SCATTER_FORWARD);
  VecGhostUpdateEnd(r, INSERT_VALUES, SCATTER_FORWARD);
  return r;
}

Mat ElasticModel::assemble_facet_matrix(
    const ufcx_form& form,
    const std::map<std::string, std::vector<double>>& values,
    const dolfinx::mesh::MeshTags<std::int32_t>& facets) const
{
  std::map<std::string, std::shared_ptr<const dfem::Constant<double>>> c;
  for (const auto& [name, value] : values)
    c[name] = std::make_shared<const dfem::Constant<double>>(
        std::span<const double>(value));
  auto a = dfem::create_form<double>(
      form, {_V, _V}, {{"mu", _mu}, {"lmbda", _lmbda}, {"rho", _rho}}, c,
      {{dfem::IntegralType::exterior_facet, &facets}}, _model.mesh);
  Mat A = dfem::petsc::create_matrix(a, _matrix_type);
  MatZeroEntries(A);
  dfem::assemble_matrix(dolfinx::la::petsc::Matrix::set_block_fn(A, ADD_VALUES),
                        a, _bcs);
  finish_matrix(A);
  return A;
}

std::shared_ptr<ElasticModel::Function>
ElasticModel::zeroed_on(const Function& f, const std::vector<int>& regions,
                        bool keep) const
{
  auto g = std::make_shared<Function>(f.function_space());
  std::span<const double> in = f.x()->array();
  std::span<double> out = g->x()->mutable_array();
  std::copy(in.begin(), in.end(), out.begin());
  const auto& tags = *_model.cell_tags;
  const auto& dofmap = *f.function_space()->dofmap();
  for (std::size_t i = 0; i < tags.indices().size(); ++i)
  {
    const bool listed = std::find(regions.begin(), regions.end(),
                                  tags.values()[i]) != regions.end();
    if (listed != keep)
      for (std::int32_t dof : dofmap.cell_dofs(tags.indices()[i]))
        out[dof] = 0.0;
  }
  g->x()->scatter_fwd();
  return g;
}

ElasticModel::Partitioned
ElasticModel::assemble_partitioned(const std::vector<int>& explicit_regions,
                                   const Reservoir* reservoir) const
{
  const std::vector<std::shared_ptr<const dfem::DirichletBC<double>>> none;
  auto assemble = [&](const dfem::Form<double>& a)
  {
    Mat A = dfem::petsc::create_matrix(a, _matrix_type);
    MatZeroEntries(A);
    dfem::assemble_matrix(
        dolfinx::la::petsc::Matrix::set_block_fn(A, ADD_VALUES), a, none);
    finish_matrix(A);
    return A;
  };
  Partitioned p;
  p.K = assemble(*make_form(_forms.a_stiffness, {_V, _V}));
  p.K_implicit = assemble(
      *make_form(_forms.a_stiffness, {_V, _V}, nullptr, {0, 0, 0}, nullptr,
                 nullptr, zeroed_on(*_mu, explicit_regions, false),
                 zeroed_on(*_lmbda, explicit_regions, false)));
  // M: consistent on the implicit cells (and the added mass), then the
  // explicit cells' HRZ-lumped diagonal.
  p.M =
      assemble(*make_form(_forms.a_mass, {_V, _V}, nullptr, {0, 0, 0}, nullptr,
                          zeroed_on(*_rho, explicit_regions, false)));
  if (reservoir && reservoir->depth() > 0.0)
  {
    auto ma = make_form(_forms.a_added_mass, {_V, _V}, reservoir);
    dfem::assemble_matrix(
        dolfinx::la::petsc::Matrix::set_block_fn(p.M, ADD_VALUES), *ma, none);
    finish_matrix(p.M);
  }
  Mat M_e =
      assemble(*make_form(_forms.a_mass, {_V, _V}, nullptr, {0, 0, 0}, nullptr,
                          zeroed_on(*_rho, explicit_regions, true)));
  Vec ones, row_sums, diagonal;
  MatCreateVecs(M_e, &ones, &row_sums);
  VecDuplicate(ones, &diagonal);
  VecSet(ones, 1.0);
  MatMult(M_e, ones, row_sums);
  MatGetDiagonal(M_e, diagonal);
  PetscScalar mass = 0.0, trace = 0.0;
  VecSum(row_sums, &mass);
  VecSum(diagonal, &trace);
  if (trace > 0.0)
  {
    VecScale(diagonal, mass / trace);
    MatDiagonalSet(p.M, diagonal, ADD_VALUES);
  }
  p.M_explicit = diagonal;
  for (Vec* v : {&ones, &row_sums})
    VecDestroy(v);
  MatDestroy(&M_e);
  return p;
}

double ElasticModel::region_measure(int region) const
{
  const auto& mesh = *_model.mesh;
  const int tdim = mesh.topology().dim();
  const std::int32_t num_owned = mesh.topology().index_map(tdim)->size_local();
  const auto& x = mesh.geometry().x();
  const auto& dofs = mesh.geometry().dofmap();
  const auto& tags = *_model.cell_tags;
  double local = 0.0;
  for (std::size_t i = 0; i < tags.indices().size(); ++i)
  {
    const std::int32_t c = tags.indices()[i];
    if (c >= num_owned || tags.values()[i] != region)
      continue;
    auto v = dofs.links(c);
    auto p = [&](int k, int j) { return x[3 * v[k] + j] - x[3 * v[0] + j]; };
    if (tdim == 2)
      local += 0.5 * std::abs(p(1, 0) * p(2, 1) - p(1, 1) * p(2, 0));
    else
    {
      local += std::abs(p(1, 0) * (p(2, 1) * p(3, 2) - p(2, 2) * p(3, 1)) -
                        p(1, 1) * (p(2, 0) * p(3, 2) - p(2, 2) * p(3, 0)) +
                        p(1, 2) * (p(2, 0) * p(3, 1) - p(2, 1) * p(3, 0))) /
               6.0;
    }
  }
  double total = 0.0;
  MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, mesh.comm());
  return total;
}
} // namespace damseis::fem
