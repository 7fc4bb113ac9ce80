#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <hemicontact/memory/memory_history.h>

#include <algorithm>

namespace hemicontact
{
  template <int dim>
  MemoryHistory<dim>::MemoryHistory(const RelaxationParameters &parameters,
                                    const std::string          &constants,
                                    MPI_Comm                    comm)
    : MemoryHistory(parameters,
                    NormalMemoryParameters{},
                    WearParameters{},
                    constants,
                    comm)
  {}

  template <int dim>
  MemoryHistory<dim>::MemoryHistory(const RelaxationParameters   &parameters,
                                    const NormalMemoryParameters &normal,
                                    const WearParameters         &wear,
                                    const std::string            &constants,
                                    MPI_Comm                      comm)
    : history(RelaxationKernel(parameters, constants), comm)
    , contact(normal, wear, constants, comm)
    , comm(comm)
  {}

  template <int dim>
  void
  MemoryHistory<dim>::reinit(const DoFHandler<dim>               &dof_handler,
                             const Mapping<dim>                  &mapping,
                             const Quadrature<dim>               &quadrature,
                             const AffineConstraints<double>     &constraints,
                             const IndexSet                      &owned,
                             const IndexSet                      &relevant,
                             const std::vector<ContactNode<dim>> &contact_nodes)
  {
    if (!active())
      return;
    owned_dofs    = owned;
    relevant_dofs = relevant;
    history.reinit(owned);
    for (VectorType *x : {&shear_sum, &volumetric_sum, &functional})
      x->reinit(owned, comm);
    contact.reinit(contact_nodes, owned);
    if (!stress_active())
      {
        clear();
        return;
      }

    TrilinosWrappers::SparsityPattern sparsity(owned, owned, relevant, comm);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    sparsity,
                                    constraints,
                                    /*keep_constrained_dofs=*/true,
                                    Utilities::MPI::this_mpi_process(comm));
    sparsity.compress();
    shear_matrix.reinit(sparsity);
    volumetric_matrix.reinit(sparsity);

