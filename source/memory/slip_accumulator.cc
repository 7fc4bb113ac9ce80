#include <deal.II/base/exceptions.h>

#include <hemicontact/memory/slip_accumulator.h>

#include <algorithm>

namespace hemicontact
{
  template <int dim>
  void
  SlipAccumulator<dim>::add(const std::vector<MemoryNode<dim>> &nodes,
                            const VectorType                   *unknown,
                            const VectorType                   *start,
                            const VectorType                   *traction,
                            const double                        k)
  {
    Assert(unknown != nullptr && (traction != nullptr || !by_pressure),
           ExcMessage(by_pressure ?
                        "the wear needs the unknown and the traction" :
                        "the slip needs the unknown"));
    for (const MemoryNode<dim> &node : nodes)
      {
        Tensor<1, dim> v;
        for (unsigned int c = 0; c < dim; ++c)
          v[c] = (*unknown)[node.dofs[c]];
        if (start != nullptr)
          for (unsigned int c = 0; c < dim; ++c)
            v[c] -= (*start)[node.dofs[c]] + k * foundation_velocity[c];
        else
          v -= foundation_velocity;
        const Tensor<1, dim> v_tau    = v - (v * node.normal) * node.normal;
        double               pressure = 1;
        if (by_pressure)
          {
            Tensor<1, dim> t;
            for (unsigned int c = 0; c < dim; ++c)
              t[c] = (*traction)[node.dofs[c]];
            pressure = std::max(t * node.normal, 0.);
          }
        // read, then set (not +=): the vector's last operation must be the
        // 'insert' its compress() names, which deal.II's debug library checks
        sum[node.dofs[0]] = sum[node.dofs[0]] + coefficient * (start ? 1. : k) *
                                                  pressure * v_tau.norm();
      }
    sum.compress(VectorOperation::insert);
  }

  template class SlipAccumulator<2>;
  template class SlipAccumulator<3>;
} // namespace hemicontact
