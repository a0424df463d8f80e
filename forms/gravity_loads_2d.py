# Static loads of gravity dams besides dead weight and water (2D section):
# silt on the upstream face and uplift on the dam base (algorithms.md 5.3).
# Compiled per displacement degree like elasticity_2d.py.
#
# Constants (SI):
#   silt_k      K_a gamma_s' : active earth pressure coefficient times the
#               submerged unit weight of the silt [N/m3]
#   silt_level  elevation of the silt surface [m]
#   p_heel, p_drain, p_toe  uplift pressure at the heel, at the drainage
#               line and at the toe [Pa] (piecewise linear between them)
#   x_heel, x_drain, x_toe  their x coordinates [m]
# Facet tags: 1 upstream face, 4 dam base (exterior on a rigid base, interior
# on a foundation block).
#
# Uplift acts on the dam: -p n_dam on the dam base. On a foundation block the
# base facets are interior and the dam side is picked by the cell indicator
# in_dam (DG0: 1 in the dam). (Equal and opposite tractions on both sides of
# a bonded interface would cancel exactly at the shared nodes; the reaction
# of the uplift on the rock is left out, as in the usual practice of loading
# the dam base.) On a rigid base the base is fixed and the load has no
# effect on the solution.
#   in_dam  DG0 indicator of the dam cells
from ufl import (Coefficient, Constant, FacetNormal, FiniteElement,
                 FunctionSpace, Mesh,
                 SpatialCoordinate, TestFunction, VectorElement, conditional,
                 dot, dS, ds, lt, max_value, triangle)

UPSTREAM, DAM_BASE = 1, 4

cell = triangle
mesh = Mesh(VectorElement("Lagrange", cell, 1))
V = FunctionSpace(mesh, VectorElement("Lagrange", cell, degree))
v = TestFunction(V)
Q = FunctionSpace(mesh, FiniteElement("DG", cell, 0))
in_dam = Coefficient(Q)
x = SpatialCoordinate(mesh)
n = FacetNormal(mesh)

silt_k, silt_level = Constant(mesh), Constant(mesh)
p_heel, p_drain, p_toe = Constant(mesh), Constant(mesh), Constant(mesh)
x_heel, x_drain, x_toe = Constant(mesh), Constant(mesh), Constant(mesh)

silt_pressure = silt_k * max_value(silt_level - x[1], 0.0)
L_silt = -silt_pressure * dot(n, v) * ds(UPSTREAM)

up_front = p_heel + (p_drain - p_heel) * (x[0] - x_heel) / (x_drain - x_heel)
up_back = p_drain + (p_toe - p_drain) * (x[0] - x_drain) / (x_toe - x_drain)
uplift = max_value(conditional(lt(x[0], x_drain), up_front, up_back), 0.0)
L_uplift = -uplift * dot(n, v) * ds(DAM_BASE) \
    - uplift('+') * (in_dam('+') * dot(v('+'), n('+'))
                     + in_dam('-') * dot(v('-'), n('-'))) * dS(DAM_BASE)

forms = [L_silt, L_uplift]
