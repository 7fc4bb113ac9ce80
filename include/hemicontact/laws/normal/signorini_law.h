#pragma once

#include <hemicontact/laws/normal_law.h>

namespace hemicontact
{
  /**
   * The Signorini condition as a law: no resistance up to a rigid wall at
   * the penetration limit g >= 0 (r <= g, -sigma_nu in N_(-inf, g](r)); g
   * = 0 is the classical non-penetration condition (doc/theory.md section 10).
   */
  class SignoriniLaw : public NormalLaw
  {
  public:
    static constexpr const char *law_name = "signorini";
    static void
    declare_parameters(ParameterHandler &prm);

    explicit SignoriniLaw(ParameterHandler &prm);
    explicit SignoriniLaw(const double penetration_limit);

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
    double
    penetration_limit() const override
    {
      return limit;
    }

  private:
    double limit;
  };
} // namespace hemicontact
