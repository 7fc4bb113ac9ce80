/**
 * The equilibrated (Prager-Synge) error bound of the static class
 * (doc/theory.md, section 12.5; equilibrated_estimate.h).
 */
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_raviart_thomas.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/lapack_templates.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/problem/equilibrated_estimate.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace hemicontact
{
  namespace
  {
    const std::string entry = "output: 'error estimate = equilibrated'";

    /**
     * The Korn constants assumed (doc/theory.md 12.5, (A2)): |grad v|^2 <=
     * korn_squared |eps(v)|^2 and |skew grad v|^2 <= (korn_squared - 1)
     * |eps(v)|^2, the values for a v that vanishes on the whole boundary.
     */
    constexpr double korn_squared = 2;

    /**
     * One patch problem: minimise (1/2) x.M x - b.x subject to G x = g, M
     * block diagonal with the square @p blocks (one per cell of the patch),
     * by the Schur complement G M^{-1} G^T, whose pseudo-inverse is taken
     * from its eigenpairs (the constraints of a patch are linearly
     * dependent). Returns
     * the largest constraint violation relative to the largest right-hand
     * side.
     */
    double
    solve_patch(std::vector<FullMatrix<double>> &blocks,
                const Vector<double>            &b,
                const FullMatrix<double>        &G,
                const Vector<double>            &g,
                Vector<double>                  &x)
    {
      const unsigned int n_b = blocks[0].m(), n = b.size(), n_c = G.m();
      // the blocks each row touches
      std::vector<std::vector<unsigned int>> touched(n_c);
      for (unsigned int c = 0; c < n_c; ++c)
        for (unsigned int k = 0; k < blocks.size(); ++k)
          for (unsigned int i = k * n_b; i < (k + 1) * n_b; ++i)
            if (G(c, i) != 0)
              {
                touched[c].push_back(k);
                break;
              }
      // Y = M^{-1} G^T, z = M^{-1} b, block by block
      FullMatrix<double> y(n, n_c);
      Vector<double>     z(n);
      for (unsigned int k = 0; k < blocks.size(); ++k)
        {
          FullMatrix<double> &inverse = blocks[k];
          inverse.gauss_jordan();
          const unsigned int off = k * n_b;
          for (unsigned int i = 0; i < n_b; ++i)
            for (unsigned int j = 0; j < n_b; ++j)
              z[off + i] += inverse(i, j) * b[off + j];
        }
      for (unsigned int c = 0; c < n_c; ++c)
        for (const unsigned int k : touched[c])
          {
            const unsigned int off = k * n_b;
            for (unsigned int i = 0; i < n_b; ++i)
              {
                double sum = 0;
                for (unsigned int j = 0; j < n_b; ++j)
                  sum += blocks[k](i, j) * G(c, off + j);
                y(off + i, c) = sum;
              }
          }
      // S = G Y (over the blocks two rows share), s = G z - g
      FullMatrix<double> s(n_c, n_c);
      Vector<double>     rhs(n_c);
      for (unsigned int c = 0; c < n_c; ++c)
        {
          for (unsigned int d = 0; d < n_c; ++d)
            {
              double sum = 0;
              for (const unsigned int k : touched[c])
                if (std::find(touched[d].begin(), touched[d].end(), k) !=
                    touched[d].end())
                  for (unsigned int i = k * n_b; i < (k + 1) * n_b; ++i)
                    sum += G(c, i) * y(i, d);
              s(c, d) = sum;
            }
          double sum = 0;
          for (const unsigned int k : touched[c])
            for (unsigned int i = k * n_b; i < (k + 1) * n_b; ++i)
              sum += G(c, i) * z[i];
          rhs[c] = sum - g[c];
        }
      // S is symmetric positive semidefinite: its pseudo-inverse from the
      // eigenpairs (LAPACK syev; the columns of a the eigenvectors)
      std::vector<double> a(n_c * n_c), eigenvalues(n_c), work(4 * n_c);
      for (unsigned int c = 0; c < n_c; ++c)
        for (unsigned int d = 0; d < n_c; ++d)
          a[d * n_c + c] = s(c, d);
      const types::blas_int size = n_c, work_size = work.size();
      types::blas_int       info = 0;
      syev("V",
           "U",
           &size,
           a.data(),
           &size,
           eigenvalues.data(),
           work.data(),
           &work_size,
           &info);
      AssertThrow(info == 0, ExcMessage("LAPACK syev failed"));
      const double cut =
        1e-11 * *std::max_element(eigenvalues.begin(), eigenvalues.end());
      Vector<double> lambda(n_c);
      for (unsigned int k = 0; k < n_c; ++k)
        if (eigenvalues[k] > cut)
          {
            double dot = 0;
            for (unsigned int c = 0; c < n_c; ++c)
              dot += a[k * n_c + c] * rhs[c];
            for (unsigned int c = 0; c < n_c; ++c)
              lambda[c] += a[k * n_c + c] * dot / eigenvalues[k];
          }
      // x = z - Y lambda
      x = z;
      for (unsigned int c = 0; c < n_c; ++c)
        for (const unsigned int k : touched[c])
          for (unsigned int i = k * n_b; i < (k + 1) * n_b; ++i)
            x[i] -= y(i, c) * lambda[c];
      double violation = 0, scale = 1e-300;
      for (unsigned int c = 0; c < n_c; ++c)
        {
          double sum = 0;
          for (const unsigned int k : touched[c])
            for (unsigned int i = k * n_b; i < (k + 1) * n_b; ++i)
              sum += G(c, i) * x[i];
          violation = std::max(violation, std::abs(sum - g[c]));
          scale     = std::max(scale, std::abs(g[c]));
        }
      return violation / scale;
    }
  } // namespace

  void
  require_equilibrated_usable(const Parameters &parameters)
  {
    if (!parameters.output.error_estimate_equilibrated)
      return;
    const std::string what =
      entry + " (doc/theory.md 12.5) reconstructs the stress of the static "
              "class on 2D quadrilateral meshes without hanging nodes, on "
              "one MPI rank, without memory; ";
    require(parameters.problem.problem_class == ProblemClass::static_,
            what + "the velocity classes' steps (their mass and viscous terms) "
                   "are not done yet. Set 'problem/class = static', or 'output/"
                   "error estimate = true' for the residual estimate.");
    require(parameters.dimension == 2,
            what + "3D is not done yet. Use 'output/error estimate = true' "
                   "(the residual estimate) in 3D.");
    require(parameters.geometry.cell_type == CellType::hypercube,
            what + "simplices are not done yet (deal.II 9.4 has no "
                   "Raviart-Thomas element on them). Use 'geometry/cell "
                   "type = hypercube' or 'output/error estimate = true'.");
    require(parameters.adaptivity.interval == 0 &&
              parameters.adaptivity.pre_refinement_steps == 0 &&
              parameters.adaptivity.target_error == 0,
            what + "adapted meshes (hanging nodes) are not done yet. Set "
                   "'adaptivity/interval', 'pre-refinement steps' and "
                   "'target error' to 0, or use 'output/error estimate = "
                   "true'.");
    require(Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1,
            what + "the patches of a vertex on another rank's cells are not "
                   "done yet. Run on one rank, or use 'output/error "
                   "estimate = true'.");
    const bool memory =
      parameters.relaxation.active() || parameters.normal_memory.active() ||
      parameters.wear.active() ||
      parameters.data.friction_bound.find("s_tau") != std::string::npos;
    require(!memory,
            what + "memory (relaxation, normal memory, wear, an accumulated "
                   "slip) is not done yet. Use 'output/error estimate = "
                   "true'.");
  }

  template <int dim>
  ErrorEstimate
  equilibrated_estimate(const ProblemState<dim>             &state,
                        const ProblemData<dim>              &data,
                        const TrilinosWrappers::MPI::Vector &u,
                        const TrilinosWrappers::MPI::Vector &xi)
  {
    const Discretization<dim> &discretization = state.discretization;
    const Triangulation<dim>  &mesh           = *discretization.triangulation;
    const std::string          what =
      entry + " (doc/theory.md 12.5) reconstructs the stress on one MPI rank "
              "of a 2D quadrilateral mesh without hanging nodes; ";
    require(Utilities::MPI::n_mpi_processes(state.mpi_communicator) == 1,
            what + "the patches of a vertex on another rank's cells are not "
                   "done yet. Run on one rank, or use 'output/error "
                   "estimate = true'.");
    require(dim == 2 && !discretization.is_simplex() &&
              !mesh.has_hanging_nodes(),
            what + "this mesh is not one. Use 'output/error estimate = "
                   "true'.");
    require(state.scheme.is_static(),
            what + "and the static class alone. Use 'output/error estimate "
                   "= true'.");
    require(!std::isfinite(state.normal_law.penetration_limit()),
            what + "a normal law with a wall (whose reaction is not a "
                   "subgradient of the law) is not done yet. Use 'output/"
                   "error estimate = true'.");
    // theta and the trace eigenvalue of the convexity check (doc/theory.md
    // 9.5): x.K x >= bound sum m_i (alpha_nu (x.nu)^2 + alpha_tau |x_tau|^2)
    // with friction, >= bound sum m_i (x.nu)^2 without
    const ConvexityCheck &check = state.convexity;
    const double alpha_nu = state.normal_law.relaxed_monotonicity_constant();
    require(check.bound > 0 && std::isfinite(check.bound) &&
              (!check.with_friction || alpha_nu > 0),
            what + "its contact term needs the trace eigenvalue of the "
                   "convexity check, which the check gives for a normal law "
                   "with a finite alpha_nu > 0 alone (not for a monotone law "
                   "nor for a downward jump). Use 'output/error estimate = "
                   "true'.");
    const double theta =
      check.with_friction ? 1. / check.bound : alpha_nu / check.bound;
    const double trace_eigenvalue =
      check.with_friction ? check.bound * alpha_nu : check.bound;

    const Mapping<dim>       &mapping = *discretization.mapping;
    const double              mu      = state.material.mu_elastic();
    const double              lambda  = state.material.lambda_elastic();
    const FESystem<dim>       fe_sigma(FE_RaviartThomas<dim>(1), dim);
    const FE_Q<dim>           fe_psi(1);
    const QGauss<dim>         cell_q(3);
    const QGauss<dim - 1>     face_q(3);
    const unsigned int        n_rt  = fe_sigma.n_dofs_per_cell();
    const unsigned int        n_psi = fe_psi.n_dofs_per_cell();
    const unsigned int        n_q = cell_q.size(), n_f = face_q.size();
    const BoundaryParameters &boundary = state.parameters.boundary;

    FEValues<dim>     sigma_values(mapping,
                               fe_sigma,
                               cell_q,
                               update_values | update_gradients |
                                 update_quadrature_points | update_JxW_values);
    FEValues<dim>     psi_values(mapping,
                             fe_psi,
                             cell_q,
                             update_values | update_gradients);
    FEValues<dim>     u_values(mapping,
                           *discretization.fe,
                           cell_q,
                           update_gradients);
    const UpdateFlags face_flags = update_values | update_normal_vectors |
                                   update_quadrature_points | update_JxW_values;
    FEFaceValues<dim> sigma_face(mapping, fe_sigma, face_q, face_flags);
    FEFaceValues<dim> sigma_face_other(mapping, fe_sigma, face_q, face_flags);
    FEFaceValues<dim> psi_face(mapping, fe_psi, face_q, update_values);
    FEFaceValues<dim> u_face(mapping,
                             *discretization.fe,
                             face_q,
                             update_values);
    std::vector<FEValuesExtractors::Vector> rows;
    for (unsigned int i = 0; i < dim; ++i)
      rows.emplace_back(i * dim);
    const FEValuesExtractors::Vector displacement(0);

    // the stress tensor of RT shape function j at point q (its rows)
    const auto shape_stress = [&](const FEValuesBase<dim> &values,
                                  const unsigned int       j,
                                  const unsigned int       q) {
      Tensor<2, dim> tau;
      for (unsigned int i = 0; i < dim; ++i)
        tau[i] = values[rows[i]].value(j, q);
      return tau;
    };
    // the compliance A^{-1}: (tau - lambda/(2 mu + d lambda) tr tau I)/(2 mu)
    const auto compliance = [&](const Tensor<2, dim> &tau) {
      Tensor<2, dim> c         = tau;
      const double   trace_tau = trace(tau);
      for (unsigned int d = 0; d < dim; ++d)
        c[d][d] -= lambda / (2 * mu + dim * lambda) * trace_tau;
      return c / (2 * mu);
    };
    const auto stress_h = [&](const Tensor<2, dim> &grad) {
      const Tensor<2, dim> eps = 0.5 * (grad + transpose(grad));
      Tensor<2, dim>       s   = 2 * mu * eps;
      for (unsigned int d = 0; d < dim; ++d)
        s[d][d] += lambda * trace(eps);
      return s;
    };
    // xi~ on Gamma_3: the continuous piecewise-linear traction whose
    // moments against the hat functions are the nodal contact forces,
    // int_Gamma3 phi_i xi~ = m_i xi_i: M_C xi~ = M_L xi with the consistent
    // and the lumped mass of Gamma_3 (m_i = sum |E|/2, doc/theory.md 12.5)
    std::map<unsigned int, unsigned int> gamma3_index;
    for (const auto &cell : state.dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() &&
            boundary.part(cell->face(f)->boundary_id()) ==
              BoundaryPart::contact)
          for (const unsigned int v : cell->face(f)->vertex_indices())
            gamma3_index.emplace(cell->face(f)->vertex_index(v),
                                 gamma3_index.size());
    const unsigned int          n_gamma3 = gamma3_index.size();
    LAPACKFullMatrix<double>    consistent(n_gamma3, n_gamma3);
    std::vector<Vector<double>> forces(dim, Vector<double>(n_gamma3));
    for (const auto &cell : state.dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (const auto face = cell->face(f);
            face->at_boundary() &&
            boundary.part(face->boundary_id()) == BoundaryPart::contact)
          {
            const double length = face->measure();
            for (unsigned int v = 0; v < 2; ++v)
              {
                const unsigned int i = gamma3_index[face->vertex_index(v)];
                for (unsigned int w = 0; w < 2; ++w)
                  consistent(i, gamma3_index[face->vertex_index(w)]) +=
                    length / (v == w ? 3. : 6.);
                for (unsigned int d = 0; d < dim; ++d)
                  forces[d][i] += length / 2 * xi(face->vertex_dof_index(v, d));
              }
          }
    std::vector<Tensor<1, dim>> xi_nodal(n_gamma3);
    if (n_gamma3 > 0)
      {
        consistent.compute_cholesky_factorization();
        for (unsigned int d = 0; d < dim; ++d)
          {
            consistent.solve(forces[d]);
            for (unsigned int i = 0; i < n_gamma3; ++i)
              xi_nodal[i][d] = forces[d][i];
          }
      }

    // the data traction g of a face off Gamma_1 at the face's points: f2 on
    // Gamma_2, 0 on an unlisted boundary, f3 - xi~ on Gamma_3 (psi_face on
    // the cell's face for xi~)
    std::vector<Vector<double>> g_values(n_f, Vector<double>(dim));
    std::vector<Tensor<1, dim>> xi_tilde(n_f), u_at(n_f);
    const auto                  traction =
      [&](const typename DoFHandler<dim>::active_cell_iterator &cell,
          const BoundaryPart                                    part,
          std::vector<Tensor<1, dim>>                          &g) {
        g.assign(n_f, Tensor<1, dim>());
        if (part == BoundaryPart::free)
          return;
        data.boundary_traction(part == BoundaryPart::traction,
                               sigma_face.get_quadrature_points(),
                               sigma_face.get_normal_vectors(),
                               g_values);
        for (unsigned int q = 0; q < n_f; ++q)
          for (unsigned int d = 0; d < dim; ++d)
            g[q][d] = g_values[q](d);
        if (part != BoundaryPart::contact)
          return;
        xi_tilde.assign(n_f, Tensor<1, dim>());
        for (const unsigned int v : cell->vertex_indices())
          if (const auto i = gamma3_index.find(cell->vertex_index(v));
              i != gamma3_index.end())
            for (unsigned int q = 0; q < n_f; ++q)
              xi_tilde[q] += psi_face.shape_value(v, q) * xi_nodal[i->second];
        for (unsigned int q = 0; q < n_f; ++q)
          g[q] -= xi_tilde[q];
      };
    // the face's linear coordinate (x - x_E).t / |E|
    const auto face_coordinate = [](const auto &face, const Point<dim> &x) {
      const Tensor<1, dim> t = face->vertex(1) - face->vertex(0);
      return (x - face->center()) * t / t.norm_square();
    };

    // the cells around each vertex
    std::vector<std::vector<typename DoFHandler<dim>::active_cell_iterator>>
      patches(mesh.n_vertices());
    for (const auto &cell : state.dof_handler.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        patches[cell->vertex_index(v)].push_back(cell);

    std::vector<Vector<double>> coefficients(mesh.n_active_cells(),
                                             Vector<double>(n_rt));
    std::vector<Tensor<2, dim>> u_grads(n_q);
    std::vector<Vector<double>> f_values(n_q, Vector<double>(dim));
    std::vector<Tensor<1, dim>> g(n_f);
    double                      largest_violation = 0;
    for (unsigned int a = 0; a < patches.size(); ++a)
      {
        const auto &cells = patches[a];
        if (cells.empty())
          continue;
        const unsigned int              m = cells.size(), n = m * n_rt;
        std::vector<FullMatrix<double>> M(m, FullMatrix<double>(n_rt, n_rt));
        Vector<double>                  b(n);
        // the constraints, one row each
        std::vector<Vector<double>> g_rows;
        std::vector<double>         g_rhs;
        const auto new_row = [&](const double value) -> Vector<double> & {
          g_rows.emplace_back(n);
          g_rhs.push_back(value);
          return g_rows.back();
        };
        for (unsigned int c = 0; c < m; ++c)
          {
            const auto        &cell = cells[c];
            const unsigned int off  = c * n_rt;
            unsigned int       va   = 0;
            for (const unsigned int v : cell->vertex_indices())
              if (cell->vertex_index(v) == a)
                va = v;
            const typename Triangulation<dim>::cell_iterator plain = cell;
            sigma_values.reinit(plain);
            psi_values.reinit(plain);
            u_values.reinit(cell);
            u_values[displacement].get_function_gradients(u, u_grads);
            data.body_force->vector_value_list(
              sigma_values.get_quadrature_points(), f_values);
            // M, b: |A^{-1/2}(sigma - psi_a sigma_h)|^2 (its skew part
            // weighted 1/(2 mu)), whose linear part is psi_a sigma : eps(u_h);
            // div sigma_i = Q1 projection of -psi_a f0_i + (sigma_h grad
            // psi_a)_i. No constraint on the skew part: its integral over the
            // patch is the residual at the rotation psi_a (-x2, x1), not zero
            // with Q1 (doc/theory.md 12.5)
            FullMatrix<double> div_rows(dim * n_psi, n_rt);
            Vector<double>     div_rhs(dim * n_psi);
            for (unsigned int q = 0; q < n_q; ++q)
              {
                const Tensor<2, dim> sigma_h = stress_h(u_grads[q]);
                const Tensor<2, dim> eps =
                  0.5 * (u_grads[q] + transpose(u_grads[q]));
                const double                psi = psi_values.shape_value(va, q);
                const Tensor<1, dim>        dpsi = psi_values.shape_grad(va, q);
                const Tensor<1, dim>        load = sigma_h * dpsi;
                const double                dx   = sigma_values.JxW(q);
                std::vector<Tensor<2, dim>> tau(n_rt), c_tau(n_rt);
                for (unsigned int j = 0; j < n_rt; ++j)
                  {
                    tau[j]   = shape_stress(sigma_values, j, q);
                    c_tau[j] = compliance(tau[j]);
                  }
                for (unsigned int j = 0; j < n_rt; ++j)
                  {
                    b[off + j] += psi * scalar_product(tau[j], eps) * dx;
                    for (unsigned int k = 0; k < n_rt; ++k)
                      M[c](j, k) += scalar_product(c_tau[j], tau[k]) * dx;
                  }
                for (unsigned int s = 0; s < n_psi; ++s)
                  {
                    const double phi = psi_values.shape_value(s, q);
                    for (unsigned int i = 0; i < dim; ++i)
                      {
                        div_rhs[i * n_psi + s] +=
                          (-psi * f_values[q](i) + load[i]) * phi * dx;
                        for (unsigned int j = 0; j < n_rt; ++j)
                          div_rows(i * n_psi + s, j) +=
                            sigma_values[rows[i]].divergence(j, q) * phi * dx;
                      }
                  }
              }
            for (unsigned int r = 0; r < div_rows.m(); ++r)
              {
                Vector<double> &row = new_row(div_rhs[r]);
                for (unsigned int j = 0; j < n_rt; ++j)
                  row[off + j] = div_rows(r, j);
              }

            // the faces: sigma nu against P1(E)^dim
            for (const unsigned int f : cell->face_indices())
              {
                const auto   face  = cell->face(f);
                unsigned int other = m;
                if (!face->at_boundary())
                  for (unsigned int c2 = 0; c2 < m; ++c2)
                    if (cells[c2] == cell->neighbor(f))
                      other = c2;
                if (face->at_boundary() &&
                    boundary.part(face->boundary_id()) == BoundaryPart::clamped)
                  continue; // free on Gamma_1
                if (other < c)
                  continue; // the continuity across it is written
                sigma_face.reinit(plain, f);
                if (face->at_boundary())
                  {
                    psi_face.reinit(plain, f);
                    u_face.reinit(cell, f);
                    traction(cell, boundary.part(face->boundary_id()), g);
                  }
                else
                  g.assign(n_f, Tensor<1, dim>());
                if (other < m)
                  sigma_face_other.reinit(
                    typename Triangulation<dim>::cell_iterator(cells[other]),
                    cell->neighbor_of_neighbor(f));
                for (unsigned int i = 0; i < dim; ++i)
                  for (unsigned int p = 0; p < 2; ++p)
                    {
                      double          target = 0;
                      Vector<double> &row    = new_row(0.);
                      for (unsigned int q = 0; q < n_f; ++q)
                        {
                          const Point<dim> &x = sigma_face.quadrature_point(q);
                          const double      weight =
                            (p == 0 ? 1. : face_coordinate(face, x)) *
                            sigma_face.JxW(q);
                          if (face->at_boundary())
                            target +=
                              psi_face.shape_value(va, q) * g[q][i] * weight;
                          for (unsigned int j = 0; j < n_rt; ++j)
                            row[off + j] += sigma_face[rows[i]].value(j, q) *
                                            sigma_face.normal_vector(q) *
                                            weight;
                        }
                      if (other < m)
                        for (unsigned int q = 0; q < n_f; ++q)
                          {
                            const Point<dim> &x =
                              sigma_face_other.quadrature_point(q);
                            const double weight =
                              (p == 0 ? 1. : face_coordinate(face, x)) *
                              sigma_face_other.JxW(q);
                            for (unsigned int j = 0; j < n_rt; ++j)
                              row[other * n_rt + j] +=
                                sigma_face_other[rows[i]].value(j, q) *
                                sigma_face_other.normal_vector(q) * weight;
                          }
                      g_rhs.back() = target;
                    }
              }
          }

        FullMatrix<double> G(g_rows.size(), n);
        Vector<double>     rhs(g_rows.size());
        for (unsigned int r = 0; r < g_rows.size(); ++r)
          {
            for (unsigned int j = 0; j < n; ++j)
              G(r, j) = g_rows[r][j];
            rhs[r] = g_rhs[r];
          }
        Vector<double> x(n);
        largest_violation =
          std::max(largest_violation, solve_patch(M, b, G, rhs, x));
        for (unsigned int c = 0; c < m; ++c)
          for (unsigned int j = 0; j < n_rt; ++j)
            coefficients[cells[c]->active_cell_index()][j] += x[c * n_rt + j];
      }
    if (largest_violation > 1e-6)
      std::cerr << "hemicontact: warning: the equilibrated stress misses its "
                   "constraints by "
                << largest_violation
                << " (relative) on some patch: the bound is not guaranteed "
                   "there (doc/theory.md 12.5)."
                << std::endl;

    // the terms per cell
    const std::map<types::global_dof_index, const ContactNode<dim> *> nodes =
      [&] {
        std::map<types::global_dof_index, const ContactNode<dim> *> map;
        for (const ContactNode<dim> &node : state.contact_nodes)
          map[node.dofs[0]] = &node;
        return map;
      }();
    double u_scale = 0;
    for (const ContactNode<dim> &node : state.contact_nodes)
      for (unsigned int d = 0; d < dim; ++d)
        u_scale = std::max(u_scale, std::abs(u[node.dofs[d]]));
    const double tolerance = 1e-8 * u_scale + 1e-300;

    const unsigned int n_cells = mesh.n_active_cells();
    ErrorEstimate      e;
    e.interior.reinit(n_cells);
    e.jumps.reinit(n_cells);
    e.neumann.reinit(n_cells);
    e.contact.reinit(n_cells);
    double stress_sum = 0, skew_sum = 0, mean_sum = 0, normal_sum = 0,
           tangential_sum                       = 0;
    const double                domain_diameter = GridTools::diameter(mesh);
    std::vector<Tensor<1, dim>> tau_n(n_f);
    for (const auto &cell : state.dof_handler.active_cell_iterators())
      {
        const unsigned int    i    = cell->active_cell_index();
        const Vector<double> &coef = coefficients[i];
        const typename Triangulation<dim>::cell_iterator plain = cell;
        sigma_values.reinit(plain);
        u_values.reinit(cell);
        u_values[displacement].get_function_gradients(u, u_grads);
        data.body_force->vector_value_list(sigma_values.get_quadrature_points(),
                                           f_values);
        double                      stress = 0, skew = 0, volume = 0;
        Tensor<1, dim>              r_mean;
        std::vector<Tensor<1, dim>> r(n_q);
        for (unsigned int q = 0; q < n_q; ++q)
          {
            Tensor<2, dim> tau;
            for (unsigned int j = 0; j < n_rt; ++j)
              {
                tau += coef[j] * shape_stress(sigma_values, j, q);
                for (unsigned int d = 0; d < dim; ++d)
                  r[q][d] += coef[j] * sigma_values[rows[d]].divergence(j, q);
              }
            for (unsigned int d = 0; d < dim; ++d)
              r[q][d] += f_values[q](d);
            const double         dx  = sigma_values.JxW(q);
            const Tensor<2, dim> sym = 0.5 * (tau + transpose(tau));
            const Tensor<2, dim> as  = 0.5 * (tau - transpose(tau));
            const Tensor<2, dim> d   = sym - stress_h(u_grads[q]);
            stress += scalar_product(compliance(d), d) * dx;
            skew += as.norm_square() / (2 * mu) * dx;
            r_mean += r[q] * dx;
            volume += dx;
          }
        r_mean /= volume;
        double oscillation = 0;
        for (unsigned int q = 0; q < n_q; ++q)
          oscillation += (r[q] - r_mean).norm_square() * sigma_values.JxW(q);
        const double h = cell->diameter();
        e.jumps[i]     = stress + skew;
        e.interior[i]  = korn_squared *
                        (std::pow(h / numbers::PI, 2) * oscillation +
                         std::pow(domain_diameter / numbers::PI, 2) *
                           r_mean.norm_square() * volume) /
                        (2 * mu);
        stress_sum += stress;
        skew_sum += skew;
        mean_sum += r_mean.norm_square() * volume;

        for (const unsigned int f : cell->face_indices())
          {
            const auto face = cell->face(f);
            if (!face->at_boundary())
              continue;
            const BoundaryPart part = boundary.part(face->boundary_id());
            if (part == BoundaryPart::clamped)
              continue;
            sigma_face.reinit(plain, f);
            psi_face.reinit(plain, f);
            u_face.reinit(cell, f);
            traction(cell, part, g);
            double mismatch = 0;
            for (unsigned int q = 0; q < n_f; ++q)
              {
                Tensor<1, dim> sn;
                for (unsigned int j = 0; j < n_rt; ++j)
                  for (unsigned int d = 0; d < dim; ++d)
                    sn[d] += coef[j] * (sigma_face[rows[d]].value(j, q) *
                                        sigma_face.normal_vector(q));
                mismatch += (g[q] - sn).norm_square() * sigma_face.JxW(q);
              }
            e.neumann[i] +=
              korn_squared * face->diameter() * mismatch / (2 * mu);
            if (part != BoundaryPart::contact)
              continue;
            // xi~ against the element xi^ of the laws' subdifferential at
            // u_h nearest to it, the normal and the tangential parts
            u_face[displacement].get_function_values(u, u_at);
            double normal = 0, tangential = 0;
            for (unsigned int q = 0; q < n_f; ++q)
              {
                const Tensor<1, dim> &nu    = sigma_face.normal_vector(q);
                double                bound = 0;
                for (const unsigned int v : cell->vertex_indices())
                  if (const auto node =
                        nodes.find(cell->vertex_dof_index(v, 0));
                      node != nodes.end())
                    bound +=
                      psi_face.shape_value(v, q) * node->second->friction_bound;
                const double         u_nu  = u_at[q] * nu;
                const Tensor<1, dim> u_tau = u_at[q] - u_nu * nu;
                const double         x_nu  = xi_tilde[q] * nu;
                const Tensor<1, dim> x_tau = xi_tilde[q] - x_nu * nu;
                double lower = std::numeric_limits<double>::infinity();
                double upper = -lower;
                for (const double r_at :
                     {u_nu - tolerance, u_nu, u_nu + tolerance})
                  {
                    const auto [lo, up] =
                      state.normal_law.subdifferential(r_at);
                    lower = std::min(lower, lo);
                    upper = std::max(upper, up);
                  }
                const double   hat_nu = std::clamp(x_nu, lower, upper);
                Tensor<1, dim> hat_tau;
                const double   slip = u_tau.norm();
                if (slip > tolerance)
                  hat_tau =
                    state.friction_law.response(bound, slip) * u_tau / slip;
                else
                  hat_tau = x_tau.norm() <= bound ?
                              x_tau :
                              Tensor<1, dim>(bound * x_tau / x_tau.norm());
                normal += std::pow(x_nu - hat_nu, 2) * sigma_face.JxW(q);
                tangential +=
                  (x_tau - hat_tau).norm_square() * sigma_face.JxW(q);
              }
            e.contact[i] += (normal + tangential) / trace_eigenvalue;
            normal_sum += normal;
            tangential_sum += tangential;
          }
      }

    // doc/theory.md 12.5: (1 - theta) |||e||| <= eta_stress + eta_skew +
    // eta_osc + eta_faces + eta_contact
    double oscillation_sum = 0, faces_sum = 0;
    for (unsigned int i = 0; i < n_cells; ++i)
      faces_sum += e.neumann[i];
    for (unsigned int i = 0; i < n_cells; ++i)
      oscillation_sum += e.interior[i];
    const double mean_part = domain_diameter / numbers::PI *
                             std::sqrt(korn_squared * mean_sum / (2 * mu));
    const double cell_part =
      std::sqrt(std::max(0., oscillation_sum - mean_part * mean_part));
    const double eta = std::sqrt(stress_sum) + std::sqrt(skew_sum) + cell_part +
                       mean_part + std::sqrt(faces_sum) +
                       (std::sqrt(normal_sum) + std::sqrt(tangential_sum)) /
                         std::sqrt(trace_eigenvalue);
    e.energy_scale = theta < 1 ? 1. / std::pow(1 - theta, 2) :
                                 std::numeric_limits<double>::infinity();
    e.interior_sum = oscillation_sum;
    e.jumps_sum    = e.jumps.l1_norm();
    e.neumann_sum  = faces_sum;
    e.contact_sum  = e.contact.l1_norm();
    e.bound =
      theta < 1 ? eta / (1 - theta) : std::numeric_limits<double>::infinity();
    return e;
  }

  template ErrorEstimate
  equilibrated_estimate(const ProblemState<2> &,
                        const ProblemData<2> &,
                        const TrilinosWrappers::MPI::Vector &,
                        const TrilinosWrappers::MPI::Vector &);
  template ErrorEstimate
  equilibrated_estimate(const ProblemState<3> &,
                        const ProblemData<3> &,
                        const TrilinosWrappers::MPI::Vector &,
                        const TrilinosWrappers::MPI::Vector &);
} // namespace hemicontact
