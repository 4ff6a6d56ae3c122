#include "python/arrays.h"

#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <string>

namespace gps::python {

std::string shown_number(double v) { return py::str(py::float_(v)).cast<std::string>(); }

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
  for (size_t i = 0; i < rows.size(); ++i) {
    rows[i] = Vec3(r(py::ssize_t(i), 0), r(py::ssize_t(i), 1), r(py::ssize_t(i), 2));
    if (!rows[i].allFinite())
      throw py::value_error(std::string(what) + ": row " + std::to_string(i) + " is not finite");
  }
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

IntArray triangles_to_array(const std::vector<std::array<int, 3>>& triangles) {
  IntArray a({py::ssize_t(triangles.size()), py::ssize_t(3)});
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

IntArray int_array(const std::vector<int>& values) {
  IntArray a(py::ssize_t(values.size()));
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

DoubleArray double_array(const std::vector<double>& values) {
  DoubleArray a(py::ssize_t(values.size()));
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

namespace {

// The values of an integer array as int64, an unsigned one past int64's range refused with its own
// value (it would wrap to a negative number).
std::vector<int64_t> index_values(const py::array& array, const char* what) {
  if (array.dtype().kind() == 'u') {
    const auto values = py::array_t<uint64_t, py::array::c_style | py::array::forcecast>::ensure(array);
    std::vector<int64_t> out(size_t(values.size()));
    for (size_t i = 0; i < out.size(); ++i) {
      const uint64_t v = values.data()[i];
      if (v > uint64_t(std::numeric_limits<int64_t>::max()))
        throw py::index_error(std::string(what) + ": " + std::to_string(v) + " out of range");
      out[i] = int64_t(v);
    }
    return out;
  }
  const auto values = py::array_t<int64_t, py::array::c_style | py::array::forcecast>::ensure(array);
  return std::vector<int64_t>(values.data(), values.data() + values.size());
}

}  // namespace

std::vector<int> indices_of(const py::object& values, int end, const char* what) {
  const py::array array = py::array::ensure(values);
  if (!array) throw py::type_error(std::string(what) + ": expected an integer or an array of integers");
  if (array.size() == 0 && array.ndim() == 1) return {};  // [] is an array of float64 to numpy
  const char kind = array.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw py::type_error(std::string(what) + ": expected integers, got an array of " +
                         py::str(array.dtype()).cast<std::string>());
  if (array.ndim() > 1) throw py::value_error(std::string(what) + ": expected an integer or a 1D array");
  const std::vector<int64_t> wide = index_values(array, what);
  std::vector<int> out(wide.size());
  for (size_t i = 0; i < out.size(); ++i) {
    if (wide[i] < 0 || wide[i] >= end)
      throw py::index_error(std::string(what) + ": " + std::to_string(wide[i]) + " out of range 0.." +
                            std::to_string(int64_t(end) - 1));
    out[i] = int(wide[i]);
  }
  return out;
}

PolygonTopology faces_from(const py::object& faces) {
  PolygonTopology t;
  if (py::isinstance<py::array>(faces)) {
    const py::array array = faces.cast<py::array>();
    const char kind = array.dtype().kind();
    if (array.ndim() != 2 || (kind != 'i' && kind != 'u'))
      throw py::type_error("faces: expected an (n, k) integer array or a sequence of index sequences");
    const std::vector<int64_t> wide = index_values(py::array::ensure(array, py::array::c_style), "faces");
    const py::ssize_t rows = array.shape(0), columns = array.shape(1);
    for (py::ssize_t f = 0; f < rows; ++f) {
      for (py::ssize_t k = 0; k < columns; ++k) {
        const int64_t v = wide[size_t(f * columns + k)];
        if (v > std::numeric_limits<int>::max())
          throw py::index_error("faces: face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                                ", past the indices a mesh holds (up to " +
                                std::to_string(std::numeric_limits<int>::max()) + ")");
        t.verts.push_back(v < 0 ? -1 : int(v));  // negative: the mesh names the face
      }
      t.offsets.push_back(int(t.verts.size()));
    }
    return t;
  }
  if (py::isinstance<py::str>(faces) || !py::isinstance<py::sequence>(faces))
    throw py::type_error("faces: expected an (n, k) integer array or a sequence of index sequences");
  std::vector<std::vector<int>> lists;
  try {
    lists = faces.cast<std::vector<std::vector<int>>>();
  } catch (const py::cast_error&) {
    throw py::type_error("faces: expected an (n, k) integer array or a sequence of index sequences");
  }
  for (const auto& face : lists) {
    t.verts.insert(t.verts.end(), face.begin(), face.end());
    t.offsets.push_back(int(t.verts.size()));
  }
  return t;
}

IntArray faces_to_array(const PolygonTopology& faces) {
  const int k = faces.n_faces() == 0 ? 3 : faces.face_size(0);
  for (int f = 1; f < faces.n_faces(); ++f)
    if (faces.face_size(f) != k)
      throw py::value_error("faces: the mesh has faces of " + std::to_string(k) + " and " +
                            std::to_string(faces.face_size(f)) +
                            " vertices, which no (n, k) array holds: read face_offsets and face_indices");
  IntArray a({py::ssize_t(faces.n_faces()), py::ssize_t(k)});
  std::copy(faces.verts.begin(), faces.verts.end(), a.mutable_data());
  return a;
}

double positive_number(double value, const char* what) {
  if (!(std::isfinite(value) && value > 0))
    throw py::value_error(std::string(what) + ": expected a finite number above 0, got " + shown_number(value));
  return value;
}

double finite_number(double value, const char* what) {
  if (!std::isfinite(value))
    throw py::value_error(std::string(what) + ": expected a finite number, got " + shown_number(value));
  return value;
}

double number_in(double value, double lo, double hi, const char* what) {
  if (!(value >= lo && value <= hi))
    throw py::value_error(std::string(what) + ": expected a number from " + shown_number(lo) + " to " +
                          shown_number(hi) + ", got " + shown_number(value));
  return value;
}

std::string path_of(const py::object& path) {
  const py::object fspath = py::module_::import("os").attr("fspath");
  const py::object text = fspath(path);  // TypeError for anything but str, bytes and os.PathLike
  return text.cast<std::string>();
}

}  // namespace gps::python
