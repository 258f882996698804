// kvd.PaperSegments: the segment BSP run on seed 003's own certificates
// (kvd/segments/aeg_kinetic_bsp.hpp), stepped from Python as kvd simulate
// --certificates paper runs it (tests/python/test_kvd.py).
#include <pybind11/stl.h>

#include <optional>
#include <vector>

#include "convert.hpp"
#include "segment_stepping.hpp"
#include "kvd/detail/tree/digest.hpp"
#include "kvd/segments/aeg_kinetic_bsp.hpp"

namespace kvd::python {

namespace {

class Paper_segments {
  // Each batch processed, recorded (defined first: its type is deduced).
  auto take() {
    return [this](const segments::Aeg_kinetic_bsp<Exact_kernel>::Batch& b) { batches_.push_back(batch(b)); };
  }

public:
  Paper_segments(const segments::Segment_scene& s, std::size_t events, bool validate, const py::handle& until)
      : run_(k_, s, validate), steps_{events, std::nullopt} {
    if (!until.is_none()) steps_.until = Exact_time(to_mpq(until));
  }

  // The next batch, or None: nothing fails any more, the event limit is
  // reached, or the next failure is after `until`.
  py::object advance() {
    if (!steps_.allows(k_, run_.next_event_time())) return py::none();
    batches_.push_back(batch(run_.advance()));
    return batches_.back();
  }
  std::size_t advance_to(const py::handle& t) {
    return steps_.advance_to(k_, run_, not_before_now(k_, run_.now(), to_mpq(t), "advance_to: t"), take());
  }
  // A flight-plan change at `at`, after the batches up to it: the batch of
  // the certificates it fails at once (failing empty when none).
  py::dict set_motion(std::size_t segment, const py::handle& motion, const py::handle& at) {
    const auto change = motion_change(k_, run_.now(), run_.scene(), segment, motion, at);
    steps_.advance_for_change(k_, run_, change.at, take());
    const auto b = run_.set_motion(segment, change.motion);
    ++motion_changes_;
    return batch(b, false);
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
    d["failures"] = steps_.failures;
    d["motion_changes"] = motion_changes_;
    d["certificates"] = run_.certificates();
    d["validations"] = run_.validations();
    d["validation_failures"] = run_.validation_failures();
    return d;
  }

private:
  // A batch as a dict; an event's is kept in `events`.
  py::dict batch(const segments::Aeg_kinetic_bsp<Exact_kernel>::Batch& b, bool event = true) {
    if (event) steps_.failures += b.failing.size();
    py::dict d;
    put_time(d, k_, b.time, "time");
    py::list failing;
    for (const auto& id : b.failing)
      failing.append(py::make_tuple(segments::aeg_certificate_kind_names[static_cast<int>(id.kind)],
                                    segments::aeg_certificate_subject(id)));
    d["failing"] = failing;
    d["changed"] = b.changed;
    d["certificates"] = b.certificates;
    d["certificates_made"] = b.certificates_made;
    d["replays"] = b.replays;
    d["frontier_replays"] = b.frontier_replays;
    d["nodes_rebuilt"] = b.nodes_rebuilt;
    d["flipped_in_place"] = b.flipped_in_place;
    d["nodes_edited"] = b.nodes_edited;
    d["signs"] = b.signs;
    d["held"] = b.held;
    d["repeated"] = b.repeated;
    py::dict by;
    for (const auto& [name, signs] : b.phases.named()) by[name] = signs;
    d["signs_by"] = by;
    d["update_seconds"] = b.update_seconds;
    d["structure_hash"] = tree::sha256_hex(run_.tree().text());
    return d;
  }

  const Exact_kernel k_;
  segments::Aeg_kinetic_bsp<Exact_kernel> run_;
  Segment_stepping<Exact_kernel> steps_;
  std::size_t motion_changes_ = 0;
  std::vector<py::dict> batches_;
};

}  // namespace

void bind_paper_segments(py::module_& m) {
  py::class_<Paper_segments>(m, "PaperSegments",
                             "The segment BSP run on seed 003's own certificates (transient nodes, endpoints'\n"
                             "neighbours, flips) with exact failure times, in the exact kernel; each batch replays the\n"
                             "subtrees its certificates name (kvd simulate --certificates paper)",
                             made_by_init())
      .def(py::init<const segments::Segment_scene&, std::size_t, bool, const py::handle&>(), py::arg("scene"),
           py::arg("events") = 100, py::arg("validate") = true, py::arg("until") = py::none())
      .def("advance", &Paper_segments::advance,
           "Processes the next batch and returns it (time, failing [(kind, of)], changed, certificates,\n"
           "certificates_made, replays, frontier_replays, nodes_rebuilt, flipped_in_place, nodes_edited, signs, held,\n"
           "repeated, signs_by {own_guard, other_guard, ties, certificates, leaves, walls}, update_seconds, "
           "structure_hash), or None when nothing fails any more, `events` failures were processed, or the\n"
           "next batch is after `until`.")
      .def("advance_to", &Paper_segments::advance_to, py::arg("t"),
           "Processes every batch at a time <= t that advance() would (within `events` and `until`), then\n"
           "moves to the earlier of t and `until` (not past the span's end; stopped by `events`, it stays at\n"
           "its last batch); how many (ValueError for a t before now).")
      .def("set_motion", &Paper_segments::set_motion, py::arg("segment"), py::arg("motion"), py::arg("at"),
           "A flight-plan change, as KineticSegments.set_motion takes it: the batches up to `at` first, then\n"
           "the segment moves by `motion` from there on, kept where it is at `at`. Only the certificates naming\n"
           "the segment are made again (Lemma 3.1); those the new motion fails at once are updated as a batch,\n"
           "returned in the form advance() gives (failing empty when none failed).")
      .def_property_readonly("events", &Paper_segments::events, "The batches processed so far.")
      .def_property_readonly("now", &Paper_segments::now)
      .def_property_readonly("next_event_time", &Paper_segments::next_event_time)
      .def_property_readonly("tree", &Paper_segments::tree, "The tree in force, as build_segments gives it.")
      .def_property_readonly("summary", &Paper_segments::summary);
}

}  // namespace kvd::python
