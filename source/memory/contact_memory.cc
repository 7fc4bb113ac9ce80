#include <hemicontact/memory/contact_memory.h>

#include <algorithm>

namespace hemicontact
{
  namespace
  {
    /** v* of @p wear, its components beyond dim dropped. */
    template <int dim>
    Tensor<1, dim>
    foundation_velocity(const WearParameters &wear)
    {
      Tensor<1, dim> v;
      for (unsigned int c = 0;
           c < std::min<std::size_t>(dim, wear.foundation_velocity.size());
           ++c)
        v[c] = wear.foundation_velocity[c];
      return v;
    }
  } // namespace

  template <int dim>
  ContactMemory<dim>::ContactMemory(const NormalMemoryParameters &parameters,
                                    const WearParameters         &wear,
                                    const std::string            &constants,
                                    MPI_Comm                      comm)
    : comm(comm)
    , history(NormalMemoryKernel(parameters, constants), comm)
    , slip_sum(0., Tensor<1, dim>(), false, comm)
    , wear_sum(wear.coefficient, foundation_velocity<dim>(wear), true, comm)
  {}

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
    slip_sum.reinit(owned);
    wear_sum.reinit(owned);
    slip_start.reinit(owned, comm);
    history.reinit(owned);
    clear();
  }

  template <int dim>
  void
  ContactMemory<dim>::clear()
  {
    if (!active())
      return;
    history.clear();
    memory_pressure = 0;
    slip_sum.clear();
    wear_sum.clear();
    prepared = false;
  }

  template <int dim>
  void
  ContactMemory<dim>::prepare_step(const double      start,
                                   const double      k,
                                   const VectorType &u_start)
  {
    prepared     = true;
    pending_step = k;
    if ((slip_active() || wear_active()) && slip_from_displacement)
      slip_start = u_start;
    if (!normal_active())
      return;
    // (u_nu)_+ of the state at start, at each node's first dof
    std::vector<types::global_dof_index> first_dofs(nodes.size());
    VectorType                           penetration(owned_dofs, comm);
    for (std::size_t i = 0; i < nodes.size(); ++i)
      {
        double u_nu = 0;
        for (unsigned int c = 0; c < dim; ++c)
          u_nu += u_start[nodes[i].dofs[c]] * nodes[i].normal[c];
        first_dofs[i]              = nodes[i].dofs[0];
        penetration[first_dofs[i]] = std::max(u_nu, 0.);
      }
    penetration.compress(VectorOperation::insert);

    VectorType sum(owned_dofs, comm);
    history.prepare_step(start, k, penetration, {{&sum}}, &first_dofs);
    memory_pressure = 0;
    for (const Node &node : nodes)
      for (unsigned int c = 0; c < dim; ++c)
        memory_pressure[node.dofs[c]] = sum[node.dofs[0]] * node.normal[c];
    memory_pressure.compress(VectorOperation::insert);
  }

  template <int dim>
  void
  ContactMemory<dim>::commit_step(const VectorType *unknown,
                                  const VectorType *traction)
  {
    Assert(prepared, ExcMessage("commit_step() without prepare_step()"));
    const VectorType *start = slip_from_displacement ? &slip_start : nullptr;
    for (SlipAccumulator<dim> *sum : {&wear_sum, &slip_sum})
      if (sum->active())
        sum->add(nodes, unknown, start, traction, pending_step);
    history.commit_step();
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
    std::vector<double> values;
    history.save_values(values);
    return values;
  }

  template <int dim>
  std::vector<const typename ContactMemory<dim>::VectorType *>
  ContactMemory<dim>::saved_fields() const
  {
    std::vector<const VectorType *> fields;
    history.save_fields(fields);
    for (const SlipAccumulator<dim> *sum : {&slip_sum, &wear_sum})
      if (sum->active())
        fields.push_back(&sum->value());
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
    const std::size_t used = history.restore(values, 0, fields);
    (void)used;
    Assert(get_kernel().type() != MemoryKernelType::expression ||
             used == values.size(),
           ExcDimensionMismatch(values.size(), used));
    for (SlipAccumulator<dim> *sum : {&slip_sum, &wear_sum})
      if (sum->active())
        fields.push_back(&sum->value());
    return fields;
  }

  template <int dim>
  std::size_t
  ContactMemory<dim>::memory_consumption() const
  {
    if (!active())
      return 0;
    return memory_pressure.memory_consumption() * (history.n_vectors() + 4) +
           nodes.capacity() * sizeof(Node);
  }

  template class ContactMemory<2>;
  template class ContactMemory<3>;
} // namespace hemicontact
