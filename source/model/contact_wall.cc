#include <hemicontact/model/contact_wall.h>

namespace hemicontact
{
  template <int dim>
  void
  set_wall_limits(std::vector<ContactNode<dim>>       &nodes,
                  const NormalLaw                     &law,
                  const TrilinosWrappers::MPI::Vector *displacement,
                  const double                         time_step,
                  const TrilinosWrappers::MPI::Vector *wear)
  {
    const double g = law.penetration_limit();
    for (ContactNode<dim> &node : nodes)
      {
        // the wear depth omega moves the foundation away (section 11.12)
        const double wall = wall_position(g, node, wear);
        node.upper_limit  = wall;
        node.law_offset =
          displacement == nullptr ? wear_depth_at(node, wear) : 0.;
        if (displacement != nullptr && std::isfinite(g))
          {
            double u_nu = 0;
            for (unsigned int c = 0; c < dim; ++c)
              u_nu += (*displacement)[node.dofs[c]] * node.normal[c];
            node.upper_limit = (wall - u_nu) / time_step;
          }
      }
  }

  template void
  set_wall_limits(std::vector<ContactNode<2>> &,
                  const NormalLaw &,
                  const TrilinosWrappers::MPI::Vector *,
                  const double,
                  const TrilinosWrappers::MPI::Vector *);
  template void
  set_wall_limits(std::vector<ContactNode<3>> &,
                  const NormalLaw &,
                  const TrilinosWrappers::MPI::Vector *,
                  const double,
                  const TrilinosWrappers::MPI::Vector *);
} // namespace hemicontact
