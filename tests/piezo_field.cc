// The electric potential as the second coupled field (doc/theory.md,
// section 14): on the sensor of prm/piezo_sensor_2d.prm (reduced),
// (c) E = 0 gives the mechanical answer of the run without phi bitwise;
// the left-point run closes its energy identity with the electric terms
// booked; a run interrupted after step 2 and resumed ends bitwise as the
// uninterrupted one (phi and u); a run that adapts its mesh after every
// step carries phi along and still closes its identity; the implicit rule
// alternates to the coupling tolerance in a few passes.
#include <hemicontact/base/exceptions.h>
#include <hemicontact/input/parameters.h>
#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/simulation/simulation.h>

#include <fstream>
#include <sstream>

#include "tests.h"

using namespace hemicontact;

namespace
{
  /** prm/piezo_sensor_2d.prm with @p changes appended. */
  std::string
  sensor(const std::string &changes)
  {
    std::ifstream     in(SOURCE_DIR "/../prm/piezo_sensor_2d.prm");
    std::stringstream text;
    text << in.rdbuf();
    return text.str() + R"(
subsection geometry
  set global refinements = 2
end
subsection time
  set end time  = 0.4
  set time step = 0.05
end
subsection output
  set terminal = quiet
end
)" + changes;
  }

  /** The problem of @p text writing to @p directory. */
  std::unique_ptr<ContactProblem<2>>
  problem(const std::string &text,
          const std::string &directory,
          const bool         adapt      = false,
          const bool         resume     = false,
          const unsigned int stop_after = 0)
  {
    ParameterHandler prm;
    Parameters       parameters      = read_parameters_from_string(prm, text);
    parameters.output.directory      = directory;
    parameters.adaptivity.interval   = adapt ? 1 : 0;
    parameters.checkpoint.interval   = 1;
    parameters.checkpoint.resume     = resume;
    parameters.checkpoint.stop_after = stop_after;
    return std::make_unique<ContactProblem<2>>(parameters,
                                               create_contact_laws(prm),
                                               MPI_COMM_WORLD);
  }

  /** max |v - w| (0 exactly: bitwise equal). */
  double
  difference(const TrilinosWrappers::MPI::Vector &v,
             const TrilinosWrappers::MPI::Vector &w)
  {
    TrilinosWrappers::MPI::Vector d(v);
    d -= w;
    return d.linfty_norm();
  }

  /** Run @p p to its end. */
  ContactProblem<2> &
  run(ContactProblem<2> &p)
  {
    Simulation<2>(p).run();
    return p;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // (c) E = 0: the mechanical answer of the run without phi
  auto zero = problem(sensor(R"(
subsection piezoelectricity
  set piezoelectric constants = 0, 0, 0
end
)"),
                      "zero");
  auto off  = problem(sensor(R"(
subsection piezoelectricity
  set enabled = false
end
)"),
                     "off");
  run(*zero);
  run(*off);
  out() << "E = 0: u as without phi: "
        << (difference(zero->state().displacement, off->state().displacement) ==
                0 ?
              "bitwise" :
              "differs")
        << ", w "
        << (difference(zero->state().velocity, off->state().velocity) == 0 ?
              "bitwise" :
              "differs")
        << "\n";

  // the sensor with the left-point rule: the identity with phi's terms
  auto whole = problem(sensor(""), "whole");
  run(*whole);
  const EnergyBalance &e = whole->state().energy;
  out()
    << "left point: relative energy defect < 1e-9: "
    << (e.relative_defect() < 1e-9 ? "yes" : "no")
    << "; electric terms booked: cross "
    << (e.coupled_term("electric_cross") != 0 ? "yes" : "no") << ", enthalpy "
    << (e.coupled_term("electric_enthalpy") < 0 ? "negative" : "not")
    << ", stress work "
    << (e.coupled_term("electric_stress_work") != 0 ? "yes" : "no")
    << "; phi not zero: "
    << (whole->get_added_fields().vector("electric_potential").linfty_norm() >
            0 ?
          "yes" :
          "no")
    << "\n";

  // interrupted after step 2 and resumed: bitwise
  try
    {
      run(*problem(sensor(""), "parts", false, false, 2));
    }
  catch (const RunInterrupted &)
    {
      out() << "interrupted after step 2\n";
    }
  auto second = problem(sensor(""), "parts", false, true);
  run(*second);
  out() << "resumed run ends as the uninterrupted one: phi "
        << (difference(second->get_added_fields().vector("electric_potential"),
                       whole->get_added_fields().vector(
                         "electric_potential")) == 0 ?
              "bitwise" :
              "differs")
        << ", u "
        << (difference(second->state().displacement,
                       whole->state().displacement) == 0 ?
              "bitwise" :
              "differs")
        << "\n";

  // adapted after every step
  auto adapted = problem(sensor(R"(
subsection adaptivity
  set strategy         = fixed number
  set refine fraction  = 0.3
  set coarsen fraction = 0.1
end
)"),
                         "adapted",
                         true);
  run(*adapted);
  out()
    << "adapted: "
    << adapted->state().dof_handler.get_triangulation().n_global_active_cells()
    << " cells, relative energy defect < 1e-9: "
    << (adapted->state().energy.relative_defect() < 1e-9 ? "yes" : "no")
    << "\n";

  // the implicit rule: alternation to the coupling tolerance
  auto implicit = problem(sensor(R"(
subsection problem
  set time scheme = implicit
end
)"),
                          "implicit");
  run(*implicit);
  out() << "implicit: relative energy defect < 1e-8: "
        << (implicit->state().energy.relative_defect() < 1e-8 ? "yes" : "no")
        << "\n";
}
