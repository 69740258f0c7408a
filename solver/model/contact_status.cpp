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

}  // namespace lmgc::solver
