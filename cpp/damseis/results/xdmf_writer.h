// XDMF 3 files (XML + HDF5) laid out for ParaView and Python users: each
// grid carries every field of its time step on one copy of the mesh, so
// the deformed shape can be coloured by any field (no filter recipe), and
// a file without time holds a single grid (envelopes, modes), which meshio
// reads as well.
//
// The mesh is the linear geometry of the model (P1 triangles or
// tetrahedra), optionally restricted to a set of cells (the dam): only the
// nodes those cells use are written. Fields are point data (one value or
// vector per node) or cell data (per cell); names carry their unit
// (displacement_m, sigma1_MPa). Vectors of 2D models are padded to three
// components, as ParaView expects.
//
// HDF5 layout: /mesh/geometry (nodes x gdim), /mesh/topology (cells x
// nodes per cell, global node numbers), then per grid /step<k>/<field>
// (series) or /fields/<field>. Parallel runs write one file (MPI-IO); the
// XML is rewritten by rank 0 after every grid, so a stopped run leaves a
// readable file.
#pragma once

#include <cstdint>
#include <dolfinx/fem/Function.h>
#include <dolfinx/mesh/Mesh.h>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace damseis::results
{
class XdmfWriter
{
public:
  /// Every cell of the mesh.
  /// @param[in] mesh the model's mesh
  /// @param[in] file the .xdmf path (the data go to the same name .h5)
  /// @param[in] series one grid per write() with its time (fields), or a
  /// single grid without time (write() once)
  XdmfWriter(std::shared_ptr<const dolfinx::mesh::Mesh> mesh,
             const std::filesystem::path& file, bool series = true);
  /// The local cells `cells` (ghosts among them are skipped; a rank may
  /// have none).
  XdmfWriter(std::shared_ptr<const dolfinx::mesh::Mesh> mesh,
             const std::filesystem::path& file,
             std::span<const std::int32_t> cells, bool series);
  ~XdmfWriter();
  XdmfWriter(const XdmfWriter&) = delete;
  XdmfWriter& operator=(const XdmfWriter&) = delete;

  /// Point data from values per local geometry node (owned and ghost),
  /// `ncomp` per node; `vector`: written as a vector (padded to 3).
  void point_field(const std::string& name, std::span<const double> values,
                   int ncomp, bool vector = false);
  /// Point data from a P1 Function (scalar or vector) of the mesh.
  void point_field(const std::string& name,
                   const dolfinx::fem::Function<double>& u);
  /// Cell data: values per local cell (at least every owned cell), `ncomp`
  /// per cell.
  void cell_field(const std::string& name, std::span<const double> values,
                  int ncomp = 1);
  /// Writes the fields given since the last write() as one grid at time t
  /// (ignored without series) and forgets them. Collective.
  void write(double t = 0.0);

  /// Number of grids written.
  int grids() const { return _grids; }

private:
  struct Field
  {
    std::string name;
    bool on_cells;
    int ncomp; ///< components in the file
    std::vector<double> values;
  };
  void write_xml() const;
  /// Numbers the nodes of _cells, writes the mesh datasets.
  void write_mesh();
  std::vector<double> node_values(std::span<const double> values, int ncomp,
                                  int padded) const;

  std::shared_ptr<const dolfinx::mesh::Mesh> _mesh;
  std::filesystem::path _xdmf, _h5;
  bool _series;
  std::int64_t _hid = -1; ///< HDF5 file handle (hid_t)
  bool _mpi_io = false;
  int _rank = 0;
  /// Cells written (local), their count over all ranks and the offset of
  /// this rank's.
  std::vector<std::int32_t> _cells;
  std::int64_t _num_cells = 0, _cell_offset = 0;
  /// Owned geometry nodes written (local index, in file order), their
  /// count over all ranks and this rank's offset.
  std::vector<std::int32_t> _nodes;
  std::int64_t _num_nodes = 0, _node_offset = 0;
  std::vector<Field> _pending;
  /// The XML of the mesh (the same in every grid) and of each grid
  /// written.
  std::string grid_xml(double t, const std::string& group,
                       const std::vector<Field>& fields) const;
  std::string _mesh_xml;
  std::vector<std::string> _written;
  int _grids = 0;
};
} // namespace damseis::results
