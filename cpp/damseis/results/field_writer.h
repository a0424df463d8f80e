// The XDMF outputs of an analysis (results/xdmf_writer.h): the time series
// of the fields, the stress envelopes and the mode shapes. Stresses in MPa,
// names with their units; no NaN anywhere.
#pragma once

#include "stress_envelope.h"
#include "xdmf_writer.h"
#include <damseis/fem/elastic_model.h>
#include <filesystem>
#include <memory>

namespace damseis::results
{
/// Cell averages of the stress-point values (`ncomp` Voigt components per
/// point: xx, yy, xy in 2D; xx, yy, zz, xy, yz, xz in 3D) of every local
/// cell, `ncomp` per cell.
std::vector<double> cell_average(const dolfinx::fem::FunctionSpace& S,
                                 std::span<const double> s, int num_cells);

/// Largest value per cell of a scalar held at the points of `S` (one value
/// per point, owned and ghost).
std::vector<double> cell_max_scalar(const dolfinx::fem::FunctionSpace& S,
                                    std::span<const double> v, int num_cells);

/// Names of the Voigt components with their unit: sigma_xx_MPa, ...
std::vector<std::string> stress_component_names(int tdim);

/// A point scalar (one value per point of the stress space, owned and
/// ghost) written as its cell maxima; the name carries the unit.
struct PointScalar
{
  std::string name;
  std::span<const double> values;
};

/// The time series fields.xdmf: per written step one grid with the
/// displacement (displacement_m, at the vertices), the cell-average stress
/// components and principal stresses (sigma_xx_MPa, ..., sigma1_MPa,
/// sigma3_MPa), the extra point scalars as cell maxima, and the region tag
/// of each cell (region: 1 dam, 2 foundation; geometry/tags.h).
class FieldWriter
{
public:
  /// @param[in] stress_space the space of the stress points (default: the
  /// model's S)
  /// @param[in] extra names of further point scalars (see write())
  FieldWriter(
      fem::ElasticModel& model, const std::filesystem::path& file,
      std::shared_ptr<const dolfinx::fem::FunctionSpace> stress_space = nullptr,
      const std::vector<std::string>& extra = {});
  /// Writes the fields at time t. `s` holds the stress-point values [Pa]
  /// (owned and ghost, layout of the stress space); `extra` one span per
  /// extra name (one value per point).
  void write(const dolfinx::fem::Function<double>& u, std::span<const double> s,
             double t, const std::vector<std::span<const double>>& extra = {});

private:
  fem::ElasticModel& _model;
  std::shared_ptr<const dolfinx::fem::FunctionSpace> _S;
  XdmfWriter _file;
  std::shared_ptr<dolfinx::fem::Function<double>> _u;
  std::vector<std::string> _extra;
  std::vector<double> _region;
};

/// Writes the envelopes over the region of `env` (the dam) as one grid
/// without time, on the region's cells only: per cell the largest and
/// smallest principal stress over its points and when they occurred
/// (max_principal_MPa, t_max_principal_s, min_principal_MPa,
/// t_min_principal_s), per vertex the extremes over the points at the
/// vertex (max_principal_vertex_MPa, min_principal_vertex_MPa), and the
/// `extra` point scalars as cell maxima.
/// `stress_space`: the space of the envelope's points (default: the
/// model's S); `vertex_points`: whether its points sit at the cell vertices
/// in vertex order (the P2 stress points) or inside the cells (quadrature
/// points: a cell's extreme feeds all its vertices).
void write_envelopes(
    fem::ElasticModel& model, const StressEnvelope& env,
    std::span<const std::int32_t> region_cells,
    const std::filesystem::path& file,
    std::shared_ptr<const dolfinx::fem::FunctionSpace> stress_space = nullptr,
    bool vertex_points = true, const std::vector<PointScalar>& extra = {});
} // namespace damseis::results
