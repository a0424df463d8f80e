#include "concrete_model.h"
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <damseis/material/plane_stress.h>
#include <dolfinx/common/IndexMap.h>
#include <dolfinx/fem/assemble_matrix_impl.h>
#include <dolfinx/fem/assemble_vector_impl.h>
#include <dolfinx/fem/assembler.h>
#include <dolfinx/fem/petsc.h>
#include <dolfinx/fem/utils.h>
#include <dolfinx/la/petsc.h>
#include <dolfinx/mesh/Mesh.h>
#include <dolfinx/mesh/MeshTags.h>
#include <numeric>
#include <stdexcept>

namespace damseis::fem
{
namespace dfem = dolfinx::fem;

namespace
{
/// Row-major view for Expression::eval.
struct RowMajor
{
  double* data;
  std::size_t cols;
  double& operator()(std::size_t i, std::size_t j)
  {
    return data[i * cols + j];
  }
};

/// |a - b|^2 in the Frobenius norm of the stress tensors (Voigt 6, shears
/// counted twice): the norm of HtcConcrete::admissible_radius.
double tensor_distance2(const material::Vector6& a, const material::Vector6& b)
{
  double d2 = 0.0;
  for (int i = 0; i < 3; ++i)
    d2 += (a[i] - b[i]) * (a[i] - b[i]) +
          2.0 * (a[3 + i] - b[3 + i]) * (a[3 + i] - b[3 + i]);
  return d2;
}

/// Largest absolute principal value of a strain (rate) in Voigt form with
/// engineering shear.
double max_abs_principal_strain(const std::array<double, 6>& e)
{
  Eigen::Matrix3d t;
  t << e[0], 0.5 * e[3], 0.5 * e[5], 0.5 * e[3], e[1], 0.5 * e[4], 0.5 * e[5],
      0.5 * e[4], e[2];
  const Eigen::Vector3d l =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(t, Eigen::EigenvaluesOnly)
          .eigenvalues();
  return std::max(std::abs(l[0]), std::abs(l[2]));
}
} // namespace

ConcreteModel::ConcreteModel(
    ElasticModel& fe,
    const std::map<int, material::ConcreteParameters>& concrete,
    const std::map<int, Material>& elastic, PlaneMode plane)
    : _fe(fe), _plane(plane), _forms(plasticity_form_set(fe.dim(), fe.degree()))
{
  auto mesh = fe.model().mesh;
  const int tdim = mesh->topology().dim();
  if (tdim == 3)
  {
    _nc = 6;
    _voigt = {0, 1, 2, 3, 4, 5};
  }
  _Sq = std::make_shared<dfem::FunctionSpace>(
      dfem::create_functionspace(_forms.space_of_residual, "sig", mesh));
  _Cq = std::make_shared<dfem::FunctionSpace>(
      dfem::create_functionspace(_forms.space_of_tangent, "Ct", mesh));
  _sig = std::make_shared<dfem::Function<double>>(_Sq);
  _Ct = std::make_shared<dfem::Function<double>>(_Cq);
  _u = std::make_shared<dfem::Function<double>>(fe.V());
  _f_work = dolfinx::la::petsc::Vector(
      dolfinx::la::petsc::create_vector(*fe.V()->dofmap()->index_map,
                                        fe.V()->dofmap()->index_map_bs()),
      false);
  auto V = fe.V();
  _L = std::make_shared<dfem::Form<double>>(dfem::create_form<double>(
      *_forms.L_residual, {V}, {{"sig", _sig}}, {}, {}, mesh));
  _a = std::make_shared<dfem::Form<double>>(dfem::create_form<double>(
      *_forms.a_tangent, {V, V}, {{"Ct", _Ct}}, {}, {}, mesh));
  _strain = std::make_unique<dfem::Expression<double>>(
      dfem::create_expression<double>(*_forms.strain, {{"u", _u}}, {}, mesh));
  _nq = static_cast<int>(_strain->X().second[0]);

  auto cmap = mesh->topology().index_map(tdim);
  _num_owned_cells = cmap->size_local();
  _num_cells = cmap->size_local() + cmap->num_ghosts();
  const std::size_t np = static_cast<std::size_t>(_num_cells) * _nq;

  // Point coordinates (and the point -> dof map).
  {
    _cells.resize(_num_cells);
    std::iota(_cells.begin(), _cells.end(), 0);
    auto position = dfem::create_expression<double>(
        *_forms.position,
        std::map<std::string, std::shared_ptr<const dfem::Function<double>>>{},
        std::map<std::string, std::shared_ptr<const dfem::Constant<double>>>{},
        mesh);
    std::vector<double> xq(np * tdim);
    RowMajor view{xq.data(), static_cast<std::size_t>(_nq) * tdim};
    position.eval(std::span<const std::int32_t>(_cells), view);
    const auto& dm = *_Sq->dofmap();
    const std::int32_t ndofs =
        dm.index_map->size_local() + dm.index_map->num_ghosts();
    _coords.assign(3 * ndofs, 0.0);
    _dof.resize(np);
    _dof_c.resize(np);
    for (std::int32_t c = 0; c < _num_cells; ++c)
    {
      auto dofs = dm.cell_dofs(c);
      for (int q = 0; q < _nq; ++q)
      {
        const std::size_t p = static_cast<std::size_t>(c) * _nq + q;
        _dof[p] = dofs[q];
        _dof_c[p] = _Cq->dofmap()->cell_dofs(c)[q];
        for (int k = 0; k < tdim; ++k)
          _coords[3 * dofs[q] + k] = xq[tdim * p + k];
      }
    }
    _sig_committed.assign(_nc * ndofs, 0.0);
    for (auto& o : _out)
      o.assign(ndofs, 0.0);
  }

  // Material object per cell: region and crack-band width bin.
  std::vector<int> region(_num_cells, -1);
  const auto& tags = *fe.model().cell_tags;
  for (std::size_t i = 0; i < tags.indices().size(); ++i)
    region[tags.indices()[i]] = tags.values()[i];
  const auto& x = mesh->geometry().x();
  const auto& gdofs = mesh->geometry().dofmap();
  std::map<std::pair<int, int>, std::int32_t> bins;
  _cell_material.resize(_num_cells);
  // Cells with a lowered tensile strength, with a raised tensile energy.
  std::array<std::int64_t, 2> large_local = {0, 0};
  for (std::int32_t c = 0; c < _num_cells; ++c)
  {
    const int r = region[c];
    auto v = gdofs.links(c);
    auto d = [&](int k, int j) { return x[3 * v[k] + j] - x[3 * v[0] + j]; };
    const double h =
        tdim == 2 ? std::sqrt(std::abs(d(1, 0) * d(2, 1) - d(1, 1) * d(2, 0)))
                  : std::cbrt(std::abs(
                        d(1, 0) * (d(2, 1) * d(3, 2) - d(2, 2) * d(3, 1)) -
                        d(1, 1) * (d(2, 0) * d(3, 2) - d(2, 2) * d(3, 0)) +
                        d(1, 2) * (d(2, 0) * d(3, 1) - d(2, 1) * d(3, 0))));
    const auto it = concrete.find(r);
    const int bin =
        it == concrete.end()
            ? 0
            : static_cast<int>(std::lround(std::log(h) / std::log(1.01)));
    auto [pos, inserted] =
        bins.emplace(std::make_pair(r, bin), std::int32_t(_dynamic.size()));
    if (inserted)
    {
      material::ConcreteParameters p;
      if (it != concrete.end())
      {
        p = it->second;
        p.element_size = std::pow(1.01, bin);
        // No material sub-stepping (max_substeps as given, default 1): a
        // point whose single backward-Euler step fails fails the global
        // trial, whose line search or step cut shortens the increment.
        // The sub-stepped retries (up to 4, with a finite-difference
        // tangent of 12 more sub-stepped maps) took half the return-map
        // time of the plastic Koyna Table 1 run and changed nothing: the
        // same Newton iterations, step cuts and crest history
        // (bench/results/koyna-nonlinear-return-map-2026-11-22.md).
      }
      else
      {
        auto e = elastic.find(r);
        if (e == elastic.end())
          throw std::invalid_argument("no material given for region tag " +
                                      std::to_string(r));
        p.mode = material::Mode::elastic;
        p.E = e->second.E;
        p.nu = e->second.nu;
      }
      _dynamic.push_back(std::make_unique<material::HtcConcrete>(p));
      if (p.mode == material::Mode::viscoplastic)
        p.mode = material::Mode::plastic;
      _static.push_back(std::make_unique<material::HtcConcrete>(p));
      _De.push_back(_dynamic.back()->elastic_tangent());
      _ct_elastic.emplace_back();
      condense(_De.back(), _ct_elastic.back().data());
    }
    _cell_material[c] = pos->second;
    // Owned concrete cells above the snap-back limit of the softening.
    const material::HtcConcrete& m = *_dynamic[pos->second];
    if (c < _num_owned_cells && m.parameters().mode != material::Mode::elastic)
    {
      const auto& d = m.derived();
      if (d.tension_strength_reduced)
      {
        ++large_local[0];
        _reduced_ft[0] = std::min(_reduced_ft[0], d.ft0);
        _reduced_ft[1] = std::max(_reduced_ft[1], d.ft0);
      }
      large_local[1] += d.tension_energy_raised;
    }
  }
  std::array<std::int64_t, 2> large;
  MPI_Allreduce(large_local.data(), large.data(), 2, MPI_INT64_T, MPI_SUM,
                mesh->comm());
  _reduced_cells = large[0];
  _raised_cells = large[1];
  _reduced_ft[1] = -_reduced_ft[1];
  MPI_Allreduce(MPI_IN_PLACE, _reduced_ft.data(), 2, MPI_DOUBLE, MPI_MIN,
                mesh->comm());
  _reduced_ft[1] = -_reduced_ft[1];
  const std::int64_t owned_points =
      static_cast<std::int64_t>(_num_owned_cells) * _nq;
  MPI_Allreduce(&owned_points, &_num_owned_points, 1, MPI_INT64_T, MPI_SUM,
                mesh->comm());

  _state.assign(np, material::State{});
  _trial = _state;
  _ball.assign(np, ElasticBall{});
  _eps.assign(np, {0, 0, 0, 0, 0, 0});
  _eps_trial = _eps;
  _dep = _eps;
  _strain_values.assign(np * _nc, 0.0);
  // Initial tangent: elastic.
  std::span<double> ct = _Ct->x()->mutable_array();
  for (std::int32_t c = 0; c < _num_cells; ++c)
  {
    const auto D = _dynamic[_cell_material[c]]->elastic_tangent();
    for (int q = 0; q < _nq; ++q)
    {
      condense(D,
               &ct[_nc * _nc * _dof_c[static_cast<std::size_t>(c) * _nq + q]]);
    }
  }
}

bool ConcreteModel::elastic_point(
    const material::HtcConcrete& m, std::int32_t material,
    const ElasticBall& ball, const material::State& old,
    const std::array<double, 6>& eps_old, const double* e,
    std::array<double, 6>& eps_new, material::State& out, double* ct) const
{
  const material::Vector6 de = strain_increment(e, eps_old, m.derived().nu);
  const material::Matrix6& D = _De[material];
  material::Vector6 tr;
  for (int i = 0; i < 6; ++i)
  {
    double v = old.stress[i];
    for (int j = 0; j < 6; ++j)
      v += D[i * 6 + j] * de[j];
    tr[i] = v;
  }
  if (_nc == 3 && _plane == PlaneMode::plane_stress)
  {
    // integrate_point()'s test of sigma_zz = 0 (its first iterate is this).
    double smax = 0.0;
    for (double v : tr)
      smax = std::max(smax, std::abs(v));
    if (std::abs(tr[2]) > 1e-8 * (smax + m.derived().ft0))
      return false;
  }
  const bool inside =
      ball.fits(m, old) && tensor_distance2(tr, ball.centre) <= ball.r2;
  if (!inside && !m.admissible(tr, old.kappa_c, old.kappa_t))
    return false;
  out = old;
  out.stress = tr;
  out.kappa_c_rate = out.kappa_t_rate = 0.0;
  for (int i = 0; i < 6; ++i)
    eps_new[i] = eps_old[i] + de[i];
  std::copy_n(_ct_elastic[material].data(), _nc * _nc, ct);
  return true;
}

material::Update ConcreteModel::integrate_point(
    const material::HtcConcrete& m, const material::State& old,
    const std::array<double, 6>& eps_old, const double* e, double dt,
    std::array<double, 6>& eps_new, double* ct, int& return_maps,
    std::int64_t& local_iterations) const
{
  material::Vector6 de = strain_increment(e, eps_old, -1.0);
  material::Update up;
  if (_nc == 6 || _plane == PlaneMode::plane_strain)
  {
    up = m.integrate(old, de, dt);
    return_maps = 1;
    local_iterations = up.iterations;
  }
  else
  {
    material::PlaneStressCounts counts;
    up = material::integrate_plane_stress(m, old, de, dt, &counts);
    return_maps = counts.return_maps;
    local_iterations = counts.local_iterations;
  }
  for (int i = 0; i < 6; ++i)
    eps_new[i] = eps_old[i] + de[i];
  // A non-finite algorithmic tangent (e.g. a degenerate corner) is replaced
  // by the elastic one: still a valid Newton-like matrix for the global
  // iteration, whose residual decides convergence.
  if (!std::all_of(up.tangent.begin(), up.tangent.end(),
                   [](double v) { return std::isfinite(v); }))
  {
    up.tangent = m.elastic_tangent();
  }
  // Plane stress: the condensation divides by the out-of-plane slope
  // d sigma_zz / d eps_zz, which vanishes where the point is perfectly
  // plastic along zz (exactly 0 at a fully cracked point, ft = 0: an
  // infinite tangent, and the global matrix has no factorisation and GMRES
  // breaks down). Where |slope| < 1e-6 of the elastic one the elastic slope
  // is used, as the local sigma_zz = 0 iteration does: the condensed tangent
  // of such a point stays (near) zero, as it should; the global residual
  // still decides convergence. (Thresholds from 1e-6 to 5e-2 gave identical
  // rcc_gravity runs (4 s); 1e-1 breaks the finite-difference tangent test.)
  if (_nc == 3 && _plane == PlaneMode::plane_stress)
  {
    const double e22 = m.elastic_tangent()[2 * 6 + 2];
    if (!(std::abs(up.tangent[2 * 6 + 2]) >= 1e-6 * e22))
      up.tangent[2 * 6 + 2] = e22;
  }
  condense(up.tangent, ct);
  return up;
}

void ConcreteModel::condense(const material::Matrix6& T, double* ct) const
{
  const bool plane_stress = _nc == 3 && _plane == PlaneMode::plane_stress;
  for (int i = 0; i < _nc; ++i)
  {
    for (int j = 0; j < _nc; ++j)
    {
      double v = T[_voigt[i] * 6 + _voigt[j]];
      if (plane_stress)
        v -= T[_voigt[i] * 6 + 2] * T[2 * 6 + _voigt[j]] / T[2 * 6 + 2];
      ct[i * _nc + j] = v;
    }
  }
}

material::Vector6 ConcreteModel::strain_increment(
    const double* e, const std::array<double, 6>& eps_old, double nu) const
{
  if (_nc == 6)
  {
    material::Vector6 de;
    for (int i = 0; i < 6; ++i)
      de[i] = e[i] - eps_old[i];
    return de;
  }
  const double d0 = e[0] - eps_old[0], d1 = e[1] - eps_old[1];
  const double dzz = _plane == PlaneMode::plane_stress && nu >= 0.0
                         ? -nu / (1.0 - nu) * (d0 + d1)
                         : 0.0;
  return {d0, d1, dzz, e[2] - eps_old[3], 0.0, 0.0};
}

MaterialUpdateStats ConcreteModel::update(const dfem::Function<double>& u,
                                          double dt)
{
  std::copy(u.x()->array().begin(), u.x()->array().end(),
            _u->x()->mutable_array().begin());
  RowMajor view{_strain_values.data(), static_cast<std::size_t>(_nq) * _nc};
  _strain->eval(std::span<const std::int32_t>(_cells), view);
  _trial_dt = dt;
  if (trial_extrapolated())
  {
    // IMPL-EX: the implicit return map waits for accept().
    extrapolate_stress(dt);
    MaterialUpdateStats s;
    s.points = _num_owned_points;
    return s;
  }
  return update_points(dt);
}

MaterialUpdateStats ConcreteModel::update_points(double dt)
{
  std::span<double> sig = _sig->x()->mutable_array();
  std::span<double> ct = _Ct->x()->mutable_array();
  std::int64_t counts[7] = {0, 0, 0, 0, 0, 0, 0};
  double seconds = 0.0; // owned points' return maps
  int max_it = 0;
  // A trial with a failed point is discarded by the caller (the line search
  // shortens the step, or the step is cut): the update stops at the first
  // failure of an owned point (a ghost point's failure is its owner's).
  bool failed = false;
  _tangent_cells.clear();
  for (std::int32_t c = 0; c < _num_cells && !failed; ++c)
  {
    const auto& m = material_of(c, dt);
    for (int q = 0; q < _nq; ++q)
    {
      const std::size_t p = static_cast<std::size_t>(c) * _nq + q;
      const std::int32_t dof = _dof[p];
      double* ct_p = &ct[_nc * _nc * _dof_c[p]];
      if (elastic_point(m, _cell_material[c], _ball[p], _state[p], _eps[p],
                        &_strain_values[_nc * p], _eps_trial[p], _trial[p],
                        ct_p))
      {
        for (int i = 0; i < _nc; ++i)
          sig[_nc * dof + i] = _trial[p].stress[_voigt[i]];
        counts[0] += c < _num_owned_cells;
        continue;
      }
      if (c < _num_owned_cells &&
          (_tangent_cells.empty() || _tangent_cells.back() != c))
      {
        _tangent_cells.push_back(c);
      }
      int maps = 0;
      std::int64_t its = 0;
      const auto t0 = std::chrono::steady_clock::now();
      const material::Update up =
          integrate_point(m, _state[p], _eps[p], &_strain_values[_nc * p], dt,
                          _eps_trial[p], ct_p, maps, its);
      if (c < _num_owned_cells)
      {
        seconds +=
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0)
                .count();
        ++counts[6];
      }
      _trial[p] = up.state;
      for (int i = 0; i < _nc; ++i)
        sig[_nc * dof + i] = up.state.stress[_voigt[i]];
      if (!up.converged && std::getenv("DAMSEIS_MATERIAL_TRACE"))
      {
        const auto& o = _state[p];
        std::fprintf(
            stderr,
            "material failure after %d return maps, %ld local iterations: dt "
            "%.17g h %.17g kc %.17g kt %.17g kcd %.17g "
            "ktd %.17g\n  stress %.17g %.17g %.17g %.17g %.17g %.17g\n"
            "  d_eps %.17g %.17g %.17g %.17g %.17g %.17g\n",
            maps, static_cast<long>(its), dt, m.parameters().element_size,
            o.kappa_c, o.kappa_t, o.kappa_c_rate, o.kappa_t_rate, o.stress[0],
            o.stress[1], o.stress[2], o.stress[3], o.stress[4], o.stress[5],
            _eps_trial[p][0] - _eps[p][0], _eps_trial[p][1] - _eps[p][1],
            _eps_trial[p][2] - _eps[p][2], _eps_trial[p][3] - _eps[p][3],
            _eps_trial[p][4] - _eps[p][4], _eps_trial[p][5] - _eps[p][5]);
      }
      if (c < _num_owned_cells)
      {
        ++counts[0];
        counts[1] += up.active != 0;
        counts[2] += !up.converged;
        counts[3] += up.substeps > 1;
        counts[4] += maps;
        counts[5] += its;
        max_it = std::max(max_it, up.iterations);
        if (!up.converged)
        {
          failed = true;
          break;
        }
      }
    }
  }
  MaterialUpdateStats s;
  std::int64_t total[7];
  MPI_Comm comm = _fe.mesh()->comm();
  MPI_Allreduce(counts, total, 7, MPI_INT64_T, MPI_SUM, comm);
  MPI_Allreduce(&seconds, &s.return_map_seconds, 1, MPI_DOUBLE, MPI_SUM, comm);
  MPI_Allreduce(&max_it, &s.max_iterations, 1, MPI_INT, MPI_MAX, comm);
  s.points = total[0];
  s.inelastic = total[1];
  s.failed = total[2];
  s.substepped = total[3];
  s.return_maps = total[4];
  s.local_iterations = total[5];
  s.returned_points = total[6];
  return s;
}

