#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hemicontact/laws/law_registry.h>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * A normal damped response law -sigma_nu in dj(w_nu) on Gamma_3 (Clarke
   * subdifferential of a locally Lipschitz, possibly nonconvex potential j).
   *
   * Every law is written in the split of doc/theory.md sections 1 and 10,
   *   dj(r) = d(a r_+)(r) + sum_j d(J_j (r - r_j)_+)(r) + p(r)
   *           [+ N_(-inf, g](r)],
   * with the convex jump part d(a r_+) = {0} (r<0), [0,a] (r=0), {a} (r>0),
   * convex kinks J_j > 0 at breakpoints r_j > 0 (kinks()), an optional
   * wall at the penetration limit g (penetration_limit()), and a
   * single-valued remainder p with p(r) = 0 for r <= 0, Lipschitz between
   * breakpoints; a downward jump of the response is a jump of p. The
   * active-set solver needs only these pieces: the jump a, the kinks, the
   * wall, the remainder p, its derivative p' and its primitive P (for the
   * step energy J_n), and the relaxed-monotonicity constant alpha.
   */
  class NormalLaw
  {
  public:
    /** An upward jump J > 0 of the response at r = position > 0. */
    struct Kink
    {
      double position;
      double jump;
    };

    virtual ~NormalLaw() = default;

    /** Name as written in the parameter file. */
    virtual std::string
    name() const = 0;

    /** The jump a >= 0 of the subdifferential at r = 0: dj(0) = [0, a]. */
    virtual double
    jump() const = 0;

    /**
     * The upward jumps of the response away from r = 0, ordered by
     * position: each is a convex kink of j (a branch "at the breakpoint").
     * None by default.
     */
    virtual const std::vector<Kink> &
    kinks() const;

    /**
     * The penetration limit g: a rigid wall r <= g behind the law (+inf,
     * the default, for none).
     */
    virtual double
    penetration_limit() const;

    /**
     * The remainder p(r): the response minus a H(r) and the kinks'
     * jumps J_j H(r - r_j) (H(0) = 0; right-continuous at r_j > 0); zero
     * for r <= 0.
     */
    virtual double
    remainder(const double r) const = 0;

    /** p'(r): the derivative of the r > 0 branch for r > 0, zero for r <= 0. */
    virtual double
    remainder_derivative(const double r) const = 0;

    /** P(r) = int_0^r p(s) ds; zero for r <= 0. */
    virtual double
    remainder_primitive(const double r) const = 0;

    /**
     * The relaxed-monotonicity constant alpha >= 0:
     * (xi1 - xi2)(r1 - r2) >= -alpha (r1 - r2)^2 for xi_i in dj(r_i).
     */
    virtual double
    relaxed_monotonicity_constant() const = 0;

    /** The potential j(r) = a r_+ + sum_j J_j (r - r_j)_+ + P(r). */
    double
    potential(const double r) const;

    /**
     * The convex part of the response below and at r: a H(r) plus the
     * jumps J_j with r_j <= r (the "staircase" of doc/theory.md section 10).
     */
    double
    staircase(const double r) const;

    /**
     * The subdifferential dj(r) as an interval [lower, upper]: [0, a] at
     * r = 0, [left, right] at a kink, a single point elsewhere (the wall's
     * normal cone is not part of it).
     */
    std::pair<double, double>
    subdifferential(const double r) const;

    /** The single-valued branch: the response right of r (0 at r <= 0). */
    double
    subgradient(const double r) const;
  };

  /** One entry of the registry of normal laws (subsection "normal law"). */
  using NormalLawEntry = LawEntry<NormalLaw>;

  /**
   * All registered normal laws: the shipped ones (one line each in
   * source/laws/normal_law.cc) and those added by register_normal_law().
   */
  const std::vector<NormalLawEntry> &
  normal_law_registry();

  /** The registry entry of a normal law class (see make_law_entry()). */
  template <class Law>
  NormalLawEntry
  normal_law_entry()
  {
    return make_law_entry<NormalLaw, Law>();
  }

  /**
   * Add a law to the registry, e.g. from a program that links the library:
   * register_normal_law(normal_law_entry<MyLaw>()). Call it before any
   * parameters are declared; a name that is already registered throws.
   */
  void
  register_normal_law(const NormalLawEntry &entry);

  /** Declare subsection "normal law" with "law" and one subsection per law. */
  void
  declare_normal_law_parameters(ParameterHandler &prm);

  /** Create the law selected in subsection "normal law" of @p prm. */
  std::unique_ptr<NormalLaw>
  create_normal_law(ParameterHandler &prm);
} // namespace hemicontact
