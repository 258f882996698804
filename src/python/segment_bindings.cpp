// The Python module's part for moving segments (seed 003): kvd-segments/1
// scenes, the cylindrical BSP at an instant, and the kinetic BSP stepped
// from Python on any kernel. It agrees with kvd build and kvd simulate on
// segment scenes (tests/python/test_kvd.py).
#include <pybind11/stl.h>

#include <algorithm>
#include <iterator>
#include <memory>
#include <optional>
#include <string>

#include "convert.hpp"
#include "segment_stepping.hpp"
#include "kvd/detail/tree/digest.hpp"
#include "kvd/kernel/convert.hpp"
#include "kvd/segments/augmented_bsp.hpp"
#include "kvd/segments/kinetic_segment_bsp.hpp"
#include "kvd/segments/segment_crossings.hpp"
#include "kvd/segments/segment_io.hpp"

namespace kvd::python {

py::dict segment_tree_dict(const segments::Cylindrical_bsp& b) {
  const segments::Bsp_counts c = b.counts();
  py::dict d;
  d["vertex_cuts"] = c.vertex_cuts;
  d["intersection_cuts"] = c.intersection_cuts;
  d["edge_cuts"] = c.edge_cuts;
  d["nodes"] = c.nodes;
  d["leaves"] = c.leaves;
  d["height"] = c.height;
  const std::string text = b.text();
  d["tree"] = text;
  d["structure_hash"] = tree::sha256_hex(text);  // as kvd diff compares segment trees
  return d;
}

namespace {

using segments::Segment_scene;

py::dict build(const Segment_scene& s, const py::handle& t) {
  const mpq_class at = instant_in_span(t, s.start, s.end);
  const Exact_kernel k;
  const segments::Segment_predicates<Exact_kernel> pred(k, s);
  const segments::Cylindrical_bsp b = segments::build_cylindrical_bsp(pred, Exact_time(at));
  py::dict d = segment_tree_dict(b);
  d["augmented"] = segments::augment(b, pred, Exact_time(at)).text();
  d["segments"] = s.segments.size();
  d["crossings"] = segments::count_crossings(s, at);
  return d;
}

// The stepping segment BSP behind kvd.KineticSegments, whatever its kernel.
class Any_segment_kinetic {
public:
  virtual ~Any_segment_kinetic() = default;
  virtual py::object advance() = 0;
  virtual std::size_t advance_to(const py::handle& t) = 0;
  virtual bool set_motion(std::size_t segment, const py::handle& motion, const py::handle& at) = 0;
  virtual py::list events() const = 0;
  virtual py::dict now() const = 0;
  virtual py::object next_event_time() = 0;
  virtual py::dict tree() const = 0;
  virtual py::dict summary() const = 0;
};

template <class K>
class Segment_kinetic_of final : public Any_segment_kinetic {
  // Each batch processed, recorded (defined first: its type is deduced).
  auto take() {
    return [this](typename Kinetic::Batch&& b) { batches_.push_back(batch(std::move(b))); };
  }

public:
  using Kinetic = segments::Kinetic_segment_bsp<K>;
  Segment_kinetic_of(const K& k, const Segment_scene& s, std::size_t events, bool validate,
                     segments::Segment_update update, const std::optional<mpq_class>& until)
      : k_(k), kin_(k_, s, validate, update), steps_{events, std::nullopt} {
    if (until) steps_.until = k_.time(from_rational<typename K::FT>(*until));
  }

