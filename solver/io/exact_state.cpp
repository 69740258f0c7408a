#include "solver/io/exact_state.hpp"

#include <fmt/format.h>

#include <cstring>
#include <sstream>
#include <type_traits>

namespace lmgc::solver {
namespace {

using grammar::ExactStateHeader;

// Appends records as bytes: a count, the record size, then the records.
class Writer {
 public:
  template <class T>
  void value(const T& v) {
    static_assert(std::is_standard_layout_v<T>);
    bytes_.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  template <class Vector>
  void array(const Vector& v) {
    using T = typename Vector::value_type;
    static_assert(std::is_standard_layout_v<T>);
    value(static_cast<std::uint64_t>(v.size()));
    value(static_cast<std::uint64_t>(sizeof(T)));
    if (!v.empty()) bytes_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  void text(const std::string& s) {
    value(static_cast<std::uint64_t>(s.size()));
    bytes_.append(s);
  }
  std::string& bytes() { return bytes_; }

 private:
  std::string bytes_;
};

class Reader {
 public:
  explicit Reader(std::string_view bytes) : bytes_(bytes) {}
  template <class T>
  bool value(T& v) {
    if (bytes_.size() - at_ < sizeof(T)) return fail("the file ends early");
    std::memcpy(reinterpret_cast<char*>(&v), bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return true;
  }
  template <class Vector>
  bool array(Vector& v, std::optional<std::size_t> expected = std::nullopt) {
    using T = typename Vector::value_type;
    std::uint64_t n = 0, size = 0;
    if (!value(n) || !value(size)) return false;
    if (size != sizeof(T))
      return fail(("written by another lmgc build (a record of " + std::to_string(size) +
                   " bytes where this build has " + std::to_string(sizeof(T)) + ")")
                      .c_str());
    if (expected && n != *expected) return fail("written for another case (its arrays differ in size)");
    if (n > (bytes_.size() - at_) / sizeof(T)) return fail("the file ends early");
    v.resize(n);
    if (n > 0) std::memcpy(reinterpret_cast<char*>(v.data()), bytes_.data() + at_, n * sizeof(T));
    at_ += n * sizeof(T);
    return true;
  }
  bool text(std::string& s) {
    std::uint64_t n = 0;
    if (!value(n)) return false;
    if (n > bytes_.size() - at_) return fail("the file ends early");
    s.assign(bytes_.data() + at_, n);
    at_ += n;
    return true;
  }
  bool skip_line() {
    const std::size_t end = bytes_.find('\n');
    if (end == std::string_view::npos) return fail("no header line");
    at_ = end + 1;
    return true;
  }
  bool finished() {
    if (at_ != bytes_.size()) return fail("the file is longer than its arrays");
    return true;
  }
  const std::string& error() const { return error_; }

 private:
  bool fail(const std::string& why) {
    if (error_.empty()) error_ = why;
    return false;
  }
  std::string_view bytes_;
  std::size_t at_ = 0;
  std::string error_;
};

std::string header_line(int dimension, long step, double time, std::size_t bodies) {
  return grammar::exact_state_header_line(ExactStateHeader{dimension, step, time, bodies});
}

// The random stream of the quick scramble, as the standard library writes an engine's state.
std::string scramble_text(const QuickScramble& s) {
  std::ostringstream out;
  out << s;
  return out.str();
}

// The bodies' arrays that a step changes (the others come from BODIES.DAT again).
template <class Bodies, class Io>
bool bodies_arrays(Bodies& b, Io& io, std::size_t n) {
  return io.array(b.reference, n) && io.array(b.displacement_begin, n) && io.array(b.displacement, n) &&
         io.array(b.velocity_begin, n) && io.array(b.velocity, n) && io.array(b.velocity_free, n) &&
         io.array(b.external_force, n) && io.array(b.impulse, n) && io.array(b.visible, n);
}

struct WriteIo {
  Writer& w;
  template <class Vector>
  bool array(const Vector& v, std::size_t) {
    w.array(v);
    return true;
  }
};
struct ReadIo {
  Reader& r;
  template <class Vector>
  bool array(Vector& v, std::size_t n) {
    return r.array(v, n);
  }
};

bool check_header(std::string_view bytes, int dimension, std::size_t bodies, ExactStateHeader& header,
                  std::string& error) {
  const auto h = grammar::read_exact_state_header(bytes);
  if (!h) {
    error = "not an lmgc exact state";
    return false;
  }
  if (h->dimension != dimension || h->bodies != bodies) {
    error = fmt::format("written for a {}D case of {} bodies; this case is {}D with {}", h->dimension,
                        h->bodies, dimension, bodies);
    return false;
  }
  header = *h;
  return true;
}

}  // namespace

std::string write_exact_state(const Scene2D& scene, const RunState2D& state) {
  Writer w;
  w.bytes() = header_line(2, state.step, state.time, scene.bodies.size());
  WriteIo io{w};
  bodies_arrays(const_cast<RigidBodies2D&>(scene.bodies), io, scene.bodies.size());
  w.array(state.contacts);
  w.array(state.previous);
  w.array(state.law_states);
  w.array(state.previous_law_states);
  w.value(static_cast<std::uint8_t>(state.contacts_stored));
  w.value(static_cast<std::uint8_t>(state.laws_initialized));
  w.text(scramble_text(state.scramble));
  return std::move(w.bytes());
}

std::string write_exact_state(const Scene3D& scene, const RunState3D& state) {
  Writer w;
  w.bytes() = header_line(3, state.step, state.time, scene.bodies.size());
  WriteIo io{w};
  RigidBodies3D& b = const_cast<RigidBodies3D&>(scene.bodies);
  bodies_arrays(b, io, b.size());
  w.array(b.frame_initial);
  w.array(b.frame_detection);
  w.array(b.frame);
  // The next step's warm start reads the stored list only (its detection makes `contacts` anew).
  w.array(state.previous);
  w.value(static_cast<std::uint8_t>(state.laws_initialized));
  w.text(scramble_text(state.scramble));
  // Field by field, never a record's padding.
  const SourcePoint3D& source = scene.source;
  w.value(static_cast<std::uint8_t>(source.active));
  w.value(static_cast<std::uint8_t>(source.stopped));
  w.value(static_cast<std::uint64_t>(source.last));
  w.value(source.radius);
  w.value(source.point);
  w.value(static_cast<std::uint64_t>(scene.point_links.size()));
  for (const PointLink3D& l : scene.point_links) {
    w.value(l.candidate);
    w.value(l.antagonist);
    w.value(l.visibility);
    w.value(l.reference_length);
    w.value(l.periods);
    w.value(static_cast<std::uint8_t>(l.shift_candidate));
    w.value(l.pair_rank);
  }
  return std::move(w.bytes());
}

bool restore_exact_state(std::string_view bytes, Scene2D& scene, RunState2D& state, std::string& error) {
  ExactStateHeader h;
  if (!check_header(bytes, 2, scene.bodies.size(), h, error)) return false;
  Reader r(bytes);
  ReadIo io{r};
  std::uint8_t stored = 0, initialized = 0;
  std::string scramble;
  const bool ok = r.skip_line() && bodies_arrays(scene.bodies, io, scene.bodies.size()) &&
                  r.array(state.contacts) && r.array(state.previous) && r.array(state.law_states) &&
                  r.array(state.previous_law_states) && r.value(stored) && r.value(initialized) &&
                  r.text(scramble) && r.finished();
  if (!ok) {
    error = r.error();
    return false;
  }
  std::istringstream in(scramble);
  in >> state.scramble;
  if (!in) {
    error = "its quick scramble state does not read";
    return false;
  }
  state.contacts_stored = stored != 0;
  state.laws_initialized = initialized != 0;
  state.step = h.step;
  state.time = h.time;
  return true;
}

bool restore_exact_state(std::string_view bytes, Scene3D& scene, RunState3D& state, std::string& error) {
  ExactStateHeader h;
  if (!check_header(bytes, 3, scene.bodies.size(), h, error)) return false;
  Reader r(bytes);
  ReadIo io{r};
  RigidBodies3D& b = scene.bodies;
  const std::size_t n = b.size();
  std::uint8_t initialized = 0, active = 0, stopped = 0;
  std::uint64_t last = 0, links = 0;
  std::string scramble;
  SourcePoint3D& source = scene.source;
  bool ok = r.skip_line() && bodies_arrays(b, io, n) && r.array(b.frame_initial, n) &&
            r.array(b.frame_detection, n) && r.array(b.frame, n) && r.array(state.previous) &&
            r.value(initialized) && r.text(scramble) && r.value(active) && r.value(stopped) &&
            r.value(last) && r.value(source.radius) && r.value(source.point) && r.value(links);
  if (ok && links > n * n + 1024) ok = false;  // a damaged count, before any allocation
  std::vector<PointLink3D> point_links(ok ? links : 0);
  for (PointLink3D& l : point_links) {
    std::uint8_t shift = 0;
    ok = ok && r.value(l.candidate) && r.value(l.antagonist) && r.value(l.visibility) &&
         r.value(l.reference_length) && r.value(l.periods) && r.value(shift) && r.value(l.pair_rank);
    l.shift_candidate = shift != 0;
  }
  ok = ok && r.finished();
  if (!ok) {
    error = r.error().empty() ? "its point links do not read" : r.error();
    return false;
  }
  source.active = active != 0;
  source.stopped = stopped != 0;
  source.last = static_cast<std::size_t>(last);
  scene.point_links = std::move(point_links);
  state.contacts.clear();
  state.law_states.clear();
  std::istringstream in(scramble);
  in >> state.scramble;
  if (!in) {
    error = "its quick scramble state does not read";
    return false;
  }
  state.laws_initialized = initialized != 0;
  state.step = h.step;
  state.time = h.time;
  return true;
}

}  // namespace lmgc::solver
