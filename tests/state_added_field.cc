// A field added to the state in one entry (doc/extending.md, "The state"):
// a scalar FE_Q(1) field on a DoFHandler of its own, with the initial value
// 1 + x y (bilinear, so that every transfer keeps it exactly). In a run
// that adapts the mesh after every step, the field is moved by the
// adaptations (equal to its interpolant on the new mesh) and written to the
// solution files. In a run on a fixed mesh interrupted after step 2, it is
// saved in the checkpoint, and the resumed run ends bitwise equal to the
// uninterrupted one (on an adapted mesh a resume agrees to the solver
// tolerance only, doc/running.md). A resume without the field, or with
// another one, is refused with their names.
#include <deal.II/base/function_parser.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/numerics/vector_tools.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/coupling/plain_field.h>
#include <hemicontact/input/parameters.h>
#include <hemicontact/problem/contact_problem.h>
#include <hemicontact/simulation/simulation.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests.h"

using namespace hemicontact;

namespace
{
  const std::string text = R"(
set dimension = 2
subsection geometry
  set upper right corner = 4, 1
  set subdivisions       = 4, 1
  set global refinements = 2
end
subsection boundary
  set clamped boundary ids  = 0
  set traction boundary ids = 3
  set contact boundary ids  = 2
end
subsection time
  set end time  = 0.4
  set time step = 0.1
end
subsection data
  set surface traction = 0; -1
end
subsection adaptivity
  set interval         = 1
  set strategy         = fixed number
  set refine fraction  = 0.3
  set coarsen fraction = 0.1
end
subsection output
  set terminal        = quiet
  set output interval = 1
end
)";

  /** The problem of @p text writing to @p directory, with @p fields added. */
  std::unique_ptr<ContactProblem<2>>
  problem_with(const std::string              &directory,
               const std::vector<std::string> &fields,
               const bool                      adapt,
               const bool                      resume,
               const unsigned int              stop_after)
  {
    ParameterHandler prm;
    Parameters       parameters      = read_parameters_from_string(prm, text);
    parameters.adaptivity.interval   = adapt ? 1 : 0;
    parameters.output.directory      = directory;
    parameters.checkpoint.interval   = 1;
    parameters.checkpoint.resume     = resume;
    parameters.checkpoint.stop_after = stop_after;
    auto problem = std::make_unique<ContactProblem<2>>(parameters,
                                                       create_contact_laws(prm),
                                                       MPI_COMM_WORLD);
    for (const std::string &name : fields)
      {
        auto initial = std::make_shared<FunctionParser<2>>(1);
        initial->initialize("x,y", name == "theta" ? "1 + x*y" : "2 - y", {});
        // the one entry
        problem->add_field(plain_field<2>({name,
                                           std::make_shared<FE_Q<2>>(1),
                                           initial,
                                           FieldLayout::scalar_nodal}));
      }
    return problem;
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

  /** Whether a VTU file of step @p step in @p directory names @p field. */
  bool
  written(const std::string &directory, const std::string &field)
  {
    bool found = false;
    for (const auto &entry : std::filesystem::directory_iterator(directory))
      if (entry.path().filename().string().rfind("solution_00002", 0) == 0 &&
          entry.path().extension() == ".vtu")
        {
          std::ifstream      in(entry.path());
          std::ostringstream content;
          content << in.rdbuf();
          found = found || content.str().find("Name=\"" + field + "\"") !=
                             std::string::npos;
        }
    return found;
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  // moved by the adaptations and written
  auto adapted = problem_with("adapted", {"theta"}, true, false, 0);
  Simulation<2>(*adapted).run();
  FunctionParser<2> exact(1);
  exact.initialize("x,y", "1 + x*y", {});
  const TrilinosWrappers::MPI::Vector &theta =
    adapted->get_added_fields().vector("theta");
  TrilinosWrappers::MPI::Vector interpolant(theta);
  VectorTools::interpolate(
    *adapted->state().discretization.mapping,
    *adapted->get_added_fields().space("theta").dof_handler,
    exact,
    interpolant);
  out() << "mesh adapted: "
        << (adapted->state()
                  .dof_handler.get_triangulation()
                  .n_global_active_cells() != 4 * 16 ?
              "yes" :
              "no")
        << "; theta moved with it exactly: "
        << (difference(interpolant, theta) < 1e-12 ? "yes" : "no") << "\n";
  MPI_Barrier(MPI_COMM_WORLD);
  out() << "theta written to the solution files: "
        << (root && written("adapted", "theta") ? "yes" : "no") << "\n";

  // the uninterrupted run on a fixed mesh ...
  auto whole = problem_with("whole", {"theta"}, false, false, 0);
  Simulation<2>(*whole).run();
  // ... and the run interrupted after step 2 ...
  try
    {
      Simulation<2>(*problem_with("parts", {"theta"}, false, false, 2)).run();
    }
  catch (const RunInterrupted &)
    {
      out() << "interrupted after step 2\n";
    }
  // ... refused without the field, or with another ...
  for (const std::vector<std::string> &fields :
       {std::vector<std::string>{}, std::vector<std::string>{"theta", "phi"}})
    try
      {
        Simulation<2>(*problem_with("parts", fields, false, true, 0)).run();
        out() << "resumed with other fields: not refused\n";
      }
    catch (const InputError &e)
      {
        const std::string what = e.what();
        out() << "resume with " << fields.size() << " added fields refused: "
              << what.substr(what.find("does not hold")) << "\n";
      }
  // ... and resumed: bitwise the uninterrupted run's end
  auto second = problem_with("parts", {"theta"}, false, true, 0);
  Simulation<2>(*second).run();
  out() << "resumed run ends as the uninterrupted one: theta "
        << (difference(second->get_added_fields().vector("theta"),
                       whole->get_added_fields().vector("theta")) == 0 ?
              "bitwise" :
              "differs")
        << ", u "
        << (difference(second->state().displacement,
                       whole->state().displacement) == 0 ?
              "bitwise" :
              "differs")
        << "\n";
}
