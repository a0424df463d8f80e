# Loads on a group of the user's mesh (dam_model): a traction on a group of
# facets (exterior; the interior form serves the means over facet groups)
# and a body force on a group of cells. Compiled per displacement
# degree like elasticity_2d.py.
#
# Constants (SI): value_x, value_y: the components of the
# traction [Pa] or of the body force [N/m3].
# Subdomain: the group's facets or cells carry the value LOADED = 1 in the
# tags the assembly passes (fem::ElasticModel::assemble_group_load).
from ufl import (Constant, FunctionSpace, Mesh, TestFunction, VectorElement,
                 as_vector, dS, ds, dx, inner, triangle)

LOADED = 1

cell = triangle
mesh = Mesh(VectorElement("Lagrange", cell, 1))
V = FunctionSpace(mesh, VectorElement("Lagrange", cell, degree))
v = TestFunction(V)
value_x = Constant(mesh)
value_y = Constant(mesh)
value = as_vector([value_x, value_y])

L_traction = inner(value, v) * ds(LOADED)
L_body_force = inner(value, v) * dx(LOADED)
# On interior facets (v is continuous: either side's trace).
L_traction_interior = inner(value, v("+")) * dS(LOADED)

forms = [L_traction, L_body_force, L_traction_interior]
