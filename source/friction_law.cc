#include <hemicontact/friction_law.h>
#include <hemicontact/friction_laws/piecewise_linear_friction.h>
#include <hemicontact/friction_laws/slip_rate_weakening.h>
#include <hemicontact/friction_laws/tresca.h>
#include <hemicontact/input_error.h>

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
    std::vector<FrictionLawEntry> &
    registry()
    {
      static std::vector<FrictionLawEntry> laws = {
        friction_law_entry<TrescaLaw>(),
        friction_law_entry<SlipRateWeakeningLaw>(),
        friction_law_entry<PiecewiseLinearFrictionLaw>(),
      };
      return laws;
    }
  } // namespace

  const std::vector<FrictionLawEntry> &
  friction_law_registry()
  {
    return registry();
  }

  void
  register_friction_law(const FrictionLawEntry &entry)
  {
    for (const FrictionLawEntry &e : registry())
      AssertThrow(e.name != entry.name,
                  ExcMessage("friction law '" + entry.name +
                             "' is registered twice."));
    registry().push_back(entry);
  }

  void
  declare_friction_law_parameters(ParameterHandler &prm)
  {
    std::string names;
    for (const FrictionLawEntry &e : friction_law_registry())
      names += (names.empty() ? "" : "|") + e.name;
    prm.enter_subsection("friction law");
    prm.declare_entry("law", "tresca", Patterns::Selection(names),
                      "Friction law -sigma_tau in dphi(w_tau) on the contact "
                      "boundary: the Tresca disk of radius 'data/friction "
                      "bound' plus the law's remainder in the slip speed. "
                      "Each law has its own subsection below.");
    for (const FrictionLawEntry &e : friction_law_registry())
      e.declare(prm);
    prm.leave_subsection();
  }

  std::unique_ptr<FrictionLaw>
  create_friction_law(ParameterHandler &prm)
  {
    prm.enter_subsection("friction law");
    const std::string            name = prm.get("law");
    std::unique_ptr<FrictionLaw> law;
    try
      {
        for (const FrictionLawEntry &e : friction_law_registry())
          if (e.name == name)
            law = e.create(prm);
      }
    catch (...)
      {
        prm.leave_subsection();
        throw;
      }
    prm.leave_subsection();
    require(law != nullptr, "friction law: unknown law '" + name + "'.");
    return law;
  }
} // namespace hemicontact
