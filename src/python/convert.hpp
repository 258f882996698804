// Exact numbers and instants between the library and Python, shared by the
// module's parts: numbers cross as fractions.Fraction, exact instants also
// as the library's text and their canonical isolating interval.
#pragma once

#include <pybind11/pybind11.h>

#include <cstdint>
#include <stdexcept>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include <nlohmann/json.hpp>

#include "kvd/kernel/convert.hpp"
#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/kernel/float_kernel.hpp"
#include "kvd/detail/scene/exact_number.hpp"
#include "kvd/detail/scene/span_check.hpp"
#include "kvd/detail/segments/motion_change.hpp"
#include "kvd/segments/segment_io.hpp"

namespace kvd::segments {
class Cylindrical_bsp;
}

namespace kvd::python {

namespace py = pybind11;

// Numbers cross in base 16: Python (3.11 on) refuses to convert integers of
// more than 4,300 decimal digits to or from text, but not in base 16.

// A number: an int, a Fraction (or any number Fraction takes), a float as
// its exact binary value (0.1 is 3602879701896397/2^55), or a str in the
// file formats' grammar ("-7/2", "0.25", "1e-3"; scene::parse_exact_number),
// as a str in a motion is read. inf and nan, which have no exact value, and
// a str out of that grammar are a ValueError; a bool, which Fraction reads
// as 0 or 1, a TypeError, as it is in a motion (the formats have no bool
// number).
inline mpq_class to_mpq(const py::handle& x) {
  if (py::isinstance<py::bool_>(x)) throw py::type_error("a number is not a bool: " + py::repr(x).cast<std::string>());
  if (py::isinstance<py::str>(x)) {
    std::string why;
    if (auto q = scene::parse_exact_number(x.cast<std::string>(), why)) return std::move(*q);
    throw py::value_error(py::repr(x).cast<std::string>() + " is " + why);
  }
  py::object fraction;
  try {
    fraction = py::module_::import("fractions").attr("Fraction")(x);
  } catch (const py::error_already_set& e) {
    if (!e.matches(PyExc_OverflowError)) throw;  // Fraction(inf); Fraction(nan) is a ValueError already
    throw py::value_error("a number is finite, not " + py::repr(x).cast<std::string>());
  }
  const py::object hex = py::module_::import("builtins").attr("format");
  mpq_class q(hex(fraction.attr("numerator"), "x").cast<std::string>() + "/" +
                  hex(fraction.attr("denominator"), "x").cast<std::string>(),
              16);
  q.canonicalize();
  return q;
}

inline py::object to_fraction(const mpq_class& q) {
  const py::object integer = py::module_::import("builtins").attr("int");
  return py::module_::import("fractions").attr("Fraction")(integer(q.get_num().get_str(16), 16),
                                                           integer(q.get_den().get_str(16), 16));
}

// The name of x's type, for a TypeError.
inline std::string type_name(const py::handle& x) { return py::str(py::type::of(x).attr("__name__")); }

// An int in [0, 2^64) (not a bool), for a seed or an index: TypeError or
// ValueError naming `what` otherwise.
inline std::uint64_t to_unsigned(const py::handle& x, const char* what) {
  if (!py::isinstance<py::int_>(x) || py::isinstance<py::bool_>(x))
    throw py::type_error(std::string(what) + " must be an int, not " + type_name(x));
  try {
    return x.cast<std::uint64_t>();
  } catch (const py::cast_error&) {
    throw py::value_error(std::string(what) + " must be in [0, 2^64), not " + py::str(x).cast<std::string>());
  }
}

// A file path as open() takes one: a str, bytes, or an os.PathLike giving
// either (os.fspath), TypeError otherwise. It goes to the C++ file functions
// as the file system's bytes (os.fsencode), so a name that is not UTF-8, as
// os.listdir gives it, is found; a NUL, where those functions would end the
// path and open another file, is a ValueError.
inline std::string to_path(const py::handle& path) {
  const py::module_ os = py::module_::import("os");
  py::object s;
  try {
    s = os.attr("fspath")(path);
  } catch (const py::error_already_set& e) {
    if (!e.matches(PyExc_TypeError)) throw;
    throw py::type_error("a path is a str, bytes or an os.PathLike, not " + type_name(path));
  }
  std::string bytes = os.attr("fsencode")(s).cast<std::string>();
  if (bytes.find('\0') != std::string::npos)
    throw py::value_error("the path " + py::repr(s).cast<std::string>() + " holds a NUL character");
  return bytes;
}

// ValueError, naming the instant `what`, unless `at` lies in the scene's
// time span [start, end] (no end: unbounded).
inline void check_in_span(const mpq_class& at, const std::string& what, const mpq_class& start,
                          const std::optional<mpq_class>& end) {
  if (!scene::in_span(at, start, end))
    throw py::value_error(what + " = " + at.get_str() + " " + scene::outside_span_text(start, end));
}

// The instant t (None: the scene's start) of a build, within the scene's
// time span as on the command line (ValueError otherwise).
inline mpq_class instant_in_span(const py::handle& t, const mpq_class& start, const std::optional<mpq_class>& end) {
  const mpq_class at = t.is_none() ? start : to_mpq(t);
  check_in_span(at, "t", start, end);
  return at;
}

// The instant t as the kernel's time, not before the run's `now`:
// ValueError naming it `what` otherwise (a run does not go back).
template <class K>
typename K::Time not_before_now(const K& k, const typename K::Time& now, const typename K::FT& t, const std::string& what) {
  typename K::Time time = k.time(t);
  if (k.compare(time, now) < 0)
    throw py::value_error(what + " = " + k.to_string(time) + " is before the run's now, " + k.to_string(now));
  return time;
}

// A list or tuple as a list: TypeError naming `what` for anything else
// (a string is not a list of its characters here).
inline py::list to_list(const py::handle& x, const char* what) {
  if (!py::isinstance<py::list>(x) && !py::isinstance<py::tuple>(x))
    throw py::type_error(std::string(what) + " must be a list or tuple, not " + type_name(x));
  return py::list(py::reinterpret_borrow<py::object>(x));
}

// An instant as Python sees it: the library's text, a float, and for an
// exact time its isolating interval as Fractions (lo == hi for a rational).
template <class K>
void put_time(py::dict& d, const K& k, const typename K::Time& t, const char* key) {
  d[key] = k.to_string(t);
  d[(std::string(key) + "_approx").c_str()] = k.to_double(t);
  if constexpr (std::is_same_v<K, Exact_kernel>) {
    const auto [lo, hi] = t.canonical_interval();
    d[(std::string(key) + "_interval").c_str()] = py::make_tuple(to_fraction(lo), to_fraction(hi));
  }
}

// Calls f with the kernel named "exact", "double" or "mpfr:BITS"
// (ValueError otherwise).
template <class F>
auto with_kernel(const std::string& kernel, F f) {
  if (kernel == "exact") return f(Exact_kernel());
  if (kernel == "double") return f(Double_kernel());
  if (kernel.rfind("mpfr:", 0) == 0) {
    const std::optional<unsigned> bits = Mpfr_kernel::bits_named(kernel.substr(5));
    if (!bits) throw py::value_error("mpfr:BITS needs BITS between 2 and 65536, not '" + kernel + "'");
    return f(Mpfr_kernel(*bits));
  }
  throw py::value_error("kernel is 'exact', 'double' or 'mpfr:BITS', not '" + kernel + "'");
}

// For a class Python cannot construct (its objects come from the module's
// functions): Class.__new__(Class) is refused, where it would make an object
// with nothing inside, which the methods would read.
inline py::custom_type_setup made_by_the_module() {
  return py::custom_type_setup([](PyHeapTypeObject* type) {
    type->ht_type.tp_new = [](PyTypeObject* t, PyObject*, PyObject*) -> PyObject* {
      PyErr_Format(PyExc_TypeError, "%s objects are made by the module's functions, not directly", t->tp_name);
      return nullptr;
    };
  });
}

// For a class Python constructs: an object made by Class.__new__(Class)
// without __init__ holds nothing, and its methods would read through a null
// pointer. Reading any attribute of one that is not a dunder raises
// TypeError instead.
inline py::custom_type_setup made_by_init() {
  return py::custom_type_setup([](PyHeapTypeObject* type) {
    type->ht_type.tp_getattro = [](PyObject* self, PyObject* name) -> PyObject* {
      auto* inst = reinterpret_cast<py::detail::instance*>(self);
      if (!inst->get_value_and_holder().holder_constructed()) {
        const char* n = PyUnicode_Check(name) ? PyUnicode_AsUTF8(name) : nullptr;
        if (n == nullptr || std::string_view(n).substr(0, 2) != "__") {
          PyErr_Format(PyExc_TypeError, "this %s object was not initialised: make one with %s(...)",
                       Py_TYPE(self)->tp_name, Py_TYPE(self)->tp_name);
          return nullptr;
        }
      }
      return PyObject_GenericGetAttr(self, name);
    };
  });
}

// The module's part for segment scenes (segment_bindings.cpp), and the run
// on the paper's certificates (paper_segment_bindings.cpp).
void bind_segments(py::module_& m);
void bind_paper_segments(py::module_& m);
// A segment tree as build_segments returns it: cuts by kind, nodes, leaves,
// height, its text and SHA-256 (segment_bindings.cpp).
py::dict segment_tree_dict(const segments::Cylindrical_bsp& b);

// A motion object as the file format's JSON: dicts (str keys), lists,
// tuples, str (a number's text, read by the format's grammar), None and
// bool as they are, any other value a number as to_mpq takes it, written
// exactly (json.dumps would write a float's shortest decimal, 11/10 for
// 1.1, and no int of more than 4,300 digits). The depth is bounded at the
// format's 64 levels, for a list that holds itself.
inline nlohmann::ordered_json motion_json(const py::handle& x, int depth = 0) {
  using Json = nlohmann::ordered_json;
  if (depth > 64) throw py::value_error("set_motion: the motion is nested deeper than 64 levels");
  if (x.is_none()) return nullptr;
  if (py::isinstance<py::bool_>(x)) return x.cast<bool>();
  if (py::isinstance<py::str>(x)) return x.cast<std::string>();
  if (py::isinstance<py::dict>(x)) {
    Json out = Json::object();
    for (const auto& [key, value] : py::reinterpret_borrow<py::dict>(x)) {
      if (!py::isinstance<py::str>(key)) throw py::type_error("a motion's keys are str, not " + type_name(key));
      out[key.cast<std::string>()] = motion_json(value, depth + 1);
    }
    return out;
  }
  if (py::isinstance<py::list>(x) || py::isinstance<py::tuple>(x)) {
    Json out = Json::array();
    for (const auto& item : x) out.push_back(motion_json(item, depth + 1));
    return out;
  }
  return to_mpq(x).get_str();
}

// A flight-plan change of segment `segment` of `scene` (the run's scene,
// with the changes made so far) at `at`, for a run now at `now`: the motion
// (SEGMENT_FORMAT.md's motion object, numbers as motion_json takes them),
// checked at `at` before the run moves there, so that a change refused
// leaves the run where it was. ValueError when `at` is before now or past
// the span's end (where the run would stop, and take the change, at the
// end) or the motion does not keep the segment where it is then, SceneError
// naming the place of a bad motion. The motion, and `at` as the kernel's time.
template <class K>
struct Motion_change {
  segments::Segment_motion motion;
  typename K::Time at;
};
template <class K>
Motion_change<K> motion_change(const K& k, const typename K::Time& now, const segments::Segment_scene& scene,
                               std::size_t segment, const py::handle& motion, const py::handle& at) {
  const mpq_class q = to_mpq(at);
  const auto t = not_before_now(k, now, from_rational<typename K::FT>(q), "set_motion: at");
  check_in_span(q, "set_motion: at", scene.start, scene.end);
  segments::Segment_motion m = segments::read_segment_motion(motion_json(motion).dump(), "set_motion");
  std::optional<typename K::Time> end;
  if (scene.end) end = k.time(from_rational<typename K::FT>(*scene.end));
  segments::check_motion_change(k, scene, segment, m, t, end);
  return {std::move(m), t};
}

}  // namespace kvd::python
