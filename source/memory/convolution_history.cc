#include <hemicontact/memory/convolution_history.h>
#include <hemicontact/memory/normal_memory_kernel.h>
#include <hemicontact/memory/relaxation_kernel.h>

#include <cmath>
#include <utility>

namespace hemicontact
{
  namespace
  {
    using VectorType = TrilinosWrappers::MPI::Vector;

    /** @p y += @p a @p x: everywhere, or only at @p entries. */
    void
    add(VectorType                                 &y,
        const double                                a,
        const VectorType                           &x,
        const std::vector<types::global_dof_index> *entries)
    {
      if (entries == nullptr)
        {
          y.add(a, x);
          return;
        }
      // read, then set (not +=): the vector's last operation must be the
      // 'insert' its compress() names, which deal.II's debug library checks
      for (const types::global_dof_index d : *entries)
        y[d] = y[d] + a * x[d];
      y.compress(VectorOperation::insert);
    }

    /** @p y *= @p a: everywhere, or only at @p entries. */
    void
    scale(VectorType                                 &y,
          const double                                a,
          const std::vector<types::global_dof_index> *entries)
    {
      if (entries == nullptr)
        {
          y *= a;
          return;
        }
      for (const types::global_dof_index d : *entries)
        y[d] = y[d] * a;
      y.compress(VectorOperation::insert);
    }
  } // namespace

  template <typename Kernel>
  void
  ConvolutionHistory<Kernel>::reinit(const IndexSet &owned)
  {
    owned_dofs = owned;
    clear();
  }

  template <typename Kernel>
  void
  ConvolutionHistory<Kernel>::clear()
  {
    terms.assign(kernel.n_terms(), VectorType(owned_dofs, comm));
    trial_terms = terms;
    past_times.clear();
    past_steps.clear();
    past_states.clear();
    pending_state.reinit(owned_dofs, comm);
  }

  template <typename Kernel>
  void
  ConvolutionHistory<Kernel>::prepare_step(
    const double                                start,
    const double                                k,
    const VectorType                           &x,
    const Sums                                 &sums,
    const std::vector<types::global_dof_index> *entries)
  {
    if (kernel.type() == MemoryKernelType::prony)
      // h_n = e^{-k/tau} (h_{n-1} + k x_{n-1}) per term
      for (unsigned int m = 0; m < terms.size(); ++m)
        {
          VectorType &h = trial_terms[m];
          h             = terms[m];
          add(h, k, x, entries);
          scale(h, std::exp(-k / kernel.relaxation_time(m)), entries);
          for (unsigned int c = 0; c < sums.size(); ++c)
            add(*sums[c], kernel.amplitude(c, m), h, entries);
        }
    else if (kernel.type() == MemoryKernelType::expression)
      {
        // the sum over the past states, the one before the step last
        const double t = start + k;
        for (unsigned int j = 0; j < past_states.size(); ++j)
          {
            const auto K = kernel.values(t - past_times[j]);
            for (unsigned int c = 0; c < sums.size(); ++c)
              add(*sums[c], past_steps[j] * K[c], past_states[j], entries);
          }
        const auto K = kernel.values(t - start);
        for (unsigned int c = 0; c < sums.size(); ++c)
          add(*sums[c], k * K[c], x, entries);
        pending_time  = start;
        pending_step  = k;
        pending_state = x;
      }
  }

  template <typename Kernel>
  void
  ConvolutionHistory<Kernel>::commit_step()
  {
    if (kernel.type() == MemoryKernelType::prony)
      std::swap(terms, trial_terms);
    else if (kernel.type() == MemoryKernelType::expression)
      {
        past_times.push_back(pending_time);
        past_steps.push_back(pending_step);
        past_states.push_back(pending_state);
      }
  }

  template <typename Kernel>
  void
  ConvolutionHistory<Kernel>::save_values(std::vector<double> &values) const
  {
    if (kernel.type() != MemoryKernelType::expression)
      {
        values.push_back(static_cast<double>(terms.size()));
        return;
      }
    values.push_back(static_cast<double>(past_states.size()));
    values.insert(values.end(), past_times.begin(), past_times.end());
    values.insert(values.end(), past_steps.begin(), past_steps.end());
  }

  template <typename Kernel>
  void
  ConvolutionHistory<Kernel>::save_fields(
    std::vector<const VectorType *> &fields) const
  {
    for (const VectorType &x :
         kernel.type() == MemoryKernelType::prony ? terms : past_states)
      fields.push_back(&x);
  }

  template <typename Kernel>
  std::size_t
  ConvolutionHistory<Kernel>::restore(const std::vector<double> &values,
                                      const std::size_t          first,
                                      std::vector<VectorType *> &fields)
  {
    clear();
    const std::size_t n =
      first < values.size() ? std::lround(values[first]) : 0;
    std::size_t size = 1;
    if (kernel.type() == MemoryKernelType::expression)
      {
        size = 1 + 2 * n;
        AssertIndexRange(first + size, values.size() + 1);
        const auto times = values.begin() + first + 1;
        past_times.assign(times, times + n);
        past_steps.assign(times + n, times + 2 * n);
        past_states.assign(n, VectorType(owned_dofs, comm));
      }
    for (VectorType &x :
         kernel.type() == MemoryKernelType::prony ? terms : past_states)
      fields.push_back(&x);
    return size;
  }

  template class ConvolutionHistory<RelaxationKernel>;
  template class ConvolutionHistory<NormalMemoryKernel>;
} // namespace hemicontact
