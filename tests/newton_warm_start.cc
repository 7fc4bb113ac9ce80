// The warm starts of a step's Newton iteration -- the extrapolated initial
// guess w_{n-1} + k (w_{n-1} - w_{n-2})/k and the Krylov solve to the Newton
// tolerance once no node changes branch -- change where Newton starts and
// how far each linear solve goes, never the solution: 15 steps of the short
// 2D and 3D block runs with both on (the defaults) and both off give the same
// final velocity, and the defaults need fewer Newton iterations.
#include <hemicontact/contact_problem.h>
#include <hemicontact/parameters.h>

#include <fstream>
#include <sstream>

#include "tests.h"

using namespace hemicontact;

namespace
{
  struct Result
  {
    TrilinosWrappers::MPI::Vector velocity;
    unsigned int                  newton_iterations = 0;
  };

  template <int dim>
  Result
  run(const std::string &file, const std::string &settings)
  {
    std::ifstream     in(file);
    std::stringstream text;
    text << in.rdbuf()
         << "subsection time\n  set end time = 0.15\nend\n"
         << "subsection output\n  set directory = output-" << dim
         << "d\n  set terminal = quiet\nend\n"
         << settings;
    ParameterHandler prm;
    const Parameters parameters = read_parameters_from_string(prm, text.str());
    ContactProblem<dim> problem(parameters, create_normal_law(prm),
                                MPI_COMM_WORLD);
    problem.setup();
    Result result;
    while (!problem.finished())
      result.newton_iterations += problem.advance().newton_iterations;
    result.velocity = problem.get_velocity();
    return result;
  }

  template <int dim>
  void
  compare(const std::string &file)
  {
    const Result warm = run<dim>(file, "");
    const Result cold =
      run<dim>(file,
               "subsection nonlinear solver\n"
               "  set initial guess = previous\nend\n"
               "subsection linear solver\n"
               "  set exact solve when settled = false\n"
               "  set maximum forcing term = 0.1\nend\n");
    const Result extrapolated_only =
      run<dim>(file,
               "subsection linear solver\n"
               "  set exact solve when settled = false\nend\n");

    const double scale = cold.velocity.l2_norm();
    for (const auto &[name, r] :
         {std::make_pair("defaults", &warm),
          std::make_pair("extrapolated guess only", &extrapolated_only)})
      {
        TrilinosWrappers::MPI::Vector difference(r->velocity);
        difference -= cold.velocity;
        out() << "  " << dim << "D " << name << " vs cold starts: "
              << (difference.l2_norm() <= 1e-7 * scale ? "agree to 1e-7" :
                                                         "DIFFER")
              << "\n";
      }
    out() << "  " << dim << "D defaults need fewer Newton iterations: "
          << (warm.newton_iterations < cold.newton_iterations ? "yes" : "NO")
          << "\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  compare<2>(SOURCE_DIR "/block_2d_short.prm");
  compare<3>(SOURCE_DIR "/block_3d_short.prm");
}