void ConcreteModel::extrapolate_stress(double dt)
{
  // r = 0 in the first dynamic step (the static stage's increments are not
  // a rate).
  const double r = _dt_last > 0.0 ? dt / _dt_last : 0.0;
  _tangent_cells.clear(); // the extrapolated tangent is elastic
  std::span<double> sig = _sig->x()->mutable_array();
  std::span<double> ct = _Ct->x()->mutable_array();
  for (std::int32_t c = 0; c < _num_cells; ++c)
  {
    const std::int32_t mat = _cell_material[c];
    for (int q = 0; q < _nq; ++q)
    {
      const std::size_t p = static_cast<std::size_t>(c) * _nq + q;
      const double* e = &_strain_values[_nc * p];
      const auto& eps = _eps[p];
      const auto& dep = _dep[p];
      const auto& s0 = _state[p].stress;
      double* out = &sig[_nc * _dof[p]];
      if (_nc == 6)
      {
        // The elastic strain increment, extrapolated plastic part removed.
        double de[6];
        for (int j = 0; j < 6; ++j)
          de[j] = e[j] - eps[j] - r * dep[j];
        const auto& D = _De[mat];
        for (int i = 0; i < 6; ++i)
        {
          double v = s0[i];
          for (int j = 0; j < 6; ++j)
            v += D[6 * i + j] * de[j];
          out[i] = v;
        }
      }
      else if (_plane == PlaneMode::plane_stress)
      {
        // sigma_zz stays 0: the condensed elastic matrix on the in-plane
        // elastic strain increment.
        const double de[3] = {e[0] - eps[0] - r * dep[0],
                              e[1] - eps[1] - r * dep[1],
                              e[2] - eps[3] - r * dep[3]};
        const auto& D = _ct_elastic[mat];
        for (int i = 0; i < 3; ++i)
          out[i] = s0[_voigt[i]] + D[3 * i] * de[0] + D[3 * i + 1] * de[1] +
                   D[3 * i + 2] * de[2];
      }
      else
      {
        // eps_zz = 0: the elastic strain increment has -r dep_zz there.
        const double de[6] = {e[0] - eps[0] - r * dep[0],
                              e[1] - eps[1] - r * dep[1],
                              -r * dep[2],
                              e[2] - eps[3] - r * dep[3],
                              -r * dep[4],
                              -r * dep[5]};
        const auto& D = _De[mat];
        for (int i = 0; i < 3; ++i)
        {
          const int row = _voigt[i];
          double v = s0[row];
          for (int j = 0; j < 6; ++j)
            v += D[6 * row + j] * de[j];
          out[i] = v;
        }
      }
      std::copy_n(_ct_elastic[mat].data(), _nc * _nc,
                  &ct[_nc * _nc * _dof_c[p]]);
    }
  }
}

