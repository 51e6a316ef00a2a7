// SPDX-License-Identifier: Apache-2.0
// The Python module `toroid`: the checked torus calls of
// toroid/torus/checked.h on NumPy arrays of rays and points. Arguments are
// converted and checked here, with the GIL held; the loops over rays then
// run without it and touch no Python object.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

#include "toroid/torus/checked.h"
#include "toroid/version.h"

namespace py = pybind11;
using namespace pybind11::literals;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

using Doubles = py::array_t<double, py::array::c_style>;

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) {
    if (i > 0) s += ", ";
    s += std::to_string(a.shape(i));
  }
  return s + (a.ndim() == 1 ? ",)" : ")");
}

std::string repr(double v) { return py::repr(py::float_(v)).cast<std::string>(); }

// obj as a NumPy array, any dtype: numpy.asarray, with its errors (a ragged
// list, an object whose __array__ raises) re-raised naming the argument.
py::array as_array(const py::handle& obj, const char* name) {
  try {
    return py::module_::import("numpy").attr("asarray")(obj);
  } catch (py::error_already_set& e) {
    if (!e.matches(PyExc_ValueError) && !e.matches(PyExc_TypeError)) throw;
    const std::string message =
        std::string(name) + " is not convertible to a NumPy array: " + py::str(e.value()).cast<std::string>();
    py::raise_from(e, e.matches(PyExc_TypeError) ? PyExc_TypeError : PyExc_ValueError, message.c_str());
    throw py::error_already_set();
  }
}

// TypeError unless NumPy casts a's dtype to float64 safely (bool, integers,
// float16/32/64): complex, strings, objects, long double are refused.
void require_real(const py::array& a, const char* name) {
  const py::module_ np = py::module_::import("numpy");
  if (!np.attr("can_cast")(a.dtype(), np.attr("float64"), "casting"_a = "safe").cast<bool>())
    throw py::type_error(std::string(name) + " must hold real numbers that convert to float64 safely, got dtype " +
                         py::str(a.dtype()).cast<std::string>());
}

// A float64 number from obj (a Python or NumPy number, or a 0-d array).
double as_scalar(const py::handle& obj, const char* name) {
  const py::array a = as_array(obj, name);
  require_real(a, name);
  if (a.ndim() != 0)
    throw py::value_error(std::string(name) + " must be a number, got an array of shape " + shape_text(a));
  return a.attr("astype")("float64").attr("item")().cast<double>();
}

// obj as an aligned, C-contiguous float64 array of shape (N, 3): a view of
// obj where it already is one, else a copy.
Doubles as_rows3(const py::handle& obj, const char* name) {
  const py::array a = as_array(obj, name);
  require_real(a, name);
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw py::value_error(std::string(name) + " must have shape (N, 3), got shape " + shape_text(a));
  const py::module_ np = py::module_::import("numpy");
  return np.attr("require")(a, "dtype"_a = np.attr("float64"), "requirements"_a = "CA");
}

void require_same_n(const Doubles& origins, const Doubles& directions) {
  if (origins.shape(0) != directions.shape(0))
    throw py::value_error("directions must have as many rows as origins: got shape " + shape_text(directions) +
                          " for directions and " + shape_text(origins) + " for origins");
}

// ValueError unless the radii are finite and > 0 (torus_radii_valid).
void require_radii(double major, double minor) {
  if (toroid::torus_radii_valid(major, minor)) return;
  const bool major_bad = !(std::isfinite(major) && major > 0);
  throw py::value_error(major_bad ? "major must be finite and > 0, got " + repr(major)
                                  : "minor must be finite and > 0, got " + repr(minor));
}

py::tuple intersect_torus(const py::object& major_obj, const py::object& minor_obj, const py::object& origins_obj,
                          const py::object& directions_obj) {
  const double major = as_scalar(major_obj, "major"), minor = as_scalar(minor_obj, "minor");
  require_radii(major, minor);
  const Doubles origins = as_rows3(origins_obj, "origins"), directions = as_rows3(directions_obj, "directions");
  require_same_n(origins, directions);
  const auto n = static_cast<std::size_t>(origins.shape(0));
  py::array_t<int> counts(static_cast<py::ssize_t>(n));
  py::array_t<double> roots({static_cast<py::ssize_t>(n), py::ssize_t{4}});
  const double* o = origins.data();
  const double* d = directions.data();
  int* c = counts.mutable_data();
  double* t = roots.mutable_data();
  {
    py::gil_scoped_release release;
    toroid::intersect_torus_batch(major, minor, n, o, d, c, t);
  }
  return py::make_tuple(counts, roots);
}

py::array_t<double> nearest(const py::object& major_obj, const py::object& minor_obj, const py::object& origins_obj,
                            const py::object& directions_obj, const py::object& t_min_obj,
                            const py::object& t_max_obj) {
  const double major = as_scalar(major_obj, "major"), minor = as_scalar(minor_obj, "minor");
  require_radii(major, minor);
  const Doubles origins = as_rows3(origins_obj, "origins"), directions = as_rows3(directions_obj, "directions");
  require_same_n(origins, directions);
  const double t_min = as_scalar(t_min_obj, "t_min"), t_max = as_scalar(t_max_obj, "t_max");
  if (std::isnan(t_min)) throw py::value_error("t_min must not be NaN");
  if (std::isnan(t_max)) throw py::value_error("t_max must not be NaN");
  if (t_min > t_max)
    throw py::value_error("t_min must not exceed t_max, got t_min=" + repr(t_min) + " and t_max=" + repr(t_max));
  const auto n = static_cast<std::size_t>(origins.shape(0));
  py::array_t<double> hits(static_cast<py::ssize_t>(n));
  const double* o = origins.data();
  const double* d = directions.data();
  double* out = hits.mutable_data();
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < n; ++i) {
      double t = kInf;
      // 0 (no root in the window, or a bad ray) leaves t at inf; -1 (bad
      // radii) cannot happen here.
      toroid::intersect_torus_nearest_checked(major, minor, o + 3 * i, d + 3 * i, t_min, t_max, &t);
      out[i] = t;
    }
  }
  return hits;
}

