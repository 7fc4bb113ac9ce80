#pragma once

#include <deal.II/base/tensor.h>

namespace hemicontact
{
  using namespace dealii;

  /**
   * Tresca friction with bound F_b >= 0: |sigma_tau| <= F_b, and
   * -sigma_tau = F_b w_tau / |w_tau| where w_tau != 0. The potential is
   * F_b |w_tau|; its subdifferential is the disk of radius F_b at 0.
   */
  namespace TrescaFriction
  {
    /** The potential F_b |v|. */
    template <int dim>
    double
    potential(const double bound, const Tensor<1, dim> &v)
    {
      return bound * v.norm();
    }

    /** Projection of q onto the disk {|lambda| <= F_b}. */
    template <int dim>
    Tensor<1, dim>
    project(const Tensor<1, dim> &q, const double bound)
    {
      const double norm = q.norm();
      return norm <= bound ? q : (bound / norm) * q;
    }

    /** Whether q lies in the disk: the stick branch. */
    template <int dim>
    bool
    sticks(const Tensor<1, dim> &q, const double bound)
    {
      return q.norm() <= bound;
    }
  } // namespace TrescaFriction
} // namespace hemicontact