  // The next batch, or None: nothing fails any more, the event limit is
  // reached, or the next failure is after `until`.
  py::object advance() override {
    if (!steps_.allows(k_, kin_.next_event_time())) return py::none();
    batches_.push_back(batch(kin_.advance()));
    return batches_.back();
  }
  std::size_t advance_to(const py::handle& t) override {
    const auto at = not_before_now(k_, kin_.now(), from_rational<typename K::FT>(to_mpq(t)), "advance_to: t");
    return steps_.advance_to(k_, kin_, at, take());
  }
  // A flight-plan change at `at` (after the batches up to it): the motion
  // in the file format's forms, its numbers as text, int or Fraction.
  bool set_motion(std::size_t segment, const py::handle& motion, const py::handle& at) override {
    const auto change = motion_change(k_, kin_.now(), kin_.scene(), segment, motion, at);
    steps_.advance_for_change(k_, kin_, change.at, take());
    const bool changed = kin_.set_motion(segment, change.motion);
    ++motion_changes_;
    return changed;
  }
  py::list events() const override {
    py::list out;
    for (const auto& b : batches_) out.append(b);
    return out;
  }
  py::dict now() const override {
    py::dict d;
    put_time(d, k_, kin_.now(), "time");
    return d;
  }
  py::object next_event_time() override {
    const auto t = kin_.next_event_time();
    if (!t) return py::none();
    py::dict d;
    put_time(d, k_, *t, "time");
    return d;
  }
  py::dict tree() const override { return segment_tree_dict(kin_.tree()); }
  py::dict summary() const override {
    py::dict d;
    d["batches"] = batches_.size();
    d["failures"] = steps_.failures;
    d["motion_changes"] = motion_changes_;
    d["certificates"] = kin_.certificates();
    d["validations"] = kin_.validations();
    d["validation_failures"] = kin_.validation_failures();
    const kinetic::Recovery& r = kin_.recovery();
    d["recovery"] = py::dict(py::arg("failed_builds") = r.failed_builds, py::arg("stale_trees") = r.stale_trees,
                             py::arg("rebuilds") = r.rebuilds, py::arg("unrepaired") = r.unrepaired);
    d["stuck"] = kin_.stuck();
    return d;
  }

private:
  py::dict batch(const typename Kinetic::Batch& b) {
    steps_.failures += b.failing.size();
    py::dict d;
    put_time(d, k_, b.time, "time");
    py::list failing;
    const std::vector<std::size_t> turning = segments::turning_segments(b.failing);
    for (const auto& key : b.failing)
      failing.append(py::make_tuple(segments::kind_name(key.kind), segments::features(key),
                                    segments::segment_event_names[static_cast<int>(
                                        segments::event_in_batch(key, kin_.scene().rank, turning))]));
    d["failing"] = failing;
    d["changed"] = b.changed;
    d["certificates"] = b.certificates;
    d["nodes_rebuilt"] = b.nodes_rebuilt;
    d["frontier_replays"] = b.frontier_replays;
    d["subtree_replays"] = b.subtree_replays;
    d["signs"] = b.signs;
    d["held"] = b.held;
    d["update_seconds"] = b.update_seconds;
    d["structure_hash"] = tree::sha256_hex(kin_.tree().text());
    return d;
  }

