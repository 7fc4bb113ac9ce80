/**
 * The subsection 'normal memory': the kernel b(t) of the memory term of the
 * normal response (NormalMemoryParameters,
 * include/hemicontact/input/parameters.h).
 */
#include <hemicontact/input/kernel_subsection.h>
#include <hemicontact/input/parameters.h>

namespace hemicontact
{
  namespace
  {
    const KernelSubsection normal_memory = {
      "normal memory",
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
      "from 'b'; every past (u_nu)_+ is kept. Adapted meshes carry the "
      "history.",
      {{"amplitudes",
        "'kernel = prony': the amplitudes b_m of b(t) = "
        "sum_m b_m exp(-t/tau_m), comma-separated finite "
        "numbers, one per term of 'relaxation times'."}},
      {},
      {{"b",
        "'kernel = expression': b(t), a scalar expression "
        "(doc/parameters.md, Expressions) in t and the "
        "constants of 'data/constants'; it must be finite at "
        "t = k, 2k, ..., T (the rule never evaluates it at "
        "t = 0)."}},
      "'relaxation times' and 'amplitudes'",
      ""};
  } // namespace

  void
  NormalMemoryParameters::declare(ParameterHandler &prm)
  {
    normal_memory.declare(prm);
  }

  void
  NormalMemoryParameters::parse(ParameterHandler &prm)
  {
    const KernelSubsection::Values values = normal_memory.parse(prm);
    kernel                                = values.kernel;
    amplitudes                            = values.amplitudes[0];
    relaxation_times                      = values.relaxation_times;
    b                                     = values.expressions[0];
    if (kernel == MemoryKernelType::prony)
      normal_memory.require_terms(values);
  }
} // namespace hemicontact
