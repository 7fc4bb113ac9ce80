#include <hemicontact/model/contact_wall.h>

namespace hemicontact
{
  template <int dim>
  void
  set_wall_limits(std::vector<ContactNode<dim>>       &nodes,
                  const NormalLaw                     &law,
                  const TrilinosWrappers::MPI::Vector *displacement,
                  const double                         time_step)
  {
    const double g = law.penetration_limit();
    for (ContactNode<dim> &node : nodes)
      {
        node.upper_limit = g;
        if (displacement != nullptr && std::isfinite(g))
          {
            double u_nu = 0;
            for (unsigned int c = 0; c < dim; ++c)
              u_nu += (*displacement)[node.dofs[c]] * node.normal[c];
            node.upper_limit = (g - u_nu) / time_step;
          }
      }
  }

  template void
  set_wall_limits(std::vector<ContactNode<2>> &,
                  const NormalLaw &,
                  const TrilinosWrappers::MPI::Vector *,
                  const double);
  template void
  set_wall_limits(std::vector<ContactNode<3>> &,
                  const NormalLaw &,
                  const TrilinosWrappers::MPI::Vector *,
                  const double);
} // namespace hemicontact
