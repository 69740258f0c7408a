#include "solver/model/contact_status.hpp"

#include <array>

namespace lmgc::solver {
namespace {
constexpr std::array<std::string_view, 26> kNames = {
    "vnish", "nknow", "noctc", "stick", "slide", "slibw", "slifw", "Cnnow", "Cnctc",
    "Cstck", "Cslid", "Cslbw", "Cslfw", "Wnnow", "Wnctc", "Wstck", "Wslid", "Wslbw",
    "Wslfw", "Mnnow", "Mnctc", "Mstck", "Mslid", "Mslbw", "Mslfw", "_RGR_"};
}

std::string_view status_name(ContactStatus status) {
  return kNames[static_cast<std::size_t>(status)];
}

bool status_from_name(std::string_view name, ContactStatus& status) {
  for (std::size_t i = 0; i < kNames.size(); ++i)
    if (kNames[i] == name) {
      status = static_cast<ContactStatus>(i);
      return true;
    }
  return false;
}

bool is_sliding(ContactStatus s) {
  switch (s) {
    case ContactStatus::slide:
    case ContactStatus::slibw:
    case ContactStatus::slifw:
    case ContactStatus::Cslid:
    case ContactStatus::Cslbw:
    case ContactStatus::Cslfw:
    case ContactStatus::Wslid:
    case ContactStatus::Wslbw:
    case ContactStatus::Wslfw:
    case ContactStatus::Mslid:
    case ContactStatus::Mslbw:
    case ContactStatus::Mslfw:
      return true;
    default:
      return false;
  }
}

ContactStatus wet_status(ContactStatus s) {
  switch (s) {
    case ContactStatus::nknow:
      return ContactStatus::Wnnow;
    case ContactStatus::noctc:
      return ContactStatus::Wnctc;
    case ContactStatus::stick:
      return ContactStatus::Wstck;
    case ContactStatus::slide:
      return ContactStatus::Wslid;
    case ContactStatus::slibw:
      return ContactStatus::Wslbw;
    case ContactStatus::slifw:
      return ContactStatus::Wslfw;
    default:
      return s;
  }
}

ContactStatus dry_status(ContactStatus s) {
  switch (s) {
    case ContactStatus::Wnnow:
      return ContactStatus::nknow;
    case ContactStatus::Wnctc:
      return ContactStatus::noctc;
    case ContactStatus::Wstck:
      return ContactStatus::stick;
    case ContactStatus::Wslid:
      return ContactStatus::slide;
    case ContactStatus::Wslbw:
      return ContactStatus::slibw;
    case ContactStatus::Wslfw:
      return ContactStatus::slifw;
    default:
      return s;
  }
}

ContactStatus cohesive_status(ContactStatus s) {
  switch (s) {
    case ContactStatus::nknow:
      return ContactStatus::Cnnow;
    case ContactStatus::noctc:
      return ContactStatus::Cnctc;
    case ContactStatus::stick:
      return ContactStatus::Cstck;
    case ContactStatus::slide:
      return ContactStatus::Cslid;
    case ContactStatus::slibw:
      return ContactStatus::Cslbw;
    case ContactStatus::slifw:
      return ContactStatus::Cslfw;
    default:
      return s;
  }
}

StatusNature status_nature(ContactStatus status) {
  switch (status) {
    case ContactStatus::noctc:
    case ContactStatus::Wnctc:
    case ContactStatus::Mnctc:
      return StatusNature::hover;
    case ContactStatus::stick:
    case ContactStatus::Wstck:
    case ContactStatus::Mstck:
    case ContactStatus::Cstck:
      return StatusNature::stick;
    case ContactStatus::slibw:
    case ContactStatus::slifw:
    case ContactStatus::Wslbw:
    case ContactStatus::Wslfw:
    case ContactStatus::Mslbw:
    case ContactStatus::Mslfw:
    case ContactStatus::Cslbw:
    case ContactStatus::Cslfw:
      return StatusNature::slide;
    default:
      return StatusNature::other;
  }
}

}  // namespace lmgc::solver
