#include "python/arrays.h"

#include <string>

namespace gps::python {

DoubleArray rows_to_array(const std::vector<Vec3>& rows) {
  DoubleArray a({py::ssize_t(rows.size()), py::ssize_t(3)});
  auto r = a.mutable_unchecked<2>();
  for (size_t i = 0; i < rows.size(); ++i)
    for (int k = 0; k < 3; ++k) r(py::ssize_t(i), k) = rows[i][k];
  return a;
}

std::vector<Vec3> array_to_rows(const DoubleArray& array, const char* what) {
  if (array.ndim() != 2 || array.shape(1) != 3) throw py::value_error(std::string(what) + ": expected an n x 3 array");
  auto r = array.unchecked<2>();
  std::vector<Vec3> rows(size_t(array.shape(0)));
  for (size_t i = 0; i < rows.size(); ++i)
    rows[i] = Vec3(r(py::ssize_t(i), 0), r(py::ssize_t(i), 1), r(py::ssize_t(i), 2));
  return rows;
}

DoubleArray matrices_to_array(const std::vector<Mat3>& matrices) {
  DoubleArray a({py::ssize_t(matrices.size()), py::ssize_t(3), py::ssize_t(3)});
  auto r = a.mutable_unchecked<3>();
  for (size_t i = 0; i < matrices.size(); ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r(py::ssize_t(i), j, k) = matrices[i](j, k);
  return a;
}

std::vector<Mat3> array_to_matrices(const DoubleArray& array, const char* what) {
  if (array.ndim() != 3 || array.shape(1) != 3 || array.shape(2) != 3)
    throw py::value_error(std::string(what) + ": expected an n x 3 x 3 array");
  auto r = array.unchecked<3>();
  std::vector<Mat3> matrices(size_t(array.shape(0)));
  for (size_t i = 0; i < matrices.size(); ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) matrices[i](j, k) = r(py::ssize_t(i), j, k);
  return matrices;
}

py::array_t<int> triangles_to_array(const std::vector<std::array<int, 3>>& triangles) {
  py::array_t<int> a({py::ssize_t(triangles.size()), py::ssize_t(3)});
  auto r = a.mutable_unchecked<2>();
  for (size_t i = 0; i < triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) r(py::ssize_t(i), k) = triangles[i][size_t(k)];
  return a;
}

std::vector<double> broadcast(const DoubleArray& values, size_t n, const char* what) {
  if (values.ndim() == 0) return std::vector<double>(n, *values.data());
  if (values.ndim() != 1 || size_t(values.shape(0)) != n)
    throw py::value_error(std::string(what) + ": expected a number or an array of " + std::to_string(n));
  return std::vector<double>(values.data(), values.data() + n);
}

}  // namespace gps::python