bool ConcreteModel::accept(MaterialUpdateStats* implicit)
{
  const std::size_t np = _state.size();
  if (trial_extrapolated())
  {
    // IMPL-EX: the implicit return map at the balanced strains updates the
    // state (and the stress coefficient: the reported stress is the
    // implicit one, on or inside the surfaces).
    _sig_extrapolated.assign(_sig->x()->array().begin(),
                             _sig->x()->array().end());
    const MaterialUpdateStats st = update_points(_trial_dt);
    if (implicit)
      *implicit = st;
    if (st.failed > 0)
      return false;
  }
  if (_trial_dt > 0.0)
  {
    // The plastic strain increment of a dynamic step, for the next
    // extrapolation (IMPL-EX, or the extrapolated Newton predictor).
    for (std::size_t p = 0; p < np; ++p)
      for (int i = 0; i < 6; ++i)
        _dep[p][i] = _trial[p].plastic_strain[i] - _state[p].plastic_strain[i];
    _dt_last = _trial_dt;
  }
  for (std::size_t p = 0; p < np; ++p)
  {
    const std::int32_t dof = _dof[p];
    const auto& s = _trial[p];
    _out[0][dof] = s.kappa_t;
    _out[1][dof] = s.kappa_c;
    _out[2][dof] = s.kappa_t_rate;
    _out[3][dof] = s.kappa_c_rate;
    if (_trial_dt > 0.0)
    {
      std::array<double, 6> rate;
      for (int i = 0; i < 6; ++i)
        rate[i] = (_eps_trial[p][i] - _eps[p][i]) / _trial_dt;
      _out[4][dof] = max_abs_principal_strain(rate);
    }
    else
      _out[4][dof] = 0.0;
  }
  std::copy(_sig->x()->array().begin(), _sig->x()->array().end(),
            _sig_committed.begin());
  _state.swap(_trial);
  _eps.swap(_eps_trial);
  _trial = _state;
  _eps_trial = _eps;
  // Elastic balls around the new states, where the old ball no longer
  // holds (other internal variables or material) or the stress has moved
  // past half its radius (most points of a dam keep theirs for many steps).
  for (std::int32_t c = 0; c < _num_cells; ++c)
  {
    const auto& m = material_of(c, _trial_dt);
    for (int q = 0; q < _nq; ++q)
    {
      const std::size_t p = static_cast<std::size_t>(c) * _nq + q;
      const material::State& s = _state[p];
      ElasticBall& b = _ball[p];
      if (b.fits(m, s) && tensor_distance2(s.stress, b.centre) <= 0.25 * b.r2)
      {
        continue;
      }
      const double r = m.admissible_radius(s.stress, s.kappa_c, s.kappa_t);
      b = {s.stress, r > 0.0 ? r * r : -1.0, s.kappa_c, s.kappa_t, &m};
    }
  }
  return true;
}

