#pragma once

#include <hemicontact/laws/friction_law.h>

namespace hemicontact
{
  /**
   * Friction with the potential F_b s0 ln(1 + s/s0) of the slip s (Jureczka
   * & Ochal's law, s0 = 1): the force F(s) = F_b/(1 + s/s0) falls from the
   * bound towards zero. Remainder r(s) = -F_b (s/s0)/(1 + s/s0),
   * alpha_tau = F_b/s0.
   */
  class RationalWeakeningLaw : public FrictionLaw
  {
  public:
    static constexpr const char *law_name = "rational weakening";
    static void
    declare_parameters(ParameterHandler &prm);

    explicit RationalWeakeningLaw(ParameterHandler &prm);
    explicit RationalWeakeningLaw(const double characteristic_slip);

    std::string
    name() const override
    {
      return law_name;
    }
    double
    remainder(const double bound, const double s) const override;
    double
    remainder_derivative(const double bound, const double s) const override;
    double
    remainder_primitive(const double bound, const double s) const override;
    double
    relaxed_monotonicity_constant(const double bound) const override;

  private:
    double s0;
  };
} // namespace hemicontact
