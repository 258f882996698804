// The Python module `kvd` (pybind11): scenes, the static KVD at an instant,
// and the kinetic KVD stepped from Python, on the exact, double or MPFR
// kernel; the same for moving segments (segment_bindings.cpp). Exact
// numbers cross as fractions.Fraction (and exact times also as the
// library's text, convert.hpp); the module is a thin client of
// include/kvd/kvd.hpp and the segments' public headers.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <nlohmann/json.hpp>

#include <cstring>
#include <memory>
#include <string>
#include <variant>

#include "convert.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/kvd.hpp"

namespace py = pybind11;

namespace {

using kvd::python::put_time;
using kvd::python::to_fraction;
using kvd::python::to_mpq;
using kvd::scene::Scene;

// A scene from Python lists: turned into kvd-scene/1 text with exact
// numbers, so that it goes through the file format's full validation.
Scene scene_from_lists(const py::list& objects, const py::handle& start, const py::handle& end, std::uint64_t seed) {
  using Json = nlohmann::ordered_json;
  const auto number = [](const py::handle& x) { return Json(to_mpq(x).get_str()); };
  const auto index = [](const py::handle& i) { return Json(kvd::python::to_unsigned(i, "a vertex index")); };
  const auto list = [](const py::handle& items, const auto& item) {
    Json out = Json::array();
    for (const auto& i : kvd::python::to_list(items, "vertices, triangles, a point and a translation")) out.push_back(item(i));
    return out;
  };
  const auto points = [&](const py::handle& items) {
    return list(items, [&](const py::handle& p) { return list(p, number); });
  };
  Json time = {{"start", number(start)}};
  if (!end.is_none()) time["end"] = number(end);
  Json scene = {{"format", "kvd-scene/1"}, {"priority", {{"seed", seed}}}, {"time", time}, {"objects", Json::array()}};
  for (const auto& o : objects) {
    if (!py::isinstance<py::dict>(o)) throw py::type_error("an object is a dict with vertices, triangles and translation");
    const auto d = py::reinterpret_borrow<py::dict>(o);
    Json object = {{"vertices", points(d["vertices"])},
                   {"triangles", list(d["triangles"], [&](const py::handle& t) { return list(t, index); })}};
    if (d.contains("translation")) object["motion"] = {{"translation", points(d["translation"])}};
    scene["objects"].push_back(object);
  }
  return kvd::scene::read_scene(scene.dump(), "the scene given to kvd.scene");
}

py::dict statistics(const kvd::tree::Kvd_tree& t) {
  const auto s = t.statistics();
  py::dict d;
  d["nodes"] = s.nodes;
  d["p_nodes"] = s.p_nodes;
  d["e_nodes"] = s.e_nodes;
  d["t_nodes"] = s.t_nodes;
  d["height"] = s.height;
  d["structure_hash"] = kvd::tree::structure_hash(t);
  return d;
}

// The T-nodes of `order` as {"triangle": id, "vertices": [[x, y, z], ...]}
// with exact Fraction coordinates at t.
py::list fragments(const kvd::predicates::Classifier<kvd::Exact_kernel>& c, const kvd::tree::Kvd_tree& t,
                   const std::vector<int>& order, const mpq_class& at) {
  py::list out;
  for (int i : order) {
    const auto& n = t.nodes[static_cast<std::size_t>(i)];
    py::list corners;
    for (const auto& v : std::get<kvd::tree::Triangle_fragment>(n.fragment).corners) {
      const auto p = kvd::query::corner_at(c, v, at);
      corners.append(py::make_tuple(to_fraction(p[0]), to_fraction(p[1]), to_fraction(p[2])));
    }
    py::dict f;
    f["triangle"] = n.cut.id;
    f["vertices"] = corners;
    out.append(f);
  }
  return out;
}

kvd::Point4<mpq_class> view_point(const py::sequence& v) {
  if (v.size() != 3) throw py::value_error("a view is three numbers (x, y, z)");
  return {{to_mpq(v[0]), to_mpq(v[1]), to_mpq(v[2]), mpq_class(1)}};
}

py::dict build(const Scene& s, const py::handle& t, const py::object& view) {
  const mpq_class at = kvd::python::instant_in_span(t, s.start, s.end);
  const kvd::Exact_kernel k;
  const kvd::predicates::Classifier<kvd::Exact_kernel> c(k, s);
  const kvd::tree::Kvd_tree tree = kvd::tree::build(c, kvd::Exact_time(at));
  py::dict d = statistics(tree);
  if (!view.is_none()) d["order"] = fragments(c, tree, kvd::query::back_to_front(c, tree, view_point(view), at), at);
  return d;
}

// The stepping KVD behind kvd.Kinetic, whatever its kernel.
class Any_kinetic {
public:
  virtual ~Any_kinetic() = default;
  virtual py::object advance() = 0;
  virtual std::size_t advance_to(const py::handle& t) = 0;
  virtual void set_motion(std::size_t object, const py::list& translation, const py::handle& at) = 0;
  virtual py::list events() const = 0;
  virtual py::dict now() const = 0;
  virtual py::object next_event_time() const = 0;
  virtual std::string structure_hash() const = 0;
  virtual py::list back_to_front(const py::sequence& view) const = 0;
  virtual py::dict summary() const = 0;
};

template <class K>
class Kinetic_of final : public Any_kinetic {
public:
  Kinetic_of(const K& k, const Scene& s, const kvd::kinetic::Options& o) : k_(k), kds_(k_, s, o) {}