void ConcreteModel::assemble_internal_force(Vec f, bool apply_bc) const
{
  // Zero the owned and the ghost entries (VecSet alone leaves the ghosts,
  // which the reverse scatter would add again).
  Vec b = _f_work.vec(), b_local;
  VecGhostGetLocalForm(b, &b_local);
  VecSet(b_local, 0.0);
  VecGhostRestoreLocalForm(b, &b_local);
  dfem::petsc::assemble_vector(b, *_L);
  finish_work_vector(f, apply_bc);
}

void ConcreteModel::finish_work_vector(Vec f, bool apply_bc) const
{
  Vec b = _f_work.vec();
  VecGhostUpdateBegin(b, ADD_VALUES, SCATTER_REVERSE);
  VecGhostUpdateEnd(b, ADD_VALUES, SCATTER_REVERSE);
  if (apply_bc)
    dfem::petsc::set_bc(b, _fe.bcs(), nullptr);
  // Owned values into f (f may or may not be ghosted).
  const double* src = nullptr;
  double* dst = nullptr;
  PetscInt n = 0;
  VecGetLocalSize(f, &n);
  VecGetArrayRead(b, &src);
  VecGetArray(f, &dst);
  std::copy_n(src, n, dst);
  VecRestoreArray(f, &dst);
  VecRestoreArrayRead(b, &src);
}

