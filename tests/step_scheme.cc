// Unit test of StepScheme (doc/theory.md, section 9): the step matrix
// coefficients of each class and rule (the dynamic left point exactly
// {1/k, 1, 0}), the displacement updates and held displacement, the
// energy terms of 9.3 and the names used in messages.
#include <deal.II/lac/vector.h>

#include <hemicontact/model/step_scheme.h>

#include "tests.h"

using namespace hemicontact;

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const double                             k = 0.04;
  for (const ProblemClass c :
       {ProblemClass::dynamic, ProblemClass::quasistatic})
    for (const TimeScheme s : {TimeScheme::left_point, TimeScheme::implicit})
      {
        const StepScheme             scheme(c, s);
        const StepMatrixCoefficients m = scheme.step_matrix(k);
        out() << scheme.name() << ": K = " << scheme.step_matrix_name()
              << " (mass " << m.mass << ", viscous " << m.viscous
              << ", elastic " << m.elastic << "), w_0 from the step: "
              << (scheme.initial_velocity_from_step() ? "yes" : "no")
              << ", time-step limit: "
              << (scheme.has_time_step_limit() ? "yes" : "no") << std::endl;

        // u = 1, w_old = 2, w = 3 (one entry): before, after, held
        dealii::Vector<double> u(1), w_old(1), w(1);
        u     = 1;
        w_old = 2;
        w     = 3;
        scheme.displacement_before_step(u, w_old, k);
        const double before = u[0];
        scheme.displacement_after_step(u, w, k);
        out() << "  u before the step " << before << ", after " << u[0]
              << ", held " << u[0] + scheme.held_displacement_offset(k) * w[0]
              << std::endl;
        // w.A w = 2, dw.M dw = 3, w.B w = 5
        const StepScheme::StepEnergy e = scheme.step_energy(k, 2, 3, 5);
        out() << "  viscous " << e.viscous << ", numerical " << e.numerical
              << ", kinetic of w.M w = 4: " << scheme.kinetic_energy(4)
              << std::endl;
      }
  // the dynamic left point multiplies by exactly the assembly's 1/k
  const StepMatrixCoefficients m =
    StepScheme(ProblemClass::dynamic, TimeScheme::left_point).step_matrix(k);
  out() << "dynamic left point mass coefficient == 1./k: "
        << (m.mass == 1. / k ? "yes" : "no") << std::endl;
}
