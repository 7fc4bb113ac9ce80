// SpatialCache: a tape evaluated through the cache at batches of points
// revisited at several times gives the same bits as ExpressionTape::evaluate()
// and computes the spatial part only once per batch; a changed batch (a new
// mesh), a batch of another loop at the same time, a cache too small for a
// batch and callers on two threads at once still get the same bits.
#include <hemicontact/expressions/expression.h>
#include <hemicontact/expressions/expression_tape.h>
#include <hemicontact/expressions/spatial_cache.h>

#include <cmath>
#include <thread>

#include "tests.h"

using namespace hemicontact;

namespace
{
  /** Batches of 4 points (x, y, t) at time @p t, shifted by @p shift. */
  std::vector<std::vector<double>>
  batches_at(const double t, const double shift = 0)
  {
    std::vector<std::vector<double>> batches;
    for (const double x0 : {0.05, 0.35, 0.65})
      {
        std::vector<double> at;
        for (const double dx : {0.0, 0.1})
          for (const double y : {0.2, 0.7})
            at.insert(at.end(), {x0 + dx + shift, y, t});
        batches.push_back(at);
      }
    return batches;
  }

  /** Whether the cache gives the bits of the tape for @p batch. */
  bool
  same_bits(const ExpressionTape      &tape,
            SpatialCache              &cache,
            const std::vector<double> &batch)
  {
    const unsigned int  n_points = batch.size() / 3;
    std::vector<double> direct(n_points * tape.n_outputs()),
      cached(direct.size());
    tape.evaluate(batch.data(), 3, n_points, direct.data());
    cache.evaluate(batch.data(), 3, n_points, cached.data());
    return direct == cached;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::vector<std::string>           variables = {"x", "y", "t"};
  const std::map<std::string, double>      constants = {{"A", 4}, {"pi", M_PI}};
  // a manufactured displacement and its derivatives, and terms mixing x
  // and t inside functions
  const Expression        u("(1-y)*A*pos(x-0.4)^3*sin(t) + "
                            "0.2*y*(1-y)*sin(pi*x)*t^2 - exp(-t*x)*cos(2*y)",
                     variables,
                     constants,
                     "test");
  std::vector<Expression> derived;
  derived.push_back(u.derivative(2));
  derived.push_back(derived[0].derivative(2));
  for (unsigned int i = 0; i < 2; ++i)
    {
      derived.push_back(u.derivative(i));
      derived.push_back(derived[0].derivative(i));
    }
  std::vector<const Expression *> all = {&u};
  for (const Expression &e : derived)
    all.push_back(&e);
  const ExpressionTape tape(all, /*uniform_variables=*/{2});
  out() << "values per point kept by the cache fewer than instructions: "
        << (tape.n_cached() > 0 && tape.n_cached() < tape.size() ? "yes" : "NO")
        << "\n";

  {
    SpatialCache cache(tape);
    bool         equal = true;
    for (const double t : {0.1, 0.2, 0.3})
      for (const auto &batch : batches_at(t))
        equal = equal && same_bits(tape, cache, batch);
    out() << "three passes of three batches: same bits "
          << (equal ? "yes" : "NO") << ", batches found in the cache "
          << cache.n_hits() << "\n";

    // a new mesh: the middle batch moves
    const auto moved = [](const double t) {
      std::vector<std::vector<double>> batches = batches_at(t);
      batches[1]                               = batches_at(t, 0.01)[1];
      return batches;
    };
    const std::size_t hits = cache.n_hits();
    for (const auto &batch : moved(0.4))
      equal = equal && same_bits(tape, cache, batch);
    out() << "a moved batch: same bits " << (equal ? "yes" : "NO") << ", found "
          << cache.n_hits() - hits << " of 3\n";
    const std::size_t after_move = cache.n_hits();
    for (const auto &batch : moved(0.5))
      equal = equal && same_bits(tape, cache, batch);
    out() << "the next pass: same bits " << (equal ? "yes" : "NO") << ", found "
          << cache.n_hits() - after_move << " of 3\n";

    // another loop at the same time as the last pass, with other points
    const std::size_t before_other = cache.n_hits();
    equal = equal && same_bits(tape, cache, moved(0.5)[0]) &&
            same_bits(tape, cache, batches_at(0.5, 0.02)[0]);
    out() << "another loop at the same time: same bits "
          << (equal ? "yes" : "NO") << ", found "
          << cache.n_hits() - before_other << "\n";
  }

  {
    SpatialCache too_small(tape, /*max_bytes=*/0);
    bool         equal = true;
    for (const double t : {0.1, 0.2})
      for (const auto &batch : batches_at(t))
        equal = equal && same_bits(tape, too_small, batch);
    out() << "a cache of 0 bytes: same bits " << (equal ? "yes" : "NO")
          << ", found " << too_small.n_hits() << ", bytes "
          << too_small.memory_consumption() << "\n";
  }

  {
    SpatialCache             shared(tape);
    std::vector<char>        equal(2, 1);
    std::vector<std::thread> threads;
    for (unsigned int i = 0; i < 2; ++i)
      threads.emplace_back([&, i]() {
        for (unsigned int step = 1; step <= 200; ++step)
          for (const auto &batch : batches_at(0.01 * step))
            equal[i] = equal[i] && same_bits(tape, shared, batch);
      });
    for (std::thread &t : threads)
      t.join();
    out() << "two threads at once: same bits "
          << (equal[0] && equal[1] ? "yes" : "NO") << "\n";
  }
}
