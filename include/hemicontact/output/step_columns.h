#pragma once

#include <hemicontact/model/energy_balance.h>
#include <hemicontact/solver/step_statistics.h>

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace hemicontact
{
  /**
   * One column of steps.csv (doc/outputs.md): its name in the header and
   * what its cell holds, written from a step's statistics and the energy
   * balance after it (nothing: an empty cell).
   */
  struct StepColumn
  {
    std::string name;
    std::function<
      void(std::ostream &, const StepStatistics &, const EnergyBalance &)>
      write;
  };

  /** The columns of steps.csv, in their order: the one list of them. */
  const std::vector<StepColumn> &
  step_columns();

  /** The header line of steps.csv (with its newline). */
  std::string
  step_columns_header();

  /**
   * The row of @p stats and @p energy (with its newline), numbers with 12
   * significant digits.
   */
  std::string
  step_columns_row(const StepStatistics &stats, const EnergyBalance &energy);
} // namespace hemicontact
