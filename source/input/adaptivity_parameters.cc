/**
 * The subsection 'adaptivity': the indicator, the marking and the state
 * transfer of adaptive meshes (AdaptivityParameters,
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
    const SelectionNames<RefinementIndicator> indicators = {
      {"kelly", RefinementIndicator::kelly},
      {"kelly contact", RefinementIndicator::kelly_contact},
      {"residual", RefinementIndicator::residual},
      {"estimator", RefinementIndicator::estimator}};
    const SelectionNames<MarkingStrategy> strategies = {
      {"fixed fraction", MarkingStrategy::fixed_fraction},
      {"fixed number", MarkingStrategy::fixed_number}};
    const SelectionNames<StateTransfer> state_transfers = {
      {"interpolation", StateTransfer::interpolation},
      {"projection", StateTransfer::projection}};
  } // namespace

  void
  AdaptivityParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("adaptivity");
    prm.declare_entry("interval",
                      "0",
                      Patterns::Integer(0),
                      "Adapt the mesh after every this many time steps "
                      "(0: never). Needs 'geometry/cell type = hypercube'.");
    prm.declare_entry(
      "indicator",
      "kelly",
      selection_pattern(indicators),
      "Cell indicator: 'kelly' (jumps of the normal derivative of w_n), "
      "'kelly contact' (plus the jumps of the nodal contact traction on "
      "Gamma_3), 'residual' (the step's residual in cells, on faces and "
      "on Gamma_3) or 'estimator' (the cell values eta_K of the a "
      "posteriori error estimate, doc/theory.md 12.1: 'residual' with "
      "contact weight 1). Formulas in doc/adaptivity.md.");
    prm.declare_entry("contact weight",
                      "1",
                      Patterns::Double(0),
                      "Weight of the contact term of 'kelly contact' and "
                      "'residual'.");
    prm.declare_entry(
      "pre-refinement steps",
      "0",
      Patterns::Integer(0),
      "After this many steps, restart once from t = 0 on the mesh reached "
      "(as deal.II's step-26), so that the early steps' coarse-mesh errors "
      "do not stay in the solution; 0: never. Needs 'interval' > 0; not "
      "with checkpoints or manufactured solutions.");
    prm.declare_entry("strategy",
                      "fixed fraction",
                      selection_pattern(strategies),
                      "'fixed fraction': refine the cells that hold 'refine "
                      "fraction' of the summed indicator and coarsen those "
                      "that hold 'coarsen fraction' of it; 'fixed number': "
                      "refine/coarsen these fractions of the cells. Cuts "
                      "avoid near-ties, so the mesh is the same on any number "
                      "of ranks (doc/adaptivity.md).");
    prm.declare_entry("refine fraction",
                      "0.3",
                      Patterns::Double(0, 1),
                      "See 'strategy'.");
    prm.declare_entry("coarsen fraction",
                      "0.05",
                      Patterns::Double(0, 1),
                      "See 'strategy'; 0 refines only.");
    prm.declare_entry("max cells",
                      "0",
                      Patterns::Integer(0),
                      "Upper limit of the number of cells (0: none).");
    prm.declare_entry("min level",
                      "0",
                      Patterns::Integer(0, 30),
                      "No cell is coarsened below this refinement level.");
    prm.declare_entry("max level",
                      "8",
                      Patterns::Integer(0, 30),
                      "No cell is refined beyond this refinement level.");
    prm.declare_entry(
      "target error",
      "0",
      Patterns::Double(0),
      "Static class: solve each load value, refine by the indicator and "
      "solve it again until the error estimate eta (doc/theory.md 12.1) is "
      "at most this fraction of the energy norm of u_h, a_B(u_h, u_h)^(1/2); "
      "stop with exit code 7 if 'max cells' or 'max level' comes first. "
      "0: off. Needs 'output/error estimate = true' and 'interval' = 0 "
      "(doc/adaptivity.md).");
    prm.declare_entry(
      "state transfer",
      "interpolation",
      selection_pattern(state_transfers),
      "How w_n and u_n move to the new mesh: 'interpolation' (deal.II's "
      "SolutionTransfer) or 'projection' (M- and a_B-projections that keep "
      "what the next step sees of the state exactly, at two linear solves "
      "per adaptation). See doc/adaptivity.md.");
    prm.leave_subsection();
  }

  void
  AdaptivityParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("adaptivity");
    interval             = prm.get_integer("interval");
    indicator            = get_selection(prm, "indicator", indicators);
    contact_weight       = prm.get_double("contact weight");
    pre_refinement_steps = prm.get_integer("pre-refinement steps");
    strategy             = get_selection(prm, "strategy", strategies);
    refine_fraction      = prm.get_double("refine fraction");
    coarsen_fraction     = prm.get_double("coarsen fraction");
    state_transfer = get_selection(prm, "state transfer", state_transfers);
    max_cells      = prm.get_integer("max cells");
    min_level      = prm.get_integer("min level");
    max_level      = prm.get_integer("max level");
    target_error   = prm.get_double("target error");
    prm.leave_subsection();
    require(refine_fraction + coarsen_fraction <= 1,
            "adaptivity: 'refine fraction' + 'coarsen fraction' must not "
            "exceed 1.");
    require(min_level <= max_level,
            "adaptivity: 'min level' must not exceed 'max level'.");
  }
} // namespace hemicontact
