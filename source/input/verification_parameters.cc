/**
 * The subsections 'manufactured solution' and 'convergence study': the
 * exact solution of a verification run and the levels of its study
 * (ManufacturedParameters, ConvergenceStudyParameters,
 * include/hemicontact/input/parameters.h).
 */
#include <deal.II/base/utilities.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/input/parameters.h>
#include <hemicontact/input/selection.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace hemicontact
{
  namespace
  {
    const SelectionNames<StudyType> study_types = {
      {"single", StudyType::single},
      {"h", StudyType::h},
      {"k", StudyType::k},
      {"coupled", StudyType::coupled}};
  } // namespace

  void
  ManufacturedParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("manufactured solution");
    prm.declare_entry("enabled",
                      "false",
                      Patterns::Bool(),
                      "Verify against a manufactured solution: the body force, "
                      "the tractions on Gamma_2 and Gamma_3 and the initial "
                      "data are derived from 'exact displacement' (exact "
                      "derivatives); the expressions in subsection 'data' "
                      "except 'friction bound' are ignored, and the errors "
                      "E_H, E_V, E_u are computed.");
    prm.declare_entry("exact displacement",
                      "0",
                      Patterns::Anything(),
                      "u(x,t): 'dimension' expressions (doc/parameters.md, "
                      "Expressions) separated by ';' in x, y, z, t and the "
                      "data constants. It must vanish on Gamma_1.");
    prm.declare_entry(
      "normal multiplier",
      "0",
      Patterns::Anything(),
      "The choice xi_nu = s*(x,t) in dj(0) = [0,a] where the "
      "normal velocity vanishes, an expression "
      "(doc/parameters.md, Expressions); should lie strictly "
      "inside (0, a). Also the choice where the exact w_nu (u_nu "
      "in the static class) sits at a kink of the law or at "
      "its wall (doc/theory.md section 10): inside the interval "
      "there.");
    prm.declare_entry("tangential multiplier",
                      "0",
                      Patterns::Anything(),
                      "The choice xi_tau = lambda*(x,t) (projected on the "
                      "tangent plane) where the tangential velocity vanishes, "
                      "'dimension' expressions (doc/parameters.md, "
                      "Expressions) separated by ';'; should satisfy "
                      "|lambda*| < F_b.");
    prm.declare_entry("exact temperature",
                      "0",
                      Patterns::Anything(),
                      "theta(x,t) with 'temperature/enabled = true' "
                      "(dynamic and quasistatic class): an expression "
                      "(doc/parameters.md, Expressions) in x, y, z, t and "
                      "the data constants. The initial and the prescribed "
                      "temperature, the heat source, the heat flux and a "
                      "heat source on Gamma_3 are derived from it (exact "
                      "derivatives, doc/theory.md 13.6); the coefficients "
                      "of subsection 'temperature' are kept, and the error "
                      "E_theta is computed.");
    prm.leave_subsection();
  }

  void
  ManufacturedParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("manufactured solution");
    enabled               = prm.get_bool("enabled");
    exact_displacement    = prm.get("exact displacement");
    normal_multiplier     = prm.get("normal multiplier");
    tangential_multiplier = prm.get("tangential multiplier");
    exact_temperature     = prm.get("exact temperature");
    prm.leave_subsection();
  }

  void
  ConvergenceStudyParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("convergence study");
    prm.declare_entry("type",
                      "single",
                      selection_pattern(study_types),
                      "With a manufactured solution: 'single' runs once; 'h' "
                      "refines the mesh once per level at a fixed time step; "
                      "'k' halves the time step per level on a fixed mesh; "
                      "'coupled' does both (k = c h). Level 0 uses "
                      "'geometry/global refinements' and 'time/time step'; "
                      "adaptive studies are described in doc/adaptivity.md.");
    prm.declare_entry("levels",
                      "4",
                      Patterns::Integer(1, 12),
                      "Number of levels.");
    prm.declare_entry(
      "reference time step",
      "0",
      Patterns::Double(0),
      "0: the errors are those against the manufactured solution. A value "
      "> 0 (with 'type = k' on a fixed mesh): the errors of each level are "
      "taken against a run with this time step on the same mesh, which runs "
      "first, so that they hold the time error of the scheme alone "
      "(doc/verification.md). The finest level's time step must be a whole "
      "multiple (at least 2) of it.");
    prm.leave_subsection();
  }

  void
  ConvergenceStudyParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("convergence study");
    type                = get_selection(prm, "type", study_types);
    n_levels            = prm.get_integer("levels");
    reference_time_step = prm.get_double("reference time step");
    prm.leave_subsection();
  }
} // namespace hemicontact
