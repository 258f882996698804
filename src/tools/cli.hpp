// Shared pieces of the kvd commands: argument walking and the exit-status
// contract (0 success, 1 failed check, 2 bad input or usage).
#pragma once

#include <gmpxx.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "kvd/kernel/convert.hpp"
#include "kvd/kernel/kernel.hpp"
#include "kvd/kinetic/simulation.hpp"
#include "kvd/scene/scene_io.hpp"
#include "kvd/segments/segment_io.hpp"
#include "kvd/detail/scene/scene_numbers.hpp"
#include "kvd/tree/build.hpp"

namespace kvd::cli {

// Bad usage: the message goes to stderr and kvd exits with status 2.
class Usage_error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// A floating-point kernel that fails on valid input (its rounding finds
// triangles crossing that the exact kernel keeps apart): the message goes to
// stderr and kvd exits with status 1, a failed run, not bad input.
class Kernel_failure : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// The arguments after the command name, consumed in order.
class Args {
public:
  Args(std::string command, std::vector<std::string> args) : command_(std::move(command)), args_(std::move(args)) {}
  bool done() const { return i_ >= args_.size(); }
  const std::string& next() { return args_.at(i_++); }
  // The value following option `flag`.
  const std::string& command() const { return command_; }
  const std::string& value(const std::string& flag);
  std::uint64_t unsigned_value(const std::string& flag);
  [[noreturn]] void unknown(const std::string& arg) const;
  // The arguments not consumed yet, as those of `command` (a subcommand).
  Args remaining(std::string command) const {
    return Args(std::move(command), std::vector<std::string>(args_.begin() + static_cast<std::ptrdiff_t>(i_), args_.end()));
  }

private:
  std::string command_;
  std::vector<std::string> args_;
  std::size_t i_ = 0;
};

// The arguments the scene commands share: SCENE (a file, or - for standard
// input), --seed S, --allow-intersecting, --json, and, where the command
// wants them, --time T and --view X,Y,Z.
struct Scene_args {
  bool wants_time = false, wants_view = false;
  std::optional<std::string> path;
  scene::Load_options load;
  std::optional<mpq_class> time;
  std::optional<std::array<mpq_class, 3>> view;
  bool json = false;

