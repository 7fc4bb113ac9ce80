#include <hemicontact/base/exceptions.h>
#include <hemicontact/laws/friction/piecewise_linear_friction.h>
#include <hemicontact/laws/friction/rational_weakening.h>
#include <hemicontact/laws/friction/slip_rate_weakening.h>
#include <hemicontact/laws/friction/tresca.h>
#include <hemicontact/laws/friction_law.h>

namespace hemicontact
{
  double
  FrictionLaw::potential(const double bound, const double s) const
  {
    return bound * s + remainder_primitive(bound, s);
  }

  double
  FrictionLaw::response(const double bound, const double s) const
  {
    return bound + remainder(bound, s);
  }

  double
  FrictionLaw::remainder_over_slip(const double bound, const double s) const
  {
    // below this slip speed r(s)/s is replaced by its limit r'(0): the
    // difference is of the order of r'' s, far below the solver tolerance
    return s > 1e-12 ? remainder(bound, s) / s :
                       remainder_derivative(bound, 0.);
  }

  namespace
  {
    LawRegistry<FrictionLaw> &
    registry()
    {
      static LawRegistry<FrictionLaw> laws(
        "friction law",
        TrescaLaw::law_name,
        "Friction law -sigma_tau in dphi(w_tau) on the contact boundary: the "
        "Tresca disk of radius 'data/friction bound' plus the law's "
        "remainder in the slip speed. Each law has its own subsection "
        "below.",
        {
          friction_law_entry<TrescaLaw>(),
          friction_law_entry<SlipRateWeakeningLaw>(),
          friction_law_entry<PiecewiseLinearFrictionLaw>(),
          friction_law_entry<RationalWeakeningLaw>(),
        });
      return laws;
    }
  } // namespace

  const std::vector<FrictionLawEntry> &
  friction_law_registry()
  {
    return registry().entries();
  }

  const std::string &
  default_friction_law_name()
  {
    return registry().default_name();
  }

  void
  register_friction_law(const FrictionLawEntry &entry)
  {
    registry().add(entry);
  }

  void
  declare_friction_law_parameters(ParameterHandler &prm)
  {
    registry().declare(prm);
  }

  std::unique_ptr<FrictionLaw>
  create_friction_law(ParameterHandler &prm)
  {
    return registry().create(prm);
  }
} // namespace hemicontact
