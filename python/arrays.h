#pragma once
// Conversions between numpy arrays and the core's Eigen vectors and matrices (copies, float64).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <vector>

#include "core/mesh/linalg.h"

namespace gps::python {

namespace py = pybind11;
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// An n x 3 array of rows (points or vectors).
DoubleArray rows_to_array(const std::vector<Vec3>& rows);
/// The rows of an n x 3 array; a ValueError naming `what` for any other shape.
std::vector<Vec3> array_to_rows(const DoubleArray& array, const char* what);
/// An n x 3 x 3 array of symmetric matrices.
DoubleArray matrices_to_array(const std::vector<Mat3>& matrices);
/// The matrices of an n x 3 x 3 array; a ValueError naming `what` for any other shape.
std::vector<Mat3> array_to_matrices(const DoubleArray& array, const char* what);
/// An m x 3 array of vertex indices.
py::array_t<int> triangles_to_array(const std::vector<std::array<int, 3>>& triangles);
/// A 1D array of `n` values broadcast from a scalar or taken from an array of n (ValueError otherwise).
std::vector<double> broadcast(const DoubleArray& values, size_t n, const char* what);

}  // namespace gps::python
