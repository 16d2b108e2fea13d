#include <deal.II/base/point.h>
#include <deal.II/base/utilities.h>

#include <fvfsi/base/exceptions.h>
#include <fvfsi/base/parsed_function.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace fvfsi
{
  using namespace dealii;

  template <int dim>
  void initialize_function(FunctionParser<dim>& f, const std::string& expression,
                           const std::string& parameter_name)
  {
    // `0` for a vector: the zero vector (a 2D default need not be re-set in a 3D case).
    std::string text = expression;
    if (f.n_components > 1 && Utilities::trim(expression) == "0")
    {
      text = "0";
      for (unsigned int c = 1; c < f.n_components; ++c)
        text += "; 0";
    }
    try
    {
      f.initialize(dim == 2 ? "x,y,t" : "x,y,z,t", text, {{"pi", numbers::PI}}, true);
      // muparser parses on first use: evaluate once so that a syntax error shows up here.
      for (unsigned int c = 0; c < f.n_components; ++c)
        f.value(Point<dim>(), c);
    }
    catch (const std::exception& e)
    {
      throw std::runtime_error(parameter_name + " = `" + expression +
                               "` is not a valid expression " + "of " +
                               (dim == 2 ? "x, y, t" : "x, y, z, t") + ": " + concise_message(e));
    }
  }

  template <int dim>
  double checked_value(const FunctionParser<dim>& f, const Point<dim>& point,
                       const unsigned int component, const std::string& parameter_name)
  {
    const double v = f.value(point, component);
    if (!(std::abs(v) <= max_input_value))
    {
      std::ostringstream message;
      message << parameter_name << " gives " << v << " (component " << component << ") at ("
              << point << "), t = " << f.get_time() << " s: values must be finite and within +-"
              << max_input_value;
      throw std::runtime_error(message.str());
    }
    return v;
  }

  template double checked_value(const FunctionParser<2>&, const Point<2>&, unsigned int,
                                const std::string&);
  template double checked_value(const FunctionParser<3>&, const Point<3>&, unsigned int,
                                const std::string&);
  template void initialize_function(FunctionParser<2>&, const std::string&, const std::string&);
  template void initialize_function(FunctionParser<3>&, const std::string&, const std::string&);
} // namespace fvfsi
