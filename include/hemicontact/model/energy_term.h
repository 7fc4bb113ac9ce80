#pragma once

#include <string>
#include <vector>

namespace hemicontact
{
  /**
   * What a coupled field's energy term is in the energy identity
   * (doc/theory.md 13.4): the defect, the energy put in and the stored
   * energy are summed from the terms by their roles, so that a field adds
   * terms without a line in the balance.
   */
  enum class EnergyRole
  {
    /** Held by the field at t_n (in the total energy E_n). */
    stored,
    /** Removed by the field's own dissipation (added to the defect). */
    dissipated,
    /** Put in by the field's data (subtracted, and in data_energy()). */
    supplied,
    /** Moved from the mechanical step to the field (subtracted). */
    coupling,
    /**
     * The field's load's share of external_work: moved from the field to
     * the body's motion, so not energy put in (taken out of data_energy()).
     */
    converted,
    /** Booked for the output only (a part of another term). */
    reported
  };

  /** A coupled field's energy term: its checkpoint name, its steps.csv
   *  column (empty: none) and its role. */
  struct EnergyTermSpec
  {
    std::string name;
    std::string column;
    EnergyRole  role;
  };

  /**
   * The energy terms of every coupled field the program knows, in the
   * order of the field registry (fields/coupled_field_registry.cc): the
   * terms of EnergyBalance::coupled, its checkpoint names after the
   * mechanical terms and its steps.csv columns. A field's terms are there
   * whether the run enables it or not (zero then), so that every run
   * writes the same columns; a field added later appends its terms, and a
   * checkpoint without them resumes with their sums from zero.
   */
  const std::vector<EnergyTermSpec> &
  coupled_energy_terms();
} // namespace hemicontact
