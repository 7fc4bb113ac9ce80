#pragma once

#include <hemicontact/expressions/expression_tape.h>

#include <cstddef>
#include <mutex>
#include <vector>

namespace hemicontact
{
  /**
   * The spatial values of one ExpressionTape (evaluate_spatial()) at the
   * batches of points a loop evaluates at every time step, such as the
   * quadrature points of the cells when the load or the errors are computed:
   * at a later time only what depends on the time is computed again.
   *
   * A pass of the loop is the run of batches with the same uniform
   * variables (the time). A batch is looked up where it was in the previous
   * pass and used only if its points are exactly the same, so the results
   * are always the same bits as ExpressionTape::evaluate()'s; any other
   * batch (a new mesh, another loop at the same time) is computed in full
   * and remembered in that place. The values take at most @p max_bytes;
   * batches beyond are computed in full. Callers on several threads are
   * served one at a time from the cache, the others without it.
   */
  class SpatialCache
  {
  public:
    explicit SpatialCache(const ExpressionTape &tape,
                          std::size_t max_bytes = std::size_t(64) << 20);

    /** ExpressionTape::evaluate() of the batch, using the cache. */
    void
    evaluate(const double      *variables,
             const unsigned int n_variables,
             const unsigned int n_points,
             double            *results);

    /** The bytes of the remembered batches. */
    std::size_t
    memory_consumption() const;

    /** The number of batches found in the cache so far. */
    std::size_t
    n_hits() const
    {
      return hits;
    }

  private:
    /** The non-uniform variables of a batch's points, then their
     *  evaluate_spatial() values (one block: one cache miss less). */
    using Batch = std::vector<double>;

    /** Whether @p batch has the points of @p variables. */
    bool
    same_points(const Batch       &batch,
                const double      *variables,
                const unsigned int n_variables,
                const unsigned int n_points) const;

    const ExpressionTape &tape;
    const std::size_t     max_bytes;
    std::mutex            mutex;
    std::vector<Batch>    batches;
    /** The indices of the non-uniform and of the uniform variables. */
    std::vector<unsigned int> point_variables, uniform_variables;
    /** Where the next batch of the current pass is looked up. */
    std::size_t next = 0;
    /** The uniform variables of the current pass. */
    std::vector<double> pass;
    std::size_t         bytes = 0;
    std::size_t         hits  = 0;
  };
} // namespace hemicontact
