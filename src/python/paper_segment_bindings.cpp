// kvd.PaperSegments: the segment BSP run on seed 003's own certificates
// (kvd/segments/aeg_kinetic_bsp.hpp), stepped from Python as kvd simulate
// --certificates paper runs it (tests/python/test_kvd.py).
#include <pybind11/stl.h>

#include <optional>
#include <vector>

#include "convert.hpp"
#include "kvd/detail/tree/digest.hpp"
#include "kvd/segments/aeg_kinetic_bsp.hpp"

namespace kvd::python {

namespace {

class Paper_segments {
public:
  Paper_segments(const segments::Segment_scene& s, std::size_t events, bool validate, const py::handle& until)
      : run_(k_, s, validate), max_events_(events) {
    if (!until.is_none()) until_ = Exact_time(to_mpq(until));
  }

  // The next batch, or None: nothing fails any more, the event limit is
  // reached, or the next failure is after `until`.
  py::object advance() {
    const auto next = run_.next_event_time();
    if (!next || failures_ >= max_events_ || (until_ && k_.compare(*next, *until_) > 0)) return py::none();
    const auto b = run_.advance();
    failures_ += b.failing.size();
    py::dict d;
    put_time(d, k_, b.time, "time");
    py::list failing;
    for (const auto& id : b.failing)
      failing.append(py::make_tuple(segments::aeg_certificate_kind_names[static_cast<int>(id.kind)],
                                    segments::aeg_certificate_subject(id)));
    d["failing"] = failing;
    d["changed"] = b.changed;
    d["certificates"] = b.certificates;
    d["replays"] = b.replays;
    d["nodes_rebuilt"] = b.nodes_rebuilt;
    d["flipped_in_place"] = b.flipped_in_place;
    d["nodes_edited"] = b.nodes_edited;
    d["update_seconds"] = b.update_seconds;
    d["structure_hash"] = tree::sha256_hex(run_.tree().text());
    batches_.push_back(d);
    return d;
  }
  py::list events() const {
    py::list out;
    for (const auto& b : batches_) out.append(b);
    return out;
  }
  py::dict now() const {
    py::dict d;
    put_time(d, k_, run_.now(), "time");
    return d;
  }
  py::object next_event_time() {
    const auto t = run_.next_event_time();
    if (!t) return py::none();
    py::dict d;
    put_time(d, k_, *t, "time");
    return d;
  }
  py::dict tree() const { return segment_tree_dict(run_.tree()); }
  py::dict summary() const {
    py::dict d;
    d["batches"] = batches_.size();
    d["failures"] = failures_;
    d["certificates"] = run_.certificates();
    d["validations"] = run_.validations();
    d["validation_failures"] = run_.validation_failures();
    return d;
  }

private:
  const Exact_kernel k_;
  segments::Aeg_kinetic_bsp<Exact_kernel> run_;
  std::size_t max_events_, failures_ = 0;
  std::optional<Exact_time> until_;
  std::vector<py::dict> batches_;
};

}  // namespace

void bind_paper_segments(py::module_& m) {
  py::class_<Paper_segments>(m, "PaperSegments",
                             "The segment BSP run on seed 003's own certificates (transient nodes, endpoints'\n"
                             "neighbours, flips) with exact failure times, in the exact kernel; each batch replays the\n"
                             "subtrees its certificates name (kvd simulate --certificates paper)")
      .def(py::init<const segments::Segment_scene&, std::size_t, bool, const py::handle&>(), py::arg("scene"),
           py::arg("events") = 100, py::arg("validate") = true, py::arg("until") = py::none())
      .def("advance", &Paper_segments::advance,
           "Processes the next batch and returns it (time, failing [(kind, of)], changed, certificates,\n"
           "replays, nodes_rebuilt, flipped_in_place, nodes_edited, update_seconds, structure_hash), or None when nothing fails any more,\n"
           "`events` failures were processed, or the next batch is after `until`.")
      .def_property_readonly("events", &Paper_segments::events, "The batches processed so far.")
      .def_property_readonly("now", &Paper_segments::now)
      .def_property_readonly("next_event_time", &Paper_segments::next_event_time)
      .def_property_readonly("tree", &Paper_segments::tree, "The tree in force, as build_segments gives it.")
      .def_property_readonly("summary", &Paper_segments::summary);
}

}  // namespace kvd::python
