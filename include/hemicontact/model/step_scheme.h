#pragma once

#include <hemicontact/input/parameters.h>

#include <string>

namespace hemicontact
{
  /**
   * The coefficients of a step matrix K = mass rho M + viscous A + elastic B
   * (M the unweighted mass matrix, A and B those of a_A and a_B).
   */
  struct StepMatrixCoefficients
  {
    double mass    = 0;
    double viscous = 1;
    double elastic = 0;

    bool
    operator==(const StepMatrixCoefficients &other) const
    {
      return mass == other.mass && viscous == other.viscous &&
             elastic == other.elastic;
    }
  };

  /**
   * What differs between the problem classes and time schemes
   * (doc/theory.md, section 9): the step matrix and
   * right-hand side, the update of the displacement, the initial velocity,
   * the terms of the energy identity (9.3), the matrix of the convexity
   * check (9.5) and the stability condition (9.6). Every step is one
   * minimisation of section 3 with the K and b given here; the Newton
   * method, the laws and the preconditioner do not see the class.
   *
   * The displacement u held between steps is the one the next step's
   * right-hand side uses: the left-point rule adds k w_{n-1} to it before
   * step n (u_n = u_{n-1} + k w_{n-1}), the implicit rule adds k w_n after
   * it (u_n = u_{n-1} + k w_n). After step n it approximates u(t_n) in both.
   *
   * In the static class the step's unknown is the displacement u_n itself
   * (the vector the velocity classes call w): K = B, b = F_n, the laws act
   * on it, and after the step the held displacement is set to it.
   */
  class StepScheme
  {
  public:
    StepScheme(const ProblemClass problem_class, const TimeScheme time_scheme);
    explicit StepScheme(const ProblemParameters &parameters);

    ProblemClass
    problem_class() const
    {
      return the_class;
    }
    TimeScheme
    time_scheme() const
    {
      return the_scheme;
    }
    /** "dynamic, left point", "quasistatic, implicit", ... */
    std::string
    name() const;

    /** Whether the step's unknown is the displacement u (static class). */
    bool
    is_static() const
    {
      return the_class == ProblemClass::static_;
    }
    /** The symbol of the step's unknown in output: "w", or "u" (static). */
    std::string
    unknown_symbol() const
    {
      return is_static() ? "u" : "w";
    }
    /**
     * The material of the class: @p material itself, without viscosity in
     * the static class (sigma = B eps(u), doc/theory.md 9.1).
     */
    MaterialParameters
    class_material(const MaterialParameters &material) const;

    /** Whether the equations hold the inertia term rho dw/dt (dynamic). */
    bool
    has_inertia() const
    {
      return the_class == ProblemClass::dynamic;
    }
    /** The density in the equations: @p rho (dynamic) or 0 (quasistatic). */
    double
    inertia_density(const double rho) const
    {
      return has_inertia() ? rho : 0.;
    }

    /**
     * K of a step of length @p k (doc/theory.md, section 9, the table):
     * rho/k M + A [+ k B], or A [+ k B] without inertia; [k B] in the
     * implicit rule. The dynamic left point is {1/k, 1, 0}.
     */
    StepMatrixCoefficients
    step_matrix(const double k) const;
    /** K of the problem for w_0 (quasistatic: A, doc/theory.md 9.2). */
    StepMatrixCoefficients
    initial_matrix() const;
    /** K as text for messages, e.g. "rho/k M + A + k B". */
    std::string
    step_matrix_name() const;

    /**
     * Whether w_0 is the solution of the step problem at t_0 with the data
     * u_0 (quasistatic, doc/theory.md 9.2) instead of 'data/initial
     * velocity'.
     */
    bool
    initial_velocity_from_step() const
    {
      return the_class == ProblemClass::quasistatic;
    }

    /**
     * b = rho/k M w_{n-1} - B u + F (without inertia: F - B u), u the
     * displacement held before the step: u_n (left point) or u_{n-1}
     * (implicit); static: b = F. @p mass is rho M.
     */
    template <class Matrix, class VectorType>
    void
    step_rhs(const Matrix     &mass,
             const Matrix     &elastic,
             const VectorType &old_velocity,
             const VectorType &displacement,
             const VectorType &load,
             const double      k,
             VectorType       &rhs,
             VectorType       &tmp) const
    {
      if (has_inertia())
        {
          mass.vmult(rhs, old_velocity);
          rhs /= k;
        }
      else
        rhs = 0;
      if (!is_static())
        {
          elastic.vmult(tmp, displacement);
          rhs -= tmp;
        }
      rhs += load;
    }

