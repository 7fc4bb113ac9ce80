// The memory term of the stress (doc/theory.md, section 11) under a
// constant strain eps0 applied at t = 0, u_j = u for every j: the memory
// stress M_n of MemoryHistory (its step functional (M_n, eps(v)) and its
// cell averages) reproduces the closed form of the left-rectangle rule,
//   M_n = sum_m (2 mu_m eps0 + lambda_m tr(eps0) I) k q_m (1 - q_m^n)/(1 -
//   q_m),
// q_m = exp(-k/tau_m), the geometric sum of M_n = k sum_{j<n} R(t_n - t_j)
// eps0, to round-off, for a Prony series (the recursion) and for the same
// kernel written as expressions mu_R(t), lambda_R(t) (the sum over the
// stored states); and both agree on steps of varying length (a halved
// step) with the sum sum_j k_j R(t_n - t_j) eps0.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/numerics/vector_tools.h>

#include <hemicontact/memory/memory_history.h>

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <vector>

#include "tests.h"

using namespace hemicontact;
using namespace dealii;

namespace
{
  const std::vector<double> mu_m{3., 1.}, lambda_m{2., 0.5}, tau_m{0.5, 2.};

  RelaxationParameters
  prony()
  {
    RelaxationParameters p;
    p.kernel            = RelaxationKernelType::prony;
    p.mu_amplitudes     = mu_m;
    p.lambda_amplitudes = lambda_m;
    p.relaxation_times  = tau_m;
    return p;
  }

  RelaxationParameters
  expression()
  {
    RelaxationParameters p;
    p.kernel = RelaxationKernelType::expression;
    p.mu     = "a1*exp(-t/t1) + a2*exp(-t/t2)";
    p.lambda = "b1*exp(-t/t1) + b2*exp(-t/t2)";
    return p;
  }
  const std::string constants = "a1=3, a2=1, b1=2, b2=0.5, t1=0.5, t2=2";

  /** u(x) = eps0 x. */
  template <int dim>
  class ConstantStrain : public Function<dim>
  {
  public:
    explicit ConstantStrain(const SymmetricTensor<2, dim> &eps0)
      : Function<dim>(dim)
      , eps0(eps0)
    {}
    double
    value(const Point<dim> &p, const unsigned int c) const override
    {
      double v = 0;
      for (unsigned int j = 0; j < dim; ++j)
        v += eps0[c][j] * p[j];
      return v;
    }

  private:
    SymmetricTensor<2, dim> eps0;
  };

  /** The functional (M, eps(v)) of a constant stress M. */
  template <int dim>
  TrilinosWrappers::MPI::Vector
  functional_of(const SymmetricTensor<2, dim> &M,
                const DoFHandler<dim>         &dofs,
                const Mapping<dim>            &mapping,
                const Quadrature<dim>         &quadrature,
                const IndexSet                &owned)
  {
    TrilinosWrappers::MPI::Vector        f(owned, MPI_COMM_WORLD);
    FEValues<dim>                        fe_values(mapping,
                            dofs.get_fe(),
                            quadrature,
                            update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     v(0);
    const unsigned int                   n = dofs.get_fe().n_dofs_per_cell();
    Vector<double>                       local(n);
    std::vector<types::global_dof_index> indices(n);
    AffineConstraints<double>            none;
    none.close();
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          local = 0;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            for (unsigned int i = 0; i < n; ++i)
              local(i) +=
                (M * fe_values[v].symmetric_gradient(i, q)) * fe_values.JxW(q);
          cell->get_dof_indices(indices);
          none.distribute_local_to_global(local, indices, f);
        }
    f.compress(VectorOperation::add);
    return f;
  }

  /** |a - b|_inf / |b|_inf. */
  double
  relative(const TrilinosWrappers::MPI::Vector &a,
           const TrilinosWrappers::MPI::Vector &b)
  {
    TrilinosWrappers::MPI::Vector d(a);
    d -= b;
    return d.linfty_norm() / b.linfty_norm();
  }

