#pragma once

#include <hemicontact/expression.h>

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
      const std::vector<unsigned int> &      uniform_variables = {});

    /**
     * The values of the expressions, in the order given to the
     * constructor, at @p variables.
     */
    void
    evaluate(const std::vector<double> &variables,
             std::vector<double> &      results) const;

    /**
     * The values at @p n_points points at once: the point p has the
     * variables variables[p n_variables + v] and gets the results
     * results[p n_outputs + k]. Each instruction is decoded once per batch,
     * so a batch costs less than its points one by one.
     */
    void
    evaluate(const double *     variables,
             const unsigned int n_variables,
             const unsigned int n_points,
             double *           results) const;

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
      function       ///< Expression::function_names()[function_id]
    };

    struct Instruction
    {
      Op           op;
      int          function_id = -1;
      unsigned int a = 0, b = 0; ///< operand instructions
      unsigned int n = 0;        ///< variable index or integer exponent
      double       value = 0;    ///< constant
      unsigned int n_operands = 0;
      /** Depends only on constants and uniform variables. */
      bool uniform = false;
    };

    /** The instruction computing @p node, appended unless it exists. */
    unsigned int
    compile(const Expression::Node &node);

    unsigned int
    append(Instruction instruction);

    std::vector<Instruction>  code;
    std::vector<unsigned int> outputs;
    std::vector<unsigned int> uniform_variables;
    /** While compiling: the instruction of each (op, function, a, b, n,
     *  value bits) appended so far. */
    using Key = std::tuple<int, int, unsigned int, unsigned int, unsigned int,
                           std::uint64_t>;
    std::map<Key, unsigned int> known;
  };
} // namespace hemicontact
