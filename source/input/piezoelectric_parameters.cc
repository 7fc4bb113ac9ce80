/**
 * The subsection 'piezoelectricity': the electric potential, the
 * piezoelectric and dielectric constants, the electrodes, charges and the
 * electric contact law (PiezoelectricParameters,
 * include/hemicontact/input/parameters.h; doc/theory.md, section 14).
 */
#include <deal.II/base/tensor.h>

#include <hemicontact/base/exceptions.h>
#include <hemicontact/input/number_list.h>
#include <hemicontact/input/parameters.h>

#include <cmath>
#include <string>

namespace hemicontact
{
  void
  PiezoelectricParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("piezoelectricity");
    prm.declare_entry(
      "enabled",
      "false",
      Patterns::Bool(),
      "Whether the body carries an electric potential phi (doc/theory.md, "
      "section 14): sigma = A eps(w) + B eps(u) + E^T grad phi, D = E eps(u) "
      "- beta grad phi, div D = q_0. Each step solves phi_n from u_n (the "
      "electric step), then the mechanical step with -(grad phi_n, E "
      "eps(v)) on its right-hand side; with the implicit rule and in the "
      "static class the two alternate to the monolithic answer. phi is a "
      "field of the state: written, checkpointed and moved by adaptations.");
    prm.declare_entry(
      "piezoelectric constants",
      "0, 0, 0",
      Patterns::Anything(),
      "e_31, e_33, e_15 of a body poled along y (2D, plane strain: E_y,xx = "
      "e_31, E_y,yy = e_33, E_x,xy = E_x,yx = e_15) or z (3D: e_31 on "
      "E_z,xx and E_z,yy, e_33 on E_z,zz, e_15 on E_x,xz, E_y,yz and their "
      "symmetric entries); or the dim^3 entries E_kij in the order k, i, j "
      "(symmetric in i, j).");
    prm.declare_entry("permittivity",
                      "1",
                      Patterns::Anything(),
                      "beta: a number > 0, or the dim^2 entries of a "
                      "symmetric positive definite tensor (row by row).");
    prm.declare_entry("volume charge",
                      "0",
                      Patterns::Anything(),
                      "q_0(x, y[, z], t): div D = q_0.");
    prm.declare_entry(
      "electrode boundary ids",
      "",
      Patterns::List(Patterns::Integer(0, 255)),
      "Boundary ids where phi = 'electrode potential' (default: none; then "
      "a conductance > 0 on Gamma_3 makes phi unique).");
    prm.declare_entry("electrode potential",
                      "0",
                      Patterns::Anything(),
                      "phi_D(x, y[, z], t) on the electrode ids.");
    prm.declare_entry(
      "surface charge boundary ids",
      "",
      Patterns::List(Patterns::Integer(0, 255)),
      "Boundary ids where D.nu = 'surface charge' (elsewhere off Gamma_3 and "
      "the electrodes D.nu = 0).");
    prm.declare_entry("surface charge",
                      "0",
                      Patterns::Anything(),
                      "q_b(x, y[, z], t) on the surface charge ids.");
    prm.declare_entry(
      "conductance",
      "0",
      Patterns::Anything(),
      "p_e >= 0 of the electric contact law D.nu = p_e (phi - phi_F) on "
      "Gamma_3 (a conductive foundation): an expression in x, y[, z], t and "
      "u_nu, e.g. 10*pos(u_nu) (current only in contact).");
    prm.declare_entry("foundation potential",
                      "0",
                      Patterns::Anything(),
                      "phi_F(x, y[, z], t), the foundation's potential.");
    prm.declare_entry(
      "coupling tolerance",
      "1e-11",
      Patterns::Double(0),
      "With the implicit rule and in the static class: the relative change "
      "of (w_n, phi_n) between two passes of the electric and the mechanical "
      "step that ends their alternation (the monolithic answer).");
    prm.declare_entry(
      "coupling iterations",
      "100",
      Patterns::Integer(1),
      "The most passes of that alternation; a step that needs more is "
      "retried with k/2, as after a Newton failure.");
    prm.leave_subsection();
  }

  void
  PiezoelectricParameters::parse(ParameterHandler  &prm,
                                 const unsigned int dimension)
  {
    const std::string section = "piezoelectricity";
    prm.enter_subsection(section);
    enabled = prm.get_bool("enabled");
    piezoelectric_constants =
      get_number_list(prm, section, "piezoelectric constants");
    permittivity         = get_number_list(prm, section, "permittivity");
    volume_charge        = prm.get("volume charge");
    electrode_ids        = get_id_list(prm, "electrode boundary ids");
    electrode_potential  = prm.get("electrode potential");
    surface_charge_ids   = get_id_list(prm, "surface charge boundary ids");
    surface_charge       = prm.get("surface charge");
    conductance          = prm.get("conductance");
    foundation_potential = prm.get("foundation potential");
    coupling_tolerance   = prm.get_double("coupling tolerance");
    coupling_iterations  = prm.get_integer("coupling iterations");
    prm.leave_subsection();

    const unsigned int d = dimension;
    require(piezoelectric_constants.size() == 3 ||
              piezoelectric_constants.size() == d * d * d,
            "piezoelectricity: 'piezoelectric constants' holds " +
              std::to_string(piezoelectric_constants.size()) +
              " numbers; give e_31, e_33, e_15 (3) or the " +
              std::to_string(d * d * d) + " entries E_kij.");
    if (piezoelectric_constants.size() == d * d * d && d * d * d != 3)
      for (unsigned int k = 0; k < d; ++k)
        for (unsigned int i = 0; i < d; ++i)
          for (unsigned int j = i + 1; j < d; ++j)
            require(piezoelectric_constants[(k * d + i) * d + j] ==
                      piezoelectric_constants[(k * d + j) * d + i],
                    "piezoelectricity: 'piezoelectric constants' E_kij must "
                    "be symmetric in i and j (E_" +
                      std::to_string(k) + std::to_string(i) +
                      std::to_string(j) + " differs from E_" +
                      std::to_string(k) + std::to_string(j) +
                      std::to_string(i) + ").");
    require(permittivity.size() == 1 || permittivity.size() == d * d,
            "piezoelectricity: 'permittivity' holds " +
              std::to_string(permittivity.size()) +
              " numbers; give one (beta I) or the " + std::to_string(d * d) +
              " entries of a symmetric positive definite tensor.");
    // SPD: symmetric, and its leading minors positive
    bool spd = true;
    if (permittivity.size() == 1)
      spd = permittivity[0] > 0;
    else
      {
        const auto b = [&](unsigned int i, unsigned int j) {
          return permittivity[i * d + j];
        };
        for (unsigned int i = 0; i < d; ++i)
          for (unsigned int j = 0; j < d; ++j)
            spd = spd && b(i, j) == b(j, i);
        spd = spd && b(0, 0) > 0 && b(0, 0) * b(1, 1) - b(0, 1) * b(1, 0) > 0;
        if (d == 3)
          {
            Tensor<2, 3> t;
            for (unsigned int i = 0; i < 3; ++i)
              for (unsigned int j = 0; j < 3; ++j)
                t[i][j] = b(i, j);
            spd = spd && determinant(t) > 0;
          }
      }
    require(spd,
            "piezoelectricity: 'permittivity' must be a number > 0 or a "
            "symmetric positive definite tensor (the electric step is then "
            "an SPD problem); the entries given are not.");
    require(coupling_tolerance > 0,
            "piezoelectricity: 'coupling tolerance' must be positive.");
  }
} // namespace hemicontact