  template <int dim>
  void
  check()
  {
    parallel::distributed::Triangulation<dim> mesh(MPI_COMM_WORLD);
    GridGenerator::hyper_cube(mesh, 0, 1);
    mesh.refine_global(2);
    const FESystem<dim> fe(FE_Q<dim>(1), dim);
    DoFHandler<dim>     dofs(mesh);
    dofs.distribute_dofs(fe);
    const IndexSet owned    = dofs.locally_owned_dofs();
    const IndexSet relevant = DoFTools::extract_locally_relevant_dofs(dofs);
    AffineConstraints<double> constraints(relevant);
    constraints.close();
    const MappingQ<dim> mapping(1);
    const QGauss<dim>   quadrature(2);

    SymmetricTensor<2, dim> eps0;
    eps0[0][0] = 0.01;
    eps0[1][1] = -0.004;
    eps0[0][1] = 0.003;
    TrilinosWrappers::MPI::Vector u(owned, MPI_COMM_WORLD);
    VectorTools::interpolate(mapping, dofs, ConstantStrain<dim>(eps0), u);

    MemoryHistory<dim> by_prony(prony(), "", MPI_COMM_WORLD);
    MemoryHistory<dim> by_expression(expression(), constants, MPI_COMM_WORLD);
    for (MemoryHistory<dim> *h : {&by_prony, &by_expression})
      h->reinit(dofs, mapping, quadrature, constraints, owned, relevant);

    // uniform steps k: the closed form
    const double       k           = 0.1;
    const unsigned int N           = 30;
    double             worst_prony = 0, worst_expression = 0, worst_cells = 0,
           worst_pair = 0;
    for (unsigned int n = 1; n <= N; ++n)
      {
        SymmetricTensor<2, dim> M;
        for (unsigned int m = 0; m < tau_m.size(); ++m)
          {
            const double q   = std::exp(-k / tau_m[m]);
            const double sum = k * q * (1 - std::pow(q, n)) / (1 - q);
            M += sum * (2 * mu_m[m] * eps0 + lambda_m[m] * trace(eps0) *
                                               unit_symmetric_tensor<dim>());
          }
        const TrilinosWrappers::MPI::Vector exact =
          functional_of(M, dofs, mapping, quadrature, owned);
        for (MemoryHistory<dim> *h : {&by_prony, &by_expression})
          h->prepare_step((n - 1) * k, k, u);
        worst_prony =
          std::max(worst_prony, relative(by_prony.step_functional(), exact));
        worst_expression =
          std::max(worst_expression,
                   relative(by_expression.step_functional(), exact));
        worst_pair = std::max(worst_pair,
                              relative(by_expression.step_functional(),
                                       by_prony.step_functional()));
        const std::vector<Vector<float>> cells =
          by_prony.cell_stress(dofs, mapping, quadrature);
        unsigned int c = 0;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = i; j < dim; ++j, ++c)
            for (const auto &cell : dofs.active_cell_iterators())
              if (cell->is_locally_owned())
                worst_cells =
                  std::max(worst_cells,
                           std::abs(cells[c][cell->active_cell_index()] -
                                    M[i][j]) /
                             M.norm());
        if (n == 1 || n == 10 || n == N)
          out() << "  " << dim << "D t = " << std::setprecision(3) << n * k
                << ": M_xx = " << std::setprecision(8) << M[0][0]
                << ", M_yy = " << M[1][1] << "\n";
        for (MemoryHistory<dim> *h : {&by_prony, &by_expression})
          h->commit_step();
      }
    // the measured values, for a report (not part of the expected output)
    if (std::getenv("HEMICONTACT_TEST_VERBOSE") != nullptr)
      std::cerr << dim << "D: Prony " << worst_prony << ", sum "
                << worst_expression << ", the two " << worst_pair << "\n";
    out() << "  " << dim << "D closed form, " << N
          << " steps: Prony recursion within 1e-13: "
          << (worst_prony < 1e-13 ? "yes" : "no")
          << ", sum over the states within 1e-13: "
          << (worst_expression < 1e-13 ? "yes" : "no")
          << ", the two within 1e-13: " << (worst_pair < 1e-13 ? "yes" : "no")
          << ", cell averages within 1e-6 (float): "
          << (worst_cells < 1e-6 ? "yes" : "no") << "\n";

    // steps of varying length (k, k/2, k/2, k, ...): sum_j k_j R(t_n - t_j)
    for (MemoryHistory<dim> *h : {&by_prony, &by_expression})
      h->clear();
    std::vector<double> starts, steps;
    double              t = 0, worst_variable = 0;
    for (unsigned int n = 0; n < 12; ++n)
      {
        const double step = (n % 3 == 0) ? k : k / 2;
        starts.push_back(t);
        steps.push_back(step);
        t += step;
        SymmetricTensor<2, dim> M;
        for (unsigned int j = 0; j < starts.size(); ++j)
          for (unsigned int m = 0; m < tau_m.size(); ++m)
            M += steps[j] * std::exp(-(t - starts[j]) / tau_m[m]) *
                 (2 * mu_m[m] * eps0 +
                  lambda_m[m] * trace(eps0) * unit_symmetric_tensor<dim>());
        const TrilinosWrappers::MPI::Vector exact =
          functional_of(M, dofs, mapping, quadrature, owned);
        for (MemoryHistory<dim> *h : {&by_prony, &by_expression})
          {
            h->prepare_step(starts.back(), step, u);
            worst_variable =
              std::max(worst_variable, relative(h->step_functional(), exact));
            h->commit_step();
          }
      }
    if (std::getenv("HEMICONTACT_TEST_VERBOSE") != nullptr)
      std::cerr << dim << "D varying steps: " << worst_variable << "\n";
    out() << "  " << dim
          << "D steps of varying length: both within 1e-13 of the sum: "
          << (worst_variable < 1e-13 ? "yes" : "no") << "\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  check<2>();
  check<3>();
}
