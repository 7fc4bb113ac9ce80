// The coupling of the mechanical and the heat step (doc/theory.md 13.2)
// on a block clamped at the top, heated by a source while its bottom is in
// damped contact with Tresca friction and frictional heating:
// (a) with c_e = 0 theta does not act on the mechanics: 'iterated' stops
//     after its second pass at every step, with w_n and theta_n those of
//     'staggered' to round-off;
// (b) with c_e = 1 'iterated' converges in a few passes per step, its
//     energy defect closes, and it differs from 'staggered' by O(k): the
//     difference of theta at the end halves with k;
// (c) a tolerance the iteration cannot reach in 'coupling iterations'
//     passes fails the step with a message naming the entry.
#include <hemicontact/base/exceptions.h>
#include <hemicontact/input/parameters.h>
#include <hemicontact/laws/contact_laws.h>
#include <hemicontact/problem/contact_problem.h>

#include <cmath>
#include <iomanip>

#include "tests.h"

using namespace hemicontact;

namespace
{
  const std::string common = R"(
set dimension = 2
subsection geometry
  set upper right corner = 2, 1
  set subdivisions       = 2, 1
  set global refinements = 3
end
subsection boundary
  set clamped boundary ids  = 3
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
    set mu     = 10
    set lambda = 10
  end
end
subsection normal law
  set law = linear damping
  subsection linear damping
    set coefficient = 10
  end
end
subsection data
  set body force     = sin(3*t); -2
  set friction bound = 0.2
end
subsection time
  set end time = 0.5
end
subsection temperature
  set enabled                  = true
  set heat capacity            = 1
  set conductivity             = 0.5
  set heat source              = 4*x
  set exchange coefficient     = 0.5
  set frictional heat fraction = 0.5
end
subsection output
  set terminal = quiet
end
)";

  /** The end of a run of common + @p text. */
  struct RunEnd
  {
    TrilinosWrappers::MPI::Vector theta, velocity;
    unsigned int                  min_passes = 1000, max_passes = 0;
    double                        relative_defect = 0;
  };

  RunEnd
  run(const std::string &text)
  {
    ParameterHandler prm;
    const Parameters parameters =
      read_parameters_from_string(prm, common + text);
    ContactProblem<2> problem(parameters,
                              create_contact_laws(prm),
                              MPI_COMM_WORLD);
    problem.setup();
    RunEnd end;
    while (!problem.finished())
      {
        const StepStatistics s = problem.advance();
        end.min_passes         = std::min(end.min_passes, s.coupling_passes);
        end.max_passes         = std::max(end.max_passes, s.coupling_passes);
      }
    end.theta           = problem.state().added_fields.vector("temperature");
    end.velocity        = problem.state().velocity;
    end.relative_defect = problem.state().energy.relative_defect();
    return end;
  }

  std::string
  settings(const double       c_e,
           const std::string &coupling,
           const double       k,
           const std::string &more = "")
  {
    std::ostringstream s;
    s << "subsection temperature\n  set thermal stress coefficient = " << c_e
      << "\n  set coupling = " << coupling << "\n"
      << more << "end\nsubsection time\n  set time step = " << k << "\nend\n";
    return s.str();
  }

  /** |a - b| / |b| */
  double
  relative_difference(TrilinosWrappers::MPI::Vector        a,
                      const TrilinosWrappers::MPI::Vector &b)
  {
    a -= b;
    return a.l2_norm() / b.l2_norm();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

  // (a) one-way coupling
  {
    const RunEnd staggered = run(settings(0, "staggered", 0.05));
    const RunEnd iterated  = run(settings(0, "iterated", 0.05));
    const double d_theta = relative_difference(iterated.theta, staggered.theta);
    const double d_w =
      relative_difference(iterated.velocity, staggered.velocity);
    out() << "(a) c_e = 0: passes per step " << iterated.min_passes << " to "
          << iterated.max_passes << " (staggered " << staggered.max_passes
          << "); theta and w as staggered to 1e-12: "
          << (d_theta < 1e-12 && d_w < 1e-12 ? "yes" : "no") << std::endl;
  }

  // (b) two-way coupling: iterated against staggered at k and k/2
  {
    double difference[2];
    for (const unsigned int level : {0u, 1u})
      {
        const double k         = 0.05 / (1 << level);
        const RunEnd staggered = run(settings(1, "staggered", k));
        const RunEnd iterated  = run(settings(1, "iterated", k));
        difference[level] =
          relative_difference(iterated.theta, staggered.theta);
        out() << "(b) c_e = 1, k = " << k << ": iterated in 3 to 8 passes: "
              << (iterated.min_passes >= 3 && iterated.max_passes <= 8 ? "yes" :
                                                                         "no")
              << ", energy defect < 1e-8: "
              << (iterated.relative_defect < 1e-8 &&
                      staggered.relative_defect < 1e-8 ?
                    "yes" :
                    "no")
              << ", theta differs from staggered: "
              << (difference[level] > 1e-6 ? "yes" : "no") << std::endl;
      }
    const double ratio = difference[0] / difference[1];
    out() << "    the difference halves with k (ratio in [1.6, 2.6]): "
          << (ratio >= 1.6 && ratio <= 2.6 ? "yes" : "no") << std::endl;
    if (ratio < 1.6 || ratio > 2.6)
      out() << "    ratio " << ratio << std::endl;
  }

  // (c) a tolerance out of reach
  try
    {
      run(settings(1,
                   "iterated",
                   0.05,
                   "  set coupling tolerance = 1e-14\n"
                   "  set coupling iterations = 2\n") +
          "subsection nonlinear solver\n  set time step halvings = 0\nend\n");
      out() << "(c) no failure" << std::endl;
    }
  catch (const SolverFailure &failure)
    {
      const std::string what = failure.what();
      out() << "(c) the step fails, naming 'coupling iterations': "
            << (what.find("'temperature/coupling iterations'") !=
                    std::string::npos ?
                  "yes" :
                  "no")
            << std::endl;
    }
}