py::array_t<double> normal(const py::object& major_obj, const py::object& minor_obj, const py::object& points_obj) {
  const double major = as_scalar(major_obj, "major"), minor = as_scalar(minor_obj, "minor");
  require_radii(major, minor);
  const Doubles points = as_rows3(points_obj, "points");
  const auto n = static_cast<std::size_t>(points.shape(0));
  py::array_t<double> normals({static_cast<py::ssize_t>(n), py::ssize_t{3}});
  const double* p = points.data();
  double* out = normals.mutable_data();
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < n; ++i) toroid::torus_unit_normal(major, minor, p + 3 * i, out + 3 * i);
  }
  return normals;
}

constexpr const char* kModuleDoc = R"(Exact ray-torus intersection on NumPy arrays of rays.

The torus is in object space: ring in the xy-plane, axis z, centred at the
origin, (sqrt(x^2 + y^2) - major)^2 + z^2 = minor^2. Any major > 0 and
minor > 0 is allowed (minor >= major: horn and spindle tori, the spindle's
inner sheet included). A ray is origin + t * direction; the direction need
not be of unit length, and t is measured in its units.

The answers are those of the C++ library (toroid/torus/checked.h) and of the
C API (toroid/torus_c.h), bit for bit.

Arguments, for every function:
  major, minor   numbers; not finite and > 0: ValueError.
  origins, directions, points
                 (N, 3) arrays or anything NumPy turns into one (lists,
                 integer or float32 arrays); N may be 0. A dtype that does
                 not convert to float64 safely (complex, strings, objects)
                 raises TypeError, another shape ValueError, each naming the
                 argument.
A ray with a NaN or infinite component, or a zero direction, is not an
error: it has no roots. The results are new C-contiguous arrays; the loops
over the rays run without the GIL, so threads can share the work.

Functions: intersect_torus (every root), nearest (the first root in a
window, as a renderer needs it), normal (unit normals at points).
)";

constexpr const char* kIntersectDoc = R"(intersect_torus(major, minor, origins, directions) -> (counts, roots)

Every real root t of each ray, ascending, negative ones too, with
multiplicity where the ray is tangent to the torus.

origins, directions: (N, 3) float64 (or convertible), ray i being
origins[i] + t * directions[i].

Returns counts, an (N,) int32 array of root counts (0 to 4), and roots, an
(N, 4) float64 array: roots[i, :counts[i]] are the roots of ray i, the rest
of its row NaN. A ray with a NaN or infinite component or a zero direction
has count 0 and a row of NaN.

Raises ValueError for major or minor not finite and > 0, for an array not of
shape (N, 3), or for directions with another N than origins; TypeError for
an array of complex, string or object values.
)";

constexpr const char* kNearestDoc = R"(nearest(major, minor, origins, directions, t_min=0.0, t_max=inf) -> t

The nearest root of each ray in the open interval (t_min, t_max): the hit a
renderer wants.

origins, directions: (N, 3) float64 (or convertible), ray i being
origins[i] + t * directions[i]. t_min may be -inf and t_max inf; a root
equal to t_min or t_max is outside the interval.

Returns an (N,) float64 array: the root of ray i, or inf where the ray has no
root in the interval (so numpy.isfinite(t) is the hit mask). A ray with a
NaN or infinite component or a zero direction gets inf.

Raises ValueError for major or minor not finite and > 0, for t_min or t_max
NaN, for t_min > t_max, for an array not of shape (N, 3), or for directions
with another N than origins; TypeError for an array of complex, string or
object values.
)";

constexpr const char* kNormalDoc = R"(normal(major, minor, points) -> normals

The unit outward normal of the torus at each point (object space): the
direction from the nearest point of the centre circle to the point (on a
spindle's inner sheet, from the point across the axis); on the axis of a
horn or spindle torus, +z or -z. Points off the surface get the same
formula.

points: (N, 3) float64 (or convertible), e.g. origins + t[:, None] *
directions for the hits of nearest().

Returns an (N, 3) float64 array; a row of NaN for a point with a NaN or
infinite component or on the centre circle (where there is no normal).

Raises ValueError for major or minor not finite and > 0 or for points not of
shape (N, 3); TypeError for an array of complex, string or object values.
)";

}  // namespace

PYBIND11_MODULE(toroid, m) {
  // The docstrings carry the signatures: pybind11's would show py::object.
  py::options options;
  options.disable_function_signatures();
  m.doc() = kModuleDoc;
  m.attr("__version__") = TOROID_VERSION_STRING;
  m.def("intersect_torus", &intersect_torus, kIntersectDoc, "major"_a, "minor"_a, "origins"_a, "directions"_a);
  m.def("nearest", &nearest, kNearestDoc, "major"_a, "minor"_a, "origins"_a, "directions"_a, "t_min"_a = 0.0,
        "t_max"_a = kInf);
  m.def("normal", &normal, kNormalDoc, "major"_a, "minor"_a, "points"_a);
}
