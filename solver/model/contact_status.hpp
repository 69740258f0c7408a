#pragma once
// Contact statuses, written as LMGC90's 5-character names. docs/lmgc90-facts/state-and-outputs.md §1.4.3.
#include <cstdint>
#include <string_view>

namespace lmgc::solver {

enum class ContactStatus : std::uint8_t {
  vnish,
  nknow,
  noctc,
  stick,
  slide,
  slibw,
  slifw,  // plain
  Cnnow,
  Cnctc,
  Cstck,
  Cslid,
  Cslbw,
  Cslfw,  // cohesive
  Wnnow,
  Wnctc,
  Wstck,
  Wslid,
  Wslbw,
  Wslfw,  // wet
  Mnnow,
  Mnctc,
  Mstck,
  Mslid,
  Mslbw,
  Mslfw,  // Mohr–Coulomb
  RGR,    // '_RGR_' gap rescue
};

std::string_view status_name(ContactStatus status);

// LMGC90's three natures of a contact status (mod_nlgs after-iteration check: Nhover, Nstick,
// Nslide), whatever the law's family of statuses; `other` for nknow, vnish, the *nnow and RGR.
enum class StatusNature : std::uint8_t { hover, stick, slide, other };
StatusNature status_nature(ContactStatus status);

// The same contact state under a wet (IQS_WET_DS_CLB) or cohesive (MAC_CZM) law, and back:
// nknow/noctc/stick/slibw/slifw <-> W... / C...; other statuses are returned unchanged.
ContactStatus wet_status(ContactStatus status);
ContactStatus dry_status(ContactStatus status);
ContactStatus cohesive_status(ContactStatus status);
// nullopt-like: returns false when `name` is not a status.
bool status_from_name(std::string_view name, ContactStatus& status);

// True for the sliding statuses (any prefix): dynamic friction applies (contact-laws.md §1.3).
bool is_sliding(ContactStatus status);

}  // namespace lmgc::solver
