# Nonlinear (concrete) material in 3D: internal force and consistent tangent
# from stress and tangent values held at the quadrature points.
#
# Compiled by FFCx once per displacement degree, like elasticity_3d.py. The
# names below are the C++ interface (cpp/damseis/fem/concrete_model.h), the
# same as plasticity_2d.py's with 6 components.
#
# Quadrature: degree 2 (4 points) for P2, degree 1 (1 point) for P1: exact
# for the elastic stiffness (the strain of a P2 field is linear), so the
# elastic material reproduces the linear solver.
# Voigt order: (xx, yy, zz, xy, yz, xz), engineering shears gamma = 2 eps
# (the order of cpp/damseis/material).
#
# Coefficients:
#   sig   stress (sxx, syy, szz, sxy, syz, sxz) at the points [Pa]
#   Ct    algorithmic tangent d(sig)/d(exx, eyy, ezz, gxy, gyz, gxz), 6x6
#         row-major [Pa]
#   u     displacement [m] (for the strain expression)
# Expressions (evaluated at the same points):
#   strain    (exx, eyy, ezz, gxy, gyz, gxz) of u
#   position  coordinates of the points
import basix
from ufl import (Coefficient, FunctionSpace, Mesh, SpatialCoordinate,
                 TensorElement, TestFunction, TrialFunction, VectorElement,
                 as_vector, dot, dx, grad, inner, sym, tetrahedron)

cell = tetrahedron
qdeg = max(1, 2 * (degree - 1))
mesh = Mesh(VectorElement("Lagrange", cell, 1))
V = FunctionSpace(mesh, VectorElement("Lagrange", cell, degree))
Sq = FunctionSpace(mesh, VectorElement("Quadrature", cell, degree=qdeg, dim=6,
                                       quad_scheme="default"))
Cq = FunctionSpace(mesh, TensorElement("Quadrature", cell, degree=qdeg,
                                       shape=(6, 6), quad_scheme="default"))

du, v = TrialFunction(V), TestFunction(V)
u = Coefficient(V)
sig, Ct = Coefficient(Sq), Coefficient(Cq)


def eps_v(w):
    e = sym(grad(w))
    return as_vector([e[0, 0], e[1, 1], e[2, 2],
                      2.0 * e[0, 1], 2.0 * e[1, 2], 2.0 * e[0, 2]])


dxq = dx(metadata={"quadrature_degree": qdeg, "quadrature_scheme": "default"})
L_residual = inner(sig, eps_v(v)) * dxq
a_tangent = inner(dot(Ct, eps_v(du)), eps_v(v)) * dxq

points, weights = basix.make_quadrature(basix.CellType.tetrahedron, qdeg)
strain = eps_v(u)
position = SpatialCoordinate(mesh)

forms = [L_residual, a_tangent]
expressions = [(strain, points), (position, points)]
