/**
 * The subsection 'temperature': the temperature field, its heat equation
 * and the contact heat law (TemperatureParameters,
 * include/hemicontact/input/parameters.h; doc/theory.md, section 13).
 */
#include <deal.II/base/utilities.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/input/number_list.h>
#include <hemicontact/input/parameters.h>

#include <cmath>
#include <sstream>
#include <string>

namespace hemicontact
{
  namespace
  {
    /** @p text as a number if it is one (else NaN, an expression). */
    double
    number_or_nan(const std::string &text)
    {
      try
        {
          std::size_t  end   = 0;
          const double value = std::stod(text, &end);
          return Utilities::trim(text.substr(end)).empty() ? value : NAN;
        }
      catch (...)
        {
          return NAN;
        }
    }
  } // namespace

  void
  TemperatureParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("temperature");
    prm.declare_entry(
      "enabled",
      "false",
      Patterns::Bool(),
      "Whether the body carries a temperature theta (doc/theory.md, section "
      "13): the stress gains -c_e theta I, and in the dynamic and the "
      "quasistatic class each step is followed by the heat step "
      "c_theta (theta_n - theta_{n-1})/k - div(K grad theta_n) = -c_e div "
      "w_n + q (staggered: the mechanical step sees theta_{n-1}); in the "
      "static class theta is 'given temperature'. theta is a field of the "
      "state: written, checkpointed and moved by adaptations.");
    prm.declare_entry("heat capacity",
                      "1",
                      Patterns::Anything(),
                      "c_theta > 0, the heat capacity per volume: a number "
                      "or an expression in x, y[, z] and the constants (not "
                      "t: it is evaluated once).");
    prm.declare_entry(
      "thermal stress coefficient",
      "0",
      Patterns::Anything(),
      "c_e >= 0 of sigma = ... - c_e theta I and of the heat equation's "
      "-c_e div w (c_e = E alpha / (1 - 2 nu) from the expansion "
      "coefficient alpha): a number or an expression in x, y[, z] (not t: "
      "it is evaluated once).");
    prm.declare_entry(
      "conductivity",
      "1",
      Patterns::Anything(),
      "K: one number or expression in x, y[, z] (isotropic, K > 0; not t: "
      "it is evaluated once), or dim x dim comma-separated numbers by rows "
      "(a symmetric positive definite tensor). Commas inside parentheses, "
      "as in max(x, 1), belong to the expression.");
    prm.declare_entry("initial temperature",
                      "0",
                      Patterns::Anything(),
                      "theta_0(x, y[, z]) of the dynamic and the quasistatic "
                      "class (no heat step at t = 0).");
    prm.declare_entry("heat source",
                      "0",
                      Patterns::Anything(),
                      "q(x, y[, z], t), the heat supplied per volume.");
    prm.declare_entry(
      "prescribed temperature boundary ids",
      "",
      Patterns::List(Patterns::Integer(0, 255)),
      "Boundary ids where theta = 'prescribed temperature' (default: none); "
      "a node both there and on Gamma_3 is held by the prescribed value.");
    prm.declare_entry("prescribed temperature",
                      "0",
                      Patterns::Anything(),
                      "theta_D(x, y[, z], t) on the prescribed ids.");
    prm.declare_entry(
      "heat flux boundary ids",
      "",
      Patterns::List(Patterns::Integer(0, 255)),
      "Boundary ids where the heat 'heat flux' enters, K d_nu theta = q_N "
      "(not Gamma_3); every other boundary part but Gamma_3 is insulated.");
    prm.declare_entry("heat flux",
                      "0",
                      Patterns::Anything(),
                      "q_N(x, y[, z], t): the heat entering per area on the "
                      "heat flux ids.");
    prm.declare_entry(
      "exchange coefficient",
      "0",
      Patterns::Anything(),
      "k_e >= 0 of the contact heat law -K d_nu theta = k_e (theta - "
      "theta_F) - gamma |sigma_tau . w_tau| on Gamma_3: an expression in x, "
      "y[, z], t and u_nu, the normal displacement (e.g. 2 * step(u_nu): "
      "exchange only in contact); 0: no exchange.");
    prm.declare_entry("foundation temperature",
                      "0",
                      Patterns::Anything(),
                      "theta_F(x, y[, z], t) of the contact heat law.");
    prm.declare_entry(
      "frictional heat fraction",
      "0",
      Patterns::Anything(),
      "gamma in [0, 1]: the fraction of the frictional power |sigma_tau . "
      "w_tau| at each contact node that enters the body.");
    prm.declare_entry(
      "given temperature",
      "",
      Patterns::Anything(),
      "The static class: theta(x, y[, z], t) as data (a thermal load); the "
      "heat equation's entries are not used there. Empty in the dynamic "
      "and the quasistatic class.");
    prm.declare_entry(
      "coupling",
      "staggered",
      Patterns::Selection("staggered|iterated"),
      "How the mechanical and the heat step meet at each time step "
      "(doc/theory.md 13.2): 'staggered', each once, the mechanical step "
      "with theta_{n-1} in its load; 'iterated', the mechanical step again "
      "with the last theta_n and the heat step again from theta_{n-1}, "
      "until the relative change of (w_n, theta_n) between two passes is "
      "at most 'coupling tolerance' (the monolithic backward Euler scheme).");
    prm.declare_entry("coupling tolerance",
                      "1e-10",
                      Patterns::Double(0),
                      "'coupling = iterated': the relative change of w_n and "
                      "of theta_n (l2 norms) between two passes that ends "
                      "the iteration.");
    prm.declare_entry(
      "coupling iterations",
      "20",
      Patterns::Integer(2),
      "'coupling = iterated': the most passes of the mechanical step per "
      "time step; a step that needs more is retried with k/2, as after a "
      "Newton failure ('nonlinear solver/time step halvings').");
    prm.leave_subsection();
  }

  void
  TemperatureParameters::parse(ParameterHandler  &prm,
                               const unsigned int dimension)
  {
    prm.enter_subsection("temperature");
    enabled                    = prm.get_bool("enabled");
    heat_capacity              = prm.get("heat capacity");
    thermal_stress_coefficient = prm.get("thermal stress coefficient");
    conductivity        = split_at_top_level_commas(prm.get("conductivity"));
    initial_temperature = prm.get("initial temperature");
    heat_source         = prm.get("heat source");
    prescribed_ids = get_id_list(prm, "prescribed temperature boundary ids");
    prescribed_temperature       = prm.get("prescribed temperature");
    flux_ids                     = get_id_list(prm, "heat flux boundary ids");
    heat_flux                    = prm.get("heat flux");
    exchange_coefficient         = prm.get("exchange coefficient");
    foundation_temperature       = prm.get("foundation temperature");
    const std::string gamma_text = prm.get("frictional heat fraction");
    given_temperature            = prm.get("given temperature");
    coupling                     = prm.get("coupling") == "iterated" ?
                                     TemperatureCoupling::iterated :
                                     TemperatureCoupling::staggered;
    coupling_tolerance           = prm.get_double("coupling tolerance");
    coupling_iterations          = prm.get_integer("coupling iterations");
    prm.leave_subsection();
    require(coupling_tolerance > 0,
            "temperature: 'coupling tolerance' must be positive (the "
            "relative change of (w_n, theta_n) that ends the iterated "
            "coupling).");

    frictional_heat_fraction = number_or_nan(gamma_text);
    require(std::isfinite(frictional_heat_fraction) &&
              frictional_heat_fraction >= 0 && frictional_heat_fraction <= 1,
            "temperature: 'frictional heat fraction' = '" + gamma_text +
              "' must be a number in [0, 1] (the fraction gamma of the "
              "frictional power that enters the body).");
    // the coefficients that are numbers are checked here, expressions where
    // they are evaluated
    const auto require_number_above = [](const std::string &text,
                                         const std::string &entry,
                                         const bool         strictly,
                                         const std::string &meaning) {
      const double value = number_or_nan(text);
      if (std::isnan(value))
        return; // an expression
      require(std::isfinite(value) && (strictly ? value > 0 : value >= 0),
              "temperature: '" + entry + "' = '" + text + "' must be a " +
                (strictly ? "positive" : "non-negative") +
                " finite number or an expression (" + meaning + ").");
    };
    require_number_above(heat_capacity,
                         "heat capacity",
                         true,
                         "c_theta, the heat capacity per volume");
    require_number_above(thermal_stress_coefficient,
                         "thermal stress coefficient",
                         false,
                         "c_e of the thermal stress -c_e theta I");
    require(conductivity.size() == 1 ||
              conductivity.size() == dimension * dimension,
            "temperature: 'conductivity' has " +
              std::to_string(conductivity.size()) +
              " entries; give one (isotropic K) or " +
              std::to_string(dimension * dimension) +
              " numbers by rows (a symmetric positive definite tensor).");
    if (conductivity.size() == 1)
      require_number_above(conductivity[0],
                           "conductivity",
                           true,
                           "the isotropic conductivity K");
    else
      {
        std::vector<double> k;
        for (const std::string &item : conductivity)
          {
            k.push_back(number_or_nan(item));
            require(std::isfinite(k.back()),
                    "temperature: 'conductivity' entry '" + item +
                      "' is not a finite number; a tensor K is given by "
                      "numbers.");
          }
        bool symmetric = true;
        for (unsigned int i = 0; i < dimension; ++i)
          for (unsigned int j = 0; j < i; ++j)
            symmetric = symmetric &&
                        std::abs(k[i * dimension + j] - k[j * dimension + i]) <=
                          1e-14 * (std::abs(k[i * dimension + j]) +
                                   std::abs(k[j * dimension + i]));
        // positive definite: the leading principal minors (Sylvester)
        const double m1 = k[0];
        const double m2 = k[0] * k[dimension + 1] - k[1] * k[dimension];
        double       m3 = 1;
        if (dimension == 3)
          m3 = k[0] * (k[4] * k[8] - k[5] * k[7]) -
               k[1] * (k[3] * k[8] - k[5] * k[6]) +
               k[2] * (k[3] * k[7] - k[4] * k[6]);
        std::string listed;
        for (const std::string &item : conductivity)
          listed += (listed.empty() ? "" : ", ") + item;
        require(symmetric && m1 > 0 && m2 > 0 && m3 > 0,
                "temperature: 'conductivity' = '" + listed +
                  "' is not symmetric positive definite; the conductivity "
                  "tensor K must be (by rows, dim x dim numbers).");
      }
    for (const unsigned int i : prescribed_ids)
      for (const unsigned int j : flux_ids)
        require(i != j,
                "temperature: boundary id " + std::to_string(i) +
                  " is listed both in 'prescribed temperature boundary ids' "
                  "and in 'heat flux boundary ids'; a boundary part has one "
                  "thermal condition.");
  }
} // namespace hemicontact
