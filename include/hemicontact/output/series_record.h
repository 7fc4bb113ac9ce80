#pragma once

#include <string>
#include <utility>

namespace hemicontact
{
  /**
   * One step of the solution series file (solution.pvd or solution.xdmf):
   * its time and the file of the step, or for HDF5 output the XDMF grid
   * element of the step.
   */
  struct SeriesRecord
  {
    double time = 0;
    /** The .pvtu file (VTU output) or the .h5 file (HDF5 output). */
    std::string file;
    /** HDF5 output: the step's XDMF grid element; empty for VTU output. */
    std::string xdmf_grid;

    /** The record in a checkpoint: (time, .pvtu file or XDMF element). */
    std::pair<double, std::string>
    stored() const
    {
      return {time, xdmf_grid.empty() ? file : xdmf_grid};
    }

    /** The record of a checkpoint's stored() entry (an XDMF element starts
     *  with a space, a file name does not). */
    static SeriesRecord
    from_stored(const std::pair<double, std::string> &entry)
    {
      SeriesRecord record;
      record.time = entry.first;
      if (!entry.second.empty() && entry.second.front() == ' ')
        record.xdmf_grid = entry.second;
      else
        record.file = entry.second;
      return record;
    }
  };
} // namespace hemicontact
