/**
 * What the parts of one solution write cost: on the meshes of the default
 * 2D example (prm/block_2d.prm, 4 x 1 cells refined r times), a DataOut with
 * the fields the program writes (w, u and the contact traction as vectors,
 * two branch indicators, four stress fields and two cell indicators) is
 * built, written as VTU (zlib 'best speed') and as HDF5, and freed. Every
 * part is timed on its own, fastest of five, one process:
 *
 *   add     add_data_vector of the fields (main thread in the program)
 *   patches build_patches (writer thread)
 *   vtu     write_vtu to a file (writer thread)
 *   filter  write_filtered_data: the HDF5 layout (writer thread)
 *   h5      write_hdf5_parallel of that layout (main thread, collective)
 *   free    freeing the HDF5 layout and the patches (writer thread)
 *
 *   cmake -S bench/write_cost -B build-write-cost -DCMAKE_BUILD_TYPE=Release
 *   cmake --build build-write-cost && build-write-cost/write_cost 4 5 6
 *
 * Prints one CSV line per refinement, in milliseconds (doc/performance.md,
 * "Limits and open targets").
 */
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <string>

using namespace dealii;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << "refinement,cells,dofs,add_ms,patches_ms,vtu_ms,filter_ms,"
               "h5_ms,free_ms\n";
  for (int a = 1; a < argc; ++a)
    {
      const unsigned int                      r = std::stoi(argv[a]);
      parallel::distributed::Triangulation<2> mesh(MPI_COMM_WORLD);
      GridGenerator::subdivided_hyper_rectangle(mesh,
                                                {4, 1},
                                                Point<2>(0, 0),
                                                Point<2>(4, 1));
      mesh.refine_global(r);
      DoFHandler<2> dof_handler(mesh);
      dof_handler.distribute_dofs(FESystem<2>(FE_Q<2>(1), 2));

      Vector<double> field(dof_handler.n_dofs());
      for (unsigned int i = 0; i < field.size(); ++i)
        field[i] = std::sin(0.1 * i);
      Vector<float> cell_field(mesh.n_active_cells());
      for (unsigned int i = 0; i < cell_field.size(); ++i)
        cell_field[i] = std::cos(0.1 * i);

      std::map<std::string, double> fastest;
      auto record = [&](const std::string &part, Timer &timer) {
        const double ms = 1e3 * timer.wall_time();
        fastest[part] = fastest.count(part) ? std::min(fastest[part], ms) : ms;
        timer.restart();
      };
      for (unsigned int repeat = 0; repeat < 5; ++repeat)
        {
          Timer timer;
          auto  data_out = std::make_unique<DataOut<2>>();
          data_out->attach_dof_handler(dof_handler);
          const std::vector<
            DataComponentInterpretation::DataComponentInterpretation>
            vector(2, DataComponentInterpretation::component_is_part_of_vector),
            scalars(2, DataComponentInterpretation::component_is_scalar);
          for (const std::string name :
               {"velocity", "displacement", "contact_traction"})
            data_out->add_data_vector(field,
                                      std::vector<std::string>(2, name),
                                      DataOut<2>::type_dof_data,
                                      vector);
          data_out->add_data_vector(
            field,
            std::vector<std::string>{"normal_branch", "tangential_branch"},
            DataOut<2>::type_dof_data,
            scalars);
          for (const std::string name : {"stress_xx",
                                         "stress_xy",
                                         "stress_yy",
                                         "von_mises",
                                         "subdomain",
                                         "level"})
            data_out->add_data_vector(cell_field,
                                      name,
                                      DataOut<2>::type_cell_data);
          record("add", timer);

          data_out->build_patches();
          record("patches", timer);

          DataOutBase::VtkFlags flags;
          // the enumerator of deal.II 9.4's and 9.6's compression types
          flags.compression_level =
            decltype(flags.compression_level)::best_speed;
          data_out->set_flags(flags);
          {
            std::ofstream vtu("write_cost.vtu");
            data_out->write_vtu(vtu);
          }
          record("vtu", timer);

          auto filter = std::make_unique<DataOutBase::DataOutFilter>(
            DataOutBase::DataOutFilterFlags(/*filter_duplicates=*/false,
                                            /*xdmf_hdf5_output=*/true));
          data_out->write_filtered_data(*filter);
          record("filter", timer);

          data_out->write_hdf5_parallel(*filter,
                                        "write_cost.h5",
                                        MPI_COMM_WORLD);
          record("h5", timer);

          filter.reset();
          data_out.reset();
          record("free", timer);
        }
      std::cout << r << "," << mesh.n_active_cells() << ","
                << dof_handler.n_dofs();
      for (const std::string part :
           {"add", "patches", "vtu", "filter", "h5", "free"})
        std::cout << "," << fastest[part];
      std::cout << std::endl;
    }
}
