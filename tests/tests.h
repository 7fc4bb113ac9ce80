#pragma once
// Shared helpers of the hemicontact tests: output goes to stdout (captured
// by deal.II's run_test.sh) and only rank 0 prints.
#include <deal.II/base/mpi.h>

#include <iostream>

inline std::ostream &
out()
{
  static std::ostream null_stream(nullptr);
  return dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0 ?
           std::cout :
           null_stream;
}
