#pragma once

#include <deal.II/base/tensor.h>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The convex, set-valued part of every friction law: the friction disk
   * {|lambda| <= F_b}, the subdifferential of F_b |v| at v = 0. The
   * active-set method projects onto it; a law's single-valued remainder
   * (FrictionLaw) comes on top.
   */
  namespace FrictionDisk
  {
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
  } // namespace FrictionDisk
} // namespace hemicontact
