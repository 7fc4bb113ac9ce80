/**
 * The checks of a parameter file that span subsections
 * (require_consistent(), include/hemicontact/input/parameters.h).
 */
#include <deal.II/base/utilities.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/expressions/expression.h>
#include <hemicontact/input/parameters.h>
#include <hemicontact/laws/friction_bound.h>
#include <hemicontact/memory/normal_memory_kernel.h>
#include <hemicontact/memory/relaxation_kernel.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace hemicontact
{
  namespace
  {
    /**
     * What 'adaptivity/target error' needs (doc/adaptivity.md, "Solving to
     * a tolerance"): the static class, the error estimate, a p4est mesh,
     * one run without memory, and no other adaptation.
     */
    void
    require_target_error_usable(const Parameters &parameters)
    {
      const AdaptivityParameters &adaptivity = parameters.adaptivity;
      if (adaptivity.target_error == 0)
        return;
      std::ostringstream value;
      value << adaptivity.target_error;
      const std::string name = "adaptivity: 'target error' = " + value.str();
      require(parameters.problem.problem_class == ProblemClass::static_,
              name +
                " refines each load value until the error estimate reaches "
                "it, which the static class alone does (its load values "
                "have no history to carry to a new mesh). Set 'problem/"
                "class = static', or 'target error' = 0.");
      require(parameters.output.error_estimate,
              name + " needs the error estimate: set 'output/error "
                     "estimate = true'.");
      require(adaptivity.interval == 0 && adaptivity.pre_refinement_steps == 0,
              name + " adapts the mesh at each load value itself: set "
                     "'adaptivity/interval = 0' and 'adaptivity/"
                     "pre-refinement steps = 0'.");
      require(parameters.geometry.cell_type == CellType::hypercube,
              name + " needs 'geometry/cell type = hypercube' (p4est "
                     "meshes), as every adaptive refinement does.");
      require(!parameters.manufactured.enabled,
              name + " does not work with a manufactured solution, whose "
                     "runs are convergence studies on meshes of their own: "
                     "set 'manufactured solution/enabled = false'.");
      const bool memory =
        parameters.relaxation.active() || parameters.normal_memory.active() ||
        parameters.wear.active() ||
        parameters.data.friction_bound.find("s_tau") != std::string::npos;
      require(!memory,
              name +
                " does not work with memory (a relaxation or normal "
                "memory kernel, wear, or a friction bound in s_tau): a load "
                "value solved again on a new mesh would add its state "
                "to the history twice (doc/theory.md, section 11.8).");
    }
    /**
     * What 'temperature' works with (doc/theory.md, section 13): theta as
     * data in the static class only, a manufactured solution in the
     * velocity classes (without a reference run), no error estimate.
     */
    void
    require_temperature_usable(const Parameters &parameters)
    {
      const TemperatureParameters &temperature = parameters.temperature;
      require(temperature.enabled || !parameters.manufactured.enabled ||
                parameters.manufactured.exact_temperature == "0",
              "manufactured solution: 'exact temperature' = " +
                quoted_expression(parameters.manufactured.exact_temperature) +
                " is set, but the body has no temperature "
                "('temperature/enabled = false'), so it would not be used. "
                "Set 'temperature/enabled = true', or 'exact temperature' = "
                "0.");
      if (!temperature.enabled)
        return;
      const bool is_static =
        parameters.problem.problem_class == ProblemClass::static_;
      require(!is_static || !temperature.given_temperature.empty(),
              "temperature: the static class takes theta as data (a "
              "thermal load, no heat equation): set 'temperature/given "
              "temperature' to theta(x, y[, z], t).");
      require(is_static || temperature.given_temperature.empty(),
              "temperature: 'given temperature' is the static class's "
              "theta; the dynamic and the quasistatic class solve the heat "
              "equation from 'initial temperature'. Leave 'given "
              "temperature' empty.");
      require(!parameters.manufactured.enabled || !is_static,
              "temperature: 'temperature/enabled = true' with 'manufactured "
              "solution/enabled = true' works in the dynamic and the "
              "quasistatic class, where theta solves the heat equation "
              "(doc/theory.md 13.6); the static class's theta is data. Set "
              "'problem/class' to dynamic or quasistatic, or 'temperature/"
              "enabled = false'.");
      require(!parameters.manufactured.enabled ||
                parameters.study.reference_time_step == 0,
              "temperature: 'convergence study/reference time step' does not "
              "work with 'temperature/enabled = true': the reference run "
              "keeps u and w, not theta. Set it to 0 (the errors against "
              "the manufactured solution).");
      require(!is_static ||
                temperature.coupling == TemperatureCoupling::staggered,
              "temperature: 'coupling = iterated' couples the mechanical "
              "step with the heat equation of the dynamic and the "
              "quasistatic class; the static class's theta is data. Set "
              "'temperature/coupling = staggered'.");
      require(!parameters.output.error_estimate,
              "temperature: 'temperature/enabled = true' does not work with "
              "'output/error estimate = true': the estimate (doc/theory.md, "
              "section 12) has no heat term and no thermal stress. Set "
              "'output/error estimate = false'.");
      for (const unsigned int id : temperature.flux_ids)
        require(parameters.boundary.part(id) != BoundaryPart::contact,
                "temperature: boundary id " + std::to_string(id) +
                  " is in 'heat flux boundary ids' and in 'contact "
                  "boundary ids'; on Gamma_3 the contact heat law holds "
                  "('exchange coefficient', 'frictional heat fraction').");
    }

    /**
     * What 'piezoelectricity' works with (doc/theory.md, section 14): phi
     * unique (an electrode, or a conductance on Gamma_3), and the
     * combinations the electric step does not do yet refused.
     */
    void
    require_piezoelectricity_usable(const Parameters &parameters)
    {
      const PiezoelectricParameters &piezo = parameters.piezoelectricity;
      if (!piezo.enabled)
        return;
      const std::string conductance = Utilities::trim(piezo.conductance);
      require(!piezo.electrode_ids.empty() ||
                (conductance != "0" && conductance != "0.0" &&
                 conductance != "0."),
              "piezoelectricity: no 'electrode boundary ids' and 'conductance "
              "= 0': the potential phi is then fixed only up to a constant "
              "(the electric step is singular). Give an electrode (phi = "
              "'electrode potential' on its ids) or a conductance > 0 of the "
              "foundation on Gamma_3.");
      for (const unsigned int id : piezo.surface_charge_ids)
        require(parameters.boundary.part(id) != BoundaryPart::contact,
                "piezoelectricity: boundary id " + std::to_string(id) +
                  " is in 'surface charge boundary ids' and in 'contact "
                  "boundary ids'; on Gamma_3 the electric contact law holds "
                  "('conductance', 'foundation potential').");
      require(!parameters.manufactured.enabled,
              "piezoelectricity: 'piezoelectricity/enabled = true' does not "
              "work with 'manufactured solution/enabled = true' (no "
              "manufactured potential is derived). Set one of them to "
              "false.");
      require(!parameters.output.error_estimate,
              "piezoelectricity: 'piezoelectricity/enabled = true' does not "
              "work with 'output/error estimate = true': the estimate "
              "(doc/theory.md, section 12) has no electric term. Set "
              "'output/error estimate = false'.");
    }
  } // namespace

  void
  require_consistent(const Parameters &parameters)
  {
    const unsigned int          dimension    = parameters.dimension;
    const GeometryParameters   &geometry     = parameters.geometry;
    const AdaptivityParameters &adaptivity   = parameters.adaptivity;
    const CheckpointParameters &checkpoint   = parameters.checkpoint;
    const bool                  manufactured = parameters.manufactured.enabled;

    // what the problem class uses of the material (doc/theory.md 9.2)
    const MaterialParameters &material      = parameters.material;
    const ProblemClass        problem_class = parameters.problem.problem_class;
    require(!parameters.boundary.clamped_ids.empty() ||
              problem_class == ProblemClass::dynamic,
            "boundary: 'clamped boundary ids' is empty; the quasistatic and "
            "the static class need a clamped part Gamma_1 of positive "
            "measure (Korn's inequality: without it their step operator "
            "vanishes on rigid motions). The dynamic class allows a free "
            "body, its mass term makes every step coercive.");
    if (problem_class == ProblemClass::dynamic)
      require(material.density > 0,
              "material: 'density' = " + std::to_string(material.density) +
                " must be positive.");
    if (problem_class != ProblemClass::static_)
      {
        require(material.viscosity.mu > 0,
                "material/viscosity: 'mu' = " +
                  std::to_string(material.viscosity.mu) +
                  " must be positive (the viscosity A must be coercive, m_A "
                  "> 0).");
        require(material.viscosity.lambda + 2. / 3. * material.viscosity.mu > 0,
                "material/viscosity: 'lambda' = " +
                  std::to_string(material.viscosity.lambda) +
                  " makes the bulk viscosity lambda + 2 mu / 3 non-positive.");
      }
    else
      require(material.elasticity.mu > 0 &&
                material.elasticity.lambda + 2. / 3. * material.elasticity.mu >
                  0,
              "material/elasticity: 'mu' = " +
                std::to_string(material.elasticity.mu) + " and 'lambda' = " +
                std::to_string(material.elasticity.lambda) +
                " leave the elastic operator B without coercivity; the static "
                "class needs mu > 0 and lambda + 2 mu / 3 > 0 (its step "
                "matrix is B, doc/theory.md section 9.1).");

    {
      std::ostringstream message;
      message << "nonlinear solver: 'tolerance' = "
              << parameters.nonlinear_solver.tolerance
              << " is below 'linear solver/relative tolerance' = "
              << parameters.linear_solver.relative_tolerance
              << ", the accuracy of every linear solve; Newton could not "
                 "reach it. Raise the Newton tolerance or lower the linear "
                 "solver's relative tolerance below it.";
      require(parameters.nonlinear_solver.tolerance >=
                parameters.linear_solver.relative_tolerance,
              message.str());
    }

    require(adaptivity.interval == 0 ||
              geometry.cell_type == CellType::hypercube,
            "adaptivity: adaptive refinement needs 'geometry/cell type = "
            "hypercube' (p4est meshes); set 'adaptivity/interval = 0' for "
            "simplex meshes.");
    require(adaptivity.pre_refinement_steps == 0 ||
              (adaptivity.interval > 0 && !manufactured &&
               checkpoint.interval == 0 && checkpoint.wall_interval == 0 &&
               checkpoint.stop_after == 0 && !checkpoint.resume),
            "adaptivity: 'pre-refinement steps' > 0 needs 'interval' > 0 and "
            "works neither with checkpoints nor with manufactured solutions.");
    // the number of steps of the run (TimeParameters::parse() made sure
    // that the time step divides the end time)
    const unsigned int n_steps = std::max<unsigned int>(
      1,
      static_cast<unsigned int>(
        std::llround(parameters.time.end_time / parameters.time.time_step)));
    require_target_error_usable(parameters);
    require(adaptivity.pre_refinement_steps <= n_steps,
            "adaptivity: 'pre-refinement steps' (" +
              std::to_string(adaptivity.pre_refinement_steps) +
              ") exceeds the number of time steps (" + std::to_string(n_steps) +
              ").");

    require(geometry.mesh_type != MeshType::rectangle ||
              (geometry.lower_left.size() >= dimension &&
               geometry.upper_right.size() >= dimension &&
               geometry.subdivisions.size() >= dimension),
            "geometry: the corners and subdivisions need at least " +
              std::to_string(dimension) + " entries for dimension " +
              std::to_string(dimension) + ".");
    if (geometry.mesh_type == MeshType::rectangle)
      for (unsigned int d = 0; d < dimension; ++d)
        require(geometry.upper_right[d] > geometry.lower_left[d],
                "geometry: 'upper right corner' must exceed 'lower left "
                "corner' in every coordinate (coordinate " +
                  std::to_string(d) + ").");

    // a convergence study runs its levels from the start, without
    // checkpoints
    if (manufactured)
      {
        std::vector<std::string> set;
        if (checkpoint.resume)
          set.push_back("'checkpoint/resume' (hemicontact --resume)");
        if (checkpoint.interval > 0)
          set.push_back("'checkpoint/interval' = " +
                        std::to_string(checkpoint.interval));
        if (checkpoint.wall_interval > 0)
          {
            std::ostringstream value;
            value << checkpoint.wall_interval;
            set.push_back("'checkpoint/wall interval' = " + value.str());
          }
        if (checkpoint.stop_after > 0)
          set.push_back("'checkpoint/stop after' = " +
                        std::to_string(checkpoint.stop_after));
        std::string list;
        for (const std::string &s : set)
          list += (list.empty() ? "" : ", ") + s;
        require(set.empty(),
                "convergence study: a convergence study ('manufactured "
                "solution/enabled = true') neither writes checkpoints nor "
                "resumes from them, but the parameter file sets " +
                  list + "; remove " + (set.size() > 1 ? "them" : "it") +
                  " (a study runs from the start).");
      }

    // a k-study against a reference run on the same mesh
    // (doc/verification.md): the reference's steps fall on every level's
    const ConvergenceStudyParameters &study = parameters.study;
    if (study.reference_time_step > 0)
      {
        std::ostringstream value;
        value << study.reference_time_step;
        const std::string name =
          "convergence study: 'reference time step' = " + value.str();
        require(manufactured && study.type == StudyType::k &&
                  adaptivity.interval == 0,
                name +
                  " needs a 'k' study ('convergence study/type = k', "
                  "'manufactured solution/enabled = true') on a fixed mesh "
                  "('adaptivity/interval = 0'): the reference runs on the "
                  "mesh of every level. Set it to 0 otherwise.");
        const double finest =
          parameters.time.time_step / std::ldexp(1., study.n_levels - 1);
        const double       ratio = finest / study.reference_time_step;
        std::ostringstream finest_value;
        finest_value << finest;
        require(std::abs(ratio - std::round(ratio)) <= 1e-9 * ratio &&
                  std::round(ratio) >= 2,
                name + " must divide the finest level's time step " +
                  finest_value.str() +
                  " ('time/time step' / 2^(levels - 1)) a whole number of "
                  "times, at least 2, so that the reference has a step at "
                  "every step of every level.");
      }

    // what the memory does not do (doc/theory.md, section 11.8): the
    // error estimate's residuals hold neither the memory stress nor a
    // moving foundation
    if (parameters.relaxation.active())
      {
        require(!parameters.output.error_estimate,
                "relaxation: a memory kernel ('relaxation/kernel' = prony or "
                "expression) does not work with 'output/error estimate = "
                "true': the estimate's residuals (doc/theory.md, section 12) "
                "do not hold the memory part of the stress. Set 'output/"
                "error estimate = false', or 'relaxation/kernel = none'.");
        RelaxationKernel(parameters.relaxation, parameters.data.constants)
          .require_finite(parameters.time.end_time / n_steps, n_steps);
      }
    if (parameters.wear.active())
      {
        require(!manufactured,
                "wear: a 'wear coefficient' > 0 does not work with "
                "'manufactured solution/enabled = true': the derived data do "
                "not hold the wear. Set 'wear/wear coefficient = 0' for a "
                "manufactured solution.");
        require(!parameters.output.error_estimate,
                "wear: a 'wear coefficient' > 0 does not work with "
                "'output/error estimate = true': the estimate's residuals "
                "(doc/theory.md, section 12) do not hold the moving "
                "foundation. Set 'output/error estimate = false', or "
                "'wear/wear coefficient = 0'.");
      }
    if (parameters.normal_memory.active())
      {
        NormalMemoryKernel(parameters.normal_memory, parameters.data.constants)
          .require_finite(parameters.time.end_time / n_steps, n_steps);
      }
    require_temperature_usable(parameters);
    require_piezoelectricity_usable(parameters);
  }
} // namespace hemicontact
