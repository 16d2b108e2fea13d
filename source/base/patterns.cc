#include <fvfsi/base/patterns.h>

#include <cmath>
#include <sstream>

namespace fvfsi
{
  PositiveDouble::PositiveDouble(const double max) : max(max) {}

  bool PositiveDouble::match(const std::string& text) const
  {
    // The real number (as Patterns::Double reads it), then nothing but blanks.
    std::istringstream in(text);
    double x;
    in >> x;
    if (in.fail())
      return false;
    std::string rest;
    in >> rest;
    return rest.empty() && std::isfinite(x) && x > 0 && x <= max;
  }

  std::string PositiveDouble::description(const OutputStyle) const
  {
    std::ostringstream text;
    text << "[Double 0 < x <= " << max << "]";
    return text.str();
  }

  std::unique_ptr<dealii::Patterns::PatternBase> PositiveDouble::clone() const
  {
    return std::make_unique<PositiveDouble>(max);
  }
} // namespace fvfsi