void ConcreteModel::assemble_extrapolation_change(Vec f) const
{
  Vec b = _f_work.vec(), b_local;
  VecGhostGetLocalForm(b, &b_local);
  VecSet(b_local, 0.0);
  if (!_sig_extrapolated.empty())
  {
    // Per point sig(implicit) - sig(extrapolated); cells where it is below
    // 1e-9 ft0 at every point (elastic points: round-off) are left out.
    std::span<const double> sig = _sig->x()->array();
    const int stride = _nc * _nq;
    std::vector<std::int32_t> cells;
    _coeff_work.clear();
    for (std::int32_t c = 0; c < _num_owned_cells; ++c)
    {
      const double small = 1e-9 * _dynamic[_cell_material[c]]->derived().ft0;
      bool differs = false;
      for (int q = 0; q < _nq && !differs; ++q)
      {
        const std::int32_t d = _dof[static_cast<std::size_t>(c) * _nq + q];
        for (int k = 0; k < _nc; ++k)
          differs |= std::abs(sig[_nc * d + k] -
                              _sig_extrapolated[_nc * d + k]) > small;
      }
      if (!differs)
        continue;
      cells.push_back(c);
      for (int q = 0; q < _nq; ++q)
      {
        const std::int32_t d = _dof[static_cast<std::size_t>(c) * _nq + q];
        for (int k = 0; k < _nc; ++k)
          _coeff_work.push_back(sig[_nc * d + k] -
                                _sig_extrapolated[_nc * d + k]);
      }
    }
    // The residual form's kernel on those cells, with that coefficient.
    const auto ids = _L->integral_ids(dfem::IntegralType::cell);
    if (ids.size() != 1 || _L->coefficient_offsets().back() != stride)
      throw std::logic_error(
          "residual form: one cell integral of sig expected");
    const dfem::FunctionSpace& V = *_fe.V();
    const auto& element = *V.element();
    // (No cell permutation data is passed: Lagrange elements need none.)
    if (element.needs_dof_transformations())
      throw std::logic_error("extrapolation change: element needs dof "
                             "transformations");
    PetscInt n = 0;
    VecGetLocalSize(b_local, &n);
    double* a = nullptr;
    VecGetArray(b_local, &a);
    dfem::impl::assemble_cells<double>(
        element.get_dof_transformation_function<double>(),
        std::span<double>(a, n), _fe.mesh()->geometry(),
        std::span<const std::int32_t>(cells), V.dofmap()->list(),
        V.dofmap()->bs(), _L->kernel(dfem::IntegralType::cell, ids.front()),
        std::span<const double>(), std::span<const double>(_coeff_work), stride,
        std::span<const std::uint32_t>());
    VecRestoreArray(b_local, &a);
  }
  VecGhostRestoreLocalForm(b, &b_local);
  finish_work_vector(f, true);
}

