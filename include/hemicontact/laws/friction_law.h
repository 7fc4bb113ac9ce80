#pragma once

#include <deal.II/base/parameter_handler.h>

#include <hemicontact/laws/law_registry.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /**
   * A friction law on Gamma_3, -sigma_tau in dphi(w_tau) (Clarke
   * subdifferential of a locally Lipschitz, possibly nonconvex potential
   * phi per unit boundary measure).
   *
   * Every law is written like a NormalLaw (doc/theory.md, section 7): the
   * convex, set-valued Tresca part plus a single-valued Lipschitz remainder
   * of the slip speed s = |v|,
   *   dphi(v) = d(F_b |v|) + r(F_b, |v|) v/|v|,   r(F_b, 0) = 0,
   * where F_b >= 0 is the friction bound at the node (the 'friction bound'
   * expression, which may depend on the normal displacement). The
   * active-set solver keeps the friction disk of radius F_b, its projection
   * and the stick/slip branches; it needs of the law only the remainder,
   * its derivative and primitive in s, and the relaxed-monotonicity
   * constant alpha_tau. Tresca friction is the law with r = 0.
   */
  class FrictionLaw
  {
  public:
    virtual ~FrictionLaw() = default;

    /** Name as written in the parameter file. */
    virtual std::string
    name() const = 0;

    /** The remainder r(F_b, s) at slip speed s >= 0; r(F_b, 0) = 0. */
    virtual double
    remainder(const double bound, const double s) const = 0;

    /** dr/ds at s >= 0 (the right derivative at s = 0 and at kinks). */
    virtual double
    remainder_derivative(const double bound, const double s) const = 0;

    /** R(F_b, s) = int_0^s r(F_b, t) dt. */
    virtual double
    remainder_primitive(const double bound, const double s) const = 0;

    /**
     * The relaxed-monotonicity constant alpha_tau(F_b) >= 0: phi(v) +
     * alpha_tau |v|^2 / 2 is convex, i.e. alpha_tau >= -dr/ds everywhere.
     */
    virtual double
    relaxed_monotonicity_constant(const double bound) const = 0;

    /** The potential phi = F_b s + R(F_b, s) at slip speed s. */
    double
    potential(const double bound, const double s) const;

    /**
     * The friction force F(s) = F_b + r(F_b, s) that opposes slip at speed
     * s > 0; at s = 0 the radius F_b of the friction disk.
     */
    double
    response(const double bound, const double s) const;

    /** r(F_b, s)/s, with its limit dr/ds(0) at s = 0. */
    double
    remainder_over_slip(const double bound, const double s) const;
  };

  /** One entry of the registry of friction laws (subsection "friction law"). */
  using FrictionLawEntry = LawEntry<FrictionLaw>;

  /** The registry entry of a friction law class (see make_law_entry()). */
  template <class Law>
  FrictionLawEntry
  friction_law_entry()
  {
    return make_law_entry<FrictionLaw, Law>();
  }

  /**
   * All registered friction laws: the shipped ones (one line each in
   * source/laws/friction_law.cc) and those added by register_friction_law().
   */
  const std::vector<FrictionLawEntry> &
  friction_law_registry();

  /** The friction law selected when the parameter file names none. */
  const std::string &
  default_friction_law_name();

  /**
   * Add a law to the registry, e.g. from a program that links the library:
   * register_friction_law(friction_law_entry<MyLaw>()). Call it before any
   * parameters are declared; a name that is already registered throws.
   */
  void
  register_friction_law(const FrictionLawEntry &entry);

  /** Declare subsection "friction law" with "law" and one subsection per law.
   */
  void
  declare_friction_law_parameters(ParameterHandler &prm);

  /** Create the law selected in subsection "friction law" of @p prm. */
  std::unique_ptr<FrictionLaw>
  create_friction_law(ParameterHandler &prm);
} // namespace hemicontact
