#pragma once

#include <hemicontact/laws/friction_law.h>

namespace hemicontact
{
  /**
   * Slip-rate weakening friction (Dieterich-Ruina-type decay from a static
   * to a dynamic coefficient): at slip speed s > 0 the friction force is
   *   F(s) = F_b (mu_d + (mu_s - mu_d) exp(-s/v0)) / mu_s,
   * the friction bound F_b being the static one (mu_s times the pressure).
   * Remainder r(s) = -F_b (1 - mu_d/mu_s)(1 - exp(-s/v0)), nonincreasing:
   * a nonconvex potential with alpha_tau = F_b (1 - mu_d/mu_s)/v0.
   */
  class SlipRateWeakeningLaw : public FrictionLaw
  {
  public:
    static constexpr const char *law_name = "slip rate weakening";
    static void
    declare_parameters(ParameterHandler &prm);

    explicit SlipRateWeakeningLaw(ParameterHandler &prm);
    SlipRateWeakeningLaw(const double static_coefficient,
                         const double dynamic_coefficient,
                         const double characteristic_slip_speed);

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
    /** 1 - mu_d/mu_s: the share of the static bound lost at high speed. */
    double drop;
    double v0;
  };
} // namespace hemicontact
