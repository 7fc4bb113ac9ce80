#pragma once

#include <hemicontact/laws/normal_law.h>

namespace hemicontact
{
  /**
   * Normal compliance with finite penetration (Han & Sofonea): the
   * response p(r) = c_p r_+ up to the penetration limit g, then a rigid
   * wall: -sigma_nu in c_p r_+ + N_(-inf, g](r) (doc/theory.md section 10).
   * Convex: alpha = 0.
   */
  class FinitePenetrationLaw : public NormalLaw
  {
  public:
    static constexpr const char *law_name =
      "normal compliance with finite penetration";
    static void
    declare_parameters(ParameterHandler &prm);

    explicit FinitePenetrationLaw(ParameterHandler &prm);
    FinitePenetrationLaw(const double stiffness,
                         const double penetration_limit);

    std::string
    name() const override
    {
      return law_name;
    }
    double
    jump() const override
    {
      return 0.;
    }
    double
    remainder(const double r) const override
    {
      return r > 0 ? stiffness * r : 0.;
    }
    double
    remainder_derivative(const double r) const override
    {
      return r > 0 ? stiffness : 0.;
    }
    double
    remainder_primitive(const double r) const override
    {
      return r > 0 ? 0.5 * stiffness * r * r : 0.;
    }
    double
    relaxed_monotonicity_constant() const override
    {
      return 0.;
    }
    double
    penetration_limit() const override
    {
      return limit;
    }

  private:
    double stiffness;
    double limit;
  };
} // namespace hemicontact
