// The temperature against closed forms (doc/theory.md, section 13), on
// a free body of the dynamic class (no clamped part: the mass term makes
// each step coercive), contact on y = 0:
// (a) a uniform theta_0 expands the body, as the viscous transient decays,
//     to the stress-free strain e = c_e theta / (2 (lambda + mu)) in each
//     direction (plane strain), theta the final mean temperature; the heat
//     equation's -c_e div w lowers theta to theta_0 - 2 c_e e / c_theta;
//     in 3D e = c_e theta / (2 mu + 3 lambda), theta_0 - 3 c_e e / c_theta;
// (b) a body at rest with theta_0 = 0 and a Robin contact at theta_F = 1
//     warms as the 1D heat equation says: for a small Biot number
//     Bi = k_e H / K, the mean follows the lumped backward Euler
//     theta_n = (theta_{n-1} + a k theta_F) / (1 + a k) with the decay rate
//     a = k_e (1 - Bi/3) / (c_theta H) of the first mode;
// (c) frictional heating with no exchange: the heat content gained equals
//     the frictional heat gamma sum_n k sum_i m_i |sigma_tau . w_tau| to the
//     solver's tolerance.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <hemicontact/input/parameters.h>
#include <hemicontact/laws/contact_laws.h>
#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/thermal/heat_field.h>

#include <cmath>
#include <iomanip>

#include "tests.h"

using namespace hemicontact;

namespace
{
  /** The unit square (refined 3 times) or cube (2 times), contact on
   *  y = 0 (id 2), then the rest of common_rest. */
  std::string
  common(const int dim)
  {
    return dim == 2 ? "set dimension = 2\nsubsection geometry\n"
                      "  set upper right corner = 1, 1\n"
                      "  set subdivisions = 1, 1\n"
                      "  set global refinements = 3\nend\n" :
                      "set dimension = 3\nsubsection geometry\n"
                      "  set upper right corner = 1, 1, 1\n"
                      "  set subdivisions = 1, 1, 1\n"
                      "  set global refinements = 2\nend\n";
  }

  const std::string common_rest = R"(
subsection boundary
  set clamped boundary ids  =
  set traction boundary ids =
  set contact boundary ids  = 2
end
subsection material
  set density = 1
  subsection viscosity
    set mu     = 1
    set lambda = 1
  end
  subsection elasticity
    set mu     = 1
    set lambda = 1
  end
end
subsection normal law
  set law = linear damping
  subsection linear damping
    set coefficient = 10
  end
end
subsection data
  set friction bound = 0
end
subsection output
  set terminal = quiet
end
)";

  /** (a): a uniform theta_0 = 1 with c_e = 0.5, run until the viscous
   *  transient has decayed. */
  const std::string free_expansion = R"(
subsection time
  set end time  = 12
  set time step = 0.05
end
subsection problem
  set time scheme = implicit
end
subsection temperature
  set enabled                    = true
  set thermal stress coefficient = 0.5
  set initial temperature        = 1