    // a_mu(u, v) = 2 (eps(u), eps(v)), a_lambda(u, v) = (div u, div v)
    const FiniteElement<dim>            &fe = dof_handler.get_fe();
    FEValues<dim>                        fe_values(mapping,
                            fe,
                            quadrature,
                            update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     v(0);
    const unsigned int                   n = fe.n_dofs_per_cell();
    FullMatrix<double>                   shear(n, n), volumetric(n, n);
    std::vector<SymmetricTensor<2, dim>> eps(n);
    std::vector<double>                  div(n);
    std::vector<types::global_dof_index> dofs(n);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          shear      = 0;
          volumetric = 0;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              for (unsigned int i = 0; i < n; ++i)
                {
                  eps[i] = fe_values[v].symmetric_gradient(i, q);
                  div[i] = fe_values[v].divergence(i, q);
                }
              const double JxW = fe_values.JxW(q);
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j < n; ++j)
                  {
                    shear(i, j) += 2. * (eps[i] * eps[j]) * JxW;
                    volumetric(i, j) += div[i] * div[j] * JxW;
                  }
            }
          cell->get_dof_indices(dofs);
          constraints.distribute_local_to_global(shear, dofs, shear_matrix);
          constraints.distribute_local_to_global(volumetric,
                                                 dofs,
                                                 volumetric_matrix);
        }
    shear_matrix.compress(VectorOperation::add);
    volumetric_matrix.compress(VectorOperation::add);
    clear();
  }

  template <int dim>
  void
  MemoryHistory<dim>::clear()
  {
    if (!active())
      return;
    contact.clear();
    history.clear();
    shear_sum      = 0;
    volumetric_sum = 0;
    functional     = 0;
    prepared       = false;
  }

  template <int dim>
  void
  MemoryHistory<dim>::prepare_step(const double      start,
                                   const double      k,
                                   const VectorType &u_start)
  {
    shear_sum      = 0;
    volumetric_sum = 0;
    functional     = 0;
    prepared       = true;
    if (contact.active())
      contact.prepare_step(start, k, u_start);
    if (!stress_active())
      {
        if (contact.normal_active())
          contact.add_functional(functional);
        return;
      }
    history.prepare_step(start, k, u_start, {{&shear_sum, &volumetric_sum}});
    VectorType tmp(owned_dofs, comm);
    shear_matrix.vmult(functional, shear_sum);
    volumetric_matrix.vmult(tmp, volumetric_sum);
    functional += tmp;
    if (contact.normal_active())
      contact.add_functional(functional);
  }

  template <int dim>
  void
  MemoryHistory<dim>::commit_step(const VectorType *unknown,
                                  const VectorType *traction)
  {
    Assert(prepared, ExcMessage("commit_step() without prepare_step()"));
    if (contact.active())
      contact.commit_step(unknown, traction);
    history.commit_step();
  }

  template <int dim>
  std::vector<Vector<float>>
  MemoryHistory<dim>::cell_stress(const DoFHandler<dim> &dof_handler,
                                  const Mapping<dim>    &mapping,
                                  const Quadrature<dim> &quadrature) const
  {
    std::vector<Vector<float>> result(
      dim * (dim + 1) / 2,
      Vector<float>(dof_handler.get_triangulation().n_active_cells()));
    VectorType shear(owned_dofs, relevant_dofs, comm);
    VectorType volumetric(shear);
    shear      = shear_sum;
    volumetric = volumetric_sum;
    FEValues<dim>                        fe_values(mapping,
                            dof_handler.get_fe(),
                            quadrature,
                            update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     v(0);
    std::vector<SymmetricTensor<2, dim>> eps(quadrature.size());
    std::vector<double>                  div(quadrature.size());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[v].get_function_symmetric_gradients(shear, eps);
          fe_values[v].get_function_divergences(volumetric, div);
          SymmetricTensor<2, dim> sigma;
          double                  volume = 0;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              sigma += (2. * eps[q] + div[q] * unit_symmetric_tensor<dim>()) *
                       fe_values.JxW(q);
              volume += fe_values.JxW(q);
            }
          sigma /= volume;
          unsigned int c = 0;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = i; j < dim; ++j)
              result[c++][cell->active_cell_index()] = sigma[i][j];
        }
    return result;
  }

  template <int dim>
  std::vector<double>
  MemoryHistory<dim>::saved_values() const
  {
    // the stress's numbers, then those of the contact memory
    std::vector<double> values;
    history.save_values(values);
    if (contact.active())
      for (const double x : contact.saved_values())
        values.push_back(x);
    return values;
  }

  template <int dim>
  std::vector<const typename MemoryHistory<dim>::VectorType *>
  MemoryHistory<dim>::saved_fields() const
  {
    std::vector<const VectorType *> fields;
    history.save_fields(fields);
    if (contact.active())
      for (const VectorType *x : contact.saved_fields())
        fields.push_back(x);
    return fields;
  }

  template <int dim>
  std::vector<typename MemoryHistory<dim>::VectorType *>
  MemoryHistory<dim>::restore(const std::vector<double> &values)
  {
    clear();
    std::vector<VectorType *> fields;
    if (!active())
      return fields;
    const std::size_t stress_size = history.restore(values, 0, fields);
    if (contact.active())
      for (VectorType *x : contact.restore(std::vector<double>(
             values.begin() + std::min(stress_size, values.size()),
             values.end())))
        fields.push_back(x);
    return fields;
  }

  template <int dim>
  std::size_t
  MemoryHistory<dim>::memory_consumption() const
  {
    if (!active())
      return 0;
    std::size_t bytes = shear_matrix.memory_consumption() +
                        volumetric_matrix.memory_consumption() +
                        contact.memory_consumption();
    const std::size_t vector = functional.memory_consumption();
    bytes += vector * (history.n_vectors() + 3);
    return bytes;
  }

  template class MemoryHistory<2>;
  template class MemoryHistory<3>;
} // namespace hemicontact
