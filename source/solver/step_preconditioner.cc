#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>

#include <hemicontact/solver/step_preconditioner.h>

#include <Teuchos_ParameterList.hpp>

#include <map>

namespace hemicontact
{
  template <int dim>
  StepPreconditioner<dim>::StepPreconditioner(const SolverTuning &tuning,
                                              MPI_Comm            comm)
    : tuning(tuning)
    , mpi_communicator(comm)
  {}

  template <int dim>
  void
  StepPreconditioner<dim>::reinit(const DoFHandler<dim> &dof_handler,
                                  const Mapping<dim>    &mapping)
  {
    const IndexSet &owned   = dof_handler.locally_owned_dofs();
    const unsigned  n_owned = owned.n_elements();
    n_modes                 = dim == 2 ? 3 : 6;
    rigid_body_modes.assign(std::size_t(n_owned) * n_modes, 0.);

    std::map<types::global_dof_index, Point<dim>> support_points;
    DoFTools::map_dofs_to_support_points(mapping, dof_handler, support_points);

    // centre of the owned points, averaged over all processes
    Point<dim> centre;
    for (const auto &p : support_points)
      if (owned.is_element(p.first))
        centre += p.second;
    const double n_points =
      Utilities::MPI::sum(static_cast<double>(n_owned), mpi_communicator);
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = Utilities::MPI::sum(centre[d], mpi_communicator) / n_points;

    const FiniteElement<dim>            &fe = dof_handler.get_fe();
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (owned.is_element(dofs[i]))
              {
                const unsigned int   row = owned.index_within_set(dofs[i]);
                const unsigned int   c = fe.system_to_component_index(i).first;
                const Tensor<1, dim> x = support_points.at(dofs[i]) - centre;
                auto mode              = [&](const unsigned int m) -> double              &{
                  return rigid_body_modes[std::size_t(m) * n_owned + row];
                };
                mode(c) = 1.;
                if constexpr (dim == 2)
                  mode(2) = (c == 0 ? -x[1] : x[0]);
                else
                  {
                    // rotations about the x, y and z axes
                    const double r[3][3] = {{0, -x[2], x[1]},
                                            {x[2], 0, -x[0]},
                                            {-x[1], x[0], 0}};
                    for (unsigned int a = 0; a < 3; ++a)
                      mode(3 + a) = r[a][c];
                  }
              }
        }
    clear();
  }

  template <int dim>
  void
  StepPreconditioner<dim>::clear()
  {
    k0_amg.reset();
    other_amg.reset();
    constrained_amg.reset();
    penalised_step_matrix.clear();
    constrained_amg_directions.clear();
    constrained_amg_dropped = false;
    amg_in_use              = nullptr;
    splits.clear();
  }

  template <int dim>
  std::unique_ptr<TrilinosWrappers::PreconditionAMG>
  StepPreconditioner<dim>::make_amg(
    const TrilinosWrappers::SparseMatrix &matrix,
    const std::vector<double>            &modes)
  {
    Assert(n_modes > 0, ExcMessage("reinit() was not called."));
    Timer                                             timer;
    TrilinosWrappers::PreconditionAMG::AdditionalData data;
    data.elliptic              = true;
    data.higher_order_elements = false;
    data.smoother_sweeps       = tuning.smoother_sweeps;
    data.aggregation_threshold = tuning.aggregation_threshold;

    Teuchos::ParameterList              ml_list;
    std::unique_ptr<Epetra_MultiVector> unused_modes;
    data.set_parameters(ml_list, unused_modes, matrix);
    ml_list.set("null space: type", "pre-computed");
    // aggregate vertices (the dim dofs of a vertex are consecutive), not
    // single dofs: on tetrahedra, dof-wise aggregates are so small that
    // the coarse levels carry an operator complexity of 8.3 (2.2 with
    // vertex aggregates), doc/performance.md "Design choices"
    ml_list.set("PDE equations", dim);
    ml_list.set("null space: dimension", static_cast<int>(n_modes));
    ml_list.set("null space: vectors", const_cast<double *>(modes.data()));

    const double heap_before = heap_bytes_in_use();
    auto         result = std::make_unique<TrilinosWrappers::PreconditionAMG>();
    result->initialize(matrix, ml_list);
    amg_bytes[result.get()] = heap_bytes_in_use() - heap_before;
    ++setups;
    setup_wall_seconds +=
      Utilities::MPI::max(timer.wall_time(), mpi_communicator);
    return result;
  }

  template <int dim>
  const TrilinosWrappers::PreconditionAMG &
  StepPreconditioner<dim>::step_amg(
    const TrilinosWrappers::SparseMatrix &step_matrix)
  {
    if (k0_amg == nullptr)
      k0_amg = make_amg(step_matrix, rigid_body_modes);
    return *k0_amg;
  }

  template <int dim>
  const TrilinosWrappers::PreconditionAMG &
  StepPreconditioner<dim>::amg_of(const TrilinosWrappers::SparseMatrix &matrix)
  {
    other_amg = make_amg(matrix, rigid_body_modes);
    return *other_amg;
  }

  template <int dim>
  double
  StepPreconditioner<dim>::constrained_mismatch(
    const ProjectedOperator<dim> &op,
    const bool                    either_way) const
  {
    AssertDimension(constrained_amg_directions.size(), op.nodes().size());
    unsigned int counts[2] = {0, 0}; // mismatched, all
    for (unsigned int i = 0; i < op.nodes().size(); ++i)
      {
        const Tensor<2, dim> &free        = op.nodes()[i].projector;
        const Tensor<2, dim> &constrained = constrained_amg_directions[i];
        ++counts[1];
        if ((either_way ? unit_symmetric_tensor<dim>() - free - constrained :
                          free * constrained * free)
              .norm() > 0.5)
          ++counts[0];
      }
    Utilities::MPI::sum(counts, mpi_communicator, counts);
    return counts[0] / std::max(1., static_cast<double>(counts[1]));
  }

  template <int dim>
  void
  StepPreconditioner<dim>::build_constrained_amg(
    const ProjectedOperator<dim> &op)
  {
    // K0 plus gamma d_i (I - Pi_i)_cc on the diagonal of each node, d_i the
    // mean diagonal of K0 there: the constrained directions become the
    // Dirichlet conditions they are for the projected operator. Only the
    // diagonal is penalised (a point smoother cannot handle a large penalty
    // coupling the components of a node): exact for constrained directions
    // along the coordinate axes, a diagonal approximation otherwise.
    // the AMG of K0 is not used while this one is: freed before the set-up
    // (whose transient memory is about twice the hierarchy it leaves), and
    // built again if this one is dropped (doc/performance.md, "Memory")
    k0_amg.reset();
    const TrilinosWrappers::SparseMatrix &k0 = op.get_step_matrix();
    penalised_step_matrix.copy_from(k0);
    for (const auto &node : op.nodes())
      {
        double d = 0;
        for (unsigned int c = 0; c < dim; ++c)
          d += k0.diag_element(node.dofs[c]) / dim;
        for (unsigned int c = 0; c < dim; ++c)
          if (1. - node.projector[c][c] > 0)
            penalised_step_matrix.add(node.dofs[c],
                                      node.dofs[c],
                                      tuning.constraint_penalty * d *
                                        (1. - node.projector[c][c]));
      }
    penalised_step_matrix.compress(VectorOperation::add);

    // its near-null space vanishes on the constrained directions
    std::vector<double> modes(rigid_body_modes);
    const std::size_t   n_owned = modes.size() / n_modes;
    for (const auto &node : op.nodes())
      for (unsigned int m = 0; m < n_modes; ++m)
        {
          Tensor<1, dim> x;
          for (unsigned int c = 0; c < dim; ++c)
            x[c] = modes[m * n_owned + node.local_index[c]];
          const Tensor<1, dim> y = node.projector * x;
          for (unsigned int c = 0; c < dim; ++c)
            modes[m * n_owned + node.local_index[c]] = y[c];
        }
    constrained_amg = make_amg(penalised_step_matrix, modes);

    constrained_amg_directions.clear();
    for (const auto &node : op.nodes())
      constrained_amg_directions.push_back(unit_symmetric_tensor<dim>() -
                                           node.projector);
  }

  template <int dim>
  ConstrainedAmgStatus
  StepPreconditioner<dim>::constrained_amg_status() const
  {
    return constrained_amg         ? ConstrainedAmgStatus::built :
           constrained_amg_dropped ? ConstrainedAmgStatus::dropped :
                                     ConstrainedAmgStatus::none;
  }

  template <int dim>
  void
  StepPreconditioner<dim>::restore(const ProjectedOperator<dim> &op,
                                   const ConstrainedAmgStatus    status)
  {
    constrained_amg.reset();
    penalised_step_matrix.clear();
    constrained_amg_directions.clear();
    constrained_amg_dropped = status == ConstrainedAmgStatus::dropped;
    amg_in_use              = nullptr;
    splits.clear();
    if (status == ConstrainedAmgStatus::built)
      build_constrained_amg(op);
  }

  template <int dim>
  void
  StepPreconditioner<dim>::prepare(const ProjectedOperator<dim> &op)
  {
    const bool follow = tuning.constrained_preconditioner &&
                        tuning.constrained_amg_follows_branches;
    const bool build_now = tuning.constrained_preconditioner &&
                           !constrained_amg_dropped &&
                           (constrained_amg == nullptr ||
                            (follow && constrained_mismatch(op, true) > 0));
    if (!follow && constrained_amg != nullptr &&
        constrained_mismatch(op) > tuning.constrained_mismatch_limit)
      {
        constrained_amg.reset();
        penalised_step_matrix.clear();
        constrained_amg_dropped = true;
      }
    // the free directions the AMG treats as constrained (none for a new one)
    const bool split_mismatched = constrained_amg != nullptr && !build_now;
    if (build_now)
      build_constrained_amg(op);
    amg_in_use =
      constrained_amg ? constrained_amg.get() : &step_amg(op.get_step_matrix());

    const TrilinosWrappers::SparseMatrix &k0 = op.get_step_matrix();
    splits.resize(op.nodes().size());
    for (unsigned int i = 0; i < op.nodes().size(); ++i)
      {
        const auto &node     = op.nodes()[i];
        NodeSplit  &split    = splits[i];
        split.local_index    = node.local_index;
        split.soft_projector = node.projector;
        split.stiff_inverse  = Tensor<2, dim>();

        Tensor<2, dim> k0_diagonal;
        for (unsigned int c = 0; c < dim; ++c)
          k0_diagonal[c][c] = k0.diag_element(node.dofs[c]);
        // the nodal (Jacobi) inverse on the unit direction v, which the AMG
        // then no longer sees
        auto split_off = [&](const Tensor<1, dim> &v) {
          const Tensor<2, dim> vv = outer_product(v, v);
          split.soft_projector -= vv;
          split.stiff_inverse +=
            vv / (v * (node.stiffness * v) + v * (k0_diagonal * v));
        };
        if (tuning.stiff_contact_threshold > 0)
          for (const auto &eigenpair : eigenvectors(symmetrize(node.stiffness)))
            if (eigenpair.first >
                tuning.stiff_contact_threshold *
                  (eigenpair.second * (k0_diagonal * eigenpair.second)))
              split_off(eigenpair.second);

        if (split_mismatched)
          {
            const Tensor<2, dim> overlap = split.soft_projector *
                                           constrained_amg_directions[i] *
                                           split.soft_projector;
            if (overlap.norm() > 0)
              for (const auto &eigenpair : eigenvectors(symmetrize(overlap)))
                if (eigenpair.first > 0.5)
                  split_off(eigenpair.second);
          }
      }
  }

  template <int dim>
  void
  StepPreconditioner<dim>::vmult(TrilinosWrappers::MPI::Vector       &dst,
                                 const TrilinosWrappers::MPI::Vector &src) const
  {
    Assert(amg_in_use != nullptr, ExcMessage("prepare() was not called."));
    projected_src = src;
    apply_node_tensors<dim>(splits, &NodeSplit::soft_projector, projected_src);
    amg_in_use->vmult(dst, projected_src);
    apply_node_tensors<dim>(splits, &NodeSplit::soft_projector, dst);
    add_node_tensors<dim>(splits, &NodeSplit::stiff_inverse, src, dst);
  }

  template <int dim>
  void
  StepPreconditioner<dim>::add_memory(MemoryBreakdown &breakdown) const
  {
    const auto bytes_of = [&](const auto &amg) {
      const auto it = amg_bytes.find(amg.get());
      return amg == nullptr || it == amg_bytes.end() ? 0. : it->second;
    };
    breakdown.add("AMG of K0", bytes_of(k0_amg));
    breakdown.add("constrained AMG", bytes_of(constrained_amg));
    breakdown.add("AMG of another matrix", bytes_of(other_amg));
    breakdown.add_matrix("penalised step matrix", penalised_step_matrix);
    breakdown.add("rigid-body modes", rigid_body_modes.size() * sizeof(double));
    breakdown.add("vectors",
                  projected_src.locally_owned_size() * sizeof(double));
  }

  template class StepPreconditioner<2>;
  template class StepPreconditioner<3>;
} // namespace hemicontact
