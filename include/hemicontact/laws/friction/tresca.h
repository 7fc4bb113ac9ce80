#pragma once

#include <hemicontact/laws/friction_law.h>

namespace hemicontact
{
  /**
   * Tresca friction: |sigma_tau| <= F_b, -sigma_tau = F_b w_tau/|w_tau|
   * where w_tau != 0. The convex potential F_b |v|: no remainder,
   * alpha_tau = 0.
   */
  class TrescaLaw : public FrictionLaw
  {
  public:
    static constexpr const char *law_name = "tresca";
    static void
    declare_parameters(ParameterHandler &)
    {}
    explicit TrescaLaw(ParameterHandler &)
    {}
    TrescaLaw() = default;

    std::string
    name() const override
    {
      return law_name;
    }
    double
    remainder(const double, const double) const override
    {
      return 0.;
    }
    double
    remainder_derivative(const double, const double) const override
    {
      return 0.;
    }
    double
    remainder_primitive(const double, const double) const override
    {
      return 0.;
    }
    double
    relaxed_monotonicity_constant(const double) const override
    {
      return 0.;
    }
  };
} // namespace hemicontact
