#pragma once
// Conversions between Python's arguments (numpy arrays, sequences, path-like objects) and the core's
// types. Arrays handed out are fresh float64 or int32 copies, read-only: writing to one raises
// instead of changing a copy nobody sees.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <string>
#include <vector>

#include "core/mesh/linalg.h"
#include "core/mesh/mesh_connectivity.h"

namespace gps::python {

namespace py = pybind11;
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
using IntArray = py::array_t<int32_t, py::array::c_style>;

/// `array`, made read-only.
template <class Array>
Array read_only(Array array) {
  array.attr("setflags")(py::arg("write") = false);
  return array;
}

/// `object` as a C-contiguous array of `dtype` (a null handle: of its own), converted or copied where it
/// is not one; a null array where numpy cannot convert it, std::bad_alloc (MemoryError) where the copy
/// does not fit in memory.
py::array contiguous_array(const py::handle& object, const py::handle& dtype);
/// contiguous_array() of T's dtype.
template <class T>
py::array_t<T, py::array::c_style | py::array::forcecast> contiguous(const py::handle& object) {
  return py::reinterpret_steal<py::array_t<T, py::array::c_style | py::array::forcecast>>(
      contiguous_array(object, py::dtype::of<T>()).release());
}

/// An n x 3 array of rows (points or vectors).
DoubleArray rows_to_array(const std::vector<Vec3>& rows);
/// The rows of an n x 3 array of points (or what numpy makes one of), finite and within
/// ±kMaxPositionMagnitude as a mesh's positions are; a TypeError or ValueError naming `what` (and the
/// row) otherwise.
std::vector<Vec3> array_to_rows(const py::handle& values, const char* what);
/// An n x 3 x 3 array of matrices.
DoubleArray matrices_to_array(const std::vector<Mat3>& matrices);
/// The matrices of an n x 3 x 3 array (or what numpy makes one of); a TypeError or ValueError naming
/// `what` for anything else.
std::vector<Mat3> array_to_matrices(const py::handle& values, const char* what);
/// An m x 3 array of vertex indices.
IntArray triangles_to_array(const std::vector<std::array<int, 3>>& triangles);
/// A 1D array of `n` values broadcast from a scalar or taken from an array of n (ValueError otherwise).
std::vector<double> broadcast(const DoubleArray& values, size_t n, const char* what);
/// A 1D int32 array of `values`.
IntArray int_array(const std::vector<int>& values);
/// A 1D float64 array of `values`.
DoubleArray double_array(const std::vector<double>& values);

/// The integers of a number or a 1D array of them: a TypeError for floats, booleans or other types,
/// an IndexError naming `what` for a value outside [0, end).
std::vector<int> indices_of(const py::object& values, int end, const char* what);
/// Faces as the core takes them, from an (n, k) integer array or a sequence of index sequences
/// (faces of several sizes); a TypeError for anything else.
PolygonTopology faces_from(const py::object& faces);
/// The faces as an (n, k) int32 array; a ValueError for a mesh with faces of several sizes.
IntArray faces_to_array(const PolygonTopology& faces);

/// A number as Python prints it, for messages.
std::string shown_number(double value);
/// `value` if finite and above 0, else a ValueError naming `what`.
double positive_number(double value, const char* what);
/// `value` if finite, else a ValueError naming `what`.
double finite_number(double value, const char* what);
/// `value` if from `lo` to `hi` (NaN refused), else a ValueError naming `what` and the range.
double number_in(double value, double lo, double hi, const char* what);
/// The file system path of a str, bytes or os.PathLike, encoded as os.fsencode encodes it (a str
/// from os.listdir names the file Python would open); a ValueError naming `what` for a NUL in it.
std::string path_of(const py::object& path, const char* what = "path");

/// An integer argument of any size: where an int parameter would refuse one past C's int with pybind11's
/// list of signatures, int_in and to_int refuse it in words.
struct Integer {
  py::int_ value;
};
/// `n` as Python prints it, for messages.
std::string shown_integer(const Integer& n);
/// `n` clamped to int64's range, wide enough for every bound checked.
long long clamped(const Integer& n);
/// `n` if it lies from `lo` to `hi`, else a ValueError "what: expected lo..hi, got n".
int int_in(const Integer& n, int lo, int hi, const char* what);
/// `n` as an int for a check of its own further on; a ValueError naming `what` past an int's range.
int to_int(const Integer& n, const char* what);

}  // namespace gps::python

namespace pybind11::detail {

/// gps::python::Integer from any Python int or object with __index__ (numpy's integers); floats refused
/// as an int parameter refuses them. Signatures show it as `int`.
template <>
struct type_caster<gps::python::Integer> {
  PYBIND11_TYPE_CASTER(gps::python::Integer, const_name("int"));
  bool load(handle source, bool) {
    if (!source || PyFloat_Check(source.ptr()) || !PyIndex_Check(source.ptr())) return false;
    PyObject* index = PyNumber_Index(source.ptr());
    if (!index) {
      PyErr_Clear();
      return false;
    }
    value.value = reinterpret_steal<int_>(index);
    return true;
  }
  static handle cast(const gps::python::Integer& source, return_value_policy, handle) { return source.value.inc_ref(); }
};

}  // namespace pybind11::detail
