#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/law_parameters.h>
#include <hemicontact/laws/normal/penalised_softening_compliance.h>

#include <cmath>

namespace hemicontact
{
  void
  PenalisedSofteningCompliance::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(law_name);
    prm.declare_entry("a",
                      "0.1",
                      Patterns::Double(),
                      "Limit a >= 0 of the response j'(r) = a + exp(-r) for "
                      "large penetration r.");
    prm.declare_entry("b",
                      "0.1",
                      Patterns::Double(),
                      "Penetration b > 0 up to which j'(r) rises linearly "
                      "to its peak a + exp(-b).");
    prm.declare_entry("penalty",
                      "1",
                      Patterns::Double(),
                      "The factor 1/lambda >= 0 of the potential "
                      "j_nu = j / lambda.");
    prm.leave_subsection();
  }

  PenalisedSofteningCompliance::PenalisedSofteningCompliance(
    ParameterHandler &prm)
    : PenalisedSofteningCompliance(get_law_double(prm, law_name, "a"),
                                   get_law_double(prm, law_name, "b"),
                                   get_law_double(prm, law_name, "penalty"))
  {}

  PenalisedSofteningCompliance::PenalisedSofteningCompliance(
    const double a,
    const double b,
    const double penalty)
    : a(a)
    , b(b)
    , penalty(penalty)
  {
    const std::string law = std::string("normal law '") + law_name + "': ";
    require(std::isfinite(a) && a >= 0,
            law + "the parameter a = " + std::to_string(a) +
              " must be a non-negative number (the limit of the response "
              "for large penetration).");
    require(std::isfinite(b) && b > 0,
            law + "the parameter b = " + std::to_string(b) +
              " must be positive (the penetration at which the response "
              "peaks).");
    require(std::isfinite(penalty) && penalty >= 0,
            law + "the parameter penalty = " + std::to_string(penalty) +
              " must be a non-negative finite number (the factor 1/lambda "
              "of the potential).");
  }

  double
  PenalisedSofteningCompliance::remainder(const double r) const
  {
    if (r <= 0)
      return 0.;
    if (r < b)
      return penalty * (a + std::exp(-b)) * r / b;
    return penalty * (a + std::exp(-r));
  }

  double
  PenalisedSofteningCompliance::remainder_derivative(const double r) const
  {
    if (r < 0)
      return 0.;
    if (r < b) // at r = 0 the right derivative
      return penalty * (a + std::exp(-b)) / b;
    return -penalty * std::exp(-r);
  }

  double
  PenalisedSofteningCompliance::remainder_primitive(const double r) const
  {
    if (r <= 0)
      return 0.;
    if (r < b)
      return penalty * (a + std::exp(-b)) * r * r / (2 * b);
    return penalty *
           (a * r - std::exp(-r) + 0.5 * ((b + 2) * std::exp(-b) - a * b));
  }

  double
  PenalisedSofteningCompliance::relaxed_monotonicity_constant() const
  {
    return penalty * std::exp(-b);
  }

  double
  PenalisedSofteningCompliance::largest_remainder_slope() const
  {
    return penalty * (a + std::exp(-b)) / b;
  }
} // namespace hemicontact
