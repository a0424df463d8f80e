// Cutting OCC volumes with tool surfaces (gmsh, rank 0).
#pragma once

#include <gmsh.h>

namespace damseis::geometry
{
/// Fragments `volumes` with the surfaces `tools` and removes the tools'
/// parts that bound no volume; returns the resulting volumes (the model
/// synchronised).
gmsh::vectorpair cut_by_surfaces(const gmsh::vectorpair& volumes,
                                 const gmsh::vectorpair& tools);
} // namespace damseis::geometry