  py::object advance() override {
    const auto* b = kds_.advance();
    if (!b) ended_ = true;
    return b ? py::object(batch(*b)) : py::object(py::none());
  }
  std::size_t advance_to(const py::handle& t) override {
    const auto at = kvd::from_rational<typename K::FT>(to_mpq(t));
    kvd::python::not_before_now(k_, kds_.now(), at, "advance_to: t");
    return kds_.advance_to(at);
  }
  void set_motion(std::size_t object, const py::list& translation, const py::handle& at) override {
    if (translation.size() != 3) throw py::value_error("a translation is three polynomials (x, y, z)");
    kvd::scene::Motion m;
    m.kind = kvd::scene::Motion::Kind::translation;
    for (std::size_t j = 0; j < 3; ++j) {
      std::vector<mpq_class> c;
      for (const auto& x : kvd::python::to_list(translation[j], "a translation's polynomial")) c.push_back(to_mpq(x));
      m.translation[j] = kvd::scene::QPoly(std::move(c));
    }
    kds_.set_motion(object, m, to_mpq(at));
  }
  py::list events() const override {
    py::list out;
    for (const auto& b : kds_.record().batches) out.append(batch(b));
    return out;
  }
  py::dict now() const override {
    py::dict d;
    put_time(d, k_, kds_.now(), "time");
    return d;
  }
  py::object next_event_time() const override {
    const auto t = kds_.next_event_time();
    if (!t) return py::none();
    py::dict d;
    put_time(d, k_, *t, "time");
    return d;
  }
  std::string structure_hash() const override { return kds_.structure_hash(); }
  py::list back_to_front(const py::sequence& view) const override {
    const auto v = view_point(view);
    const kvd::Point4<typename K::FT> eye{{kvd::from_rational<typename K::FT>(v[0]), kvd::from_rational<typename K::FT>(v[1]),
                                           kvd::from_rational<typename K::FT>(v[2]), typename K::FT(1)}};
    py::list out;
    for (int i : kds_.back_to_front(eye)) out.append(kds_.tree().nodes[static_cast<std::size_t>(i)].cut.id);
    return out;
  }
  py::dict summary() const override {
    const auto& r = kds_.record();
    py::dict d;
    d["batches"] = r.batches.size();
    d["events"] = r.failures;
    d["motion_changes"] = r.motion_changes.size();
    d["validations"] = r.validations;
    d["validation_failures"] = r.validation_failures;
    d["valid"] = r.valid();
    d["structure_hash"] = r.structure_hash;
    // Why the run stopped, once it has: advance() returned None, or a batch
    // ended it (a collision, a stuck floating-point run). Until then the
    // record holds its default, "exhausted", whatever will stop the run (no
    // batch due may mean the limit or the event count), and set_motion may
    // still give it batches.
    static const char* const stops[] = {"events", "limit", "exhausted", "collision", "stuck"};
    const bool stopped = ended_ || r.stopped != kvd::kinetic::Stop::exhausted;
    d["stopped"] = stopped ? py::object(py::str(stops[static_cast<int>(r.stopped)])) : py::object(py::none());
    return d;
  }

private:
  py::dict batch(const kvd::kinetic::Batch<typename K::Time>& b) const {
    py::dict d;
    put_time(d, k_, b.time, "time");
    py::list failing;
    for (const auto& f : b.failing) failing.append(py::make_tuple(kvd::kinetic::to_string(f.type), kvd::kinetic::features(f)));
    d["failing"] = failing;
    d["changed"] = b.changed;
    d["structure_hash"] = b.structure;
    d["scope"] = b.scope == kvd::kinetic::Update_scope::none
                     ? py::object(py::none())
                     : py::object(py::str(kvd::kinetic::update_scope_names[static_cast<std::size_t>(b.scope)]));
    d["nodes_touched"] = b.nodes_touched;
    d["nodes_changed"] = b.nodes_changed;
    d["certificates_recomputed"] = b.certificates_recomputed;
    d["update_seconds"] = b.tree_seconds + b.certificate_seconds + b.record_seconds;
    return d;
  }

