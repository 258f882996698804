// kvd certify on a segment scene: the exact kinetic cylindrical BSP's
// event-order certificate, kvd-segment-event-order/1
// (proofs/event-order-certificate.md, "Segment scenes").
#include <iostream>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "json_out.hpp"
#include "left_at_exit.hpp"
#include "kvd/kinetic/event_order.hpp"
#include "segment_commands.hpp"

namespace kvd::cli {

namespace {

using Key = segments::Segment_certificate_key;
using Kinetic = segments::Kinetic_segment_bsp<Exact_kernel>;
using Coefficients = std::vector<mpq_class>;  // constant term first

// A certificate as the file lists it: the sign the construction decided just
// after the instant it was made, and the polynomials that decided it.
struct Entry {
  Key key;
  int sign;
  std::vector<Coefficients> polys;
};

struct Event {
  std::size_t certificate, factor;  // the factor that changes sign
  mpq_class lo, hi;                 // isolating the event time as a root of the factor
  int multiplicity;
  bool equal_to_previous;
};

class Recorder {
public:
  explicit Recorder(const Exact_kernel& k) : k_(k) {}

  // The certificates in force from the run's instant on.
  void in_force(const Kinetic& kin);
  // The failures of a batch, among the certificates in force before it:
  // call it before in_force(kin) after the batch.
  void batch(const Kinetic::Batch& b);

  std::vector<Entry> entries;
  std::vector<Event> events;
  std::vector<std::vector<std::size_t>> intervals;  // the ids in force from the start and after each batch

private:
  const Exact_kernel& k_;
  std::map<std::tuple<Key, int, std::vector<Coefficients>>, std::size_t> ids_;
  std::map<Key, std::size_t> current_;
};

void Recorder::in_force(const Kinetic& kin) {
  std::map<Key, std::size_t> next;
  std::vector<std::size_t> active;
  for (const auto& [key, nodes] : kin.certificate_list()) {
    const int sign = kin.sign(key);
    std::vector<Coefficients> polys;
    for (const auto& q : kin.polynomials(key)) polys.push_back(q.coefficients());
    const auto was = current_.find(key);
    std::size_t id;
    if (was != current_.end() && entries[was->second].sign == sign && entries[was->second].polys == polys) {
      id = was->second;
    } else {
      const auto [it, fresh] = ids_.try_emplace({key, sign, polys}, entries.size());
      if (fresh) entries.push_back({key, sign, std::move(polys)});
      id = it->second;
    }
    next[key] = id;
    active.push_back(id);
  }
  current_ = std::move(next);
  intervals.push_back(std::move(active));
}

void Recorder::batch(const Kinetic::Batch& b) {
  for (std::size_t n = 0; n < b.failing.size(); ++n) {
    const std::size_t id = current_.at(b.failing[n]);
    const auto& polys = entries[id].polys;
    std::size_t f = 0;
    int multiplicity = 0;
    for (; f < polys.size(); ++f) {
      multiplicity = kinetic::root_multiplicity(k_, zpoly::to_zpoly(Exact_kernel::Poly(polys[f])), b.time);
      if (multiplicity % 2) break;
    }
    if (f == polys.size()) throw std::logic_error("a failing segment certificate with no factor changing sign");
    const auto [lo, hi] = kinetic::isolating_interval(zpoly::to_zpoly(Exact_kernel::Poly(polys[f])), b.time);
    events.push_back({id, f, lo, hi, multiplicity, n > 0});
  }
}

Json entry_json(const Entry& e) {
  const Key& k = e.key;
  Json points = Json::array(), segs = Json::array(), polys = Json::array();
  if (k.kind == Key::Kind::x_order) {
    points.push_back(segments::point_name(k.p));
    points.push_back(segments::point_name(k.q));
  } else {
    points.push_back(segments::point_name(k.p));
    segs.push_back(k.i);
    if (k.kind == Key::Kind::order_at) segs.push_back(k.j);
  }
  for (const auto& q : e.polys) {
    Json c = Json::array();
    for (const auto& a : q) c.push_back(a.get_str());
    polys.push_back(c);
  }
  return {{"kind", segments::kind_name(k.kind)}, {"points", points}, {"segments", segs}, {"sign", e.sign},
          {"polynomials", polys}};
}

std::string document(const segments::Segment_scene& s, const Recorder& r, const std::optional<mpq_class>& end,
                     const char* stopped_by) {
  Json certificates = Json::array(), events = Json::array(), intervals = Json::array();
  for (const auto& e : r.entries) certificates.push_back(entry_json(e));
  for (const auto& e : r.events)
    events.push_back({{"certificate", e.certificate}, {"factor", e.factor},
                      {"interval", Json::array({e.lo.get_str(), e.hi.get_str()})}, {"multiplicity", e.multiplicity},
                      {"order", e.equal_to_previous ? "=" : "<"}});
  for (const auto& active : r.intervals) intervals.push_back({{"active", active}});
  const Json doc = {{"format", "kvd-segment-event-order/1"},
                    {"scene", verbatim(segments::write_segments(s))},
                    {"start", s.start.get_str()},
                    {"end", end ? Json(end->get_str()) : Json(nullptr)},
                    {"stopped_by", stopped_by},
                    {"certificates", certificates},
                    {"events", events},
                    {"intervals", intervals}};
  return json_lines(doc) + "\n";
}

}  // namespace

int segment_certify(const Scene_args& sa, const std::string& text, const Segment_certify_options& o) {
  const segments::Segment_scene s = sa.read_segments("certify", text);
  if (o.until) require_in_span("certify", "--until", *o.until, s.start, s.end);
  const Exact_kernel k;
  Kinetic& kin = left_at_exit<Kinetic>(k, s, o.validate);
  Recorder rec(k);
  rec.in_force(kin);
  const auto progress = progress_every_few_seconds("kvd certify");
  std::size_t batches = 0;
  const char* stopped_by = "exhausted";
  while (const auto next = kin.next_event_time()) {
    if (o.until && k.compare(*next, Exact_time(*o.until)) > 0) {
      stopped_by = "until";
      break;
    }
    if (rec.events.size() >= o.max_events) {
      stopped_by = "events";
      break;
    }
    const Kinetic::Batch b = kin.advance();
    rec.batch(b);
    rec.in_force(kin);
    progress(++batches, rec.events.size());
  }
  for (const auto& f : kin.validation_failures()) std::cerr << "kvd certify: validation failed: " << f << "\n";
  if (!kin.validation_failures().empty()) return 1;
  // The last interval: none after the last batch when the run stopped at an
  // event it did not process, or when the time limit is that batch's time;
  // else up to the limit (--until, or the span's end), or +infinity.
  std::optional<mpq_class> end = o.until ? o.until : s.end;
  if (std::string(stopped_by) == "events" || (end && k.compare(kin.now(), Exact_time(*end)) >= 0)) {
    rec.intervals.pop_back();
    end.reset();
  }
  write_atomically("certify", o.out, document(s, rec, end, stopped_by));
  std::cout << "kvd certify: " << rec.events.size() << " events in " << batches << " batches, " << rec.entries.size()
            << " certificates, stopped by " << stopped_by << "; wrote " << o.out << "\n";
  return 0;
}

}  // namespace kvd::cli