    /** The right-hand side of the problem for w_0: F_0 - B u_0. */
    template <class Matrix, class VectorType>
    void
    initial_rhs(const Matrix     &elastic,
                const VectorType &displacement,
                const VectorType &load,
                VectorType       &rhs) const
    {
      elastic.vmult(rhs, displacement);
      rhs *= -1.;
      rhs += load;
    }

    /**
     * Before step n: u += k w_{n-1} (left point), nothing (implicit,
     * static).
     */
    template <class VectorType>
    void
    displacement_before_step(VectorType       &u,
                             const VectorType &old_velocity,
                             const double      k) const
    {
      if (uses_left_point())
        u.add(k, old_velocity);
    }
    /** Take displacement_before_step() back (a step that failed). */
    template <class VectorType>
    void
    undo_displacement_before_step(VectorType       &u,
                                  const VectorType &old_velocity,
                                  const double      k) const
    {
      if (uses_left_point())
        u.add(-k, old_velocity);
    }
    /**
     * After step n: u += k w_n (implicit), nothing (left point); static:
     * u = the step's unknown.
     */
    template <class VectorType>
    void
    displacement_after_step(VectorType       &u,
                            const VectorType &velocity,
                            const double      k) const
    {
      if (is_static())
        u = velocity;
      else if (the_scheme == TimeScheme::implicit)
        u.add(k, velocity);
    }
    /** Take displacement_after_step() back (velocity classes). */
    template <class VectorType>
    void
    undo_displacement_after_step(VectorType       &u,
                                 const VectorType &velocity,
                                 const double      k) const
    {
      if (the_scheme == TimeScheme::implicit)
        u.add(-k, velocity);
    }

    /**
     * The displacement held after step n (doc/theory.md 9.3) is
     * u + held_displacement_offset(k) w_n: u_{n+1} = u_n + k w_n (left
     * point, offset k) or u_n itself (implicit, offset 0).
     */
    double
    held_displacement_offset(const double k) const
    {
      return uses_left_point() ? k : 0.;
    }

    /**
     * The length over which the solved w_n moves the displacement, which
     * the wall's limit on w_n divides by (doc/theory.md 10.2): @p k itself
     * in the implicit rule (u_n = u_{n-1} + k w_n), the length
     * @p following_k of the interval after the step in the left-point rule
     * (u_{n+1} = u_n + k_{n+1} w_n); the two differ where a halved interval
     * ends.
     */
    double
    wall_step_length(const double k, const double following_k) const
    {
      return uses_left_point() ? following_k : k;
    }

    /** The terms of the energy identity of one step (doc/theory.md 9.3). */
    struct StepEnergy
    {
      double viscous;   ///< k w_n.A w_n
      double numerical; ///< D_n = rho/2 |w_n - w_{n-1}|_M^2 -+ k^2/2 w_n.B w_n
    };
    /**
     * From w_n.A w_n, (w_n - w_{n-1}).rho M (w_n - w_{n-1}) and w_n.B w_n:
     * - for the left point, + for the implicit rule; no kinetic part
     * without inertia.
     */
    StepEnergy
    step_energy(const double k,
                const double w_A_w,
                const double dw_M_dw,
                const double w_B_w) const;
    /** The kinetic energy rho/2 w.M w from w.rho M w (0 without inertia). */
    double
    kinetic_energy(const double w_M_w) const
    {
      return has_inertia() ? 0.5 * w_M_w : 0.;
    }

    /**
     * Whether the scheme is stable only below a time-step limit: the left
     * point (doc/theory.md 9.6); the implicit rule has none.
     */
    bool
    has_time_step_limit() const
    {
      return uses_left_point();
    }
    /** The stability condition as text, for messages. */
    std::string
    stability_condition() const;
    /**
     * Why the step energy may fail to be convex and what helps, for the
     * messages of the convexity check (doc/theory.md 9.5).
     */
    std::string
    convexity_remedy(const double k) const;

    /**
     * One line naming the parameters this class does not use that
     * @p parameters sets to other values than their defaults
     * (doc/theory.md 9.2); empty if none.
     */
    std::string
    ignored_parameters(const Parameters &parameters) const;

  private:
    /** The left-point rule in a velocity class. */
    bool
    uses_left_point() const
    {
      return !is_static() && the_scheme == TimeScheme::left_point;
    }

    ProblemClass the_class;
    TimeScheme   the_scheme;
  };
} // namespace hemicontact
