#pragma once
// Patterns of .prm entries that deal.II does not have: a real number that must be strictly
// positive (a density, a modulus, a tolerance that can be met). Patterns::Double's bounds are
// inclusive, so that `Density = 0` would pass it and make NaN of the first time step.

#include <deal.II/base/patterns.h>

#include <memory>
#include <string>

namespace fvfsi
{
  /// A finite real number x with 0 < x <= max.
  class PositiveDouble : public dealii::Patterns::PatternBase
  {
  public:
    explicit PositiveDouble(double max);
    bool match(const std::string& text) const override;
    std::string description(OutputStyle style = Machine) const override;
    std::unique_ptr<dealii::Patterns::PatternBase> clone() const override;

  private:
    double max;
  };
} // namespace fvfsi
