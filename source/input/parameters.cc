#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/input/number_list.h>
#include <hemicontact/input/parameters.h>
#include <hemicontact/input/selection.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace hemicontact
{
  namespace
  {
    /** How a Lame pair is given ('parametrisation'). */
    enum class LameParametrisation
    {
      lame,
      young
    };

    const SelectionNames<ProblemClass> problem_classes = {
      {"dynamic", ProblemClass::dynamic},
      {"quasistatic", ProblemClass::quasistatic},
      {"static", ProblemClass::static_}};
    const SelectionNames<TimeScheme> time_schemes = {
      {"left point", TimeScheme::left_point},
      {"implicit", TimeScheme::implicit}};
    const SelectionNames<MeshType> mesh_types = {{"rectangle",
                                                  MeshType::rectangle},
                                                 {"gmsh", MeshType::gmsh}};
    const SelectionNames<CellType> cell_types =
      {{"hypercube", CellType::hypercube}, {"simplex", CellType::simplex}};
    const SelectionNames<LameParametrisation> parametrisations = {
      {"lame", LameParametrisation::lame},
      {"young", LameParametrisation::young}};
    const SelectionNames<SolutionFormat> solution_formats =
      {{"vtu", SolutionFormat::vtu}, {"hdf5", SolutionFormat::hdf5}};
    const SelectionNames<VtuCompression> compression_levels = {
      {"best speed", VtuCompression::best_speed},
      {"default", VtuCompression::default_compression},
      {"best compression", VtuCompression::best_compression},
      {"none", VtuCompression::no_compression}};
    const SelectionNames<OutputPrecision> output_precisions = {
      {"float", OutputPrecision::single_precision},
      {"double", OutputPrecision::double_precision}};
    const SelectionNames<TerminalOutput> terminal_outputs = {
      {"progress", TerminalOutput::progress},
      {"quiet", TerminalOutput::quiet},
      {"test", TerminalOutput::test}};
  } // namespace

  void
  GeometryParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("geometry");
    prm.declare_entry(
      "mesh",
      "rectangle",
      selection_pattern(mesh_types),
      "'rectangle' builds a rectangle (2D) or box (3D) from the "
      "corners below, with boundary ids 0 (x = x0), 1 (x = x1), "
      "2 (y = y0), 3 (y = y1), 4 (z = z0), 5 (z = z1). 'gmsh' "
      "reads 'mesh file' (physical tags become boundary ids).");
    prm.declare_entry(
      "cell type",
      "hypercube",
      selection_pattern(cell_types),
      "'hypercube': quadrilaterals/hexahedra, FE_Q(1)^d on a "
      "p4est distributed mesh. 'simplex': triangles/tetrahedra, "
      "FE_SimplexP(1)^d on a fully distributed mesh (uniform "
      "refinement only).");
    prm.declare_entry("lower left corner",
                      "0, 0, 0",
                      Patterns::List(Patterns::Double(), 2, 3),
                      "Corner (x0, y0[, z0]) of the rectangle/box; only the "
                      "first 'dimension' entries are used.");
    prm.declare_entry("upper right corner",
                      "4, 1, 1",
                      Patterns::List(Patterns::Double(), 2, 3),
                      "Opposite corner (x1, y1[, z1]).");
    prm.declare_entry("subdivisions",
                      "4, 1, 1",
                      Patterns::List(Patterns::Integer(1), 2, 3),
                      "Number of coarse cells in each direction.");
    prm.declare_entry("mesh file",
                      "",
                      Patterns::Anything(),
                      "Gmsh .msh file (relative to the working directory) for "
                      "mesh = gmsh. Its cells must all be of 'cell type', in "
                      "2D its nodes in z = 0, without duplicated nodes or "
                      "self-intersecting cells.");
    prm.declare_entry("global refinements",
                      "3",
                      Patterns::Integer(0, 20),
                      "Number of uniform refinements of the coarse mesh. For "
                      "a simplex rectangle/box the mesh is instead built "
                      "with 2^r times the subdivisions (same mesh size, "
                      "better shapes than refined tetrahedra). Refused when "
                      "the estimated memory exceeds the machine's.");
    prm.leave_subsection();
  }

  void
  GeometryParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("geometry");
    mesh_type  = get_selection(prm, "mesh", mesh_types);
    cell_type  = get_selection(prm, "cell type", cell_types);
    lower_left = Utilities::string_to_double(
      Utilities::split_string_list(prm.get("lower left corner")));
    upper_right = Utilities::string_to_double(
      Utilities::split_string_list(prm.get("upper right corner")));
    for (const int s : Utilities::string_to_int(
           Utilities::split_string_list(prm.get("subdivisions"))))
      subdivisions.push_back(s);
    mesh_file          = prm.get("mesh file");
    global_refinements = prm.get_integer("global refinements");
    prm.leave_subsection();
    if (mesh_type == MeshType::gmsh)
      require(!mesh_file.empty(),
              "geometry: 'mesh = gmsh' needs a 'mesh file', but none is set.");
  }

  void
  BoundaryParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("boundary");
    prm.declare_entry("clamped boundary ids",
                      "0",
                      Patterns::List(Patterns::Integer(0, 255)),
                      "Boundary ids of Gamma_1 (u = 0). Empty only in the "
                      "dynamic class (a free body: the mass term makes each "
                      "step coercive).");
    prm.declare_entry("traction boundary ids",
                      "1, 3",
                      Patterns::List(Patterns::Integer(0, 255)),
                      "Boundary ids of Gamma_2 (sigma nu = f2); may be empty. "
                      "Boundary parts in no list are traction free.");
    prm.declare_entry("contact boundary ids",
                      "2",
                      Patterns::List(Patterns::Integer(0, 255)),
                      "Boundary ids of Gamma_3 (contact). Must not be empty.");
    prm.leave_subsection();
  }

  void
  BoundaryParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("boundary");
    clamped_ids  = get_id_list(prm, "clamped boundary ids");
    traction_ids = get_id_list(prm, "traction boundary ids");
    contact_ids  = get_id_list(prm, "contact boundary ids");
    prm.leave_subsection();
    require(!contact_ids.empty(),
            "boundary: 'contact boundary ids' is empty; the contact part "
            "Gamma_3 must have positive measure.");
    // Gamma_1, Gamma_2 and Gamma_3 are disjoint parts of the boundary
    const auto require_disjoint = [](const std::vector<unsigned int> &a,
                                     const std::vector<unsigned int> &b,
                                     const std::string               &what) {
      for (const unsigned int i : a)
        for (const unsigned int j : b)
          require(i != j,
                  "boundary: id " + std::to_string(i) + " is listed both as " +
                    what +
                    "; Gamma_1 (clamped), Gamma_2 (traction) and "
                    "Gamma_3 (contact) are disjoint parts of the "
                    "boundary, so each id belongs to one list.");
    };
    require_disjoint(contact_ids, clamped_ids, "clamped and as contact");
    require_disjoint(traction_ids, contact_ids, "traction and as contact");
    require_disjoint(traction_ids, clamped_ids, "clamped and as traction");
  }

  void
  LamePair::declare(ParameterHandler &prm)
  {
    prm.declare_entry("parametrisation",
                      "lame",
                      selection_pattern(parametrisations),
                      "'lame': use 'mu' and 'lambda'; 'young': use 'young "
                      "modulus' and 'poisson ratio'.");
    prm.declare_entry("mu", "1", Patterns::Double(), "Lame parameter mu.");
    prm.declare_entry("lambda",
                      "1",
                      Patterns::Double(),
                      "Lame parameter lambda.");
    prm.declare_entry("young modulus",
                      "1",
                      Patterns::Double(),
                      "Young's modulus E > 0.");
    prm.declare_entry("poisson ratio",
                      "0.3",
                      Patterns::Double(),
                      "Poisson's ratio, -1 < nu < 0.5.");
  }

  void
  LamePair::parse(ParameterHandler &prm, const std::string &name)
  {
    if (get_selection(prm, "parametrisation", parametrisations) ==
        LameParametrisation::lame)
      {
        mu     = prm.get_double("mu");
        lambda = prm.get_double("lambda");
      }
    else
      {
        const double E  = prm.get_double("young modulus");
        const double nu = prm.get_double("poisson ratio");
        require(E > 0,
                "material/" + name + ": 'young modulus' = " +
                  std::to_string(E) + " must be positive.");
        require(nu > -1 && nu < 0.5,
                "material/" + name + ": 'poisson ratio' = " +
                  std::to_string(nu) + " must lie in (-1, 0.5).");
        mu     = E / (2 * (1 + nu));
        lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
      }
  }

  void
  MaterialParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("material");
    prm.declare_entry("density",
                      "1",
                      Patterns::Double(),
                      "Mass density rho > 0.");
    prm.enter_subsection("viscosity");
    LamePair::declare(prm);
    prm.leave_subsection();
    prm.enter_subsection("elasticity");
    LamePair::declare(prm);
    prm.leave_subsection();
    prm.leave_subsection();
  }

  void
  MaterialParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("material");
    density = prm.get_double("density");
    prm.enter_subsection("viscosity");
    viscosity.parse(prm, "viscosity");
    prm.leave_subsection();
    prm.enter_subsection("elasticity");
    elasticity.parse(prm, "elasticity");
    prm.leave_subsection();
    prm.leave_subsection();

    // the density and the viscosity are checked with the problem class,
    // which may not use them (require_consistent())
    require(elasticity.mu >= 0,
            "material/elasticity: 'mu' = " + std::to_string(elasticity.mu) +
              " must be non-negative.");
    require(elasticity.lambda + 2. / 3. * elasticity.mu >= 0,
            "material/elasticity: 'lambda' = " +
              std::to_string(elasticity.lambda) +
              " makes the bulk modulus lambda + 2 mu / 3 negative.");
  }

  void
  TimeParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("time");
    prm.declare_entry("end time", "1", Patterns::Double(), "Final time T > 0.");
    prm.declare_entry("time step",
                      "0.01",
                      Patterns::Double(),
                      "Time step k > 0; it must divide the end time (the run "
                      "takes T/k uniform steps).");
    prm.declare_entry(
      "allow unstable time step",
      "false",
      Patterns::Bool(),
      "The left-point rule is stable only for k below a limit set by the "
      "viscosity, the elasticity and the mesh, and the memory rule "
      "('relaxation', 'normal memory') below a limit set by the kernel; "
      "a larger time step is refused at start-up. 'true' runs it anyway, "
      "with a warning.");
    prm.leave_subsection();
  }

  void
  TimeParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("time");
    end_time                 = prm.get_double("end time");
    time_step                = prm.get_double("time step");
    allow_unstable_time_step = prm.get_bool("allow unstable time step");
    prm.leave_subsection();
    require(end_time > 0,
            "time: 'end time' = " + std::to_string(end_time) +
              " must be positive.");
    require(time_step > 0,
            "time: 'time step' = " + std::to_string(time_step) +
              " must be positive.");
    require(time_step <= end_time,
            "time: 'time step' = " + std::to_string(time_step) +
              " is larger than 'end time' = " + std::to_string(end_time) + ".");
    // the scheme takes N uniform steps k = T/N: a time step that does not
    // divide the end time would be changed, so it is refused
    const double n_steps = end_time / time_step;
    if (std::abs(n_steps - std::round(n_steps)) > 1e-8 * n_steps)
      {
        std::ostringstream message;
        message << std::setprecision(12) << "time: 'end time' = " << end_time
                << " is not a whole number of steps of 'time step' = "
                << time_step << " (" << n_steps
                << " steps); the scheme takes uniform steps, so choose a "
                   "time step that divides the end time (e.g. "
                << end_time / std::max(1., std::round(n_steps)) << ").";
        throw InputError(message.str());
      }
    // the step counter is an unsigned int
    if (std::round(n_steps) > std::numeric_limits<unsigned int>::max())
      {
        std::ostringstream message;
        message << std::setprecision(12) << "time: 'end time' = " << end_time
                << " takes " << n_steps
                << " steps of 'time step' = " << time_step
                << ", more than the program counts (at most "
                << std::numeric_limits<unsigned int>::max()
                << "); choose a larger time step or a shorter end time.";
        throw InputError(message.str());
      }
  }

  void
  ProblemParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("problem");
    prm.declare_entry(
      "class",
      "dynamic",
      selection_pattern(problem_classes),
      "The problem class (doc/theory.md, section 9): 'dynamic' (rho dw/dt "
      "= Div sigma + f0), 'quasistatic' (0 = Div sigma + f0: no inertia; "
      "'material/density' and 'data/initial velocity' are not used, the "
      "initial velocity is the step problem at t = 0) or 'static' (0 = Div "
      "B eps(u) + f0, the laws act on the displacement; the time axis is a "
      "load parameter, one problem per load value; density, viscosity, the "
      "initial values and the time scheme are not used).");
    prm.declare_entry(
      "time scheme",
      "left point",
      selection_pattern(time_schemes),
      "The rule for the displacement: 'left point' (u_{n+1} = u_n + k w_n, "
      "the elastic term explicit, stable below a time-step limit) or "
      "'implicit' (u_n = u_{n-1} + k w_n, the elastic term in the step "
      "matrix, stable for every time step).");
    prm.leave_subsection();
  }

  void
  ProblemParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("problem");
    problem_class = get_selection(prm, "class", problem_classes);
    time_scheme   = get_selection(prm, "time scheme", time_schemes);
    prm.leave_subsection();
  }

  void
  DataParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("data");
    prm.declare_entry(
      "constants",
      "",
      Patterns::Anything(),
      "User constants for the expressions below, e.g. "
      "'g=9.81, v=0.1': finite numbers, each name once and "
      "none of a variable (x, y, z, t, u_nu, w_nu) or a function "
      "(sin, ...). 'pi', '_pi' and '_e' are predefined.");
    const std::string vec_help =
      " Vector-valued: 'dimension' expressions (doc/parameters.md, "
      "Expressions) separated by ';' in x, y, z and t. A single number (e.g. "
      "0) means that value in every component.";
    prm.declare_entry("body force",
                      "0",
                      Patterns::Anything(),
                      "Body force density f0(x,t)." + vec_help);
    prm.declare_entry("surface traction",
                      "0",
                      Patterns::Anything(),
                      "Traction f2(x,t) on Gamma_2." + vec_help);
    prm.declare_entry("contact traction",
                      "0",
                      Patterns::Anything(),
                      "An additional given traction f3(x,t) on Gamma_3 "
                      "(zero in physical runs; used by manufactured "
                      "solutions)." +
                        vec_help);
    prm.declare_entry("friction bound",
                      "0",
                      Patterns::Anything(),
                      "Friction bound F_b >= 0 on Gamma_3: the radius of the "
                      "friction disk (the static bound of a weakening law). A "
                      "scalar expression (doc/parameters.md, Expressions) in "
                      "x, y, z, t, u_nu, the normal displacement at the "
                      "node (positive into the foundation), w_nu, the "
                      "normal velocity (velocity classes), p_nu, the "
                      "contact pressure -sigma_nu at the node, and s_tau, "
                      "the slip accumulated up to the state before the step "
                      "(doc/theory.md, section 11.10). u_nu is the "
                      "displacement known when the step starts, p_nu in the "
                      "velocity classes the pressure of the step before; a "
                      "bound in the step's own unknown (w_nu; u_nu or p_nu "
                      "in the static class) is found by fixed-point "
                      "iterations (doc/theory.md, sections 9.8 and 9.9). "
                      "E.g. mu*cp*pos(u_nu) for normal compliance with "
                      "friction, mu*pos(p_nu) for Coulomb friction, "
                      "0.2 + 0.3*exp(-s_tau/0.01) for a bound weakening "
                      "with the distance slid, or x < 0.5 ? 0.3 : 0.2.");
    prm.declare_entry("initial displacement",
                      "0",
                      Patterns::Anything(),
                      "u0(x); must vanish on Gamma_1." + vec_help);
    prm.declare_entry("initial velocity",
                      "0",
                      Patterns::Anything(),
                      "w0(x); must vanish on Gamma_1." + vec_help);
    prm.leave_subsection();
  }

  void
  DataParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("data");
    constants            = prm.get("constants");
    body_force           = prm.get("body force");
    surface_traction     = prm.get("surface traction");
    contact_traction     = prm.get("contact traction");
    friction_bound       = prm.get("friction bound");
    initial_displacement = prm.get("initial displacement");
    initial_velocity     = prm.get("initial velocity");
    prm.leave_subsection();
  }

  void
  OutputParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("output");
    prm.declare_entry("directory",
                      "output",
                      Patterns::Anything(),
                      "Directory for all output (created if missing).");
    prm.declare_entry("output interval",
                      "10",
                      Patterns::Integer(0),
                      "Write the solution files (VTU or HDF5) and the rows "
                      "of the contact CSV files every this many steps; 0 "
                      "writes none.");
    // 'vtu interval' is read as 'output interval'
    prm.declare_alias("output interval", "vtu interval");
    prm.declare_entry("format",
                      "vtu",
                      selection_pattern(solution_formats),
                      "Solution files: 'vtu' (.vtu per rank and .pvtu per "
                      "output time, series solution.pvd) or 'hdf5' (one .h5 "
                      "per output time written by all ranks, series "
                      "solution.xdmf). ParaView opens either series.");
    prm.declare_entry("precision",
                      "float",
                      selection_pattern(output_precisions),
                      "'float': the solution files only, whose values are "
                      "single precision; 'double': at the same output times "
                      "also nodal_NNNNN.h5 with the nodes, the cells and w, u "
                      "and the contact traction per node in double "
                      "precision, series nodal.xdmf (either 'format').");
    prm.declare_entry("compression",
                      "best speed",
                      selection_pattern(compression_levels),
                      "zlib compression of VTU files: 'best speed' "
                      "(fast, files somewhat larger), 'default', 'best "
                      "compression' (smallest files, slowest) or 'none'. "
                      "Lossless at every level.");
    prm.declare_entry("probe points",
                      "",
                      Patterns::Anything(),
                      "Points whose w and u are written to probes.csv each "
                      "step, separated by ';', coordinates by ',' (e.g. "
                      "'1, 0.5; 2, 1').");
    prm.declare_entry("terminal",
                      "progress",
                      selection_pattern(terminal_outputs),
                      "'progress': one line per step; 'quiet': start and end "
                      "only; 'test': rounded, machine-independent lines for "
                      "the test suite.");
    prm.declare_entry(
      "performance summary",
      "false",
      Patterns::Bool(),
      "At the end, time one solve of the step matrix rho/k M + A with the "
      "same solver (fresh AMG set-up plus CG from zero to 'relative "
      "tolerance') and write performance.csv: iteration counts, wall time "
      "per step, the time split, peak memory and bytes per dof (bench/ uses "
      "it).");
    prm.declare_entry("timing summary",
                      "true",
                      Patterns::Bool(),
                      "Print the TimerOutput summary at the end.");
    prm.declare_entry(
      "error estimate",
      "false",
      Patterns::Selection("false|true|equilibrated"),
      "After every step, evaluate the residual a posteriori error estimate "
      "eta_n in the energy norm of the step (doc/theory.md, section 12): "
      "its terms in steps.csv, eta_K per cell ('error_estimate') in the "
      "solution files, the run's estimate in the summary line, and the "
      "estimate and effectivity index of each level of a convergence "
      "study; in the velocity classes also the time indicator "
      "(the energy norm of w_n - w_{n-1}, section 12.4). 'equilibrated': "
      "in its place the bound of an equilibrated stress (section 12.5: "
      "guaranteed under its assumptions; static class, 2D quadrilaterals "
      "without hanging nodes, one MPI rank).");
    prm.leave_subsection();
  }

  void
  OutputParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("output");
    directory           = prm.get("directory");
    output_interval     = prm.get_integer("output interval");
    format              = get_selection(prm, "format", solution_formats);
    precision           = get_selection(prm, "precision", output_precisions);
    probe_points        = prm.get("probe points");
    terminal            = get_selection(prm, "terminal", terminal_outputs);
    compression         = get_selection(prm, "compression", compression_levels);
    timing_summary      = prm.get_bool("timing summary");
    performance_summary = prm.get_bool("performance summary");
    error_estimate      = prm.get("error estimate") != "false";
    error_estimate_equilibrated = prm.get("error estimate") == "equilibrated";
    prm.leave_subsection();
    require(!directory.empty(), "output: 'directory' must not be empty.");
  }

  void
  CheckpointParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("checkpoint");
    prm.declare_entry("interval",
                      "0",
                      Patterns::Integer(0),
                      "Write a checkpoint (mesh and state, to "
                      "OUTPUT/checkpoint/) after every this many steps; 0: "
                      "never. The last two checkpoints are kept; each is "
                      "written aside, then renamed. A simplex mesh resumes "
                      "on the number of MPI ranks that wrote it.");
    prm.declare_entry("wall interval",
                      "0",
                      Patterns::Double(0),
                      "Also write one when this many wall-clock seconds have "
                      "passed since the last; 0: never.");
    prm.declare_entry("stop after",
                      "0",
                      Patterns::Integer(0),
                      "Stop after this many steps of this run with a "
                      "checkpoint, as SIGTERM does (exit code 5); for job "
                      "chunks under batch time limits. 0: run to the end.");
    prm.declare_entry(
      "resume",
      "false",
      Patterns::Bool(),
      "Continue from the newest checkpoint in OUTPUT/checkpoint "
      "(also: hemicontact --resume FILE.prm). steps.csv, "
      "probes.csv and solution.pvd are continued; the number "
      "of MPI ranks may differ from the interrupted run's.");
    prm.leave_subsection();
  }

  void
  CheckpointParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("checkpoint");
    interval      = prm.get_integer("interval");
    wall_interval = prm.get_double("wall interval");
    stop_after    = prm.get_integer("stop after");
    resume        = prm.get_bool("resume");
    prm.leave_subsection();
  }

  void
  Parameters::declare(ParameterHandler &prm)
  {
    prm.declare_entry("dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "Space dimension, 2 or 3.");
    GeometryParameters::declare(prm);
    BoundaryParameters::declare(prm);
    MaterialParameters::declare(prm);
    TimeParameters::declare(prm);
    ProblemParameters::declare(prm);
    DataParameters::declare(prm);
    RelaxationParameters::declare(prm);
    NormalMemoryParameters::declare(prm);
    WearParameters::declare(prm);
    TemperatureParameters::declare(prm);
    PiezoelectricParameters::declare(prm);
    NonlinearSolverParameters::declare(prm);
    LinearSolverParameters::declare(prm);
    OutputParameters::declare(prm);
    AdaptivityParameters::declare(prm);
    CheckpointParameters::declare(prm);
    ManufacturedParameters::declare(prm);
    ConvergenceStudyParameters::declare(prm);
  }

  void
  Parameters::parse(ParameterHandler &prm)
  {
    dimension = prm.get_integer("dimension");
    geometry.parse(prm);
    boundary.parse(prm);
    material.parse(prm);
    time.parse(prm);
    problem.parse(prm);
    data.parse(prm);
    relaxation.parse(prm);
    normal_memory.parse(prm);
    wear.parse(prm, dimension);
    temperature.parse(prm, dimension);
    piezoelectricity.parse(prm, dimension);
    nonlinear_solver.parse(prm);
    linear_solver.parse(prm);
    output.parse(prm);
    adaptivity.parse(prm);
    checkpoint.parse(prm);
    manufactured.parse(prm);
    study.parse(prm);

    require_consistent(*this);
  }
} // namespace hemicontact
