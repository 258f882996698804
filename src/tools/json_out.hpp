// The JSON that kvd prints: values built as nlohmann::ordered_json (keys in
// the order they are set) and written in the layouts the commands use.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <type_traits>

#include "kvd/kernel/exact_kernel.hpp"
#include "kvd/kinetic/simulation.hpp"

namespace kvd::cli {

using Json = nlohmann::ordered_json;

// On one line, with ", " between items and ": " after keys:
// {"a": 1, "b": ["x", "y"]}.
std::string json_line(const Json& v);
// An object with one member a line, and the items of a non-empty array
// member one a line after a space, each item as json_line writes it.
std::string json_lines(const Json& v);

// JSON text made by another writer (a motion, a scene), which json_line and
// json_lines copy as it is, so that its own layout stays.
Json verbatim(const std::string& json_text);

// A number printed as decimal text (by fixed, scientific or seconds_since),
// written as that text: "1.000" stays, and "1.00e-400" does not underflow.
Json decimal(const std::string& text);

// A floating-point run's recovery counts.
Json recovery_json(const kinetic::Recovery& r);
// Counts by certificate type, keyed by the type's name.
Json type_counts_json(const kinetic::Type_counts& counts);

// How often each stage of the exact kernel's filtered predicates decided:
// {"on": BOOL, "classify": {"filter", "exact", "after", "perturbation",
// "filter_share"}, "sign_at": {"filter", "exact"}, "compare": {"filter",
// "exact"}}; null for the floating-point kernels.
Json filter_json(const Exact_kernel& k);
template <class K>
Json filter_json(const K& k) {
  if constexpr (std::is_same_v<K, Exact_kernel>) return filter_json(static_cast<const Exact_kernel&>(k));
  else return nullptr;
}

}  // namespace kvd::cli
