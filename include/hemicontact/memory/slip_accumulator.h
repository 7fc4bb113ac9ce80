#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/trilinos_vector.h>

#include <array>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /** What the contact memory needs of a contact node. */
  template <int dim>
  struct MemoryNode
  {
    std::array<types::global_dof_index, dim> dofs;
    Tensor<1, dim>                           normal;
    double                                   mass;
  };

  /**
   * A sum over the steps at each contact node, held at its first degree of
   * freedom: c sum_{j=1}^{n-1} p_j |u_tau,j - u_tau,j-1 - k_j v*_tau| in
   * the static class, c sum_{j=1}^{n-1} k_j p_j |w_tau,j - v*_tau| in the
   * velocity classes. The accumulated slip s_tau (doc/theory.md, section
   * 11.10) is c = 1, p_j = 1, v* = 0; the wear depth omega (section 11.12)
   * is c = k_w with the contact pressure p_j = (-sigma_nu)_+ and the
   * foundation's velocity v*.
   */
  template <int dim>
  class SlipAccumulator
  {
  public:
    using VectorType = TrilinosWrappers::MPI::Vector;

    /**
     * The sum with c = @p coefficient, v* = @p foundation_velocity and
     * p_j the contact pressure (@p by_pressure) or 1, on @p comm.
     */
    SlipAccumulator(const double          coefficient,
                    const Tensor<1, dim> &foundation_velocity,
                    const bool            by_pressure,
                    MPI_Comm              comm)
      : coefficient(coefficient)
      , foundation_velocity(foundation_velocity)
      , by_pressure(by_pressure)
      , comm(comm)
    {}

    /** Whether c > 0: a sum to accumulate, and to checkpoint. */
    bool
    active() const
    {
      return coefficient > 0;
    }

    /** A zero sum of the layout @p owned. */
    void
    reinit(const IndexSet &owned)
    {
      sum.reinit(owned, comm);
    }

    /** A zero sum. */
    void
    clear()
    {
      sum = 0;
    }

    /**
     * Add the step of length @p k at @p nodes with the unknown @p unknown
     * (u_n in the static class, w_n otherwise), u_{n-1} @p start in the
     * static class (nullptr otherwise), and the nodal traction -sigma nu
     * @p traction if p_j is the pressure.
     */
    void
    add(const std::vector<MemoryNode<dim>> &nodes,
        const VectorType                   *unknown,
        const VectorType                   *start,
        const VectorType                   *traction,
        const double                        k);

    /** The sum up to the step added last (zero elsewhere). */
    const VectorType &
    value() const
    {
      return sum;
    }
    VectorType &
    value()
    {
      return sum;
    }

  private:
    double         coefficient;
    Tensor<1, dim> foundation_velocity;
    bool           by_pressure;
    MPI_Comm       comm;
    VectorType     sum;
  };
} // namespace hemicontact
