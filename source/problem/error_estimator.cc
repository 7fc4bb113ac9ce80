#include <deal.II/fe/fe_values.h>

#include <hemicontact/problem/error_estimator.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace hemicontact
{
  Vector<float>
  ErrorEstimate::cell_values(const double contact_weight,
                             const bool   in_energy_norm) const
  {
    const double  scale = in_energy_norm ? energy_scale : 1.;
    Vector<float> values(interior.size());
    for (unsigned int i = 0; i < values.size(); ++i)
      values[i] =
        std::sqrt(scale * (interior[i] + jumps[i] + neumann[i] +
                           contact_weight * contact_weight * contact[i]));
    return values;
  }

  template <int dim>
  ErrorEstimator<dim>::ErrorEstimator(const Discretization<dim> &discretization,
                                      const DoFHandler<dim>     &dof_handler,
                                      const KelvinVoigtMaterial<dim> &material,
                                      const StepScheme               &scheme,
                                      const ProblemData<dim>         &data,
                                      const BoundaryParameters       &boundary)
    : discretization(discretization)
    , dof_handler(dof_handler)
    , material(material)
    , scheme(scheme)
    , data(data)
    , boundary(boundary)
  {}

  template <int dim>
  ErrorEstimate
  ErrorEstimator<dim>::estimate(const TrilinosWrappers::MPI::Vector &w,
                                const TrilinosWrappers::MPI::Vector &w_old,
                                const TrilinosWrappers::MPI::Vector &u,
                                const TrilinosWrappers::MPI::Vector &xi,
                                const double                         k,
                                MPI_Comm                             comm) const
  {
    const FiniteElement<dim>        &fe      = *discretization.fe;
    const Mapping<dim>              &mapping = *discretization.mapping;
    const Quadrature<dim - 1>        face_q = discretization.face_quadrature(2);
    const FEValuesExtractors::Vector v(0);
    const UpdateFlags                face_flags =
      update_gradients | update_normal_vectors | update_JxW_values;
    // one object per kind of point set, reinitialised cell by cell and face
    // by face (a cell that is a translation of the last reuses its mapping)
    FEValues<dim>     fe_values(mapping,
                            fe,
                            discretization.cell_quadrature(2),
                            update_values | update_hessians |
                              update_quadrature_points | update_JxW_values);
    FEFaceValues<dim> fe_boundary(mapping,
                                  fe,
                                  face_q,
                                  face_flags | update_values |
                                    update_quadrature_points);
    FEFaceValues<dim> fe_face(mapping, fe, face_q, face_flags);
    // the neighbour's side of a face: its gradients alone
    FEFaceValues<dim>    fe_face_other(mapping, fe, face_q, update_gradients);
    FESubfaceValues<dim> fe_subface(mapping, fe, face_q, face_flags);
    FESubfaceValues<dim> fe_subface_other(mapping,
                                          fe,
                                          face_q,
                                          update_gradients);

    const unsigned int          n_q    = fe_values.n_quadrature_points;
    const unsigned int          n_f    = face_q.size();
    const unsigned int          n_dofs = fe.n_dofs_per_cell();
    std::vector<Tensor<1, dim>> w_values(n_q), w_old_values(n_q);
    std::vector<Tensor<3, dim>> w_hessians(n_q), u_hessians(n_q);
    std::vector<Vector<double>> f_values(n_q, Vector<double>(dim));
    std::vector<Tensor<2, dim>> w_grads(n_f), u_grads(n_f);
    std::vector<Tensor<2, dim>> sigma(n_f), sigma_other(n_f);
    std::vector<Tensor<1, dim>> xi_values(n_f);
    std::vector<Vector<double>> g_values(n_f, Vector<double>(dim));

    // a part of sigma_h with zero moduli (the static class's A) adds exact
    // zeros: its field is neither read nor differentiated
    const bool with_w =
      material.mu_viscous() != 0 || material.lambda_viscous() != 0;
    const bool with_u =
      material.mu_elastic() != 0 || material.lambda_elastic() != 0;
    // the local values of the cell at hand, read once per cell, and of the
    // neighbour across the face at hand
    std::vector<types::global_dof_index> dof_indices(n_dofs),
      other_dof_indices(n_dofs);
    std::vector<double> w_local(n_dofs), w_old_local(n_dofs), u_local(n_dofs),
      xi_local(n_dofs), w_other(n_dofs), u_other(n_dofs);
    const auto read = [n_dofs](const TrilinosWrappers::MPI::Vector &vector,
                               const std::vector<types::global_dof_index> &at,
                               std::vector<double> &values) {
      for (unsigned int j = 0; j < n_dofs; ++j)
        values[j] = vector(at[j]);
    };
    const auto read_other = [&](const auto &other) {
      other->get_dof_indices(other_dof_indices);
      if (with_w)
        read(w, other_dof_indices, w_other);
      if (with_u)
        read(u, other_dof_indices, u_other);
    };

    const double rho = scheme.inertia_density(material.density());
    // sigma_h at the points of a face from a cell's local values
    const auto stresses = [&](const FEFaceValuesBase<dim> &face_values,
                              const std::vector<double>   &w_cell,
                              const std::vector<double>   &u_cell,
                              std::vector<Tensor<2, dim>> &result) {
      if (with_w)
        face_values[v].get_function_gradients_from_local_dof_values(w_cell,
                                                                    w_grads);
      if (with_u)
        face_values[v].get_function_gradients_from_local_dof_values(u_cell,
                                                                    u_grads);
      for (unsigned int q = 0; q < n_f; ++q)
        result[q] = Tensor<2, dim>(
          material.stress(symmetrize(w_grads[q]), symmetrize(u_grads[q])));
    };
    // |[sigma_h nu]|^2 over a face seen from the cell at hand (@p here) and
    // from the neighbour whose values read_other() read (@p there)
    const auto jump = [&](const FEFaceValuesBase<dim> &here,
                          const FEFaceValuesBase<dim> &there) {
      stresses(here, w_local, u_local, sigma);
      stresses(there, w_other, u_other, sigma_other);
      double integral = 0;
      for (unsigned int q = 0; q < n_f; ++q)
        integral +=
          ((sigma[q] - sigma_other[q]) * here.normal_vector(q)).norm_square() *
          here.JxW(q);
      return integral;
    };

    const unsigned int n_cells = discretization.triangulation->n_active_cells();
    ErrorEstimate      e;
    e.interior.reinit(n_cells);
    e.jumps.reinit(n_cells);
    e.neumann.reinit(n_cells);
    e.contact.reinit(n_cells);
    const StepMatrixCoefficients c = scheme.step_matrix(k);
    e.energy_scale = 1. / (2 * (c.viscous * material.mu_viscous() +
                                c.elastic * material.mu_elastic()));

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const unsigned int i = cell->active_cell_index();
          cell->get_dof_indices(dof_indices);
          if (with_w || rho != 0)
            read(w, dof_indices, w_local);
          if (with_u)
            read(u, dof_indices, u_local);

          // h_K^2 |f0 - rho/k (w_n - w_{n-1}) + div sigma_h|^2 over K, the
          // inertia only where rho > 0 (the dynamic class)
          fe_values.reinit(cell);
          if (with_w)
            fe_values[v].get_function_hessians_from_local_dof_values(
              w_local, w_hessians);
          if (with_u)
            fe_values[v].get_function_hessians_from_local_dof_values(
              u_local, u_hessians);
          if (rho != 0)
            {
              read(w_old, dof_indices, w_old_local);
              fe_values[v].get_function_values_from_local_dof_values(w_local,
                                                                     w_values);
              fe_values[v].get_function_values_from_local_dof_values(
                w_old_local, w_old_values);
            }
          data.body_force->vector_value_list(fe_values.get_quadrature_points(),
                                             f_values);
          double cell_residual = 0;
          for (unsigned int q = 0; q < n_q; ++q)
            {
              Tensor<1, dim> r =
                material.stress_divergence(w_hessians[q], u_hessians[q]);
              if (rho != 0)
                r -= rho / k * (w_values[q] - w_old_values[q]);
              for (unsigned int d = 0; d < dim; ++d)
                r[d] += f_values[q](d);
              cell_residual += r.norm_square() * fe_values.JxW(q);
            }
          e.interior[i] = std::pow(cell->diameter(), 2) * cell_residual;

          for (const unsigned int f : cell->face_indices())
            {
              const auto face = cell->face(f);
              if (face->at_boundary())
                {
                  // h_E |g - sigma_h nu - xi_h|^2 with g = f2 (or f3, or 0),
                  // xi_h only on Gamma_3; nothing on Gamma_1
                  const BoundaryPart part = boundary.part(face->boundary_id());
                  if (part == BoundaryPart::clamped)
                    continue;
                  const bool on_traction = part == BoundaryPart::traction;
                  const bool on_contact  = part == BoundaryPart::contact;
                  fe_boundary.reinit(cell, f);
                  stresses(fe_boundary, w_local, u_local, sigma);
                  for (auto &g : g_values)
                    g = 0;
                  if (on_traction || on_contact)
                    data.boundary_traction(on_traction,
                                           fe_boundary.get_quadrature_points(),
                                           fe_boundary.get_normal_vectors(),
                                           g_values);
                  if (on_contact)
                    {
                      read(xi, dof_indices, xi_local);
                      fe_boundary[v].get_function_values_from_local_dof_values(
                        xi_local, xi_values);
                    }
                  double boundary_residual = 0;
                  for (unsigned int q = 0; q < n_f; ++q)
                    {
                      Tensor<1, dim> r =
                        -sigma[q] * fe_boundary.normal_vector(q);
                      if (on_contact)
                        r -= xi_values[q];
                      for (unsigned int d = 0; d < dim; ++d)
                        r[d] += g_values[q](d);
                      boundary_residual += r.norm_square() * fe_boundary.JxW(q);
                    }
                  (on_contact ? e.contact : e.neumann)[i] +=
                    face->diameter() * boundary_residual;
                  continue;
                }

              // 1/2 h_E |[sigma_h nu]|^2 to each side of an interior face E
              // (each child face where the neighbour is finer), integrated
              // once: from the coarser side, between equals from the cell of
              // lower index; from both sides where they are on two ranks
              const auto neighbor = cell->neighbor(f);
              if (face->has_children())
                for (unsigned int sf = 0; sf < face->n_children(); ++sf)
                  {
                    const auto child = cell->neighbor_child_on_subface(f, sf);
                    read_other(child);
                    fe_subface.reinit(cell, f, sf);
                    fe_face_other.reinit(child, cell->neighbor_face_no(f));
                    const double half = 0.5 * face->child(sf)->diameter() *
                                        jump(fe_subface, fe_face_other);
                    e.jumps[i] += half;
                    if (child->is_locally_owned())
                      e.jumps[child->active_cell_index()] += half;
                  }
              else if (cell->neighbor_is_coarser(f))
                {
                  if (neighbor->is_locally_owned())
                    continue;
                  const auto [nf, nsf] = cell->neighbor_of_coarser_neighbor(f);
                  read_other(neighbor);
                  fe_face.reinit(cell, f);
                  fe_subface_other.reinit(neighbor, nf, nsf);
                  e.jumps[i] +=
                    0.5 * face->diameter() * jump(fe_face, fe_subface_other);
                }
              else
                {
                  const bool other_owned = neighbor->is_locally_owned();
                  if (other_owned && neighbor->active_cell_index() < i)
                    continue;
                  read_other(neighbor);
                  fe_face.reinit(cell, f);
                  fe_face_other.reinit(neighbor, cell->neighbor_of_neighbor(f));
                  const double half =
                    0.5 * face->diameter() * jump(fe_face, fe_face_other);
                  e.jumps[i] += half;
                  if (other_owned)
                    e.jumps[neighbor->active_cell_index()] += half;
                }
            }
        }
    e.interior_sum = Utilities::MPI::sum(e.interior.l1_norm(), comm);
    e.jumps_sum    = Utilities::MPI::sum(e.jumps.l1_norm(), comm);
    e.neumann_sum  = Utilities::MPI::sum(e.neumann.l1_norm(), comm);
    e.contact_sum  = Utilities::MPI::sum(e.contact.l1_norm(), comm);
    return e;
  }

  template class ErrorEstimator<2>;
  template class ErrorEstimator<3>;
} // namespace hemicontact
