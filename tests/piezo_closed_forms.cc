// Closed forms of piezoelectricity (doc/theory.md, section 14), on the
// unit square in the static class with lambda = 0 (so that a clamped
// bottom is compatible with a uniform strain), Gamma_3 the left side with
// no law (traction-free) and electrodes at the bottom (phi = 0) and the
// top:
// (a) the converse effect: the top at phi = V, no load, e_31 = e_15 = 0:
//     phi = V y, and the free top gives sigma_yy = 2 mu eps_yy + e_33 V =
//     0, so u = (0, -e_33 V y / (2 mu));
// (b) the direct effect: both electrodes grounded, the top pressed by p:
//     u = (0, -p y / (2 mu)) is uniform strain, E eps(u) is constant with
//     no x component, so phi = 0.
// Q1 holds both exactly: the nodal values agree to round-off.
#include <deal.II/base/function_parser.h>
#include <deal.II/numerics/vector_tools.h>

#include <hemicontact/input/parameters.h>
#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/simulation/simulation.h>

#include "tests.h"

using namespace hemicontact;

namespace
{
  const std::string common = R"(
set dimension = 2
subsection geometry
  set subdivisions       = 1, 1
  set global refinements = 2
end
subsection boundary
  set clamped boundary ids  = 2
  set traction boundary ids = 3
  set contact boundary ids  = 0
end
subsection material
  subsection elasticity
    set mu     = 2
    set lambda = 0
  end
end
subsection problem
  set class = static
end
subsection time
  set end time  = 1
  set time step = 1
end
subsection normal law
  set law = none
end
subsection data
  set friction bound = 0
end
subsection output
  set terminal = quiet
end
)";

  /** max |v - the interpolant of @p exact| / max |the interpolant|. */
  double
  relative_error(const TrilinosWrappers::MPI::Vector &v,
                 const DoFHandler<2>                 &dofs,
                 const Mapping<2>                    &mapping,
                 const std::string                   &exact,
                 const unsigned int                   components)
  {
    FunctionParser<2> f(components);
    f.initialize("x,y", exact, {});
    TrilinosWrappers::MPI::Vector interpolant(v);
    VectorTools::interpolate(mapping, dofs, f, interpolant);
    const double size = interpolant.linfty_norm();
    interpolant -= v;
    return size > 0 ? interpolant.linfty_norm() / size :
                      interpolant.linfty_norm();
  }

  void
  check(const std::string &name,
        const std::string &changes,
        const std::string &exact_phi,
        const std::string &exact_u)
  {
    ParameterHandler prm;
    Parameters parameters = read_parameters_from_string(prm, common + changes);
    parameters.output.directory = name;
    ContactProblem<2> problem(parameters,
                              create_contact_laws(prm),
                              MPI_COMM_WORLD);
    Simulation<2>(problem).run();
    const Mapping<2> &mapping = *problem.state().discretization.mapping;
    const double      e_phi   = relative_error(
      problem.get_added_fields().vector("electric_potential"),
      *problem.get_added_fields().space("electric_potential").dof_handler,
      mapping,
      exact_phi,
      1);
    const double e_u = relative_error(problem.state().displacement,
                                      problem.state().dof_handler,
                                      mapping,
                                      exact_u,
                                      2);
    const double phi_size =
      problem.get_added_fields().vector("electric_potential").linfty_norm();
    out() << name << ": phi "
          << (exact_phi == "0" ? (phi_size < 1e-12 ? "= 0 to 1e-12" : "not 0") :
                                 (e_phi < 1e-10 ? "exact to 1e-10" : "off"))
          << ", u " << (e_u < 1e-10 ? "exact to 1e-10" : "off") << "\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // (a) e_33 = 0.5, V = 0.2: eps_yy = -0.5 * 0.2 / 4 = -0.025
  check("converse",
        R"(
subsection piezoelectricity
  set enabled                 = true
  set piezoelectric constants = 0, 0.5, 0
  set electrode boundary ids  = 2, 3
  set electrode potential     = y > 0.5 ? 0.2 : 0
end
)",
        "0.2*y",
        "0; -0.025*y");
  // (b) p = 0.4: eps_yy = -0.4 / 4 = -0.1
  check("direct",
        R"(
subsection data
  set surface traction = 0; -0.4
end
subsection piezoelectricity
  set enabled                 = true
  set piezoelectric constants = -0.59, -0.61, 1.14
  set electrode boundary ids  = 2, 3
end
)",
        "0",
        "0; -0.1*y");
}