  // Consumes `a` (and its value) if it is one of these; returns whether it did.
  bool take(Args& args, const std::string& a);
  // The scene (Usage_error if SCENE is missing, Scene_error if it is bad):
  // read_scene(command, read_text(command)).
  scene::Scene load_scene(const std::string& command) const;
  // SCENE's bytes, read once (Usage_error if SCENE is missing, Scene_error
  // if it cannot be read), for a command that dispatches on the format.
  std::string read_text(const std::string& command) const;
  // The triangle scene of SCENE's text (Scene_error if it is bad).
  scene::Scene read_scene(const std::string& command, const std::string& text) const;
  // The segment scene of SCENE's text (kvd-segments/1), --seed and --time
  // checked alike.
  segments::Segment_scene read_segments(const std::string& command, const std::string& text) const;
  // --view, which this command requires.
  const std::array<mpq_class, 3>& required_view(const std::string& command) const;
};

// What f returns; triangles that intersect where f needs them disjoint
// (tree::Build_error) are bad input, reported with the scene's path.
template <class F>
auto with_disjoint_triangles(const std::string& command, const std::string& path, F&& f) {
  try {
    return f();
  } catch (const tree::Build_error& e) {
    throw Usage_error("kvd " + command + ": " + path + ": " + e.what());
  }
}

// The kernel as --kernel names it: "exact", "double", "mpfr:256".
template <class K>
std::string kernel_label(const K& k) {
  if constexpr (std::is_same_v<K, Mpfr_kernel>) return "mpfr:" + std::to_string(k.bits());
  else return K::name;
}

// What f returns, f building scene s's KVD at instant t in kernel k (at its
// start, then running on). Triangles that intersect there are bad input, as
// in with_disjoint_triangles, when the exact kernel finds them too; when
// only a floating-point kernel does, by rounding, it is that kernel's
// failure (Kernel_failure).
template <class K, class F>
auto with_disjoint_triangles_in(const std::string& command, const std::string& path, const K& k,
                                const scene::Scene& s, const scene::Q& t, F&& f) {
  return with_disjoint_triangles(command, path, [&] {
    try {
      return f();
    } catch (const tree::Build_error& e) {
      if constexpr (!std::is_same_v<K, Exact_kernel>) {
        const Exact_kernel exact;  // held by reference in the classifier
        bool apart = true;
        try {
          tree::build(predicates::Classifier<Exact_kernel>(exact, s), Exact_time(t));
        } catch (const tree::Build_error&) {
          apart = false;
        }
        if (apart)
          throw Kernel_failure("kvd " + command + ": " + path + ": the " + kernel_label(k) + " kernel's build at t = " +
                               t.get_str() + " failed by rounding (" + e.what() +
                               "); the exact kernel keeps the triangles apart there");
      }
      throw;
    }
  });
}

// The KVD just after t.
template <class K>
tree::Kvd_tree build_tree(const std::string& command, const std::string& path,
                          const predicates::Classifier<K>& classifier, const typename K::Time& t) {
  return with_disjoint_triangles(command, path, [&] { return tree::build(classifier, t); });
}

// Scene_error naming the first number of the scene that the field FT cannot
// hold (1e400 is infinite in double), "not a finite number in " `where`.
template <class FT>
void require_finite_in(const std::string& path, const scene::Scene& s, const std::string& where) {
  const auto bad = scene::first_number(s, [](const scene::Q& q) { return !is_finite(from_rational<FT>(q)); });
  if (!bad) return;
  throw scene::Scene_error(path + ": " + bad->place + ": " +
                           (bad->power ? "the coefficient of t^" + std::to_string(bad->power) + ", " : "") + "about " +
                           Mpfr_number(bad->value).to_string(5) + ", is not a finite number in " + where);
}
// The same for K's coefficient field; the exact kernel holds all.
template <class K>
void require_representable(const std::string& path, const scene::Scene& s, const K& k) {
  require_finite_in<typename K::FT>(path, s, "the " + kernel_label(k) + " kernel; use --kernel exact or mpfr:BITS");
}
// Pictures are drawn in double: what one cannot hold would be drawn as NaN.
inline const std::string drawn_in_double = "double, in which pictures are drawn";

// Usage_error unless start <= t <= end (the span's end, when it has one).
void require_in_span(const std::string& command, const std::string& flag, const mpq_class& t, const mpq_class& start,
                     const std::optional<mpq_class>& end);
inline void require_in_span(const std::string& command, const std::string& flag, const mpq_class& t,
                            const scene::Scene& s) {
  require_in_span(command, flag, t, s.start, s.end);
}

// An exact number given to option `flag` ("1/3", "0.25"); Usage_error if not.
mpq_class exact_option(const std::string& command, const std::string& flag, const std::string& text);
// Three exact numbers "X,Y,Z" given to option `flag`.
std::array<mpq_class, 3> point_option(const std::string& command, const std::string& flag, const std::string& text);

// Writes `text` to `path` through a temporary file in the same folder and a
// rename, so that the file is either complete or untouched
// (src/tools/atomic_file.cpp: exclusive, unpredictable, synced, removed on
// errors and on SIGINT/SIGTERM/SIGHUP).
void write_atomically(const std::string& command, const std::string& path, const std::string& text);

// The value of an option with named choices ("--queue tree|heap"), E given
// explicitly; a Usage_error "kvd COMMAND: FLAG expects a, b or c" for any
// other.
template <class E>
E choice_option(const std::string& command, const std::string& flag, const std::string& value,
                std::initializer_list<std::pair<const char*, E>> choices) {
  std::string names;
  std::size_t i = 0;
  for (const auto& [name, e] : choices) {
    if (value == name) return e;
    names += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + std::string(name);
    ++i;
  }
  throw Usage_error("kvd " + command + ": " + flag + " expects " + names);
}

// every, end or none, given to --validate.
kinetic::Validation validation_option(const std::string& command, const std::string& value);
// The value of --collisions: reverse or stop.
kinetic::Collisions collisions_option(const std::string& command, const std::string& value);

// The option value that names v ("every").
const char* validation_name(kinetic::Validation v);

// The items of a comma-separated option value, non-empty, each once, in order.
std::vector<std::string> comma_list(const std::string& text);

// BITS of a --kernel mpfr:BITS option, between 2 and 65536.
unsigned mpfr_bits(const std::string& command, const std::string& bits);

// Calls f with the kernel a --kernel option names: exact, double or
// mpfr:BITS; a floating-point one with `epsilon` when given (--epsilon; the
// exact kernel has none), the exact one without its interval filter when
// `filter` is false (--no-filter); returns what f returns.
template <class F>
auto with_kernel(const std::string& command, const std::string& name, F&& f,
                const std::optional<mpq_class>& epsilon = std::nullopt, bool filter = true) {
  if (epsilon && *epsilon <= 0) throw Usage_error("kvd " + command + ": --epsilon must be positive");
  if (name == "exact") {
    if (epsilon) throw Usage_error("kvd " + command + ": --epsilon needs --kernel double or mpfr:BITS");
    return f(Exact_kernel(filter));
  }
  if (!filter) throw Usage_error("kvd " + command + ": --no-filter needs --kernel exact");
  if (name == "double") {
    // An epsilon double cannot hold (1e400 is infinite, 1e-400 zero) would
    // swamp every sign, or none.
    if (epsilon && !(std::isfinite(epsilon->get_d()) && epsilon->get_d() > 0))
      throw Usage_error("kvd " + command + ": --epsilon is beyond double's range (it rounds to " +
                        (epsilon->get_d() > 0 ? "infinity" : "zero") + ")");
    return f(epsilon ? Double_kernel(epsilon->get_d()) : Double_kernel());
  }
  if (name.rfind("mpfr:", 0) == 0) {
    const unsigned bits = mpfr_bits(command, name.substr(5));
    return f(epsilon ? Mpfr_kernel(bits, Mpfr_number(*epsilon)) : Mpfr_kernel(bits));
  }
  throw Usage_error("kvd " + command + ": unknown kernel '" + name + "' (exact, double or mpfr:BITS)");
}

// A progress callback for a long run: "kvd simulate: 1200 batches, 1350
// failures" on stderr, at most every two seconds (nothing for a short run);
// with `of`, a count of a total instead: "kvd view: 12 of 40 intervals".
std::function<void(std::size_t batches, std::size_t failures)> progress_every_few_seconds(std::string label,
                                                                                         std::string of = "");

// Seconds elapsed since `start`, with microsecond digits ("0.012345").
std::string seconds_since(std::chrono::steady_clock::time_point start);

// The process's peak resident memory so far, in MiB (getrusage).
double peak_rss_mib();

// Whether a file name ends with `tail` (".svg"): which output to write.
bool ends_with(const std::string& name, const std::string& tail);

}  // namespace kvd::cli