Mat ConcreteModel::assemble_tangent() const
{
  Mat A = dfem::petsc::create_matrix(*_a, "baij");
  assemble_tangent(A);
  return A;
}

void ConcreteModel::assemble_tangent(Mat A) const
{
  MatZeroEntries(A);
  dfem::assemble_matrix(dolfinx::la::petsc::Matrix::set_block_fn(A, ADD_VALUES),
                        *_a, _fe.bcs());
  MatAssemblyBegin(A, MAT_FLUSH_ASSEMBLY);
  MatAssemblyEnd(A, MAT_FLUSH_ASSEMBLY);
  dfem::set_diagonal(dolfinx::la::petsc::Matrix::set_fn(A, INSERT_VALUES),
                     *_fe.V(), _fe.bcs(), 1.0);
  MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY);
}

void ConcreteModel::add_tangent_change(Mat A, double scale) const
{
  add_tangent_change(dolfinx::la::petsc::Matrix::set_block_fn(A, ADD_VALUES),
                     scale);
  MatAssemblyBegin(A, MAT_FINAL_ASSEMBLY);
  MatAssemblyEnd(A, MAT_FINAL_ASSEMBLY);
}

void ConcreteModel::add_tangent_change(const BlockSetter& set,
                                       double scale) const
{
  const dfem::FunctionSpace& V = *_fe.V();
  const dfem::DofMap& dofmap = *V.dofmap();
  const int bs = dofmap.bs();
  if (_bc_marker.empty())
  {
    const auto& map = *dofmap.index_map;
    _bc_marker.assign(bs * (map.size_local() + map.num_ghosts()), 0);
    for (const auto& bc : _fe.bcs())
      bc->mark_dofs(_bc_marker);
  }
  // The tangent coefficient of the listed cells minus the elastic one,
  // packed per cell as DOLFINx packs a quadrature coefficient (the cell's
  // points in dofmap order, nc^2 values each); the form is linear in it.
  const int nt = _nc * _nc;
  const int cstride = nt * _nq;
  _coeff_work.resize(_tangent_cells.size() * cstride);
  std::span<const double> ct = _Ct->x()->array();
  for (std::size_t i = 0; i < _tangent_cells.size(); ++i)
  {
    const std::int32_t c = _tangent_cells[i];
    const auto& ce = _ct_elastic[_cell_material[c]];
    for (int q = 0; q < _nq; ++q)
    {
      const std::int32_t d = _dof_c[static_cast<std::size_t>(c) * _nq + q];
      for (int k = 0; k < nt; ++k)
        _coeff_work[i * cstride + nt * q + k] =
            scale * (ct[nt * d + k] - ce[k]);
    }
  }
  const auto ids = _a->integral_ids(dfem::IntegralType::cell);
  if (ids.size() != 1 || _a->coefficient_offsets().back() != cstride)
    throw std::logic_error("tangent form: one cell integral of Ct expected");
  const auto& element = *V.element();
  // (No cell permutation data is passed: Lagrange elements need none.)
  if (element.needs_dof_transformations())
    throw std::logic_error("tangent change: element needs dof transformations");
  dfem::impl::assemble_cells(
      set, _fe.mesh()->geometry(),
      std::span<const std::int32_t>(_tangent_cells),
      element.get_dof_transformation_function<double>(), dofmap.list(), bs,
      element.get_dof_transformation_to_transpose_function<double>(),
      dofmap.list(), bs, _bc_marker, _bc_marker,
      _a->kernel(dfem::IntegralType::cell, ids.front()),
      std::span<const double>(_coeff_work), cstride, std::span<const double>(),
      std::span<const std::uint32_t>());
}

