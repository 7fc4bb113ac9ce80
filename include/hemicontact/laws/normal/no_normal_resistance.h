#pragma once

#include <hemicontact/laws/normal_law.h>

namespace hemicontact
{
  /** No normal resistance at all: j = 0 (a = 0, p = 0, alpha = 0). */
  class NoNormalResistance : public NormalLaw
  {
  public:
    static constexpr const char *law_name = "none";
    static void
    declare_parameters(ParameterHandler &prm);

    explicit NoNormalResistance(ParameterHandler &prm);
    NoNormalResistance() = default;

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
    remainder(const double) const override
    {
      return 0.;
    }
    double
    remainder_derivative(const double) const override
    {
      return 0.;
    }
    double
    remainder_primitive(const double) const override
    {
      return 0.;
    }
    double
    relaxed_monotonicity_constant() const override
    {
      return 0.;
    }
  };
} // namespace hemicontact
