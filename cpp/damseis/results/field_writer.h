// XDMF/HDF5 output of displacement and stress fields, and of the stress
// envelopes, readable by ParaView.
#pragma once

#include "stress_envelope.h"
#include <damseis/fem/elastic_model.h>
#include <dolfinx/io/XDMFFile.h>
#include <filesystem>
#include <memory>

namespace damseis::results
{
/// Cell averages (DG0) of the stress-point values of every local cell:
/// returns the tensor (tdim x tdim, row-major) per cell.
std::vector<double> cell_average_tensor(const dolfinx::fem::FunctionSpace& S,
                                        std::span<const double> s,
                                        int num_cells, int tdim);

/// Largest value per cell of a scalar held at the points of `S` (one value
/// per point, owned and ghost).
std::vector<double> cell_max_scalar(const dolfinx::fem::FunctionSpace& S,
                                    std::span<const double> v, int num_cells);

/// A time series: displacement at the vertices (P1), cell stress tensor,
/// and the cell's largest and smallest principal stresses; optionally more
/// point scalars written as their cell maxima.
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
  ~FieldWriter();
  /// Writes the fields at time t. `s` holds the stress-point values
  /// (owned and ghost, layout of the stress space); `extra` one span per
  /// extra name (one value per point).
  void write(const dolfinx::fem::Function<double>& u, std::span<const double> s,
             double t, const std::vector<std::span<const double>>& extra = {});

private:
  fem::ElasticModel& _model;
  std::shared_ptr<const dolfinx::fem::FunctionSpace> _S;
  std::unique_ptr<dolfinx::io::XDMFFile> _file;
  std::shared_ptr<dolfinx::fem::Function<double>> _u, _sig, _pmax, _pmin;
  std::vector<std::shared_ptr<dolfinx::fem::Function<double>>> _extra;
};

/// A named point scalar (one value per point of the stress space, owned and
/// ghost) written by write_envelopes as its cell maxima.
struct PointScalar
{
  std::string name;
  std::span<const double> values;
};

/// Writes the envelopes as cell fields (largest value over the cell's
/// points) and vertex fields (largest over the points at the vertex), plus
/// Values in Pa; NaN outside the envelope's region.
/// `stress_space`: the space of the envelope's points (default: the
/// model's S); `vertex_points`: whether its points sit at the cell vertices
/// in vertex order (the P2 stress points) or inside the cells (quadrature
/// points: a cell's maximum feeds all its vertices); `extra`: further point
/// scalars written as cell maxima.
void write_envelopes(
    fem::ElasticModel& model, const StressEnvelope& env,
    const std::filesystem::path& file,
    std::shared_ptr<const dolfinx::fem::FunctionSpace> stress_space = nullptr,
    bool vertex_points = true, const std::vector<PointScalar>& extra = {});
} // namespace damseis::results
