#pragma once
// Shared by the one-step tests whose exact discrete answer is known in
// closed form (one_step_exact.cc, one_step_slip_rate.cc): the block
// [0,2]x[0,1] (2D) or the unit cube (3D), refined twice, clamped on top,
// traction on the sides, contact at the bottom, one time step k; and one
// step of it with the velocity's relative maximum error against the exact
// one.
#include <deal.II/numerics/vector_tools.h>

#include <hemicontact/input/parameters.h>
#include <hemicontact/problem/contact_problem.h>

#include <sstream>
#include <string>

/** @p x with 17 digits, for constants in expressions. */
inline std::string
num(const double x)
{
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

/** The material of the block: density, viscosity and elasticity. */
struct BlockMaterial
{
  double rho, mu_v, lambda_v, mu_e, lambda_e;
};

/**
 * The subsections geometry, boundary, material and time of the block with
 * cells of @p cell_type and the single time step @p k.
 */
inline std::string
one_step_block(const unsigned int   dim,
               const std::string   &cell_type,
               const BlockMaterial &m,
               const double         k)
{
  std::ostringstream p;
  p << "set dimension = " << dim << "\n"
    << "subsection geometry\n  set cell type = " << cell_type << "\n"
    << (dim == 2 ? "  set upper right corner = 2, 1\n"
                   "  set subdivisions = 2, 1\n" :
                   "  set upper right corner = 1, 1, 1\n"
                   "  set subdivisions = 1, 1, 1\n")
    << "  set global refinements = 2\nend\n"
    << "subsection boundary\n"
    << (dim == 2 ? "  set clamped boundary ids = 3\n"
                   "  set traction boundary ids = 0, 1\n"
                   "  set contact boundary ids = 2\n" :
                   "  set clamped boundary ids = 5\n"
                   "  set traction boundary ids = 0, 1, 2, 3\n"
                   "  set contact boundary ids = 4\n")
    << "end\n"
    << "subsection material\n  set density = " << m.rho << "\n"
    << "  subsection viscosity\n    set mu = " << m.mu_v
    << "\n    set lambda = " << m.lambda_v << "\n  end\n"
    << "  subsection elasticity\n    set mu = " << m.mu_e
    << "\n    set lambda = " << m.lambda_e << "\n  end\n"
    << "end\n"
    << "subsection time\n  set end time = " << k << "\n  set time step = " << k
    << "\nend\n";
  return p.str();
}

/** What one step of a parameter file gave. */
struct OneStepResult
{
  hemicontact::StepStatistics stats;
  /** max |w_h - I_h w| / V, w the exact velocity (in x, y[, z], V, H = 1). */
  double error;
  /** The start-up estimate of the convexity condition (> 1: convex). */
  double convexity_bound;
};

/** Run one step of @p parameter_text and compare with @p exact_w. */
template <int dim>
OneStepResult
one_step(const std::string &parameter_text,
         const std::string &exact_w,
         const double       V)
{
  using namespace hemicontact;
  dealii::ParameterHandler prm;
  const Parameters         parameters =
    read_parameters_from_string(prm, parameter_text);
  ContactProblem<dim> problem(parameters,
                              create_contact_laws(prm),
                              MPI_COMM_WORLD);
  problem.setup();
  OneStepResult result;
  result.stats = problem.advance();

  auto                                  exact = parse_function<dim>(exact_w,
                                   dim,
                                   "V=" + num(V) + ", H=1",
                                   "exact velocity");
  dealii::TrilinosWrappers::MPI::Vector w(problem.state().velocity);
  dealii::VectorTools::interpolate(*problem.state().discretization.mapping,
                                   problem.state().dof_handler,
                                   *exact,
                                   w);
  w -= problem.state().velocity;
  result.error           = w.linfty_norm() / V;
  result.convexity_bound = problem.state().convexity.bound;
  return result;
}
