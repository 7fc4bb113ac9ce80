#include <deal.II/fe/fe_interface_values.h>
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
    FEValues<dim>                    fe_values(mapping,
                            fe,
                            discretization.cell_quadrature(2),
                            update_values | update_hessians |
                              update_quadrature_points | update_JxW_values);
    FEFaceValues<dim>                fe_face(mapping,
                              fe,
                              face_q,
                              update_values | update_gradients |
                                update_quadrature_points |
                                update_normal_vectors | update_JxW_values);
    FEInterfaceValues<dim>           fe_interface(mapping,
                                        fe,
                                        face_q,
                                        update_gradients |
                                          update_normal_vectors |
                                          update_JxW_values);

    const unsigned int          n_q = fe_values.n_quadrature_points;
    const unsigned int          n_f = face_q.size();
    std::vector<Tensor<1, dim>> w_values(n_q), w_old_values(n_q);
    std::vector<Tensor<3, dim>> w_hessians(n_q), u_hessians(n_q);
    std::vector<Vector<double>> f_values(n_q, Vector<double>(dim));
    std::vector<Tensor<2, dim>> w_grads(n_f), u_grads(n_f), w_grads_n(n_f),
      u_grads_n(n_f);
    std::vector<Tensor<1, dim>> xi_values(n_f);
    std::vector<Vector<double>> g_values(n_f, Vector<double>(dim));

    const auto is_in = [](const std::vector<unsigned int> &ids,
                          const types::boundary_id         id) {
      return std::find(ids.begin(), ids.end(), id) != ids.end();
    };
    const double rho    = scheme.inertia_density(material.density());
    const auto   stress = [&](const Tensor<2, dim> &grad_w,
                            const Tensor<2, dim> &grad_u) {
      return Tensor<2, dim>(
        material.stress(symmetrize(grad_w), symmetrize(grad_u)));
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

          // h_K^2 |f0 - rho/k (w_n - w_{n-1}) + div sigma_h|^2 over K
          fe_values.reinit(cell);
          fe_values[v].get_function_values(w, w_values);
          fe_values[v].get_function_values(w_old, w_old_values);
          fe_values[v].get_function_hessians(w, w_hessians);
          fe_values[v].get_function_hessians(u, u_hessians);
          data.body_force->vector_value_list(fe_values.get_quadrature_points(),
                                             f_values);
          double cell_residual = 0;
          for (unsigned int q = 0; q < n_q; ++q)
            {
              Tensor<1, dim> r =
                -rho / k * (w_values[q] - w_old_values[q]) +
                material.stress_divergence(w_hessians[q], u_hessians[q]);
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
                  const types::boundary_id id = face->boundary_id();
                  if (is_in(boundary.clamped_ids, id))
                    continue;
                  const bool on_traction = is_in(boundary.traction_ids, id);
                  const bool on_contact =
                    !on_traction && is_in(boundary.contact_ids, id);
                  fe_face.reinit(cell, f);
                  fe_face[v].get_function_gradients(w, w_grads);
                  fe_face[v].get_function_gradients(u, u_grads);
                  for (auto &g : g_values)
                    g = 0;
                  if (on_traction || on_contact)
                    data.boundary_traction(on_traction,
                                           fe_face.get_quadrature_points(),
                                           fe_face.get_normal_vectors(),
                                           g_values);
                  if (on_contact)
                    fe_face[v].get_function_values(xi, xi_values);
                  double boundary_residual = 0;
                  for (unsigned int q = 0; q < n_f; ++q)
                    {
                      Tensor<1, dim> r = -stress(w_grads[q], u_grads[q]) *
                                         fe_face.normal_vector(q);
                      if (on_contact)
                        r -= xi_values[q];
                      for (unsigned int d = 0; d < dim; ++d)
                        r[d] += g_values[q](d);
                      boundary_residual += r.norm_square() * fe_face.JxW(q);
                    }
                  (on_contact ? e.contact : e.neumann)[i] +=
                    face->diameter() * boundary_residual;
                  continue;
                }

              // 1/2 h_E |[sigma_h nu]|^2, the half of each face of K: all
              // of it when the neighbour is as fine or coarser, each child
              // face when it is finer (hanging nodes)
              const auto add_jump = [&](const unsigned int subface) {
                const auto &side  = fe_interface.get_fe_face_values(0);
                const auto &other = fe_interface.get_fe_face_values(1);
                side[v].get_function_gradients(w, w_grads);
                side[v].get_function_gradients(u, u_grads);
                other[v].get_function_gradients(w, w_grads_n);
                other[v].get_function_gradients(u, u_grads_n);
                double jump = 0;
                for (unsigned int q = 0; q < n_f; ++q)
                  jump += ((stress(w_grads[q], u_grads[q]) -
                            stress(w_grads_n[q], u_grads_n[q])) *
                           fe_interface.normal(q))
                            .norm_square() *
                          fe_interface.JxW(q);
                const double h = subface == numbers::invalid_unsigned_int ?
                                   face->diameter() :
                                   face->child(subface)->diameter();
                e.jumps[i] += 0.5 * h * jump;
              };
              const auto neighbor = cell->neighbor(f);
              if (face->has_children())
                for (unsigned int sf = 0; sf < face->n_children(); ++sf)
                  {
                    const auto child = cell->neighbor_child_on_subface(f, sf);
                    fe_interface.reinit(cell,
                                        f,
                                        sf,
                                        child,
                                        cell->neighbor_face_no(f),
                                        numbers::invalid_unsigned_int);
                    add_jump(sf);
                  }
              else if (cell->neighbor_is_coarser(f))
                {
                  const auto [nf, nsf] = cell->neighbor_of_coarser_neighbor(f);
                  fe_interface.reinit(
                    cell, f, numbers::invalid_unsigned_int, neighbor, nf, nsf);
                  add_jump(numbers::invalid_unsigned_int);
                }
              else
                {
                  fe_interface.reinit(cell,
                                      f,
                                      numbers::invalid_unsigned_int,
                                      neighbor,
                                      cell->neighbor_of_neighbor(f),
                                      numbers::invalid_unsigned_int);
                  add_jump(numbers::invalid_unsigned_int);
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