  K k_;
  Kinetic kin_;
  Segment_stepping<K> steps_;
  std::size_t motion_changes_ = 0;
  std::vector<py::dict> batches_;
};

std::unique_ptr<Any_segment_kinetic> make_kinetic(const Segment_scene& s, const std::string& kernel, std::size_t events,
                                                  bool validate, const std::string& update, const py::handle& until) {
  const auto& names = segments::segment_update_names;
  const auto at = std::find(std::begin(names), std::end(names), update);
  if (at == std::end(names)) throw py::value_error("update is 'local', 'subtree' or 'rebuild', not '" + update + "'");
  const auto u = static_cast<segments::Segment_update>(at - std::begin(names));
  const std::optional<mpq_class> end = until.is_none() ? std::nullopt : std::optional(to_mpq(until));
  return with_kernel(kernel, [&](const auto& k) -> std::unique_ptr<Any_segment_kinetic> {
    using K = std::decay_t<decltype(k)>;
    return std::make_unique<Segment_kinetic_of<K>>(k, s, events, validate, u, end);
  });
}

}  // namespace

void bind_segments(py::module_& m) {
  py::class_<Segment_scene>(m, "SegmentScene", "A scene of moving segments in the plane (SEGMENT_FORMAT.md)",
                            made_by_the_module())
      .def_property_readonly("segments", [](const Segment_scene& s) { return s.segments.size(); })
      .def_property_readonly("start", [](const Segment_scene& s) { return to_fraction(s.start); })
      .def_property_readonly("end",
                             [](const Segment_scene& s) { return s.end ? to_fraction(*s.end) : py::object(py::none()); })
      .def("__repr__", [](const Segment_scene& s) {
        return "<kvd.SegmentScene: " + std::to_string(s.segments.size()) + " segments>";
      });
  m.def(
      "load_segments",
      [](const py::object& path, const py::object& seed) {
        segments::Segment_load_options o;
        if (!seed.is_none()) o.seed = to_unsigned(seed, "seed");
        return segments::load_segments(to_path(path), o);
      },
      py::arg("path"), py::arg("seed") = py::none(),
      "Reads a kvd-segments/1 file (path: a str, bytes or os.PathLike; seed: another priority seed); SceneError\n"
      "(a ValueError) names the place of a bad input.");
  m.def("build_segments", &build, py::arg("scene"), py::arg("t") = py::none(),
        "The cylindrical BSP of the segments just after t (default: the scene's start), exactly (seed 003,\n"
        "section 2.1): its cuts by kind, nodes, leaves, height, the tree as nested parentheses (as kvd build\n"
        "--tree prints it) and its SHA-256 (structure_hash), the augmented tree of section 3.1.4 (augmented, as\n"
        "kvd build --augmented prints it); segments and crossings at t.");
  py::class_<Any_segment_kinetic>(m, "KineticSegments", "The kinetic BSP of moving segments (seed 003), stepped batch by batch",
                                   made_by_init())
      .def(py::init(&make_kinetic), py::arg("scene"), py::arg("kernel") = "exact", py::arg("events") = 100,
           py::arg("validate") = true, py::arg("update") = "local", py::arg("until") = py::none())
      .def("advance", &Any_segment_kinetic::advance,
           "Processes the next batch and returns it, or None when nothing fails any more, `events` failures\n"
           "were processed, or the next batch is after `until`.")
      .def("advance_to", &Any_segment_kinetic::advance_to, py::arg("t"),
           "Processes every batch at a time <= t that advance() would (within `events` and `until`), then\n"
           "moves to the earlier of t and `until` (not past the span's end; stopped by `events`, it stays at\n"
           "its last batch); how many (ValueError for a t before now).")
      .def("set_motion", &Any_segment_kinetic::set_motion, py::arg("segment"), py::arg("motion"), py::arg("at"),
           "A flight-plan change: the batches up to `at` first, then the segment moves by `motion` from there on,\n"
           "given as SEGMENT_FORMAT.md's motion object ({'translation': [x, y]}, {'matrix': ...} or\n"
           "{'endpoints': ...}; None: static), numbers as text, int, Fraction or float (its exact binary value),\n"
           "polynomials in t as lists of coefficients. It must keep the segment where it is at `at`, an instant\n"
           "from now to the span's end.\n"
           "Only the certificates naming the segment are decided again (Lemma 3.1); whether the tree changed.\n"
           "ValueError (SceneError for a bad motion, naming its place) otherwise.")
      .def_property_readonly("events", &Any_segment_kinetic::events, "The batches processed so far.")
      .def_property_readonly("now", &Any_segment_kinetic::now)
      .def_property_readonly("next_event_time", &Any_segment_kinetic::next_event_time)
      .def_property_readonly("tree", &Any_segment_kinetic::tree, "The tree in force, as build_segments gives it.")
      .def_property_readonly("summary", &Any_segment_kinetic::summary);
}

}  // namespace kvd::python