end
)";

  /** The problem of common + @p text in @p dim dimensions, run to its
   *  end. */
  template <int dim = 2>
  std::unique_ptr<ContactProblem<dim>>
  run(const std::string &text)
  {
    ParameterHandler prm;
    const Parameters parameters =
      read_parameters_from_string(prm, common(dim) + common_rest + text);
    auto problem =
      std::make_unique<ContactProblem<dim>>(parameters,
                                            create_contact_laws(prm),
                                            MPI_COMM_WORLD);
    problem->setup();
    while (!problem->finished())
      problem->advance();
    return problem;
  }

  /** The heat model's balance of @p problem's temperature. */
  template <int dim>
  const HeatBalance &
  heat_balance(const ContactProblem<dim> &problem)
  {
    return dynamic_cast<const HeatField<dim> &>(
             *problem.state().coupled_fields.list().at(0).field)
      .model()
      .balance();
  }

  /** The mean of the nodal values of @p v's component @p c where x_c = @p at. */
  template <int dim>
  double
  mean_on(const ContactProblem<dim> &problem,
          const unsigned int         c,
          const double               at)
  {
    const auto                    state = problem.state();
    TrilinosWrappers::MPI::Vector u(state.locally_owned_dofs,
                                    state.locally_relevant_dofs,
                                    state.mpi_communicator);
    u                       = state.displacement;
    double            sum   = 0;
    unsigned int      count = 0;
    std::vector<bool> seen(state.dof_handler.n_dofs(), false);
    for (const auto &cell : state.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto i = cell->vertex_dof_index(v, c);
            if (std::abs(cell->vertex(v)[c] - at) < 1e-12 && !seen[i] &&
                state.locally_owned_dofs.is_element(i))
              {
                seen[i] = true;
                sum += u[i];
                ++count;
              }
          }
    return Utilities::MPI::sum(sum, state.mpi_communicator) /
           Utilities::MPI::sum(count, state.mpi_communicator);
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  out() << std::setprecision(4);

  // (a) the stress-free expansion
  {
    const auto   problem = run(free_expansion);
    const double theta =
      heat_balance(*problem).heat_content; // |Omega| = 1, c_theta = 1
    const double e_x = mean_on(*problem, 0, 1) - mean_on(*problem, 0, 0);
    const double e_y = mean_on(*problem, 1, 1) - mean_on(*problem, 1, 0);
    const double e   = 0.5 * theta / (2 * (1 + 1));
    out() << "(a) free expansion: strain x/e = " << e_x / e
          << ", y/e = " << e_y / e << "; theta = " << theta
          << ", theta_0 - 2 c_e e_x / c_theta = " << 1 - 2 * 0.5 * e_x
          << std::endl;
    out() << "    within 1e-3 of the closed form: "
          << (std::abs(e_x / e - 1) < 1e-3 && std::abs(e_y / e - 1) < 1e-3 &&
                  std::abs(theta - (1 - 2 * 0.5 * e_x)) < 1e-3 ?
                "yes" :
                "no")
          << std::endl;
  }

  // (a) in 3D: e = c_e theta / (2 mu + 3 lambda), theta = theta_0 -
  // 3 c_e e / c_theta
  {
    const auto   problem = run<3>(free_expansion);
    const double theta   = heat_balance(*problem).heat_content;
    double       worst   = 0;
    for (unsigned int c = 0; c < 3; ++c)
      worst =
        std::max(worst,
                 std::abs((mean_on(*problem, c, 1) - mean_on(*problem, c, 0)) /
                            (0.5 * theta / (2 * 1 + 3 * 1)) -
                          1));
    const double e_x = mean_on(*problem, 0, 1) - mean_on(*problem, 0, 0);
    out() << "(a) in 3D: strain/e - 1 in each direction below 1e-3: "
          << (worst < 1e-3 ? "yes" : "no")
          << "; theta = theta_0 - 3 c_e e_x / c_theta to 1e-3: "
          << (std::abs(theta - (1 - 3 * 0.5 * e_x)) < 1e-3 ? "yes" : "no")
          << std::endl;
  }

  // (b) the Robin contact, Bi = k_e H / K = 0.01
  {
    const auto   problem = run(R"(
subsection time
  set end time  = 1
  set time step = 0.05
end
subsection temperature
  set enabled                = true
  set conductivity           = 100
  set exchange coefficient   = 1
  set foundation temperature = 1
end
)");
    const double bi = 0.01, a = 1 * (1 - bi / 3), k = 0.05;
    double       lumped = 0;
    for (unsigned int n = 0; n < 20; ++n)
      lumped = (lumped + a * k * 1) / (1 + a * k);
    const double theta = heat_balance(*problem).heat_content;
    out() << "(b) Robin contact: mean theta(1) = " << theta
          << ", lumped first mode " << lumped << ", within 2e-4: "
          << (std::abs(theta - lumped) < 2e-4 ? "yes" : "no") << std::endl;
    const HeatBalance   &h = heat_balance(*problem);
    const EnergyBalance &e = problem->state().energy;
    out() << "    heat content gained = exchanged heat to 1e-8: "
          << (std::abs(h.heat_content - h.initial_heat_content -
                       e.coupled_term("exchanged_heat")) <
                  1e-8 * e.coupled_term("exchanged_heat") ?
                "yes" :
                "no")
          << std::endl;
  }

  // (c) frictional heating, no exchange: a block dragged over the
  // foundation with Tresca friction
  {
    const auto           problem = run(R"(
subsection boundary
  set traction boundary ids = 3
end
subsection time
  set end time  = 0.5
  set time step = 0.02
end
subsection data
  set surface traction = 2; -1
  set friction bound   = 0.5
end
subsection temperature
  set enabled                  = true
  set frictional heat fraction = 0.8
end
)");
    const HeatBalance   &h       = heat_balance(*problem);
    const double         gained  = h.heat_content - h.initial_heat_content;
    const EnergyBalance &e       = problem->state().energy;
    out() << "(c) frictional heating: heat gained " << gained
          << ", frictional heat " << e.coupled_term("frictional_heat")
          << ", equal to 1e-8: "
          << (e.coupled_term("frictional_heat") > 0 &&
                  std::abs(gained - e.coupled_term("frictional_heat")) <
                    1e-8 * e.coupled_term("frictional_heat") ?
                "yes" :
                "no")
          << std::endl;
  }
}
