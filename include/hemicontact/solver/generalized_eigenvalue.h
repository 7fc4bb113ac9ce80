#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include <algorithm>
#include <cmath>

namespace hemicontact
{
  using namespace dealii;

  /** What largest_generalized_eigenvalue() found. */
  struct EigenvalueEstimate
  {
    /** The largest Ritz value: a lower estimate of the largest eigenvalue. */
    double value = 0;
    /**
     * sqrt(r.T r) / value for the residual r = N x - value K x of the last
     * Ritz vector (x.K x = 1), T the preconditioner: with T = K^{-1} some
     * eigenvalue lies within this fraction of the value.
     */
    double relative_residual = 0;
    /** Rayleigh-Ritz steps taken. */
    unsigned int iterations = 0;
    /** relative_residual reached the tolerance. */
    bool converged = false;
  };

  /**
   * The largest eigenvalue mu of N x = mu K x, K symmetric positive definite
   * and N symmetric positive semidefinite, by LOBPCG with block size one
   * (Knyazev 2001): every iteration is a Rayleigh-Ritz step on
   * span{x, T r, p}, with x the current Ritz vector, r = N x - mu K x its
   * residual, T ~ K^{-1} a preconditioner and p the previous update. Unlike
   * the power iteration on K^{-1} N, it converges like a Krylov method, at
   * one application of T, K and N per iteration.
   *
   * If @p x has no K-norm, or N does not see it (x.N x = 0), it returns
   * value 0, not converged, after no iteration.
   *
   * @p apply_n(in, out), @p apply_k(in, out) and @p precondition(in, out)
   * write into @p out. @p x is the start vector on entry and the Ritz vector
   * (K-normalised) on return. Stops when the relative residual is at most
   * @p tolerance, or after @p max_iterations steps. VectorType needs
   * copying, operator*, operator/=, add(a, V) and sadd(s, a, V).
   */
  template <typename VectorType,
            typename ApplyN,
            typename ApplyK,
            typename Precondition>
  EigenvalueEstimate
  largest_generalized_eigenvalue(const ApplyN       &apply_n,
                                 const ApplyK       &apply_k,
                                 const Precondition &precondition,
                                 VectorType         &x,
                                 const double        tolerance,
                                 const unsigned int  max_iterations)
  {
    VectorType kx(x), nx(x), w(x), kw(x), nw(x), p(x), kp(x), np(x), r(x);
    EigenvalueEstimate result;

    const auto normalise = [&]() {
      const double norm = std::sqrt(x * kx);
      x /= norm;
      kx /= norm;
      nx /= norm;
    };
    apply_k(x, kx);
    apply_n(x, nx);
    // a zero start (e.g. every dof it touches constrained), or one that
    // N does not see: no estimate, value 0 and not converged
    if (!(x * kx > 0))
      return result;
    normalise();
    result.value = x * nx;
    if (!(result.value > 0))
      return result;

    bool have_p = false;
    for (;; ++result.iterations)
      {
        r = nx;
        r.add(-result.value, kx);
        precondition(r, w);
        result.relative_residual =
          std::sqrt(std::max(r * w, 0.)) / result.value;
        if (result.relative_residual <= tolerance)
          {
            result.converged = true;
            return result;
          }
        if (result.iterations == max_iterations)
          return result;
        apply_k(w, kw);
        apply_n(w, nw);

        // Rayleigh-Ritz: the Gram matrices of the basis in the K and N
        // products ...
        const VectorType  *v[3]  = {&x, &w, &p};
        const VectorType  *kv[3] = {&kx, &kw, &kp};
        const VectorType  *nv[3] = {&nx, &nw, &np};
        const unsigned int m     = have_p ? 3 : 2;
        double             b[3][3], a[3][3];
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int j = i; j < m; ++j)
            {
              b[i][j] = b[j][i] = *v[i] * *kv[j];
              a[i][j] = a[j][i] = *v[i] * *nv[j];
            }
        // ... a K-orthonormal basis of coefficient vectors (Gram-Schmidt,
        // twice; a direction that is numerically dependent is dropped) ...
        double       c[3][3] = {};
        unsigned int n_kept  = 0;
        for (unsigned int j = 0; j < m; ++j)
          {
            double e[3] = {0, 0, 0};
            e[j]        = 1;
            for (unsigned int pass = 0; pass < 2; ++pass)
              for (unsigned int q = 0; q < n_kept; ++q)
                {
                  double projection = 0;
                  for (unsigned int s = 0; s < m; ++s)
                    for (unsigned int t = 0; t < m; ++t)
                      projection += c[q][s] * b[s][t] * e[t];
                  for (unsigned int s = 0; s < m; ++s)
                    e[s] -= projection * c[q][s];
                }
            double norm2 = 0;
            for (unsigned int s = 0; s < m; ++s)
              for (unsigned int t = 0; t < m; ++t)
                norm2 += e[s] * b[s][t] * e[t];
            if (norm2 > 1e-12 * b[j][j])
              {
                for (unsigned int s = 0; s < m; ++s)
                  c[n_kept][s] = e[s] / std::sqrt(norm2);
                ++n_kept;
              }
          }
        // ... and the largest eigenpair of N in that basis (padded with
        // zeros: N is semidefinite, so the padding never wins)
        SymmetricTensor<2, 3> h;
        for (unsigned int q1 = 0; q1 < n_kept; ++q1)
          for (unsigned int q2 = q1; q2 < n_kept; ++q2)
            for (unsigned int s = 0; s < m; ++s)
              for (unsigned int t = 0; t < m; ++t)
                h[q1][q2] += c[q1][s] * a[s][t] * c[q2][t];
        const Tensor<1, 3> y = eigenvectors(h)[0].second; // descending order
        double             coefficient[3] = {0, 0, 0};
        for (unsigned int q = 0; q < n_kept; ++q)
          for (unsigned int s = 0; s < m; ++s)
            coefficient[s] += y[q] * c[q][s];

        // p <- c_1 w + c_2 p, x <- c_0 x + p, and their images alike
        VectorType       *ps[3] = {&p, &kp, &np};
        VectorType       *xs[3] = {&x, &kx, &nx};
        const VectorType *ws[3] = {&w, &kw, &nw};
        for (unsigned int i = 0; i < 3; ++i)
          {
            ps[i]->sadd(have_p ? coefficient[2] : 0., coefficient[1], *ws[i]);
            xs[i]->sadd(coefficient[0], 1., *ps[i]);
          }
        have_p = true;
        normalise();
        result.value = x * nx;
      }
  }
} // namespace hemicontact
