#pragma once
// The convection schemes of fv/terms.h, in a header of their own so that parameter structs can name
// one without the terms.

namespace fvfsi
{
  /// The face value of a convected quantity: upwind (first order), or a higher-order value
  /// reached from it by a deferred correction (fvc::convection_correction).
  enum class ConvectionScheme
  {
    upwind,        ///< first order
    linear_upwind, ///< upwind value + its gradient times (r_f - r_U): second order
    central        ///< linear interpolation: second order, unbounded
  };
} // namespace fvfsi
