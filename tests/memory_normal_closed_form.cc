// The memory of the normal response (doc/theory.md, section 11.9) at a
// constant penetration g applied at t = 0, (u_nu,j)_+ = g for every j, on
// half of the bottom face of a block, the other half separated: the
// memory pressure N_n of ContactMemory (through MemoryHistory: its step
// functional m_i N_i nu_i and its pressure N_i nu_i) reproduces the closed
// form of the left-rectangle rule,
//   N_n = g sum_m b_m k q_m (1 - q_m^n)/(1 - q_m),   q_m = exp(-k/tau_m),
// the geometric sum of N_n = k sum_{j<n} b(t_n - t_j) g, to round-off, for
// a Prony series (the recursion) and for the same kernel as an expression
// b(t) (the sum over the stored states); zero at the separated nodes. Then
// the nodes separate: N keeps acting and decays as the sum over the
// penetrated states, and steps of varying length follow sum_j k_j b(t_n -
// t_j) (u_nu,j)_+.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/affine_constraints.h>

#include <hemicontact/memory/memory_history.h>

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <map>
#include <vector>

#include "tests.h"

using namespace hemicontact;
using namespace dealii;

namespace
{
  const std::vector<double> b_m{40., 5.}, tau_m{0.5, 2.};
  const double              g = 0.02;

  NormalMemoryParameters
  prony()
  {
    NormalMemoryParameters p;
    p.kernel           = RelaxationKernelType::prony;
    p.amplitudes       = b_m;
    p.relaxation_times = tau_m;
    return p;
  }

  NormalMemoryParameters
  expression()
  {
    NormalMemoryParameters p;
    p.kernel = RelaxationKernelType::expression;
    p.b      = "b1*exp(-t/t1) + b2*exp(-t/t2)";
    return p;
  }
  const std::string constants = "b1=40, b2=5, t1=0.5, t2=2";

  double
  b(const double t)
  {
    double v = 0;
    for (unsigned int m = 0; m < tau_m.size(); ++m)
      v += b_m[m] * std::exp(-t / tau_m[m]);
    return v;
  }

  /** The nodes of the face y = 0, normal -e_y, mass 1 + x. */
  template <int dim>
  std::vector<ContactNode<dim>>
  bottom_nodes(const DoFHandler<dim> &dofs, const IndexSet &owned)
  {
    std::map<types::global_dof_index, ContactNode<dim>> nodes;
    for (const auto &cell : dofs.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (std::abs(cell->vertex(v)[1]) < 1e-12)
          {
            ContactNode<dim> node;
            for (unsigned int c = 0; c < dim; ++c)
              node.dofs[c] = cell->vertex_dof_index(v, c);
            node.position       = cell->vertex(v);
            node.normal[1]      = -1;
            node.mass           = 1 + node.position[0];
            node.locally_owned  = owned.is_element(node.dofs[0]);
            nodes[node.dofs[0]] = node;
          }
    std::vector<ContactNode<dim>> result;
    for (const auto &[dof, node] : nodes)
      result.push_back(node);
    return result;
  }

  /**
   * The largest |N_i - expected_i| / max|expected| over the nodes, of the
   * pressure and of the functional / m_i, with expected_i = @p N at
   * the penetrated nodes (x < 0.5), 0 elsewhere.
   */
  template <int dim>
  double
  error(const MemoryHistory<dim>            &h,
        const std::vector<ContactNode<dim>> &nodes,
        const double                         N)
  {
    double worst = 0;
    for (const ContactNode<dim> &node : nodes)
      {
        const double expected = node.position[0] < 0.5 ? N : 0.;
        const double pressure =
          nodal_vector(node, h.contact_memory().pressure()) * node.normal;
        const double force =
          nodal_vector(node, h.step_functional()) * node.normal / node.mass;
        worst = std::max({worst,
                          std::abs(pressure - expected) / N,
                          std::abs(force - expected) / N});
      }
    return worst;
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
    const IndexSet                      owned = dofs.locally_owned_dofs();
    const std::vector<ContactNode<dim>> nodes = bottom_nodes(dofs, owned);

    // u_nu = +g (into the foundation) at x < 0.5, -g elsewhere, and no
    // normal displacement: the separated state
    TrilinosWrappers::MPI::Vector pressed(owned, MPI_COMM_WORLD);
    TrilinosWrappers::MPI::Vector separated(owned, MPI_COMM_WORLD);
    for (const ContactNode<dim> &node : nodes)
      {
        pressed[node.dofs[1]] = node.position[0] < 0.5 ? -g : g;
        pressed[node.dofs[0]] = 0.3 * g; // tangential: no part in N
      }
    pressed.compress(VectorOperation::insert);

    const RelaxationParameters no_relaxation{};
    const WearParameters       no_wear{};
    MemoryHistory<dim>         by_prony(
      no_relaxation, prony(), no_wear, "", MPI_COMM_WORLD);
    MemoryHistory<dim> by_expression(
      no_relaxation, expression(), no_wear, constants, MPI_COMM_WORLD);
    for (MemoryHistory<dim> *h : {&by_prony, &by_expression})
      h->reinit(dofs,
                MappingQ1<dim>(),
                QGauss<dim>(2),
                AffineConstraints<double>(),
                owned,
                owned,
                nodes);

    // uniform steps: the closed form while pressed, then separated at
    // t = 1 (n = 10): N_n = g sum_{j<10} k b(t_n - t_j)
    const double       k     = 0.1;
    const unsigned int N     = 30;
    double             worst = 0, worst_after = 0;
    for (unsigned int n = 1; n <= N; ++n)
      {
        double closed = 0;
        if (n <= 10)
          for (unsigned int m = 0; m < tau_m.size(); ++m)
            {
              const double q = std::exp(-k / tau_m[m]);
              closed += g * b_m[m] * k * q * (1 - std::pow(q, n)) / (1 - q);
            }
        else
          for (unsigned int j = 0; j < 10; ++j)
            closed += g * k * b((n - j) * k);
        for (MemoryHistory<dim> *h : {&by_prony, &by_expression})
          {
            h->prepare_step((n - 1) * k, k, n <= 10 ? pressed : separated);
            (n <= 10 ? worst : worst_after) =
              std::max(n <= 10 ? worst : worst_after, error(*h, nodes, closed));
            h->commit_step();
          }
        if (n == 1 || n == 10 || n == N)
          out() << "  " << dim << "D t = " << std::setprecision(3) << n * k
                << ": N = " << std::setprecision(8) << closed << "\n";
      }
    if (std::getenv("HEMICONTACT_TEST_VERBOSE") != nullptr)
      std::cerr << dim << "D: pressed " << worst << ", separated "
                << worst_after << "\n";
    out() << "  " << dim << "D closed form, 10 steps pressed: Prony and sum "
          << "within 1e-13: " << (worst < 1e-13 ? "yes" : "no")
          << "; 20 steps separated, N from the past states within 1e-13: "
          << (worst_after < 1e-13 ? "yes" : "no") << "\n";

    // steps of varying length (k, k/2, k/2, k, ...), pressed
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
        double sum = 0;
        for (unsigned int j = 0; j < starts.size(); ++j)
          sum += steps[j] * b(t - starts[j]) * g;
        for (MemoryHistory<dim> *h : {&by_prony, &by_expression})
          {
            h->prepare_step(starts.back(), step, pressed);
            worst_variable = std::max(worst_variable, error(*h, nodes, sum));
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
