#include <hemicontact/memory/contact_memory.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace hemicontact
{
  template <int dim>
  ContactMemory<dim>::ContactMemory(const NormalMemoryParameters &parameters,
                                    const WearParameters         &wear,
                                    const std::string            &constants,
                                    MPI_Comm                      comm)
    : kernel(parameters, constants)
    , comm(comm)
    , wear_coefficient(wear.coefficient)
  {
    for (unsigned int c = 0;
         c < std::min<std::size_t>(dim, wear.foundation_velocity.size());
         ++c)
      foundation_velocity[c] = wear.foundation_velocity[c];
  }

  template <int dim>
  void
  ContactMemory<dim>::reinit(const std::vector<ContactNode<dim>> &contact_nodes,
                             const IndexSet                      &owned)
  {
    if (!active())
      return;
    owned_dofs = owned;
    nodes.clear();
    for (const ContactNode<dim> &node : contact_nodes)
      if (node.locally_owned)
        nodes.push_back({node.dofs, node.normal, node.mass});
    memory_pressure.reinit(owned, comm);
    accumulated_slip.reinit(owned, comm);
    slip_start.reinit(owned, comm);
    wear_depth.reinit(owned, comm);
    clear();
  }

  template <int dim>
  void
  ContactMemory<dim>::clear()
  {
    if (!active())
      return;
    terms.assign(kernel.n_terms(), VectorType(owned_dofs, comm));
    trial_terms = terms;
    past_times.clear();
    past_steps.clear();
    past_states.clear();
    pending_state.reinit(owned_dofs, comm);
    memory_pressure  = 0;
    accumulated_slip = 0;
    wear_depth       = 0;
    prepared         = false;
  }

  template <int dim>
  void
  ContactMemory<dim>::prepare_step(const double      start,
                                   const double      k,
                                   const VectorType &u_start)
  {
    prepared     = true;
    pending_time = start;
    pending_step = k;
    if ((slip_measured || wear_active()) && slip_from_displacement)
      slip_start = u_start;
    if (!normal_active())
      return;
    // (u_nu)_+ of the state at start, at each node's first dof
    std::vector<double> penetration(nodes.size());
    for (std::size_t i = 0; i < nodes.size(); ++i)
      {
        double u_nu = 0;
        for (unsigned int c = 0; c < dim; ++c)
          u_nu += u_start[nodes[i].dofs[c]] * nodes[i].normal[c];
        penetration[i] = std::max(u_nu, 0.);
      }

    std::vector<double> sum(nodes.size(), 0.);
    if (kernel.type() == RelaxationKernelType::prony)
      // h_n = e^{-k/tau} (h_{n-1} + k (u_nu,n-1)_+) per term
      for (unsigned int m = 0; m < terms.size(); ++m)
        {
          VectorType  &h     = trial_terms[m];
          const double decay = std::exp(-k / kernel.relaxation_time(m));
          h                  = terms[m];
          for (std::size_t i = 0; i < nodes.size(); ++i)
            {
              const auto d = nodes[i].dofs[0];
              h[d]         = (h[d] + k * penetration[i]) * decay;
              sum[i] += kernel.amplitude(m) * h[d];
            }
          h.compress(VectorOperation::insert);
        }
    else
      {
        // the sum over the past states, the one before the step last
        const double t = start + k;
        for (unsigned int j = 0; j < past_states.size(); ++j)
          {
            const double weight = past_steps[j] * kernel(t - past_times[j]);
            for (std::size_t i = 0; i < nodes.size(); ++i)
              sum[i] += weight * past_states[j][nodes[i].dofs[0]];
          }
        const double weight = k * kernel(t - start);
        pending_state       = 0;
        for (std::size_t i = 0; i < nodes.size(); ++i)
          {
            sum[i] += weight * penetration[i];
            pending_state[nodes[i].dofs[0]] = penetration[i];
          }
        pending_state.compress(VectorOperation::insert);
      }
    memory_pressure = 0;
    for (std::size_t i = 0; i < nodes.size(); ++i)
      for (unsigned int c = 0; c < dim; ++c)
        memory_pressure[nodes[i].dofs[c]] = sum[i] * nodes[i].normal[c];
    memory_pressure.compress(VectorOperation::insert);
  }

  template <int dim>
  void
  ContactMemory<dim>::commit_step(const VectorType *unknown,
                                  const VectorType *traction)
  {
    Assert(prepared, ExcMessage("commit_step() without prepare_step()"));
    if (wear_active())
      {
        Assert(unknown != nullptr && traction != nullptr,
               ExcMessage("the wear needs the unknown and the traction"));
        // k_w p_n |u_tau,n - u_tau,n-1 - k_n v*| (static) or
        // k_w k_n p_n |w_tau,n - v*| per node, p_n = (-sigma_nu)_+
        for (const Node &node : nodes)
          {
            Tensor<1, dim> v, t;
            for (unsigned int c = 0; c < dim; ++c)
              {
                v[c] = (*unknown)[node.dofs[c]];
                t[c] = (*traction)[node.dofs[c]];
              }
            const double pressure = std::max(t * node.normal, 0.);
            if (slip_from_displacement)
              {
                for (unsigned int c = 0; c < dim; ++c)
                  v[c] -= slip_start[node.dofs[c]] +
                          pending_step * foundation_velocity[c];
                const Tensor<1, dim> v_tau =
                  v - (v * node.normal) * node.normal;
                // read, then set (not +=): the vector's last operation
                // must be the 'insert' its compress() names, which deal.II's
                // debug library checks
                wear_depth[node.dofs[0]] =
                  wear_depth[node.dofs[0]] +
                  wear_coefficient * pressure * v_tau.norm();
              }
            else
              {
                v -= foundation_velocity;
                const Tensor<1, dim> v_tau =
                  v - (v * node.normal) * node.normal;
                wear_depth[node.dofs[0]] =
                  wear_depth[node.dofs[0]] +
                  wear_coefficient * pending_step * pressure * v_tau.norm();
              }
          }
        wear_depth.compress(VectorOperation::insert);
      }
    if (slip_measured)
      {
        Assert(unknown != nullptr, ExcMessage("the slip needs the unknown"));
        // |u_tau,n - u_tau,n-1| (static) or k_n |w_tau,n| per node
        const double k = slip_from_displacement ? 1. : pending_step;
        for (const Node &node : nodes)
          {
            Tensor<1, dim> v;
            for (unsigned int c = 0; c < dim; ++c)
              v[c] = (*unknown)[node.dofs[c]] -
                     (slip_from_displacement ? slip_start[node.dofs[c]] : 0.);
            const Tensor<1, dim> v_tau = v - (v * node.normal) * node.normal;
            accumulated_slip[node.dofs[0]] =
              accumulated_slip[node.dofs[0]] + k * v_tau.norm();
          }
        accumulated_slip.compress(VectorOperation::insert);
      }
    if (kernel.type() == RelaxationKernelType::prony)
      std::swap(terms, trial_terms);
    else if (kernel.type() == RelaxationKernelType::expression)
      {
        past_times.push_back(pending_time);
        past_steps.push_back(pending_step);
        past_states.push_back(pending_state);
      }
  }

  template <int dim>
  void
  ContactMemory<dim>::add_functional(VectorType &functional) const
  {
    for (const Node &node : nodes)
      for (unsigned int c = 0; c < dim; ++c)
        functional[node.dofs[c]] =
          functional[node.dofs[c]] + node.mass * memory_pressure[node.dofs[c]];
    functional.compress(VectorOperation::insert);
  }

  template <int dim>
  std::vector<double>
  ContactMemory<dim>::saved_values() const
  {
    if (kernel.type() != RelaxationKernelType::expression)
      return {static_cast<double>(terms.size())};
    std::vector<double> values{static_cast<double>(past_states.size())};
    values.insert(values.end(), past_times.begin(), past_times.end());
    values.insert(values.end(), past_steps.begin(), past_steps.end());
    return values;
  }

  template <int dim>
  std::vector<const typename ContactMemory<dim>::VectorType *>
  ContactMemory<dim>::saved_fields() const
  {
    std::vector<const VectorType *> fields;
    for (const VectorType &x :
         kernel.type() == RelaxationKernelType::prony ? terms : past_states)
      fields.push_back(&x);
    if (slip_measured)
      fields.push_back(&accumulated_slip);
    if (wear_active())
      fields.push_back(&wear_depth);
    return fields;
  }

  template <int dim>
  std::vector<typename ContactMemory<dim>::VectorType *>
  ContactMemory<dim>::restore(const std::vector<double> &values)
  {
    clear();
    std::vector<VectorType *> fields;
    if (!active())
      return fields;
    const std::size_t n = values.empty() ? 0 : std::lround(values[0]);
    if (kernel.type() == RelaxationKernelType::expression)
      {
        AssertDimension(values.size(), 1 + 2 * n);
        past_times.assign(values.begin() + 1, values.begin() + 1 + n);
        past_steps.assign(values.begin() + 1 + n, values.end());
        past_states.assign(n, VectorType(owned_dofs, comm));
      }
    for (VectorType &x :
         kernel.type() == RelaxationKernelType::prony ? terms : past_states)
      fields.push_back(&x);
    if (slip_measured)
      fields.push_back(&accumulated_slip);
    if (wear_active())
      fields.push_back(&wear_depth);
    return fields;
  }

  template <int dim>
  std::size_t
  ContactMemory<dim>::memory_consumption() const
  {
    if (!active())
      return 0;
    return memory_pressure.memory_consumption() *
             (2 * terms.size() + past_states.size() + 5) +
           nodes.capacity() * sizeof(Node);
  }

  template class ContactMemory<2>;
  template class ContactMemory<3>;
} // namespace hemicontact
