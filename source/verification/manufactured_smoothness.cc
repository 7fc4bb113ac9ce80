#include <deal.II/base/mpi.h>

#include <hemicontact/verification/manufactured_smoothness.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <sstream>

namespace hemicontact
{
  namespace
  {
    constexpr unsigned int max_cells = 32;
    /** Each path is bisected from this many equal pieces, so that a jump
     *  smaller than the smooth change over the whole path is still met. */
    constexpr unsigned int pieces     = 4;
    constexpr unsigned int bisections = 40;
    /** A field whose increment stays above this fraction of its size is
     *  taken to jump (a continuous one falls to about 2^-40 of it). */
    constexpr double jump_threshold = 1e-6;

    constexpr unsigned int n_fields              = 4;
    const char *const      field_names[n_fields] = {"u",
                                                    "w = du/dt",
                                                    "grad u",
                                                    "grad w"};

    /** The four fields of @p v flattened, per field. */
    template <int dim>
    std::array<std::vector<double>, n_fields>
    fields(const typename ManufacturedSolution<dim>::Values &v)
    {
      std::array<std::vector<double>, n_fields> f;
      for (unsigned int i = 0; i < dim; ++i)
        {
          f[0].push_back(v.u[i]);
          f[1].push_back(v.w[i]);
          for (unsigned int j = 0; j < dim; ++j)
            {
              f[2].push_back(v.grad_u[i][j]);
              f[3].push_back(v.grad_w[i][j]);
            }
        }
      return f;
    }

    double
    distance(const std::vector<double> &a, const std::vector<double> &b)
    {
      double d = 0;
      for (std::size_t i = 0; i < a.size(); ++i)
        d = std::max(d, std::abs(a[i] - b[i]));
      return d;
    }

    double
    size(const std::vector<double> &a)
    {
      double s = 0;
      for (const double x : a)
        s = std::max(s, std::abs(x));
      return s;
    }
  } // namespace

  template <int dim>
  std::string
  find_manufactured_jump(const ManufacturedSolution<dim> &exact,
                         const Triangulation<dim>        &mesh,
                         const double                     end_time,
                         MPI_Comm                         comm)
  {
    // the fields as functions of a parameter s in [0, 1] along a segment in
    // x (at a fixed t) or in t (at a fixed x)
    using Path = std::function<std::pair<Point<dim>, double>(double)>;
    std::vector<Path> paths;
    unsigned int      n_owned = 0;
    for (const auto &cell : mesh.active_cell_iterators())
      n_owned += cell->is_locally_owned();
    const unsigned int stride = std::max(1u, n_owned / max_cells);
    unsigned int       index  = 0;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned() && index++ % stride == 0)
        for (const unsigned int a : cell->vertex_indices())
          {
            const Point<dim> pa = cell->vertex(a);
            paths.push_back([pa, end_time](const double s) {
              return std::make_pair(pa, s * end_time);
            });
            for (const unsigned int b : cell->vertex_indices())
              if (b > a)
                for (const double t : {0., end_time / 2, end_time})
                  {
                    const Point<dim> pb = cell->vertex(b);
                    paths.push_back([pa, pb, t](const double s) {
                      return std::make_pair(Point<dim>(pa + s * (pb - pa)), t);
                    });
                  }
          }

    const auto at = [&](const Path &path, const double s) {
      const auto [p, t] = path(s);
      return fields<dim>(exact.evaluate_fields(p, t));
    };

    // the size of each field over the ends of every path
    std::array<double, n_fields> scale{};
    for (const Path &path : paths)
      for (const double s : {0., 1.})
        {
          const auto f = at(path, s);
          for (unsigned int i = 0; i < n_fields; ++i)
            scale[i] = std::max(scale[i], size(f[i]));
        }
    for (double &s : scale)
      s = Utilities::MPI::max(s, comm);

    std::string found;
    for (const Path &path : paths)
      {
        for (unsigned int i = 0; i < n_fields && found.empty(); ++i)
          {
            if (!(scale[i] > 0))
              continue;
            for (unsigned int piece = 0; piece < pieces && found.empty();
                 ++piece)
              {
                double lower = double(piece) / pieces,
                       upper = double(piece + 1) / pieces;
                auto f_lower = at(path, lower)[i], f_upper = at(path, upper)[i];
                for (unsigned int j = 0; j < bisections; ++j)
                  {
                    const double mid   = (lower + upper) / 2;
                    const auto   f_mid = at(path, mid)[i];
                    if (distance(f_lower, f_mid) >= distance(f_mid, f_upper))
                      {
                        upper   = mid;
                        f_upper = f_mid;
                      }
                    else
                      {
                        lower   = mid;
                        f_lower = f_mid;
                      }
                  }
                const double jump = distance(f_lower, f_upper) / scale[i];
                if (jump > jump_threshold || !std::isfinite(jump))
                  {
                    const auto [p, t] = path((lower + upper) / 2);
                    std::ostringstream where;
                    where << field_names[i] << " jumps by " << jump
                          << " of its size near x = (" << p << "), t = " << t;
                    found = where.str();
                  }
              }
          }
        if (!found.empty())
          break;
      }
    for (const std::string &message : Utilities::MPI::all_gather(comm, found))
      if (!message.empty())
        return message;
    return "";
  }

  template std::string
  find_manufactured_jump<2>(const ManufacturedSolution<2> &,
                            const Triangulation<2> &,
                            const double,
                            MPI_Comm);
  template std::string
  find_manufactured_jump<3>(const ManufacturedSolution<3> &,
                            const Triangulation<3> &,
                            const double,
                            MPI_Comm);
} // namespace hemicontact
