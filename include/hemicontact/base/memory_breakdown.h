#pragma once

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <mpi.h>

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace hemicontact
{
  using namespace dealii;

  /** Bytes that malloc has handed out and not taken back (all arenas). */
  double
  heap_bytes_in_use();

  /** Peak resident set size of this process in bytes. */
  double
  peak_resident_bytes();

  /** Bytes of the value arrays of a Trilinos matrix (its graph excluded). */
  double
  matrix_value_bytes(const TrilinosWrappers::SparseMatrix &matrix);

  /** Bytes of the sparsity graph of a Trilinos matrix (indices, maps). */
  double
  matrix_graph_bytes(const TrilinosWrappers::SparseMatrix &matrix);

  /**
   * The parts of a run's memory on this rank, by name: matrices (values,
   * and each sparsity graph once however many matrices share it), AMG
   * hierarchies, vectors, mesh and dofs. doc/performance.md shows one.
   */
  class MemoryBreakdown
  {
  public:
    /** Add @p bytes to the part @p name (a new part at the end). */
    void
    add(const std::string &name, const double bytes);

    /**
     * Add a matrix: its values as @p name, its graph as "sparsity graph"
     * unless a matrix added before shares it.
     */
    void
    add_matrix(const std::string                    &name,
               const TrilinosWrappers::SparseMatrix &matrix);

    /** Every part summed over the ranks of @p comm (collective). */
    std::vector<std::pair<std::string, double>>
    summed(MPI_Comm comm) const;

  private:
    std::vector<std::pair<std::string, double>> parts;
    std::set<const void *>                      graphs;
  };
} // namespace hemicontact
