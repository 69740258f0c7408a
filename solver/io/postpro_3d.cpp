#include "solver/io/postpro_3d.hpp"

#include <fmt/format.h>

#include "grammar/common/fortran_format.hpp"

namespace lmgc::solver {
namespace {

// ES15.8 for the time, then (1X,ES14.7) per value (state-and-outputs.md §4).
void line(std::ofstream& out, double time, std::initializer_list<double> values) {
  std::string text;
  grammar::append_fortran_es(text, time, 15, 8);
  for (double v : values) {
    text += ' ';
    grammar::append_fortran_es(text, v, 14, 7);
  }
  text += '\n';
  out << text;
}

}  // namespace

bool Postpro3D::provides(PostproKind2D kind) {
  return kind == PostproKind2D::body_tracking || kind == PostproKind2D::solver_informations;
}

bool Postpro3D::open(const std::filesystem::path& dir, std::vector<PostproCommand2D> commands,
                     std::string& error) {
  commands_ = std::move(commands);
  streams_.clear();
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  auto create = [&](const std::string& name, std::size_t command, std::int64_t body) {
    auto file = std::make_unique<std::ofstream>(dir / name, std::ios::trunc);
    if (!*file) {
      error = "cannot write '" + (dir / name).string() + "'";
      return false;
    }
    streams_.push_back({command, body, std::move(file), dir / name});
    return true;
  };
  // POSTPRO.OUT is created empty (datbox-inputs.md §8).
  std::ofstream(dir / "POSTPRO.OUT", std::ios::trunc);
  for (std::size_t i = 0; i < commands_.size(); ++i) {
    const PostproCommand2D& c = commands_[i];
    bool ok = true;
    if (c.kind == PostproKind2D::solver_informations) {
      ok = create("SOLVER_INFORMATIONS.DAT", i, 0);
    } else if (c.kind == PostproKind2D::body_tracking) {
      for (std::int64_t b : c.bodies) ok = ok && create(fmt::format("BODY_{:07d}.DAT", b), i, b);
    }
    if (!ok) return false;
  }
  return true;
}

bool Postpro3D::write(const Scene3D& scene, const RunState3D& state, const NlgsResult& solver,
                      std::string& error) {
  const RigidBodies3D& b = scene.bodies;
  const double t = state.time;
  if (!state.contacts.empty()) last_norms_ = solver.norms;
  for (Stream& s : streams_) {
    const PostproCommand2D& c = commands_[s.command];
    if (c.period <= 0 || state.step % c.period != 0) continue;
    std::ofstream& out = *s.file;
    switch (c.kind) {
      case PostproKind2D::solver_informations: {
        out << solver_informations_line(t, state.contacts.empty() ? 0 : solver.iterations, last_norms_,
                                        state.contacts.size());
        break;
      }
      case PostproKind2D::body_tracking: {
        // coor(1:3) (centre of inertia), X(1:3) (translation from the reference), V(1:6)
        // (v global, ω in the body's principal axes, as in DOF.OUT).
        if (s.body < 1 || static_cast<std::size_t>(s.body) > b.size()) break;
        const auto i = static_cast<std::size_t>(s.body - 1);
        const Eigen::Vector3d x = b.displacement[i].head<3>();
        const Eigen::Vector3d coor = b.reference[i] + x;
        const Vector6d& v = b.velocity[i];
        line(out, t, {coor.x(), coor.y(), coor.z(), x.x(), x.y(), x.z(), v(0), v(1), v(2), v(3), v(4), v(5)});
        break;
      }
      default:
        break;  // not provided in 3D: no stream was opened for it
    }
  }
  if (flush_clock_.due())
    for (Stream& s : streams_) s.file->flush();
  return streams_good(error);
}

bool Postpro3D::close(std::string& error) {
  for (Stream& s : streams_) s.file->flush();
  const bool ok = streams_good(error);
  streams_.clear();
  return ok;
}

bool Postpro3D::streams_good(std::string& error) const {
  for (const Stream& s : streams_)
    if (!*s.file) {
      error = "cannot write '" + s.path.string() + "' (disk full?)";
      return false;
    }
  return true;
}

}  // namespace lmgc::solver
