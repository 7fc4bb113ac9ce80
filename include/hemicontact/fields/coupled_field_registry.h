#pragma once

#include <hemicontact/coupling/coupled_fields.h>
#include <hemicontact/input/parameters.h>
#include <hemicontact/model/problem_data.h>

#include <string>
#include <vector>

namespace hemicontact
{
  /** What the registry hands a coupled field's factory. */
  template <int dim>
  struct CoupledFieldContext
  {
    const Parameters &parameters;
    /** The run's class is static (the fields are data there, or absent). */
    bool static_class;
    /** The data derived by a manufactured solution (else the entries'). */
    const ProblemData<dim> &data;
    MPI_Comm                comm;
  };

  /**
   * Add to @p coupled every coupled field that @p context's parameters
   * enable, in the registry's order, each with its field in @p fields
   * (its name checked against @p reserved and the others').
   */
  template <int dim>
  void
  create_coupled_fields(const CoupledFieldContext<dim> &context,
                        const bool                      simplex,
                        AddedFields<dim>               &fields,
                        const std::vector<std::string> &reserved,
                        CoupledFields<dim>             &coupled);
} // namespace hemicontact
