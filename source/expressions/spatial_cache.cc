#include <hemicontact/expressions/spatial_cache.h>

namespace hemicontact
{
  SpatialCache::SpatialCache(const ExpressionTape &tape,
                             const std::size_t     max_bytes)
    : tape(tape)
    , max_bytes(max_bytes)
  {}

  bool
  SpatialCache::same_points(const Batch       &batch,
                            const double      *variables,
                            const unsigned int n_variables,
                            const unsigned int n_points) const
  {
    const std::size_t n = point_variables.size();
    if (batch.size() != (n + tape.n_cached()) * n_points)
      return false;
    for (unsigned int p = 0; p < n_points; ++p)
      for (std::size_t i = 0; i < n; ++i)
        if (batch[p * n + i] !=
            variables[std::size_t(p) * n_variables + point_variables[i]])
          return false;
    return true;
  }

  void
  SpatialCache::evaluate(const double      *variables,
                         const unsigned int n_variables,
                         const unsigned int n_points,
                         double            *results)
  {
    std::unique_lock<std::mutex> lock(mutex, std::try_to_lock);
    if (!lock.owns_lock() || n_points == 0)
      {
        tape.evaluate(variables, n_variables, n_points, results);
        return;
      }

    if (point_variables.size() + uniform_variables.size() != n_variables)
      {
        point_variables.clear();
        uniform_variables.clear();
        for (unsigned int v = 0; v < n_variables; ++v)
          (tape.is_uniform_variable(v) ? uniform_variables : point_variables)
            .push_back(v);
        batches.clear();
        bytes = 0;
        next  = 0;
      }

    // a new pass: keep the batches the previous one visited
    bool new_pass = pass.size() != uniform_variables.size();
    for (std::size_t i = 0; i < uniform_variables.size() && !new_pass; ++i)
      new_pass = pass[i] != variables[uniform_variables[i]];
    if (new_pass)
      {
        for (std::size_t b = next; b < batches.size(); ++b)
          bytes -= batches[b].size() * sizeof(double);
        batches.resize(std::min(next, batches.size()));
        pass.clear();
        for (const unsigned int v : uniform_variables)
          pass.push_back(variables[v]);
        next = 0;
      }

    const std::size_t at = next++;
    if (at < batches.size() &&
        same_points(batches[at], variables, n_variables, n_points))
      {
        ++hits;
        tape.evaluate_cached(variables,
                             n_variables,
                             n_points,
                             batches[at].data() +
                               point_variables.size() * n_points,
                             results);
        return;
      }

    Batch batch;
    for (unsigned int p = 0; p < n_points; ++p)
      for (const unsigned int v : point_variables)
        batch.push_back(variables[std::size_t(p) * n_variables + v]);
    const std::size_t n_coordinates = batch.size();
    batch.resize(n_coordinates + std::size_t(tape.n_cached()) * n_points);
    double *const spatial = batch.data() + n_coordinates;
    tape.evaluate_spatial(variables, n_variables, n_points, spatial);
    tape.evaluate_cached(variables, n_variables, n_points, spatial, results);

    const std::size_t size = batch.size() * sizeof(double);
    if (at < batches.size())
      {
        bytes -= batches[at].size() * sizeof(double);
        if (bytes + size <= max_bytes)
          {
            batches[at] = std::move(batch);
            bytes += size;
          }
        else // drop the stale batch and keep the pass aligned
          batches[at] = Batch();
      }
    else if (at == batches.size() && bytes + size <= max_bytes)
      {
        batches.push_back(std::move(batch));
        bytes += size;
      }
  }

  std::size_t
  SpatialCache::memory_consumption() const
  {
    return bytes;
  }
} // namespace hemicontact
