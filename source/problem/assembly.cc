#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/problem/cell_matrices.h>
#include <hemicontact/problem/contact_problem.h>

#include <cmath>
#include <sstream>
#include <string>

namespace hemicontact
{
  template <int dim>
  void
  ContactProblem<dim>::assemble_constant_matrices(
    const StepMatrixCoefficients &c)
  {
    TimerOutput::Scope t(timer, "assembly: constant matrices");
    mass_matrix    = 0;
    step_matrix    = 0;
    elastic_matrix = 0;
    // K = c_M rho M + c_A A + c_B B of the class and scheme (doc/theory.md,
    // section 9); the dynamic left point is rho/k M + A

    const FiniteElement<dim> &fe = *discretization.fe;
    FEValues<dim>             fe_values(*discretization.mapping,
                            fe,
                            discretization.cell_quadrature(2),
                            update_values | update_gradients |
                              update_JxW_values);
    const unsigned int        n = fe.n_dofs_per_cell();
    FullMatrix<double> cell_mass(n, n), cell_viscous(n, n), cell_elastic(n, n),
      cell_step(n, n);
    std::vector<types::global_dof_index> dofs(n);

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          cell_matrices(
            material, fe_values, cell_mass, cell_viscous, cell_elastic);
          cell_step = cell_viscous;
          if (c.viscous != 1.)
            cell_step *= c.viscous;
          if (c.mass != 0.)
            cell_step.add(c.mass, cell_mass);
          if (c.elastic != 0.)
            cell_step.add(c.elastic, cell_elastic);
          cell->get_dof_indices(dofs);
          base_constraints.distribute_local_to_global(cell_mass,
                                                      dofs,
                                                      mass_matrix);
          base_constraints.distribute_local_to_global(cell_step,
                                                      dofs,
                                                      step_matrix);
          base_constraints.distribute_local_to_global(cell_elastic,
                                                      dofs,
                                                      elastic_matrix);
        }
    mass_matrix.compress(VectorOperation::add);
    step_matrix.compress(VectorOperation::add);
    elastic_matrix.compress(VectorOperation::add);
  }

  template <int dim>
  void
  cell_matrices(const KelvinVoigtMaterial<dim> &material,
                const FEValues<dim>            &fe_values,
                FullMatrix<double>             &mass,
                FullMatrix<double>             &viscous,
                FullMatrix<double>             &elastic)
  {
    const FEValuesExtractors::Vector     v(0);
    const unsigned int                   n = fe_values.dofs_per_cell;
    std::vector<SymmetricTensor<2, dim>> eps(n);
    std::vector<Tensor<1, dim>>          phi(n);
    const double                         rho = material.density();
    mass                                     = 0;
    viscous                                  = 0;
    elastic                                  = 0;
    for (const unsigned int q : fe_values.quadrature_point_indices())
      {
        for (unsigned int i = 0; i < n; ++i)
          {
            eps[i] = fe_values[v].symmetric_gradient(i, q);
            phi[i] = fe_values[v].value(i, q);
          }
        const double JxW = fe_values.JxW(q);
        for (unsigned int i = 0; i < n; ++i)
          {
            const SymmetricTensor<2, dim> a_i = material.viscous_stress(eps[i]);
            const SymmetricTensor<2, dim> b_i = material.elastic_stress(eps[i]);
            for (unsigned int j = 0; j < n; ++j)
              {
                mass(i, j) += rho * (phi[i] * phi[j]) * JxW;
                viscous(i, j) += (a_i * eps[j]) * JxW;
                elastic(i, j) += (b_i * eps[j]) * JxW;
              }
          }
      }
  }

  template <int dim>
  void
  ContactProblem<dim>::assemble_load(const double time)
  {
    TimerOutput::Scope t(timer, "assembly: load");
    data.set_time(time);
    load = 0;

    const FiniteElement<dim>            &fe = *discretization.fe;
    FEValues<dim>                        fe_values(*discretization.mapping,
                            fe,
                            discretization.cell_quadrature(3),
                            update_values | update_quadrature_points |
                              update_JxW_values);
    FEFaceValues<dim>                    fe_face(*discretization.mapping,
                              fe,
                              discretization.face_quadrature(3),
                              update_values | update_quadrature_points |
                                update_normal_vectors | update_JxW_values);
    const unsigned int                   n = fe.n_dofs_per_cell();
    Vector<double>                       cell_load(n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<Vector<double>>          values(fe_values.n_quadrature_points,
                                       Vector<double>(dim));
    std::vector<Vector<double>> face_values(fe_face.n_quadrature_points,
                                            Vector<double>(dim));

    // zero data (the default body force, an unloaded contact boundary)
    // contribute nothing: skip their integrals
    const auto is_zero = [](const Function<dim> *f) {
      return dynamic_cast<const Functions::ZeroFunction<dim> *>(f) != nullptr;
    };
    const bool body_force       = !is_zero(data.body_force.get());
    const bool surface_traction = !is_zero(data.surface_traction.get()) ||
                                  data.surface_traction_with_normal != nullptr;
    const bool contact_traction = !is_zero(data.contact_traction.get()) ||
                                  data.contact_traction_with_normal != nullptr;

    // a value that is not a finite number is reported by name, point and
    // time, on every rank (none may wait for another in compress())
    std::string not_finite;
    const auto  check_finite = [&](const std::vector<Vector<double>> &v,
                                  const std::vector<Point<dim>>     &points,
                                  const std::string                 &name) {
      if (!not_finite.empty())
        return;
      for (unsigned int q = 0; q < v.size(); ++q)
        for (unsigned int c = 0; c < dim; ++c)
          if (!std::isfinite(v[q](c)))
            {
              std::ostringstream message;
              message << "data: " << name << " is not a finite number ("
                      << v[q](c) << " in component " << c << ") at x = ("
                      << points[q] << "), t = " << time
                      << "; check the expression for that point and time.";
              not_finite = message.str();
              return;
            }
    };
    const bool manufactured = data.surface_traction_with_normal != nullptr;

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell_load = 0;
          if (body_force)
            {
              fe_values.reinit(cell);
              data.body_force->vector_value_list(
                fe_values.get_quadrature_points(), values);
              check_finite(values,
                           fe_values.get_quadrature_points(),
                           manufactured ?
                             "the body force f0 derived from 'manufactured "
                             "solution/exact displacement'" :
                             "'body force' = '" + parameters.data.body_force +
                               "'");
              for (const unsigned int q : fe_values.quadrature_point_indices())
                for (unsigned int i = 0; i < n; ++i)
                  {
                    const unsigned int c =
                      fe.system_to_component_index(i).first;
                    cell_load(i) += values[q](c) *
                                    fe_values.shape_value_component(i, q, c) *
                                    fe_values.JxW(q);
                  }
            }

          for (const unsigned int f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                const BoundaryPart part =
                  parameters.boundary.part(cell->face(f)->boundary_id());
                const bool on_traction =
                  surface_traction && part == BoundaryPart::traction;
                const bool on_contact =
                  contact_traction && part == BoundaryPart::contact;
                if (!on_traction && !on_contact)
                  continue;
                fe_face.reinit(cell, f);
                data.boundary_traction(on_traction,
                                       fe_face.get_quadrature_points(),
                                       fe_face.get_normal_vectors(),
                                       face_values);
                check_finite(face_values,
                             fe_face.get_quadrature_points(),
                             manufactured ?
                               std::string(on_traction ?
                                             "the traction f2" :
                                             "the contact traction f3") +
                                 " derived from 'manufactured solution/exact "
                                 "displacement' and the multipliers" :
                             on_traction ?
                               "'surface traction' = '" +
                                 parameters.data.surface_traction + "'" :
                               "'contact traction' = '" +
                                 parameters.data.contact_traction + "'");
                for (const unsigned int q : fe_face.quadrature_point_indices())
                  for (unsigned int i = 0; i < n; ++i)
                    {
                      const unsigned int c =
                        fe.system_to_component_index(i).first;
                      cell_load(i) += face_values[q](c) *
                                      fe_face.shape_value_component(i, q, c) *
                                      fe_face.JxW(q);
                    }
              }
          if (cell_load.linfty_norm() == 0)
            continue;
          cell->get_dof_indices(dofs);
          base_constraints.distribute_local_to_global(cell_load, dofs, load);
        }
    for (const std::string &message :
         Utilities::MPI::all_gather(mpi_communicator, not_finite))
      if (!message.empty())
        throw InputError(message);
    load.compress(VectorOperation::add);
    // the coupled fields' loads, e.g. the thermal stress +(c_e theta, div
    // v) (doc/theory.md 13.2)
    coupled_fields.add_mechanical_loads(time,
                                        mechanical_view(state()),
                                        added_fields,
                                        load);
  }

  template <int dim>
  void
  ContactProblem<dim>::assemble_step_rhs()
  {
    // b = rho/k M w_{n-1} - B u + F_n (without inertia F_n - B u), u the
    // displacement held before the step (doc/theory.md, section 9)
    TrilinosWrappers::MPI::Vector tmp(locally_owned_dofs, mpi_communicator);
    scheme.step_rhs(mass_matrix,
                    elastic_matrix,
                    old_velocity,
                    displacement,
                    load,
                    time_step,
                    step_rhs,
                    tmp);
    // the memory term -(M_n, eps(v)) (doc/theory.md, section 11)
    if (memory.active())
      memory.subtract_from(step_rhs);
    base_constraints.set_zero(step_rhs);
  }

#define HEMICONTACT_INSTANTIATE(dim)                              \
  template void ContactProblem<dim>::assemble_constant_matrices(  \
    const StepMatrixCoefficients &);                              \
  template void cell_matrices(const KelvinVoigtMaterial<dim> &,   \
                              const FEValues<dim> &,              \
                              FullMatrix<double> &,               \
                              FullMatrix<double> &,               \
                              FullMatrix<double> &);              \
  template void ContactProblem<dim>::assemble_load(const double); \
  template void ContactProblem<dim>::assemble_step_rhs();

  HEMICONTACT_INSTANTIATE(2)
  HEMICONTACT_INSTANTIATE(3)
#undef HEMICONTACT_INSTANTIATE
} // namespace hemicontact
