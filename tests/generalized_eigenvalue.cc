// The largest eigenvalue of N x = mu K x by LOBPCG
// (largest_generalized_eigenvalue), the estimate behind the convexity
// bound: K a 1D Laplacian plus a mass term, N a positive "boundary mass" on
// the last nodes only (semidefinite, like sum m_i nu nu on Gamma_3), Jacobi
// as the preconditioner. The result must agree with LAPACK's dense
// generalised eigensolver; with too few iterations it must say it did not
// converge rather than return a value as converged. The power iteration
// that this replaced stopped, after 30 iterations, up to 6% below the largest
// eigenvalue on the examples.
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hemicontact/solver/generalized_eigenvalue.h>

#include <algorithm>
#include <cmath>

#include "tests.h"

using namespace hemicontact;
using namespace dealii;

namespace
{
  constexpr unsigned int n = 120;
  /** N is nonzero on the last n_contact nodes. */
  constexpr unsigned int n_contact = 20;

  /**
   * K = tridiag(-1, 2 + 0.5, -1): SPD, condition number about 9, like the
   * mass-dominated step matrix.
   */
  void
  apply_k(const Vector<double> &in, Vector<double> &out)
  {
    for (unsigned int i = 0; i < n; ++i)
      out[i] = (2 + 0.5) * in[i] - (i > 0 ? in[i - 1] : 0.) -
               (i + 1 < n ? in[i + 1] : 0.);
  }

  /** N = diag(0, ..., 0, m_1, ..., m_20), m_j = 1 + j / 20. */
  double
  n_diagonal(const unsigned int i)
  {
    return i + n_contact >= n ? 1. + (i + n_contact - n) / 20. : 0.;
  }

  void
  apply_n(const Vector<double> &in, Vector<double> &out)
  {
    for (unsigned int i = 0; i < n; ++i)
      out[i] = n_diagonal(i) * in[i];
  }

  void
  jacobi(const Vector<double> &in, Vector<double> &out)
  {
    for (unsigned int i = 0; i < n; ++i)
      out[i] = in[i] / (2 + 0.5);
  }

  /** The largest eigenvalue from LAPACK, on the dense matrices. */
  double
  reference()
  {
    LAPACKFullMatrix<double> a(n, n), b(n, n);
    Vector<double>           e(n), column(n);
    for (unsigned int j = 0; j < n; ++j)
      {
        e    = 0;
        e[j] = 1;
        apply_k(e, column);
        for (unsigned int i = 0; i < n; ++i)
          b(i, j) = column[i];
        a(j, j) = n_diagonal(j);
      }
    std::vector<Vector<double>> eigenvectors(n, Vector<double>(n));
    a.compute_generalized_eigenvalues_symmetric(b, eigenvectors);
    double largest = 0;
    for (unsigned int i = 0; i < n; ++i)
      largest = std::max(largest, a.eigenvalue(i).real());
    return largest;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                     exact = reference();
  out() << "LAPACK: largest eigenvalue " << exact << "\n";

  for (const unsigned int max_iterations : {300u, 3u})
    {
      Vector<double> x(n);
      x = 1.; // the start: the same weight everywhere
      const EigenvalueEstimate estimate = largest_generalized_eigenvalue(
        apply_n, apply_k, jacobi, x, 1e-6, max_iterations);
      const double error = std::abs(estimate.value - exact) / exact;
      out() << "LOBPCG with at most " << max_iterations << " iterations:\n"
            << "  converged: " << (estimate.converged ? "yes" : "no") << "\n"
            << "  relative residual <= 1e-6: "
            << (estimate.relative_residual <= 1e-6 ? "yes" : "no") << "\n"
            << "  estimate below the eigenvalue (a Ritz value): "
            << (estimate.value <= exact * (1 + 1e-12) ? "yes" : "no") << "\n"
            << "  relative error below 1e-9: " << (error < 1e-9 ? "yes" : "no")
            << "\n";
      if (estimate.converged)
        out() << "  iterations at most 50: "
              << (estimate.iterations <= 50 ? "yes" : "no") << "\n";
    }

  // a start N does not see (zero on the last 20 nodes), and a zero start:
  // value 0, not converged, no iteration and nothing that is not a number
  for (const bool zero : {false, true})
    {
      Vector<double> x(n);
      for (unsigned int i = 0; i < n - n_contact; ++i)
        x[i] = zero ? 0. : 1.;
      const EigenvalueEstimate estimate =
        largest_generalized_eigenvalue(apply_n, apply_k, jacobi, x, 1e-6, 300);
      out() << (zero ? "zero start" : "start outside the range of N")
            << ": value " << estimate.value << ", converged "
            << (estimate.converged ? "yes" : "no") << ", iterations "
            << estimate.iterations << ", x finite "
            << (std::isfinite(x.l2_norm()) ? "yes" : "no") << "\n";
    }
}
