/// \file
/// Vector and matrix types of the method, fixed-size and dimension-generic (Dim = 1 or 2).
#pragma once
#include <Eigen/Core>
#include <Eigen/LU>

namespace mpm {

/// A point, velocity or force in Dim dimensions.
template <int Dim> using Vector = Eigen::Matrix<double, Dim, 1>;
/// A second-order tensor (strain, stress, the LME Hessian J) in Dim dimensions.
template <int Dim> using Matrix = Eigen::Matrix<double, Dim, Dim>;

/// Names of the axes as they appear in scene keys and output headers.
inline const char* axis_name(int axis) { return axis == 0 ? "x" : axis == 1 ? "y" : "z"; }

}  // namespace mpm
