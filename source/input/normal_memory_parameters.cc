/**
 * The subsection 'normal memory': the kernel b(t) of the memory term of the
 * normal response (NormalMemoryParameters,
 * include/hemicontact/input/parameters.h).
 */
#include <hemicontact/base/exceptions.h>
#include <hemicontact/input/number_list.h>
#include <hemicontact/input/parameters.h>
#include <hemicontact/input/selection.h>

#include <sstream>
#include <string>

namespace hemicontact
{
  namespace
  {
    const SelectionNames<RelaxationKernelType> kernel_types = {
      {"none", RelaxationKernelType::none},
      {"prony", RelaxationKernelType::prony},
      {"expression", RelaxationKernelType::expression}};
  } // namespace

  void
  NormalMemoryParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("normal memory");
    prm.declare_entry(
      "kernel",
      "none",
      selection_pattern(kernel_types),
      "Memory in the normal response (doc/theory.md, section 11.9): "
      "-sigma_nu gains N(t) = int_0^t b(t - s) (u_nu(s))_+ ds at each "
      "contact node, a foundation whose reaction grows with the time it was "
      "penetrated (u_nu > 0 into it); N acts also after the node separates. "
      "The integral is the left-rectangle sum over the states before the "
      "step, N_n = sum_{j<n} k_j b(t_n - t_j) (u_nu,j)_+, a known nodal "
      "pressure on the step's right-hand side, with every normal law and "
      "problem class, and part of the pressure p_nu of a friction bound. "
      "'none': no memory. 'prony': b(t) = sum_m b_m exp(-t/tau_m) from "
      "'amplitudes' and 'relaxation times', one history value per node and "
      "term, updated exactly at a fixed cost per step. 'expression': b(t) "
      "from 'b'; every past (u_nu)_+ is kept. Adapted meshes carry the history.");
    prm.declare_entry("amplitudes",
                      "",
                      Patterns::Anything(),
                      "'kernel = prony': the amplitudes b_m of b(t) = "
                      "sum_m b_m exp(-t/tau_m), comma-separated finite "
                      "numbers, one per term of 'relaxation times'.");
    prm.declare_entry("relaxation times",
                      "",
                      Patterns::Anything(),
                      "'kernel = prony': the relaxation times tau_m > 0 of "
                      "the terms, comma-separated finite numbers.");
    prm.declare_entry("b",
                      "0",
                      Patterns::Anything(),
                      "'kernel = expression': b(t), a scalar expression "
                      "(doc/parameters.md, Expressions) in t and the "
                      "constants of 'data/constants'; it must be finite at "
                      "t = k, 2k, ..., T (the rule never evaluates it at "
                      "t = 0).");
    prm.leave_subsection();
  }

  void
  NormalMemoryParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("normal memory");
    kernel     = get_selection(prm, "kernel", kernel_types);
    amplitudes = get_number_list(prm, "normal memory", "amplitudes");
    relaxation_times =
      get_number_list(prm, "normal memory", "relaxation times");
    b = prm.get("b");
    prm.leave_subsection();

    if (kernel != RelaxationKernelType::prony)
      return;
    require(!relaxation_times.empty(),
            "normal memory: 'kernel = prony' needs at least one term: set "
            "'relaxation times' and 'amplitudes'.");
    for (const double tau : relaxation_times)
      {
        std::ostringstream message;
        message << "normal memory: 'relaxation times' holds " << tau
                << "; every relaxation time tau_m must be positive (the "
                   "terms are exp(-t/tau_m)).";
        require(tau > 0, message.str());
      }
    require(amplitudes.size() == relaxation_times.size(),
            "normal memory: 'amplitudes' has " +
              std::to_string(amplitudes.size()) +
              " values and 'relaxation times' " +
              std::to_string(relaxation_times.size()) +
              "; give one amplitude per term.");
  }
} // namespace hemicontact
