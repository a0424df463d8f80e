# Linear elasticity of a dam and its foundation in 3D (z is vertical).
#
# Compiled by FFCx once per displacement degree ("degree = 1" or
# "degree = 2" is put in front; see forms/CMakeLists.txt). The names below
# are the C++ interface: keep them stable. Same coefficients, constants and
# facet tags as elasticity_2d.py; the stress vector is
# (sxx, syy, szz, sxy, syz, sxz).
from ufl import (Coefficient, Constant, FacetNormal, FiniteElement,
                 FunctionSpace, Identity, Mesh, SpatialCoordinate,
                 TensorElement, TestFunction, TrialFunction, VectorElement,
                 as_vector, dot, ds, dx, grad, inner, max_value, sqrt, sym,
                 tetrahedron, tr)

UPSTREAM, RESERVOIR_FLOOR, UPSTREAM_WETTED = 1, 7, 12
# The upstream face: one tag, or a dry part (UPSTREAM) and a wetted part
# (UPSTREAM_WETTED) when the mesh follows the water line.
UPSTREAM_FACE = (UPSTREAM, UPSTREAM_WETTED)

cell = tetrahedron
mesh = Mesh(VectorElement("Lagrange", cell, 1))
V = FunctionSpace(mesh, VectorElement("Lagrange", cell, degree))
Q = FunctionSpace(mesh, FiniteElement("DG", cell, 0))
S = FunctionSpace(mesh, VectorElement("DG", cell, degree - 1, dim=6))

du, v = TrialFunction(V), TestFunction(V)
u = Coefficient(V)
mu, lmbda, rho = Coefficient(Q), Coefficient(Q), Coefficient(Q)
gravity = Constant(mesh, shape=(3,))
rho_w, g_w, H_w, H_0, floor_on = (Constant(mesh), Constant(mesh),
                                  Constant(mesh), Constant(mesh),
                                  Constant(mesh))
x = SpatialCoordinate(mesh)
n = FacetNormal(mesh)


def eps(w):
    return sym(grad(w))


def sigma(w):
    return 2.0 * mu * eps(w) + lmbda * tr(eps(w)) * Identity(3)


depth = max_value(H_w - x[2], 0.0)
pressure = rho_w * g_w * depth

a_stiffness = inner(sigma(du), eps(v)) * dx
a_mass = rho * inner(du, v) * dx
westergaard = 7.0 / 8.0 * rho_w * sqrt(H_0 * depth)
a_added_mass = westergaard * dot(du, n) * dot(v, n) * \
    ds(UPSTREAM_FACE, metadata={"quadrature_degree": 8})

L_gravity = rho * inner(gravity, v) * dx
L_hydrostatic = -pressure * dot(n, v) * ds(UPSTREAM_FACE) \
    - floor_on * pressure * dot(n, v) * ds(RESERVOIR_FLOOR)

L_internal = inner(sigma(u), eps(v)) * dx

tau = TestFunction(S)
if degree == 1:
    dxs = dx(metadata={"quadrature_degree": 0})
else:
    dxs = dx(metadata={"quadrature_rule": "vertex", "quadrature_degree": 1})
sig_du = sigma(du)
a_stress = inner(as_vector([sig_du[0, 0], sig_du[1, 1], sig_du[2, 2],
                            sig_du[0, 1], sig_du[1, 2], sig_du[0, 2]]),
                 tau) * dxs
L_stress_weight = (tau[0] + tau[1] + tau[2] + tau[3] + tau[4] + tau[5]) * dxs

T0 = FunctionSpace(mesh, TensorElement("DG", cell, 0))
P1 = FunctionSpace(mesh, VectorElement("Lagrange", cell, 1))
P1s = FunctionSpace(mesh, FiniteElement("Lagrange", cell, 1))
sig_cell, s_cell = Coefficient(T0), Coefficient(Q)
u_vertex, s_vertex = Coefficient(P1), Coefficient(P1s)
M_output = (inner(sig_cell, sig_cell) + s_cell * s_cell
            + inner(u_vertex, u_vertex) + s_vertex * s_vertex) * dx

forms = [a_stiffness, a_mass, a_added_mass, L_gravity, L_hydrostatic,
         L_internal, a_stress, L_stress_weight, M_output]