  K k_;
  kvd::Kinetic_kvd<K> kds_;
  bool ended_ = false;  // advance() returned None
};

std::unique_ptr<Any_kinetic> make_kinetic(const Scene& s, const std::string& kernel, std::size_t events,
                                          const std::string& validate, const py::handle& until) {
  kvd::kinetic::Options o;
  o.max_events = events;
  if (validate == "every") o.validate = kvd::kinetic::Validation::every;
  else if (validate == "end") o.validate = kvd::kinetic::Validation::end;
  else if (validate == "none") o.validate = kvd::kinetic::Validation::none;
  else throw py::value_error("validate is 'every', 'end' or 'none', not '" + validate + "'");
  if (!until.is_none()) o.until = to_mpq(until);
  return kvd::python::with_kernel(kernel, [&](const auto& k) -> std::unique_ptr<Any_kinetic> {
    return std::make_unique<Kinetic_of<std::decay_t<decltype(k)>>>(k, s, o);
  });
}

}  // namespace

PYBIND11_MODULE(kvd, m) {
  m.doc() = "Kinetic Vertical Decomposition trees of moving triangles, decided exactly (kvd/kvd.hpp)";
  static py::exception<kvd::scene::Scene_error> scene_error(m, "SceneError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const kvd::scene::Scene_error& e) {
      // The message may quote the input's bytes, which need not be UTF-8.
      const auto text = py::reinterpret_steal<py::object>(PyUnicode_DecodeUTF8(e.what(), std::strlen(e.what()), "replace"));
      PyErr_SetObject(scene_error.ptr(), text.ptr());
    }
  });
  py::register_exception<kvd::tree::Build_error>(m, "BuildError", PyExc_ValueError);

  py::class_<Scene>(m, "Scene", "A scene of moving triangles (SCENE_FORMAT.md)", kvd::python::made_by_the_module())
      .def_property_readonly("triangles", [](const Scene& s) { return s.triangles.size(); })
      .def_property_readonly("vertices", [](const Scene& s) { return s.rest.size(); })
      .def_property_readonly("objects", [](const Scene& s) { return s.objects.size(); })
      .def_property_readonly("start", [](const Scene& s) { return to_fraction(s.start); })
      .def_property_readonly("end", [](const Scene& s) { return s.end ? to_fraction(*s.end) : py::object(py::none()); })
      .def("__repr__", [](const Scene& s) {
        return "<kvd.Scene: " + std::to_string(s.objects.size()) + " objects, " + std::to_string(s.triangles.size()) +
               " triangles>";
      });

  m.def(
      "load_scene",
      [](const py::object& path, const py::object& seed) {
        kvd::scene::Load_options o;
        if (!seed.is_none()) o.seed = kvd::python::to_unsigned(seed, "seed");
        return kvd::scene::load_scene(kvd::python::to_path(path), o);
      },
      py::arg("path"), py::arg("seed") = py::none(),
      "Reads a kvd-scene/1 file (path: a str, bytes or os.PathLike; seed: another priority seed); SceneError\n"
      "(a ValueError) names the place of a bad input.");
  m.def(
      "scene",
      [](const py::list& objects, const py::object& start, const py::object& end, std::uint64_t seed) {
        return scene_from_lists(objects, start, end, seed);
      },
      py::arg("objects"), py::arg("start") = 0, py::arg("end") = py::none(), py::arg("seed") = 0,
      "A scene from lists: objects = [{'vertices': [[x, y, z], ...], 'triangles': [[i, j, k], ...],\n"
      "'translation': [[x0, x1, ...], [y0, ...], [z0, ...]]}, ...], numbers exact (int, Fraction, '1/3').");
  m.def("build", &build, py::arg("scene"), py::arg("t") = py::none(), py::arg("view") = py::none(),
        "The KVD just after t (default: the scene's start), exactly: node counts, height, structure_hash,\n"
        "and with view=(x, y, z) the fragments back to front with Fraction coordinates.");

  py::class_<Any_kinetic>(m, "Kinetic", "The kinetic KVD, stepped event by event", kvd::python::made_by_init())
      .def(py::init(&make_kinetic), py::arg("scene"), py::arg("kernel") = "exact", py::arg("events") = 100,
           py::arg("validate") = "every", py::arg("until") = py::none())
      .def("advance", &Any_kinetic::advance, "Processes the next batch and returns it, or None when the run stops.")
      .def("advance_to", &Any_kinetic::advance_to, py::arg("t"),
           "Processes every batch at a time <= t; how many (ValueError for a t before now).")
      .def("set_motion", &Any_kinetic::set_motion, py::arg("object"), py::arg("translation"), py::arg("at"),
           "A flight-plan change: the object translates by the given polynomials from the instant `at` on.")
      .def_property_readonly("events", &Any_kinetic::events, "The batches processed so far.")
      .def_property_readonly("now", &Any_kinetic::now)
      .def_property_readonly("next_event_time", &Any_kinetic::next_event_time)
      .def_property_readonly("structure_hash", &Any_kinetic::structure_hash)
      .def("back_to_front", &Any_kinetic::back_to_front, py::arg("view"),
           "The triangle ids of the tree in force's fragments, back to front from view = (x, y, z).")
      .def_property_readonly("summary", &Any_kinetic::summary);

  kvd::python::bind_segments(m);
  kvd::python::bind_paper_segments(m);
}
