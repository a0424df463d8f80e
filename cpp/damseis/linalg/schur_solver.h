// Sparse Cholesky factorisation (MUMPS) of a symmetric positive definite
// matrix that keeps a few chosen unknowns s out of the factors: it returns
// their dense Schur complement
//   S = A_ss - A_si A_ii^-1 A_is
// and solves A x = b in two halves around a dense problem on s, which the
// caller solves (the contact of joint pairs, whose unknowns are s):
//   condense: y = b_s - A_si A_ii^-1 b_i       (forward elimination)
//   the caller finds x_s (S x_s = y, plus its own constraints)
//   expand:   x_i = A_ii^-1 (b_i - A_is x_s)   (backward substitution)
// Together they cost one ordinary solve. S, y and x_s live on rank 0
// (MUMPS' centralised Schur complement); other ranks hold empty arrays.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <petscmat.h>
#include <span>

namespace damseis::linalg
{
class SchurSolver
{
public:
  /// Factorises A (collective). `schur` lists the global indices of the
  /// Schur unknowns, the same list on every rank (distinct, in range).
  /// Throws std::runtime_error if MUMPS fails (message with INFOG(1..2)).
  SchurSolver(Mat A, std::span<const PetscInt> schur);
  ~SchurSolver();
  SchurSolver(const SchurSolver&) = delete;
  SchurSolver& operator=(const SchurSolver&) = delete;

  /// The Schur unknowns, in the order of S's rows.
  std::span<const PetscInt> unknowns() const;
  /// S, full symmetric (rank 0; 0 x 0 on other ranks).
  const Eigen::MatrixXd& schur_complement() const { return _S; }
  /// S moved out (the solver keeps none: condense and expand do not need
  /// it).
  Eigen::MatrixXd take_schur_complement() { return std::move(_S); }
  /// The forward half of a solve of A x = b (collective): y = b_s - A_si
  /// A_ii^-1 b_i on rank 0. Keeps the interior part for expand().
  void condense(Vec b, Eigen::VectorXd& y);
  /// The backward half (collective): x with x_s given on rank 0 and x_i =
  /// A_ii^-1 (b_i - A_is x_s), b that of the last condense().
  void expand(const Eigen::VectorXd& x_s, Vec x);
  /// Wall time of the analysis and factorisation [s].
  double factor_seconds() const { return _factor_seconds; }

private:
  struct Mumps;
  std::unique_ptr<Mumps> _mumps;
  Eigen::MatrixXd _S;
  double _factor_seconds = 0.0;
};
} // namespace damseis::linalg
