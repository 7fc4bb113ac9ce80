#include <deal.II/base/mpi.h>

#include <hemicontact/base/memory_breakdown.h>

#include <Epetra_CrsGraph.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_Map.h>
#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>

namespace hemicontact
{
  double
  heap_bytes_in_use()
  {
    const struct mallinfo2 info = mallinfo2();
    return static_cast<double>(info.uordblks) +
           static_cast<double>(info.hblkhd);
  }

  double
  peak_resident_bytes()
  {
    rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    return 1024. * usage.ru_maxrss; // Linux reports kilobytes
  }

  double
  matrix_value_bytes(const TrilinosWrappers::SparseMatrix &matrix)
  {
    const Epetra_CrsMatrix &m = matrix.trilinos_matrix();
    // the values, one pointer and one allocated length per row
    return static_cast<double>(m.NumMyNonzeros()) * sizeof(double) +
           static_cast<double>(m.NumMyRows()) *
             (sizeof(double *) + sizeof(int));
  }

  double
  matrix_graph_bytes(const TrilinosWrappers::SparseMatrix &matrix)
  {
    const Epetra_CrsGraph &g = matrix.trilinos_matrix().Graph();
    // the column indices, per row a pointer, a count, an allocated count
    // and an offset, and the row, column and domain maps' global indices
    return static_cast<double>(g.NumMyNonzeros()) * sizeof(int) +
           static_cast<double>(g.NumMyRows()) *
             (sizeof(int *) + 3 * sizeof(int)) +
           static_cast<double>(g.RowMap().NumMyElements() +
                               g.ColMap().NumMyElements() +
                               g.DomainMap().NumMyElements()) *
             2 * sizeof(int);
  }

  void
  MemoryBreakdown::add(const std::string &name, const double bytes)
  {
    const auto it =
      std::find_if(parts.begin(), parts.end(), [&](const auto &part) {
        return part.first == name;
      });
    if (it == parts.end())
      parts.emplace_back(name, bytes);
    else
      it->second += bytes;
  }

  void
  MemoryBreakdown::add_matrix(const std::string                    &name,
                              const TrilinosWrappers::SparseMatrix &matrix)
  {
    if (matrix.m() == 0)
      {
        add(name, 0.);
        return;
      }
    add(name, matrix_value_bytes(matrix));
    const void *graph = matrix.trilinos_matrix().Graph().DataPtr();
    add("sparsity graph",
        graphs.insert(graph).second ? matrix_graph_bytes(matrix) : 0.);
  }

  std::vector<std::pair<std::string, double>>
  MemoryBreakdown::summed(MPI_Comm comm) const
  {
    std::vector<double> bytes;
    for (const auto &part : parts)
      bytes.push_back(part.second);
    Utilities::MPI::sum(bytes, comm, bytes);
    std::vector<std::pair<std::string, double>> result;
    for (unsigned int i = 0; i < parts.size(); ++i)
      result.emplace_back(parts[i].first, bytes[i]);
    return result;
  }
} // namespace hemicontact
