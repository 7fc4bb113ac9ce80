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
   * Every law is written in the split of doc/theory.md section 1,
   *   dj(r) = d(a r_+)(r) + p(r),
   * with the convex jump part d(a r_+) = {0} (r<0), [0,a] (r=0), {a} (r>0)
   * and a single-valued Lipschitz remainder p with p(r) = 0 for r <= 0.
   * The active-set solver needs only these pieces: the jump a, the
   * remainder p, its derivative p' and its primitive P (for the step
   * energy J_n), and the relaxed-monotonicity constant alpha.
   */
  class NormalLaw
  {
  public:
    virtual ~NormalLaw() = default;

    /** Name as written in the parameter file. */
    virtual std::string
    name() const = 0;

    /** The jump a >= 0 of the subdifferential at r = 0: dj(0) = [0, a]. */
    virtual double
    jump() const = 0;

    /** The remainder p(r); zero for r <= 0. */
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

    /** The potential j(r) = a r_+ + P(r). */
    double
    potential(const double r) const;

    /**
     * The subdifferential dj(r) as an interval [lower, upper]: a single
     * point for r != 0, [0, a] at r = 0.
     */
    std::pair<double, double>
    subdifferential(const double r) const;

    /** The single-valued branch used for r != 0 (and 0 at r = 0). */
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
