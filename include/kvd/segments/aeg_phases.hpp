// Where an update of the run on the paper's set decided its signs
// (Aeg_kinetic_bsp::Batch::phases), for the reports that print it.
#pragma once

#include <array>
#include <cstddef>
#include <utility>

namespace kvd::segments {

// Of a batch's signs, those decided by: the guards over the changing
// segments' own steps (above the nodes a reroute starts from, above a
// collinear endpoint's leaves, between nested frontiers), the guard over
// other segments' steps at the nodes where a changed key is decided, the
// ties on the paths above the nodes made again, the certificates (read at
// the instant, and made), the endpoints' leaves found again, and the checks
// that an old subtree keeps its signs with its moved walls renamed. The rest
// decided the cuts made again and the flips' and collinear endpoints'
// checks.
struct Aeg_phases {
  static constexpr std::size_t count = 6;
  long own_guard = 0, other_guard = 0, ties = 0, certificates = 0, leaves = 0, walls = 0;

  // Each with its name, in this order.
  std::array<std::pair<const char*, long>, count> named() const {
    return {{{"own_guard", own_guard},
             {"other_guard", other_guard},
             {"ties", ties},
             {"certificates", certificates},
             {"leaves", leaves},
             {"walls", walls}}};
  }
};

}  // namespace kvd::segments
