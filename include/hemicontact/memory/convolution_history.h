#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/trilinos_vector.h>

#include <hemicontact/input/parameters.h>

#include <array>
#include <cstddef>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * The history of a memory sum (doc/theory.md, section 11): the step on
   * [t_{n-1}, t_n] gets, for each component K_c of the kernel,
   *
   *   S_c = sum_{j<n} k_j K_c(t_n - t_j) x_j,   k_j = t_{j+1} - t_j,
   *
   * x_j the vector of state j. A Prony series keeps one vector per term,
   * h_n = e^{-k_n/tau} (h_{n-1} + k_n x_{n-1}), the same sum exactly; an
   * expression kernel keeps every past x_j with t_j and k_j.
   * prepare_step() forms S without changing the history, commit_step()
   * adds the step to it after the step converged.
   *
   * @p Kernel a MemoryKernel: the stress's RelaxationKernel, the normal
   * memory's NormalMemoryKernel.
   */
  template <typename Kernel>
  class ConvolutionHistory
  {
  public:
    using VectorType = TrilinosWrappers::MPI::Vector;

    /** The sums S_c, one per component of the kernel. */
    using Sums = std::array<VectorType *, Kernel::n_components>;

    /** The history of @p kernel, its vectors on @p comm. */
    ConvolutionHistory(const Kernel &kernel, MPI_Comm comm)
      : kernel(kernel)
      , comm(comm)
    {}

    const Kernel &
    get_kernel() const
    {
      return kernel;
    }

    /** Whether the kernel is not none. */
    bool
    active() const
    {
      return kernel.type() != MemoryKernelType::none;
    }

    /** Vectors of @p owned and an empty history. */
    void
    reinit(const IndexSet &owned);

    /** Forget every past state. */
    void
    clear();

    /**
     * @p sums += S of the step on [@p start, @p start + @p k] from the
     * history and @p x, the state at @p start, which the step adds. With
     * @p entries, only there: a Prony term keeps its other entries.
     */
    void
    prepare_step(const double                                start,
                 const double                                k,
                 const VectorType                           &x,
                 const Sums                                 &sums,
                 const std::vector<types::global_dof_index> *entries = nullptr);

    /** The step prepared last converged: its state joins the history. */
    void
    commit_step();

    /** @name Checkpoints */
    /** @{ */
    /** Appends the size of the history and, for an expression, t_j, k_j. */
    void
    save_values(std::vector<double> &values) const;
    /** Appends the vectors: one per Prony term or per past state. */
    void
    save_fields(std::vector<const VectorType *> &fields) const;
    /**
     * An empty history made of the numbers from @p values[@p first] on
     * (from save_values()), its vectors appended to @p fields to read into;
     * returns how many numbers it read.
     */
    std::size_t
    restore(const std::vector<double> &values,
            const std::size_t          first,
            std::vector<VectorType *> &fields);
    /** @} */

    /** The number of vectors held. */
    std::size_t
    n_vectors() const
    {
      return 2 * terms.size() + past_states.size() + 1;
    }

  private:
    Kernel   kernel;
    IndexSet owned_dofs;
    MPI_Comm comm;

    /** Prony: h_{n-1} of each term, and h_n of the step prepared. */
    std::vector<VectorType> terms;
    std::vector<VectorType> trial_terms;

    /** Expression: t_j, k_j and x_j of every state j < n - 1 ... */
    std::vector<double>     past_times;
    std::vector<double>     past_steps;
    std::vector<VectorType> past_states;
    /** ... and the state the step prepared adds. */
    double     pending_time = 0;
    double     pending_step = 0;
    VectorType pending_state;
  };
} // namespace hemicontact
