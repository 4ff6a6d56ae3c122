#include "python/arrays.h"

#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <new>
#include <string>

#include "core/mesh/covariance_mesh.h"

namespace gps::python {

std::string shown_number(double v) { return py::str(py::float_(v)).cast<std::string>(); }

py::array contiguous_array(const py::handle& object, const py::handle& dtype) {
  auto& api = py::detail::npy_api::get();
  PyObject* array = api.PyArray_FromAny_(
      object.ptr(), dtype.inc_ref().ptr(), 0, 0,  // takes the dtype's reference
      int(py::detail::npy_api::NPY_ARRAY_ENSUREARRAY_) | py::array::c_style | py::array::forcecast, nullptr);
  if (!array) {
    const bool out_of_memory = PyErr_ExceptionMatches(PyExc_MemoryError);
    PyErr_Clear();
    if (out_of_memory) throw std::bad_alloc();
  }
  return py::reinterpret_steal<py::array>(array);
}

DoubleArray rows_to_array(const std::vector<Vec3>& rows) {
  DoubleArray a({py::ssize_t(rows.size()), py::ssize_t(3)});
  auto r = a.mutable_unchecked<2>();
  for (size_t i = 0; i < rows.size(); ++i)
    for (int k = 0; k < 3; ++k) r(py::ssize_t(i), k) = rows[i][k];
  return a;
}

namespace {

// `values` as a float64 array; a TypeError naming `what` where numpy cannot make one of it (ragged
// rows, text).
DoubleArray numbers_of(const py::handle& values, const char* what) {
  DoubleArray array = contiguous<double>(values);
  if (!array) throw py::type_error(std::string(what) + ": expected an array of numbers");
  return array;
}

}  // namespace

std::vector<Vec3> array_to_rows(const py::handle& values, const char* what) {
  const DoubleArray array = numbers_of(values, what);
  if (array.ndim() != 2 || array.shape(1) != 3) throw py::value_error(std::string(what) + ": expected an n x 3 array");
  auto r = array.unchecked<2>();
  std::vector<Vec3> rows(size_t(array.shape(0)));
  for (size_t i = 0; i < rows.size(); ++i) {
    rows[i] = Vec3(r(py::ssize_t(i), 0), r(py::ssize_t(i), 1), r(py::ssize_t(i), 2));
    if (!rows[i].allFinite())
      throw py::value_error(std::string(what) + ": row " + std::to_string(i) + " is not finite");
    if (const std::string problem = position_problem(rows[i]); !problem.empty())
      throw py::value_error(std::string(what) + ": row " + std::to_string(i) + " " + problem);
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

std::vector<Mat3> array_to_matrices(const py::handle& values, const char* what) {
  const DoubleArray array = numbers_of(values, what);
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

// The values of an integer array as int64 in C order, an unsigned one past int64's range refused with
// its own value (it would wrap to a negative number).
std::vector<int64_t> index_values(const py::array& array, const char* what) {
  if (array.dtype().kind() == 'u') {
    const auto values = contiguous<uint64_t>(array);
    std::vector<int64_t> out(size_t(values.size()));
    for (size_t i = 0; i < out.size(); ++i) {
      const uint64_t v = values.data()[i];
      if (v > uint64_t(std::numeric_limits<int64_t>::max()))
        throw py::index_error(std::string(what) + ": " + std::to_string(v) + " out of range");
      out[i] = int64_t(v);
    }
    return out;
  }
  const auto values = contiguous<int64_t>(array);
  return std::vector<int64_t>(values.data(), values.data() + values.size());
}

}  // namespace

std::vector<int> indices_of(const py::object& values, int end, const char* what) {
  const py::array array = contiguous_array(values, py::handle());
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
    const std::vector<int64_t> wide = index_values(array, "faces");
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

std::string path_of(const py::object& path, const char* what) {
  const py::object fsencode = py::module_::import("os").attr("fsencode");
  // TypeError for anything but str, bytes and os.PathLike.
  const std::string bytes = fsencode(path).cast<std::string>();
  if (bytes.find('\0') != std::string::npos) throw py::value_error(std::string(what) + ": embedded null byte");
  return bytes;
}

std::string shown_integer(const Integer& n) { return py::repr(n.value).cast<std::string>(); }

long long clamped(const Integer& n) {
  int overflow = 0;
  const long long value = PyLong_AsLongLongAndOverflow(n.value.ptr(), &overflow);
  return overflow > 0   ? std::numeric_limits<long long>::max()
         : overflow < 0 ? std::numeric_limits<long long>::min()
                        : value;
}

int int_in(const Integer& n, int lo, int hi, const char* what) {
  const long long value = clamped(n);
  if (value < lo || value > hi)
    throw py::value_error(std::string(what) + ": expected " + std::to_string(lo) + ".." + std::to_string(hi) +
                          ", got " + shown_integer(n));
  return int(value);
}

int to_int(const Integer& n, const char* what) {
  const long long value = clamped(n);
  if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max())
    throw py::value_error(std::string(what) + ": " + shown_integer(n) + " out of range");
  return int(value);
}

}  // namespace gps::python
