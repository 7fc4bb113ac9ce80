#pragma once

#include <hemicontact/expressions/expression.h>

#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

namespace hemicontact
{
  /**
   * Several expressions in the same variables compiled into one list of
   * instructions in which every common subexpression appears once, and
   * evaluated in doubles in one pass: the derivatives of a manufactured
   * solution share most of their terms (sin(t), the cut-offs, ...), so one
   * pass over the list costs a fraction of evaluating each tree.
   */
  class ExpressionTape
  {
  public:
    /**
     * Compile @p expressions (which need not outlive the tape). The
     * @p uniform_variables (e.g. the time) are the same at all points of a
     * batch: what depends only on them is computed once per batch.
     */
    explicit ExpressionTape(
      const std::vector<const Expression *> &expressions,
      const std::vector<unsigned int>       &uniform_variables = {});

    /**
     * The values of the expressions, in the order given to the
     * constructor, at @p variables.
     */
    void
    evaluate(const std::vector<double> &variables,
             std::vector<double>       &results) const;

    /**
     * The values at @p n_points points at once: the point p has the
     * variables variables[p n_variables + v] and gets the results
     * results[p n_outputs + k]. Each instruction is decoded once per batch,
     * so a batch costs less than its points one by one.
     */
    void
    evaluate(const double      *variables,
             const unsigned int n_variables,
             const unsigned int n_points,
             double            *results) const;

    /**
     * The values, at each of @p n_points points, that depend on no uniform
     * variable and that evaluate_cached() reads: n_cached() per point,
     * stored as spatial[k n_points + p]. They are the same at every time.
     */
    void
    evaluate_spatial(const double      *variables,
                     const unsigned int n_variables,
                     const unsigned int n_points,
                     double            *spatial) const;

    /**
     * evaluate() at points whose evaluate_spatial() values are @p spatial:
     * only what depends on the uniform variables is computed. The results
     * are the same bits as evaluate()'s.
     */
    void
    evaluate_cached(const double      *variables,
                    const unsigned int n_variables,
                    const unsigned int n_points,
                    const double      *spatial,
                    double            *results) const;

    /** The number of values per point evaluate_spatial() returns. */
    unsigned int
    n_cached() const
    {
      return n_cached_values;
    }

    /** Whether variable @p v is uniform (the same at all points). */
    bool
    is_uniform_variable(const unsigned int v) const;

    /** The number of expressions (results per point). */
    unsigned int
    n_outputs() const
    {
      return outputs.size();
    }

    /** The number of instructions (distinct subexpressions). */
    unsigned int
    size() const
    {
      return code.size();
    }

  private:
    enum class Op : unsigned char
    {
      constant,
      variable,
      negate,
      add,
      subtract,
      multiply,
      divide,
      integer_power, ///< a^n, n = 2..8, by multiplication as Expression
      function       ///< Expression::Function
    };

    struct Instruction
    {
      Op                   op;
      Expression::Function function = Expression::Function::sin;
      unsigned int         a = 0, b = 0, c = 0; ///< operand instructions
      unsigned int         n     = 0; ///< variable index or integer exponent
      double               value = 0; ///< constant
      unsigned int         n_operands = 0;
      /** Depends only on constants and uniform variables. */
      bool uniform = false;
      /** Depends on a uniform variable. */
      bool timed = false;
      /** Depends on a non-uniform variable and on no uniform one. */
      bool spatial = false;
      /** Its place among the evaluate_spatial() values, or -1. */
      int cached = -1;
    };

    /** Which instructions execute() runs. */
    enum class Pass
    {
      all,          ///< every instruction
      time_free,    ///< constants and spatial ones (evaluate_spatial())
      given_spatial ///< all but spatial ones, cached ones copied
    };

    /** Run the instructions of @p pass at @p n_points points. */
    double *
    execute(const double      *variables,
            const unsigned int n_variables,
            const unsigned int n_points,
            const Pass         pass,
            const double      *spatial) const;

    /** The results from the registers @p r of execute(). */
    void
    gather(const double *r, const unsigned int n_points, double *results) const;

    /** The instruction computing @p node, appended unless it exists. */
    unsigned int
    compile(const Expression::Node &node);

    unsigned int
    append(Instruction instruction);

    std::vector<Instruction>  code;
    std::vector<unsigned int> outputs;
    std::vector<unsigned int> uniform_variables;
    unsigned int              n_cached_values = 0;
    /** The instructions each Pass runs, in order. */
    std::vector<unsigned int> all_instructions, time_free_instructions,
      given_spatial_instructions;
    /** While compiling: the instruction of each (op, function, a, b, c,
     *  n, value bits) appended so far. */
    using Key = std::tuple<int,
                           int,
                           unsigned int,
                           unsigned int,
                           unsigned int,
                           unsigned int,
                           std::uint64_t>;
    std::map<Key, unsigned int> known;
  };
} // namespace hemicontact
