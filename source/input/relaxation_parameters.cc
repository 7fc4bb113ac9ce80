/**
 * The subsection 'relaxation': the kernel of the memory term of the stress
 * (RelaxationParameters, include/hemicontact/input/parameters.h).
 */
#include <deal.II/base/utilities.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/input/kernel_subsection.h>
#include <hemicontact/input/number_list.h>
#include <hemicontact/input/parameters.h>

#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace hemicontact
{
  namespace
  {
    const KernelSubsection relaxation = {
      "relaxation",
      "Long memory in the stress (doc/theory.md, section 11): sigma = "
      "A eps(w) + B eps(u) + int_0^t R(t - s) eps(u(s)) ds, R(t) eps = "
      "2 mu_R(t) eps + lambda_R(t) tr(eps) I, in every problem class "
      "(static: sigma = B eps(u) + int R eps(u)). The integral is the "
      "left-rectangle sum over the states before the step, M_n = sum_{j<n} "
      "k_j R(t_n - t_j) eps(u_j), on the step's right-hand side. 'none': no "
      "memory. 'prony': R(t) = sum_m exp(-t/tau_m) (2 mu_m eps + lambda_m "
      "tr(eps) I) from the three lists below, one vector of history per "
      "term, updated exactly at a fixed cost per step. 'expression': "
      "mu_R(t) and lambda_R(t) from 'mu' and 'lambda'; every past state is "
      "kept, so a step costs time and memory growing with the number of "
      "steps before it. Adapted meshes carry the history.",
      {{"mu amplitudes",
        "'kernel = prony': the amplitudes mu_m of mu_R(t) = "
        "sum_m mu_m exp(-t/tau_m), comma-separated finite "
        "numbers, one per term of 'relaxation times'."},
       {"lambda amplitudes",
        "'kernel = prony': the amplitudes lambda_m of "
        "lambda_R(t) = sum_m lambda_m exp(-t/tau_m), "
        "comma-separated finite numbers, one per term of "
        "'relaxation times'."}},
      {{"young amplitudes",
        "",
        std::make_shared<Patterns::Anything>(),
        "'kernel = prony', in place of 'mu amplitudes' and "
        "'lambda amplitudes': the amplitudes E_m of E_R(t) = "
        "sum_m E_m exp(-t/tau_m), one per term, with the one "
        "'poisson ratio' nu_R of the kernel: mu_m = E_m/(2 (1 + "
        "nu_R)), lambda_m = E_m nu_R/((1 + nu_R)(1 - 2 nu_R)), "
        "as 'material/elasticity' converts E and nu."},
       {"poisson ratio",
        "0",
        std::make_shared<Patterns::Double>(),
        "'kernel = prony' with 'young amplitudes': nu_R, -1 < "
        "nu_R < 0.5."}},
      {{"mu",
        "'kernel = expression': mu_R(t), a scalar expression "
        "(doc/parameters.md, Expressions) in t and the "
        "constants of 'data/constants'; it must be finite at "
        "t = k, 2k, ..., T (the rule never evaluates it at "
        "t = 0)."},
       {"lambda", "'kernel = expression': lambda_R(t), as 'mu'."}},
      "'relaxation times' (and the amplitudes of each term)",
      " (0 for none)"};
  } // namespace

  void
  RelaxationParameters::declare(ParameterHandler &prm)
  {
    relaxation.declare(prm);
  }

  void
  RelaxationParameters::parse(ParameterHandler &prm)
  {
    std::vector<double>      young_amplitudes;
    double                   poisson_ratio = 0;
    KernelSubsection::Values values =
      relaxation.parse(prm, [&](const ParameterHandler &p) {
        young_amplitudes = get_number_list(p, "relaxation", "young amplitudes");
        poisson_ratio    = p.get_double("poisson ratio");
      });
    kernel = values.kernel;
    mu     = values.expressions[0];
    lambda = values.expressions[1];

    if (kernel == MemoryKernelType::prony)
      {
        if (!young_amplitudes.empty())
          {
            require(values.amplitudes[0].empty() &&
                      values.amplitudes[1].empty(),
                    "relaxation: both 'young amplitudes' and 'mu amplitudes' "
                    "or 'lambda amplitudes' are set; give the terms either "
                    "as E_m with 'poisson ratio' or as mu_m and lambda_m, "
                    "not both.");
            std::ostringstream message;
            message << "relaxation: 'poisson ratio' = " << poisson_ratio
                    << " must lie in (-1, 0.5) with 'young amplitudes'.";
            require(poisson_ratio > -1 && poisson_ratio < 0.5, message.str());
            for (const double E : young_amplitudes)
              {
                values.amplitudes[0].push_back(E / (2 * (1 + poisson_ratio)));
                values.amplitudes[1].push_back(
                  E * poisson_ratio /
                  ((1 + poisson_ratio) * (1 - 2 * poisson_ratio)));
              }
          }
        if (young_amplitudes.empty())
          relaxation.require_terms(values);
        else
          relaxation.require_terms(values,
                                   {"young amplitudes", "young amplitudes"});
      }
    mu_amplitudes     = values.amplitudes[0];
    lambda_amplitudes = values.amplitudes[1];
    relaxation_times  = values.relaxation_times;
  }
} // namespace hemicontact
