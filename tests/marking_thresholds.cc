// Unit test of the marking of adaptive refinement (marking_thresholds):
// the counts of both strategies, ties never split, and values perturbed by
// a relative 3e-7 (float round-off and solver tolerances, as between runs on
// 1 and 2 MPI ranks) marked exactly as the unperturbed ones, also where
// mirror-image pairs of equal values straddle the aimed cut.
#include <hemicontact/mesh/marking.h>

#include <cstdint>
#include <iostream>
#include <random>
#include <string>
#include <utility>
#include <vector>

using namespace hemicontact;

namespace
{
  struct Counts
  {
    unsigned int refine = 0, coarsen = 0;
  };

  Counts
  count(const std::vector<float> &v, const MarkingThresholds &t)
  {
    Counts c;
    for (const float x : v)
      {
        c.refine += (x > t.refine);
        c.coarsen += (x < t.coarsen);
      }
    return c;
  }

  /** 2n values in mirror-image pairs, each pair equal up to round-off. */
  std::vector<float>
  pairs(const unsigned int  n,
        const double        relative_perturbation,
        const std::uint32_t seed)
  {
    std::mt19937       random(seed);
    std::vector<float> v;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double x = 1e-3 * (1 + random() % 1000000); // 1e-3 ... 1e3
        const double s = (random() % 2 == 0 ? 1 : -1) * relative_perturbation;
        v.push_back(x);
        v.push_back(x * (1 + s));
      }
    return v;
  }
} // namespace

int
main()
{
  // distinct values 1..100: exact counts
  std::vector<float> v;
  for (unsigned int i = 1; i <= 100; ++i)
    v.push_back(i);
  Counts c =
    count(v, marking_thresholds(v, MarkingStrategy::fixed_number, 0.2, 0.3));
  std::cout << "fixed number 0.2/0.3 of 100 distinct: refine " << c.refine
            << ", coarsen " << c.coarsen << "\n";
  // sum 5050: the top 29 hold 2494 < 2525, the top 30 2565; the bottom 31
  // hold 496 <= 505, the bottom 32 528
  c =
    count(v, marking_thresholds(v, MarkingStrategy::fixed_fraction, 0.5, 0.1));
  std::cout << "fixed fraction 0.5/0.1 of 1..100: refine " << c.refine
            << ", coarsen " << c.coarsen << "\n";

  // a tie across the aimed cut moves it to the nearest untied place, the
  // one with fewer marked cells first
  v = {10, 9, 8, 8, 7, 6, 5, 4, 3, 2};
  c = count(v, marking_thresholds(v, MarkingStrategy::fixed_number, 0.3, 0.));
  std::cout << "tie at the refinement cut (aim 3): refine " << c.refine << "\n";
  v = {10, 9, 8, 7, 6, 5, 4, 3, 2, 2};
  c = count(v, marking_thresholds(v, MarkingStrategy::fixed_number, 0., 0.1));
  std::cout << "tie at the coarsening cut (aim 1): coarsen " << c.coarsen
            << "\n";
  v = std::vector<float>(10, 1.f);
  c = count(v, marking_thresholds(v, MarkingStrategy::fixed_number, 0.3, 0.3));
  std::cout << "all equal: refine " << c.refine << ", coarsen " << c.coarsen
            << "\n";

  // near-ties: pairs equal up to 3e-7 mark alike, and as exact pairs do
  for (const auto &[name, strategy] :
       {std::make_pair("fixed number", MarkingStrategy::fixed_number),
        std::make_pair("fixed fraction", MarkingStrategy::fixed_fraction)})
    {
      unsigned int split = 0, differ = 0;
      for (std::uint32_t seed = 1; seed <= 200; ++seed)
        {
          const std::vector<float> exact     = pairs(500, 0., seed);
          const std::vector<float> perturbed = pairs(500, 3e-7, seed);
          // fixed number: odd counts (201, 199), aimed inside a pair
          const bool   number = strategy == MarkingStrategy::fixed_number;
          const double r      = number ? 0.201 : 0.5;
          const double k      = number ? 0.199 : 0.02;
          const MarkingThresholds te =
            marking_thresholds(exact, strategy, r, k);
          const MarkingThresholds tp =
            marking_thresholds(perturbed, strategy, r, k);
          for (unsigned int i = 0; i < perturbed.size(); i += 2)
            {
              const auto flag = [](const float x, const MarkingThresholds &t) {
                return x > t.refine ? 1 : (x < t.coarsen ? -1 : 0);
              };
              split += flag(perturbed[i], tp) != flag(perturbed[i + 1], tp);
              differ += flag(perturbed[i], tp) != flag(exact[i], te);
            }
        }
      std::cout << name << ", 200 sets of 500 near-equal pairs: pairs "
                << "split " << split << ", cells marked unlike the exact "
                << "pairs " << differ << "\n";
    }
}
