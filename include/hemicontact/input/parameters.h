#pragma once

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/parameter_handler.h>

#include <hemicontact/input/solver_tuning.h>

#include <algorithm>
#include <string>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /** Where the coarse mesh comes from ('geometry/mesh'). */
  enum class MeshType
  {
    rectangle, ///< a rectangle (2D) or box (3D) from the corners
    gmsh       ///< a Gmsh file
  };

  /** The element type ('geometry/cell type'). */
  enum class CellType
  {
    hypercube, ///< quadrilaterals/hexahedra, FE_Q, p4est mesh
    simplex    ///< triangles/tetrahedra, FE_SimplexP, fully distributed mesh
  };

  /** Mesh: built-in rectangle/box or a Gmsh file, and the element type. */
  struct GeometryParameters
  {
    MeshType                  mesh_type;
    CellType                  cell_type;
    std::vector<double>       lower_left; ///< corner of the rectangle/box
    std::vector<double>       upper_right;
    std::vector<unsigned int> subdivisions;
    std::string               mesh_file;
    unsigned int              global_refinements;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /** The three boundary parts, each a set of boundary ids. */
  /** The part of the boundary a boundary id belongs to. */
  enum class BoundaryPart
  {
    clamped,  ///< Gamma_1
    traction, ///< Gamma_2
    contact,  ///< Gamma_3
    free      ///< listed nowhere: sigma nu = 0
  };

  struct BoundaryParameters
  {
    std::vector<unsigned int> clamped_ids;  ///< Gamma_1: u = 0
    std::vector<unsigned int> traction_ids; ///< Gamma_2: sigma nu = f2
    std::vector<unsigned int> contact_ids;  ///< Gamma_3: contact

    /**
     * The part of boundary id @p id: the one list that names it (parse()
     * requires the lists to be disjoint), or free. The one classification
     * every face loop uses.
     */
    BoundaryPart
    part(const unsigned int id) const
    {
      const auto in = [id](const std::vector<unsigned int> &ids) {
        return std::find(ids.begin(), ids.end(), id) != ids.end();
      };
      return in(clamped_ids)  ? BoundaryPart::clamped :
             in(traction_ids) ? BoundaryPart::traction :
             in(contact_ids)  ? BoundaryPart::contact :
                                BoundaryPart::free;
    }

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /** An isotropic Lame pair, given either as (mu, lambda) or as (E, nu). */
  struct LamePair
  {
    double mu;
    double lambda;

    static void
    declare(ParameterHandler &prm);
    /** Parse; @p name ("elasticity"/"viscosity") is used in error messages. */
    void
    parse(ParameterHandler &prm, const std::string &name);
  };

  /** Kelvin-Voigt material: density, viscosity A and elasticity B. */
  struct MaterialParameters
  {
    double   density;
    LamePair viscosity;
    LamePair elasticity;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /** Uniform time stepping t_n = n k on [0, T]. */
  struct TimeParameters
  {
    double end_time;
    double time_step;
    /** Run a time step above the left-point rule's stability limit. */
    bool allow_unstable_time_step;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /** The problem class (doc/theory.md, section 9). */
  enum class ProblemClass
  {
    dynamic,     ///< rho dw/dt = Div sigma + f0 (sections 1-8)
    quasistatic, ///< 0 = Div sigma + f0: no inertia, viscosity kept
    static_      ///< 0 = Div B eps(u) + f0: the laws act on u
  };

  /** The rule for the displacement of the velocity classes (section 9). */
  enum class TimeScheme
  {
    left_point, ///< u_{n+1} = u_n + k w_n: u_n known in step n
    implicit    ///< u_n = u_{n-1} + k w_n: u_n part of step n
  };

  /** The problem class and the time scheme (subsection 'problem'). */
  struct ProblemParameters
  {
    ProblemClass problem_class;
    TimeScheme   time_scheme;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /** Data of the problem as expressions in x, y, z, t. */
  struct DataParameters
  {
    std::string constants;
    std::string body_force;       ///< f0(x,t)
    std::string surface_traction; ///< f2(x,t) on Gamma_2
    std::string contact_traction; ///< f3(x,t) on Gamma_3 (manufactured data)
    std::string friction_bound;   ///< F_b(x) >= 0
    std::string initial_displacement; ///< u0(x)
    std::string initial_velocity;     ///< w0(x)

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /** The kind of a memory kernel (each kernel subsection's 'kernel'). */
  enum class MemoryKernelType
  {
    none,      ///< no memory
    prony,     ///< K(t) = sum_m K_m exp(-t/tau_m), O(1) history per term
    expression ///< K(t) as expressions in t: every past state
  };

  /** The kind of the relaxation tensor's kernel R(t). */
  using RelaxationKernelType = MemoryKernelType;

  /**
   * Long memory in the stress (doc/theory.md, section 10): the isotropic
   * relaxation tensor R(t) eps = 2 mu_R(t) eps + lambda_R(t) tr(eps) I of
   * sigma = ... + int_0^t R(t - s) eps(u(s)) ds.
   */
  struct RelaxationParameters
  {
    MemoryKernelType kernel;
    /** The Prony series: mu_m, lambda_m and tau_m of each term. */
    std::vector<double> mu_amplitudes;
    std::vector<double> lambda_amplitudes;
    std::vector<double> relaxation_times;
    /** The general kernel: expressions in t. */
    std::string mu;
    std::string lambda;

    /** Whether the stress has a memory term. */
    bool
    active() const
    {
      return kernel != MemoryKernelType::none;
    }

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /**
   * Memory in the normal response (doc/theory.md, section 11.9): the
   * kernel b(t) of N_n = sum_{j<n} k_j b(t_n - t_j) (u_nu,j)_+, the part of
   * -sigma_nu a foundation adds for the time it was penetrated.
   */
  struct NormalMemoryParameters
  {
    MemoryKernelType kernel;
    /** The Prony series b(t) = sum_m b_m exp(-t/tau_m): b_m and tau_m. */
    std::vector<double> amplitudes;
    std::vector<double> relaxation_times;
    /** The general kernel b(t): an expression in t. */
    std::string b;

    /** Whether the normal response has a memory term. */
    bool
    active() const
    {
      return kernel != MemoryKernelType::none;
    }

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /**
   * Archard wear on a foundation moving tangentially (doc/theory.md,
   * section 11.12): the wear depth omega_n = k_w sum_{j<n} p_j |slip_j|
   * at each contact node moves the foundation away.
   */
  struct WearParameters
  {
    /** k_w >= 0; 0: no wear. */
    double coefficient = 0;
    /** v*, dim components (zero when the entry is empty). */
    std::vector<double> foundation_velocity;

    /** Whether the foundation wears (k_w > 0). */
    bool
    active() const
    {
      return coefficient > 0;
    }

    static void
    declare(ParameterHandler &prm);
    /** The entries, checked for @p dimension components of v*. */
    void
    parse(ParameterHandler &prm, const unsigned int dimension);
  };

  /**
   * The subsection 'temperature' (doc/theory.md, section 13): the
   * temperature theta of the body, sigma = A eps(w) + B eps(u) - c_e theta I,
   * its heat equation c_theta dtheta/dt - div(K grad theta) = -c_e div w + q
   * with its boundary conditions and the contact heat law on Gamma_3; in
   * the static class theta is data.
   */
  /** How the mechanical and the heat step meet at a time step. */
  enum class TemperatureCoupling
  {
    staggered, ///< each once, the mechanical step with theta_{n-1}
    iterated   ///< both repeated until (w_n, theta_n) no longer change
  };

  struct TemperatureParameters
  {
    bool enabled = false;
    /** c_theta(x) > 0, an expression in x, y[, z]. */
    std::string heat_capacity;
    /** c_e(x) >= 0, an expression in x, y[, z]. */
    std::string thermal_stress_coefficient;
    /**
     * K: one expression in x, y[, z] (isotropic, K(x) > 0), or dim x dim
     * numbers by rows (symmetric positive definite).
     */
    std::vector<std::string>  conductivity;
    std::string               initial_temperature;    ///< theta_0(x)
    std::string               heat_source;            ///< q(x, t)
    std::vector<unsigned int> prescribed_ids;         ///< theta = theta_D there
    std::string               prescribed_temperature; ///< theta_D(x, t)
    std::vector<unsigned int> flux_ids;               ///< K d_nu theta = q_N
    std::string               heat_flux;              ///< q_N(x, t)
    /** k_e(x, t, u_nu) >= 0 on Gamma_3. */
    std::string exchange_coefficient;
    std::string foundation_temperature; ///< theta_F(x, t)
    /** gamma in [0, 1]: the fraction of the frictional power that enters. */
    double frictional_heat_fraction = 0;
    /** The static class: theta(x, t) as data. */
    std::string         given_temperature;
    TemperatureCoupling coupling = TemperatureCoupling::staggered;
    /** iterated: the relative change of (w_n, theta_n) that ends it */
    double coupling_tolerance = 1e-10;
    /** iterated: the most passes of the mechanical step per time step */
    unsigned int coupling_iterations = 20;

    /** Whether K is a tensor of numbers (else one expression). */
    bool
    anisotropic() const
    {
      return conductivity.size() > 1;
    }

    static void
    declare(ParameterHandler &prm);
    /** The entries, checked for a @p dimension x dimension tensor K. */
    void
    parse(ParameterHandler &prm, const unsigned int dimension);
  };

  /**
   * The subsection 'piezoelectricity' (doc/theory.md, section 14): the
   * electric potential phi of the body, sigma = A eps(w) + B eps(u) +
   * E^T grad phi and D = E eps(u) - beta grad phi with div D = q_0, phi =
   * phi_D on the electrodes, D.nu = q_b on the surface charge ids and the
   * electric contact law D.nu = p_e(u_nu) (phi - phi_F) on Gamma_3.
   */
  struct PiezoelectricParameters
  {
    bool enabled = false;
    /** e_31, e_33, e_15, or the dim^3 entries E_kij (k, i, j in order) */
    std::vector<double> piezoelectric_constants;
    /** beta: one number, or the dim^2 entries of an SPD tensor */
    std::vector<double>       permittivity;
    std::string               volume_charge;       ///< q_0(x, t)
    std::vector<unsigned int> electrode_ids;       ///< phi = phi_D there
    std::string               electrode_potential; ///< phi_D(x, t)
    std::vector<unsigned int> surface_charge_ids;  ///< D.nu = q_b there
    std::string               surface_charge;      ///< q_b(x, t)
    /** p_e(x, t, u_nu) >= 0, the conductance of the foundation */
    std::string conductance;
    std::string foundation_potential; ///< phi_F(x, t)
    /** The relative change of (u_n, phi_n) that ends the alternation of
     *  the implicit rule and the static class. */
    double coupling_tolerance = 1e-11;
    /** The most passes of that alternation. */
    unsigned int coupling_iterations = 100;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm, const unsigned int dimension);
  };

  /** Where Newton starts in a step. */
  enum class InitialGuess
  {
    extrapolated, ///< w_{n-1} + k_n/k_{n-1} (w_{n-1} - w_{n-2})
    previous      ///< w_{n-1}
  };

  /** Settings of the semismooth Newton / active-set iteration of one step. */
  struct NonlinearSolverParameters
  {
    double       tolerance; ///< relative nonsmooth residual
    unsigned int max_iterations;
    /** How often a failing step may be retried with half the time step. */
    unsigned int time_step_halvings;
    bool         line_search;
    InitialGuess initial_guess;
    bool         strict_convexity_check;
    /**
     * The fixed point on a friction bound that depends on the step's
     * unknown (doc/theory.md 9.8): relative change of the bounds at which
     * it stops, and the iterations allowed.
     */
    double       bound_tolerance;
    unsigned int bound_iterations;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /** The linear solver of a Newton iteration. */
  enum class LinearSolverType
  {
    cg_amg, ///< CG on the projected operator, AMG-based preconditioner
    direct  ///< sparse direct solve of the projected Newton matrix (reference)
  };

  /** How far each Krylov solve of a Newton iteration goes. */
  enum class ForcingTerm
  {
    eisenstat_walker, ///< follows the decrease of the Newton residual
    fixed             ///< always to 'relative tolerance'
  };

  /** Linear solver of each Newton step. */
  struct LinearSolverParameters
  {
    LinearSolverType type;
    ForcingTerm      forcing_term;
    double           relative_tolerance;
    unsigned int     max_iterations;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /** The format of the solution files. */
  enum class SolutionFormat
  {
    vtu, ///< .vtu per rank, .pvtu per output time, the .pvd series
    hdf5 ///< one .h5 per output time (parallel HDF5), the .xdmf series
  };

  /** The precision of the nodal fields written. */
  enum class OutputPrecision
  {
    single_precision, ///< the solution files only (float values)
    double_precision  ///< also nodal_NNNNN.h5 and nodal.xdmf (doubles)
  };

  /** What a run prints on the terminal. */
  enum class TerminalOutput
  {
    progress, ///< one line per step
    quiet,    ///< start and end only
    test      ///< rounded, machine-independent lines for the test suite
  };

  /**
   * The zlib level of the VTU files: the type of VtkFlags::compression_level,
   * DataOutBase::CompressionLevel in deal.II 9.6 and
   * VtkFlags::ZlibCompressionLevel (deprecated in 9.6) in 9.4; both have
   * the enumerators best_speed, default_compression, best_compression and
   * no_compression.
   */
  using VtuCompression = decltype(DataOutBase::VtkFlags::compression_level);

  /** What is written, where and how often. */
  struct OutputParameters
  {
    std::string directory;
    /** Solution files and contact tables every this many steps, 0 = never. */
    unsigned int    output_interval;
    SolutionFormat  format;
    OutputPrecision precision;
    std::string     probe_points; ///< "x,y; x,y" (empty: none)
    TerminalOutput  terminal;
    /** zlib level of the VTU files (lossless at every level). */
    VtuCompression compression;
    bool           timing_summary;
    /** Write performance.csv (and time one step-matrix solve) at the end. */
    bool performance_summary;
    /**
     * Evaluate an error estimate after every step ('error estimate' =
     * true or equilibrated).
     */
    bool error_estimate;
    /**
     * The estimate is the equilibrated bound of doc/theory.md 12.5
     * ('equilibrated'), not the residual estimate of 12.1 ('true').
     */
    bool error_estimate_equilibrated = false;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /**
   * A manufactured solution: the exact displacement u(x,t) and the
   * multiplier choices where the contact subdifferentials are intervals;
   * f0, f2, f3, u0 and w0 are derived from them (doc/theory.md section 4).
   */
  struct ManufacturedParameters
  {
    bool        enabled;
    std::string exact_displacement;    ///< dim expressions in x, y, z, t
    std::string normal_multiplier;     ///< s* in (0, a) where w_nu = 0
    std::string tangential_multiplier; ///< lambda* (|.| < F_b) where w_tau = 0
    /** theta(x, t) with 'temperature/enabled' (doc/theory.md 13.6) */
    std::string exact_temperature;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /** The cell indicator of adaptive refinement ('adaptivity/indicator'). */
  enum class RefinementIndicator
  {
    kelly,         ///< jumps of the normal derivative of w_n
    kelly_contact, ///< plus the jumps of the contact traction on Gamma_3
    residual,      ///< the step's residual in cells, on faces and on Gamma_3
    estimator      ///< eta_K of the error estimate (doc/theory.md 12.1)
  };

  /** Which cells adaptive refinement marks ('adaptivity/strategy'). */
  enum class MarkingStrategy
  {
    fixed_fraction, ///< the cells holding a fraction of the summed indicator
    fixed_number    ///< a fraction of the cells
  };

  /** How the state moves to an adapted mesh ('adaptivity/state transfer'). */
  enum class StateTransfer
  {
    interpolation, ///< deal.II's SolutionTransfer
    projection     ///< M- and a_B-projections
  };

  /** Adaptive mesh refinement during the time loop (hypercube meshes). */
  struct AdaptivityParameters
  {
    unsigned int interval; ///< adapt after every this many steps, 0 = never
    RefinementIndicator indicator;
    double contact_weight; ///< weight of the Gamma_3 traction jumps
    unsigned int
      pre_refinement_steps; ///< restart from t = 0 after these, 0 = never
    MarkingStrategy strategy;
    double          refine_fraction;
    double          coarsen_fraction;
    unsigned int    max_cells; ///< 0 = no limit
    unsigned int    min_level;
    unsigned int    max_level;
    StateTransfer   state_transfer;
    /** Refine each load value until eta <= target_error |||u_h|||; 0 = off. */
    double target_error;

    /** Whether the mesh changes during the run. */
    bool
    changes_mesh() const
    {
      return interval > 0 || pre_refinement_steps > 0 || target_error > 0;
    }

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /** Checkpoints of the time loop and resuming from them. */
  struct CheckpointParameters
  {
    unsigned int interval;      ///< every this many steps, 0 = never
    double       wall_interval; ///< every this many wall seconds, 0 = never
    unsigned int stop_after; ///< stop (with a checkpoint) after this many steps
    bool         resume;     ///< continue from the newest checkpoint

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /** What a convergence study refines from level to level. */
  enum class StudyType
  {
    single, ///< one run
    h,      ///< the mesh
    k,      ///< the time step
    coupled ///< both, k = c h
  };

  /** A convergence study over refinement levels (manufactured solutions). */
  struct ConvergenceStudyParameters
  {
    StudyType    type;
    unsigned int n_levels; ///< number of levels
    /**
     * A 'k' study's errors against the run with this time step on the same
     * mesh instead of the manufactured solution (0: against the
     * manufactured solution), doc/verification.md
     */
    double reference_time_step;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /** All parameters of a run, one struct per subsection. */
  struct Parameters
  {
    unsigned int              dimension;
    GeometryParameters        geometry;
    BoundaryParameters        boundary;
    MaterialParameters        material;
    TimeParameters            time;
    ProblemParameters         problem;
    DataParameters            data;
    RelaxationParameters      relaxation;
    NormalMemoryParameters    normal_memory;
    WearParameters            wear;
    TemperatureParameters     temperature;
    PiezoelectricParameters   piezoelectricity;
    NonlinearSolverParameters nonlinear_solver;
    LinearSolverParameters    linear_solver;
    /** Set from C++ only (tests, benchmarks): see SolverTuning. */
    SolverTuning               solver_tuning;
    OutputParameters           output;
    AdaptivityParameters       adaptivity;
    CheckpointParameters       checkpoint;
    ManufacturedParameters     manufactured;
    ConvergenceStudyParameters study;
    /**
     * Every entry that defines the problem, as "path/entry = value" (all
     * subsections but output, checkpoint, the solvers and the convergence
     * study), and output/format and output/precision, which name the
     * series files a resume continues: a checkpoint records them, and a
     * resume that would change one is refused.
     */
    std::vector<std::string> problem_definition;

    static void
    declare(ParameterHandler &prm);
    void
    parse(ParameterHandler &prm);
  };

  /**
   * Throw an InputError if the entries of different subsections of
   * @p parameters contradict each other (each subsection's own checks are
   * in its parse()).
   */
  void
  require_consistent(const Parameters &parameters);

  /** Declare every parameter of the program (including the laws). */
  void
  declare_all_parameters(ParameterHandler &prm);

  /**
   * Read @p filename into @p prm and return the parsed parameters. Any
   * problem (missing file, syntax, unknown key, wrong type, non-physical
   * value) throws an InputError that names the cause.
   */
  Parameters
  read_parameters(ParameterHandler &prm, const std::string &filename);

  /**
   * Read @p filename, then the entries of @p overrides (parameter-file
   * text) on top of it -- e.g. coarser levels of a shipped study in a test.
   */
  Parameters
  read_parameters(ParameterHandler  &prm,
                  const std::string &filename,
                  const std::string &overrides);

  /** Same, from a string holding a parameter file (used by tests). */
  Parameters
  read_parameters_from_string(ParameterHandler &prm, const std::string &text);
} // namespace hemicontact
