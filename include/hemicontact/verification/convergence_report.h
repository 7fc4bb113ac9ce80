#pragma once

#include <deal.II/base/convergence_table.h>

#include <hemicontact/input/parameters.h>
#include <hemicontact/verification/convergence_study.h>

#include <mpi.h>

#include <string>

namespace hemicontact
{
  using namespace dealii;

  /**
   * What a convergence study reports (doc/verification.md): the rows of
   * convergence.csv, the terminal's table of errors and orders, and the
   * branch shares of each level.
   */
  namespace convergence_report
  {
    /**
     * Check that convergence.csv can be written in the output directory
     * (created if needed) without touching an earlier study's file.
     */
    void
    require_writable_csv(const Parameters &parameters, MPI_Comm comm);

    /** The header of convergence.csv. */
    std::string
    csv_header();

    /** The row of level @p level with its result @p r. */
    std::string
    csv_row(const unsigned int level, const LevelResult &r);

    /** The shares of the contact branches over level @p level's steps. */
    void
    print_branch_shares(const unsigned int level, const LevelResult &r);

    /**
     * One row of the table; an adaptive study has the mean and maximum dofs
     * over the steps instead of the final mesh's.
     */
    void
    add_table_row(ConvergenceTable  &table,
                  const unsigned int level,
                  const LevelResult &r,
                  const bool         adaptive);

    /**
     * Formats and orders: log2 of the error ratio between levels, or
     * -log(error ratio) / log(mean dofs ratio) if @p against_dofs (the
     * table has the column "mean dofs"); the columns of the estimate
     * @p with_estimate, those of the time indicator @p with_time_estimate
     * and the temperature's @p with_temperature.
     */
    void
    format_table(ConvergenceTable  &table,
                 const unsigned int n_levels,
                 const bool         against_dofs,
                 const bool         with_estimate,
                 const bool         with_time_estimate,
                 const bool         with_temperature);
  } // namespace convergence_report
} // namespace hemicontact