std::map<std::string, std::vector<double>> ConcreteModel::save() const
{
  const std::size_t np = _state.size();
  std::vector<double> state;
  state.reserve(np * 22);
  for (std::size_t p = 0; p < np; ++p)
  {
    const auto& s = _state[p];
    state.insert(state.end(), s.stress.begin(), s.stress.end());
    state.insert(state.end(), s.plastic_strain.begin(), s.plastic_strain.end());
    state.insert(state.end(),
                 {s.kappa_c, s.kappa_t, s.kappa_c_rate, s.kappa_t_rate});
    state.insert(state.end(), _eps[p].begin(), _eps[p].end());
  }
  std::vector<double> dep;
  dep.reserve(np * 6 + 1);
  for (const auto& d : _dep)
    dep.insert(dep.end(), d.begin(), d.end());
  dep.push_back(_dt_last);
  std::map<std::string, std::vector<double>> out = {
      {"material_state", state},
      {"material_sigma", _sig_committed},
      {"material_implex", dep}};
  for (int k = 0; k < 5; ++k)
    out["material_out" + std::to_string(k)] = _out[k];
  return out;
}

void ConcreteModel::restore(
    const std::map<std::string, std::vector<double>>& arrays)
{
  const auto& state = arrays.at("material_state");
  const std::size_t np = _state.size();
  if (state.size() != np * 22)
    throw std::runtime_error("checkpoint material state has the wrong size");
  for (std::size_t p = 0; p < np; ++p)
  {
    const double* v = &state[22 * p];
    auto& s = _state[p];
    std::copy_n(v, 6, s.stress.begin());
    std::copy_n(v + 6, 6, s.plastic_strain.begin());
    s.kappa_c = v[12];
    s.kappa_t = v[13];
    s.kappa_c_rate = v[14];
    s.kappa_t_rate = v[15];
    std::copy_n(v + 16, 6, _eps[p].begin());
  }
  _trial = _state;
  _eps_trial = _eps;
  const auto dep = arrays.find("material_implex");
  if (dep != arrays.end())
  {
    if (dep->second.size() != np * 6 + 1)
      throw std::runtime_error("checkpoint IMPL-EX state has the wrong size");
    for (std::size_t p = 0; p < np; ++p)
      std::copy_n(&dep->second[6 * p], 6, _dep[p].begin());
    _dt_last = dep->second.back();
  }
  _sig_committed = arrays.at("material_sigma");
  std::copy(_sig_committed.begin(), _sig_committed.end(),
            _sig->x()->mutable_array().begin());
  for (int k = 0; k < 5; ++k)
    _out[k] = arrays.at("material_out" + std::to_string(k));
}
} // namespace damseis::fem
