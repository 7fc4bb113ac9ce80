/**
 * What a sparse direct solve would cost the 2D step: on the meshes of the
 * default 2D example (prm/block_2d.prm at 'global refinements' r), a matrix
 * with the sparsity pattern of the step matrix K0 (Q1 vector elements,
 * 100 M + 100 A) is factorised once by CHOLMOD (SuiteSparse) with the AMD
 * and nested-dissection orderings, and one solve by the factor is timed
 * against one iteration of CG preconditioned by Trilinos ML (smoothed
 * aggregation, vertex aggregates), in the same run. Fill, and so the cost
 * of a solve, depends only on the pattern and the ordering. The last column
 * is the dense Cholesky factorisation (LAPACK) of a symmetric positive
 * definite matrix of the size of the contact boundary's dofs (the bottom,
 * 2 (4 2^r + 1) dofs), which a Schur complement on the contact boundary
 * would need in every Newton iteration.
 *
 *   cmake -S bench/direct_solve_cost -B build-direct -DCMAKE_BUILD_TYPE=Release
 *   cmake --build build-direct && build-direct/direct_solve_cost 4 5 6
 *
 * Prints one CSV line per refinement and ordering (doc/performance.md,
 * "Alternatives measured").
 */
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/numerics/matrix_creator.h>

#include <suitesparse/cholmod.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using namespace dealii;

namespace
{
  constexpr unsigned int n_repeats = 20;

  /** The upper triangle of @p matrix as a CHOLMOD matrix (caller frees). */
  cholmod_sparse *
  to_cholmod(const SparseMatrix<double> &matrix, cholmod_common &common)
  {
    const int   n   = matrix.m();
    std::size_t nnz = 0;
    for (int row = 0; row < n; ++row)
      for (auto e = matrix.begin(row); e != matrix.end(row); ++e)
        nnz += (static_cast<int>(e->column()) <= row);
    // stype 1: the upper triangle by columns, i.e. the lower one by rows
    cholmod_sparse *result =
      cholmod_allocate_sparse(n, n, nnz, 1, 1, 1, CHOLMOD_REAL, &common);
    int        *start  = static_cast<int *>(result->p);
    int        *index  = static_cast<int *>(result->i);
    double     *values = static_cast<double *>(result->x);
    std::size_t k      = 0;
    for (int column = 0; column < n; ++column)
      {
        start[column] = k;
        std::vector<std::pair<int, double>> entries;
        for (auto e = matrix.begin(column); e != matrix.end(column); ++e)
          if (static_cast<int>(e->column()) <= column)
            entries.emplace_back(e->column(), e->value());
        std::sort(entries.begin(), entries.end());
        for (const auto &entry : entries)
          {
            index[k]    = entry.first;
            values[k++] = entry.second;
          }
      }
    start[n] = k;
    return result;
  }

  void
  measure(const unsigned int refinements)
  {
    Triangulation<2> mesh;
    GridGenerator::subdivided_hyper_rectangle(mesh,
                                              {4u, 1u},
                                              Point<2>(0, 0),
                                              Point<2>(4, 1));
    mesh.refine_global(refinements);
    const FESystem<2> fe(FE_Q<2>(1), 2);
    DoFHandler<2>     dof_handler(mesh);
    dof_handler.distribute_dofs(fe);

    DynamicSparsityPattern dsp(dof_handler.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler, dsp);
    SparsityPattern pattern;
    pattern.copy_from(dsp);
    SparseMatrix<double> matrix(pattern), stiffness(pattern);
    MatrixCreator::create_mass_matrix(dof_handler, QGauss<2>(2), matrix);
    MatrixCreator::create_laplace_matrix(dof_handler, QGauss<2>(2), stiffness);
    matrix *= 100.;
    matrix.add(100., stiffness);
    const unsigned int n = dof_handler.n_dofs();

    // AMG-preconditioned CG: seconds per iteration
    TrilinosWrappers::SparseMatrix trilinos_matrix;
    trilinos_matrix.reinit(matrix);
    TrilinosWrappers::PreconditionAMG                 amg;
    TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
    amg_data.elliptic              = true;
    amg_data.higher_order_elements = false;
    amg_data.smoother_sweeps       = 2;
    amg_data.aggregation_threshold = 1e-4;
    amg.initialize(trilinos_matrix, amg_data);
    TrilinosWrappers::MPI::Vector b(complete_index_set(n), MPI_COMM_SELF);
    TrilinosWrappers::MPI::Vector x(b);
    b = 1.;
    Timer        timer;
    unsigned int cg_iterations = 0;
    for (unsigned int r = 0; r < n_repeats; ++r)
      {
        x = 0.;
        SolverControl control(1000, 1e-10 * b.l2_norm());
        SolverCG<TrilinosWrappers::MPI::Vector> cg(control);
        cg.solve(trilinos_matrix, x, b, amg);
        cg_iterations = control.last_step();
      }
    const double cg_iteration_seconds =
      timer.wall_time() / n_repeats / cg_iterations;

    // the dense boundary factorisation
    const unsigned int       n_boundary = 2 * (4 * (1u << refinements) + 1);
    LAPACKFullMatrix<double> boundary(n_boundary, n_boundary);
    for (unsigned int i = 0; i < n_boundary; ++i)
      for (unsigned int j = 0; j < n_boundary; ++j)
        boundary(i, j) =
          (i == j ? n_boundary : 1. / (1. + std::abs(int(i) - int(j))));
    boundary.set_property(LAPACKSupport::symmetric);
    timer.restart();
    boundary.compute_cholesky_factorization();
    const double boundary_cholesky_seconds = timer.wall_time();

    const std::vector<std::pair<std::string, int>> orderings = {
      {"amd", CHOLMOD_AMD}, {"nested dissection", CHOLMOD_NESDIS}};
    for (const auto &ordering : orderings)
      {
        cholmod_common common;
        cholmod_start(&common);
        common.supernodal         = CHOLMOD_SIMPLICIAL;
        common.nmethods           = 1;
        common.method[0].ordering = ordering.second;
        cholmod_sparse *a         = to_cholmod(matrix, common);
        timer.restart();
        cholmod_factor *factor = cholmod_analyze(a, &common);
        cholmod_factorize(a, factor, &common);
        const double factor_seconds = timer.wall_time();

        cholmod_dense *rhs = cholmod_ones(n, 1, CHOLMOD_REAL, &common);
        timer.restart();
        for (unsigned int r = 0; r < n_repeats; ++r)
          {
            cholmod_dense *solution =
              cholmod_solve(CHOLMOD_A, factor, rhs, &common);
            cholmod_free_dense(&solution, &common);
          }
        const double solve_seconds = timer.wall_time() / n_repeats;
        std::cout << refinements << ',' << n << ',' << ordering.first << ','
                  << common.lnz << ',' << factor_seconds << ',' << solve_seconds
                  << ',' << cg_iterations << ',' << cg_iteration_seconds << ','
                  << solve_seconds / cg_iteration_seconds << ',' << n_boundary
                  << ',' << boundary_cholesky_seconds << std::endl;
        cholmod_free_dense(&rhs, &common);
        cholmod_free_factor(&factor, &common);
        cholmod_free_sparse(&a, &common);
        cholmod_finish(&common);
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << "refinements,dofs,ordering,nnz_factor,factor_s,solve_s,"
               "cg_iterations,cg_iteration_s,solve_over_cg_iteration,"
               "boundary_dofs,boundary_cholesky_s"
            << std::endl;
  for (int i = 1; i < argc; ++i)
    measure(std::stoi(argv[i]));
  return 0;
}
