#include "bench/scenes/generated_files.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string_view>
#include <vector>

#include "grammar/bodies/writer.hpp"
#include "grammar/vloc_rloc/interaction_catalogue.hpp"
#include "grammar/vloc_rloc/writer.hpp"

namespace lmgc::bench {

std::string generated_bodies_dat(std::size_t count) {
  using namespace grammar;
  BodiesFile file;
  file.bodies.reserve(count);
  const std::size_t side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(count))));
  for (std::size_t i = 0; i < count; ++i) {
    Body b;
    b.type = BodyType::rbdy2;
    RigidBulk bulk;
    bulk.type = Word{"PLAIN"};
    bulk.behav = Word{"PLEXx"};
    bulk.avrd = Real{1.0e-3 * (1.0 + 0.1 * static_cast<double>(i % 7))};
    bulk.gyrd = Real{bulk.avrd.value / std::sqrt(2.0)};
    b.rigid_bulk = bulk;
    Node node;
    node.type = Word{"NO3xx"};
    node.coordinates = {Real{0.0025 * static_cast<double>(i % side)},
                        Real{0.0025 * static_cast<double>(i / side)}, Real{0.0}};
    b.nodes.push_back(node);
    Contactor c;
    c.color = Word{"BLEUx"};
    if (i % 2 == 0) {
      c.type = Word{"DISKx"};
      c.values = {bulk.avrd};
    } else {
      c.type = Word{"POLYG"};
      for (int k = 0; k < 5; ++k) {
        const double angle = 2.0 * M_PI * k / 5.0;
        c.vertices.push_back(
            {Real{bulk.avrd.value * std::cos(angle)}, Real{bulk.avrd.value * std::sin(angle)}, Real{0.0}});
      }
    }
    b.contactors.push_back(c);
    file.bodies.push_back(std::move(b));
  }
  return write_bodies(file);
}

namespace {

// Deterministic pseudo-random numbers (splitmix64): the same sequence on every platform.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  // Uniform in [0, 1).
  double uniform() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
  }
  double uniform(double low, double high) { return low + (high - low) * uniform(); }
  // Log-uniform in [low, high), low > 0.
  double log_uniform(double low, double high) { return low * std::pow(high / low, uniform()); }

 private:
  std::uint64_t state_;
};

// The scene behind the generated Vloc_Rloc.INI: 4 JONCx walls (bodies 1-4), then the disks,
// then the pentagons, on a grid like generated_bodies_dat's (2.5 mm spacing, radii 1-1.6 mm).
constexpr std::int64_t kWalls = 4;
constexpr double kSpacing = 0.0025;

struct Body2D {
  std::int64_t number;  // 1-based body number
  std::int64_t serial;  // 1-based rank among the contactors of its type (LMGC90's module lists)
  double x, y, radius;
};

class VlocRlocGenerator {
 public:
  VlocRlocGenerator(std::size_t disks, std::size_t polygons)
      : disks_(disks),
        side_(static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(disks + polygons))))) {}

  Body2D disk(std::size_t k) const { return body(k, kWalls + 1 + static_cast<std::int64_t>(k)); }
  Body2D polygon(std::size_t k) const {
    return body(disks_ + k, kWalls + 1 + static_cast<std::int64_t>(disks_ + k));
  }
  Body2D wall(std::size_t k) const {
    const double extent = kSpacing * static_cast<double>(side_);
    return Body2D{static_cast<std::int64_t>(k + 1), static_cast<std::int64_t>(k + 1), k == 2 ? extent : 0.0,
                  k == 3 ? extent : 0.0, 0.0};
  }

  // One interaction of `type`, its data line from `words` and `integers`, its vectors drawn at
  // random around the contact point between `cd` and `an`.
  grammar::VlocRlocInteraction make(std::string_view type, std::int64_t number,
                                    std::vector<std::string> words, std::vector<std::int64_t> integers,
                                    const Body2D& cd, const Body2D& an, bool sliding) {
    using grammar::Real;
    const grammar::InteractionKind* kind = grammar::find_interaction_kind(type);
    grammar::VlocRlocInteraction c;
    c.type = grammar::Word{std::string(type)};
    c.number = grammar::Integer{number};
    c.title = std::string(kind->title);
    for (std::string& w : words) c.words.push_back(grammar::Word{std::move(w)});
    for (std::int64_t n : integers) c.integers.push_back(grammar::Integer{n});
    // Normal from the candidate to the antagonist (walls: along the wall's normal), jittered.
    double angle = std::atan2(an.y - cd.y, an.x - cd.x);
    if (an.radius == 0.0)
      angle = an.number == 1   ? -std::numbers::pi / 2
              : an.number == 2 ? std::numbers::pi
              : an.number == 3 ? 0.0
                               : std::numbers::pi / 2;
    angle += random_.uniform(-0.2, 0.2);
    const double nx = std::cos(angle), ny = std::sin(angle);
    const double rln = random_.log_uniform(1.0e-3, 20.0);  // impulse / H, N
    const double mu = 0.3;
    const double rlt =
        sliding ? (random_.uniform() < 0.5 ? -mu : mu) * rln : mu * rln * random_.uniform(-0.95, 0.95);
    const double vlt = sliding ? random_.uniform(-1.0e-2, 1.0e-2) : random_.uniform(-1.0e-17, 1.0e-17);
    const double vln = random_.uniform(-1.0e-8, 1.0e-8);
    const double gap = -random_.log_uniform(1.0e-12, 1.0e-7);
    const double cx = cd.x + cd.radius * nx, cy = cd.y + cd.radius * ny;
    for (const grammar::VectorLineKind& line : kind->vectors) {
      grammar::VlocRlocVector v;
      for (int k = 0; k < line.count; ++k) v.labels.emplace_back(line.labels[k]);
      const std::string_view first = line.labels[0];
      if (first.starts_with("rl"))
        v.values = {Real{rlt}, Real{rln}, Real{0.0}};
      else if (first.starts_with("vl"))
        v.values = {Real{vlt}, Real{vln}, Real{0.0}};
      else if (first == "gapTT" || first == "gap =")
        v.values = {Real{gap}};
      else if (first == "n(1)=")
        v.values = {Real{nx}, Real{ny}, Real{0.0}};
      else
        v.values = {Real{cx}, Real{cy}, Real{0.0}};
      c.vectors.push_back(std::move(v));
    }
    return c;
  }

  Random& random() { return random_; }
  // Bodies per grid row: k + side() is the neighbour above k.
  std::size_t side() const { return side_; }

 private:
  Body2D body(std::size_t grid_index, std::int64_t number) const {
    const std::int64_t serial = grid_index < disks_ ? static_cast<std::int64_t>(grid_index)
                                                    : static_cast<std::int64_t>(grid_index - disks_);
    return Body2D{number, serial + 1, kSpacing * static_cast<double>(grid_index % side_),
                  kSpacing * static_cast<double>(grid_index / side_),
                  1.0e-3 * (1.0 + 0.1 * static_cast<double>(grid_index % 7))};
  }

  std::size_t disks_, side_;
  Random random_{20240611};
};

// The '#' line naming the 5 internal variables of a cohesive (MAC_CZM-like) law, as LMGC90 writes
// it: names at columns 2, 17, 32, 47, 62, the line padded with blanks to 285 columns.
std::string cohesive_internal_comment() {
  std::string line(285, ' ');
  line[0] = '#';
  constexpr std::string_view kNames[] = {"taille_ele", "saut_de_ut", "saut_de_un", "beta", "TPSini"};
  for (std::size_t k = 0; k < 5; ++k) line.replace(1 + 15 * k, kNames[k].size(), kNames[k]);
  return line;
}

std::string status(Random& random, bool sliding, bool cohesive) {
  const bool forward = random.uniform() < 0.5;
  if (cohesive) return sliding ? (forward ? "Cslfw" : "Cslbw") : "Cstck";
  return sliding ? (forward ? "slifw" : "slibw") : "stick";
}

}  // namespace

std::string generated_vloc_rloc_ini(std::size_t count) {
  using grammar::Real;
  // Shares of the modules; the polygon modules come in vertex pairs, so their counts are even.
  const std::size_t plpl = count * 3 / 10 / 2 * 2;
  const std::size_t pljc = count / 10 / 2 * 2;
  const std::size_t dkjc = count / 10;
  const std::size_t dkdk = count - plpl - pljc - dkjc;
  const std::size_t disks = std::max<std::size_t>(2, dkdk * 3 / 5);
  const std::size_t polygons = std::max<std::size_t>(2, plpl * 2 / 3);
  VlocRlocGenerator gen(disks, polygons);
  Random& random = gen.random();

  grammar::VlocRlocFile file;
  file.step = grammar::Integer{1200};
  file.time = Real{0.24};
  file.interactions.reserve(count);
  // DKDKx: 1-2 contacts per candidate disk (with its right or upper neighbour), in candidate order;
  // iadj = the antagonist's serial.
  for (std::size_t m = 0; m < dkdk; ++m) {
    const std::size_t k = m * disks / std::max<std::size_t>(1, dkdk);
    const Body2D cd = gen.disk(k), an = gen.disk((k + (m % 2 == 0 ? 1 : gen.side())) % disks);
    const bool sliding = random.uniform() < 0.3;
    file.interactions.push_back(
        gen.make("DKDKx", static_cast<std::int64_t>(m + 1),
                 {"RBDY2", "DISKx", "iqsc0", "RBDY2", "DISKx", status(random, sliding, false)},
                 {cd.number, 1, an.number, 1, an.serial}, cd, an, sliding));
  }
  // DKJCx: disks against the 4 walls.
  for (std::size_t m = 0; m < dkjc; ++m) {
    const Body2D cd = gen.disk(m * disks / std::max<std::size_t>(1, dkjc)), an = gen.wall(m % kWalls);
    const bool sliding = random.uniform() < 0.3;
    file.interactions.push_back(
        gen.make("DKJCx", static_cast<std::int64_t>(m + 1),
                 {"RBDY2", "DISKx", "iqsc0", "RBDY2", "JONCx", status(random, sliding, false)},
                 {cd.number, 1, an.number, 1, an.serial}, cd, an, sliding));
  }
  // PLJCx: two vertices of a pentagon on a wall; iadj counts the candidate's contacts.
  for (std::size_t m = 0; m < pljc; ++m) {
    const std::size_t pair = m / 2;
    const Body2D cd = gen.polygon(pair * 2 * polygons / std::max<std::size_t>(1, pljc) % polygons),
                 an = gen.wall(pair % kWalls);
    const bool sliding = random.uniform() < 0.3;
    file.interactions.push_back(
        gen.make("PLJCx", static_cast<std::int64_t>(m + 1),
                 {"RBDY2", "POLYG", "CDVER", "iqsc0", "RBDY2", "JONCx", status(random, sliding, false)},
                 {cd.number, 1, static_cast<std::int64_t>(1 + (pair + m % 2) % 5), an.number, 1,
                  static_cast<std::int64_t>(1 + m % 2)},
                 cd, an, sliding));
  }
  // PLPLx: two vertices of a pentagon on a segment of its right or upper neighbour; every other pair
  // cohesive, with the law's 5 internal variables (named '#' line, values on one line).
  const std::string comment = cohesive_internal_comment();
  for (std::size_t m = 0; m < plpl; ++m) {
    const std::size_t pair = m / 2;
    const std::size_t k = pair * 2 * polygons / std::max<std::size_t>(1, plpl);
    const Body2D cd = gen.polygon(k), an = gen.polygon((k + (pair % 2 == 0 ? 1 : gen.side())) % polygons);
    const bool cohesive = pair % 2 == 0;
    const bool sliding = random.uniform() < (cohesive ? 0.1 : 0.3);
    grammar::VlocRlocInteraction c =
        gen.make("PLPLx", static_cast<std::int64_t>(m + 1),
                 {"RBDY2", "POLYG", "CDVER", cohesive ? "mac01" : "iqsc0", "RBDY2", "POLYG", "ANSEG",
                  status(random, sliding, cohesive)},
                 {cd.number, 1, static_cast<std::int64_t>(1 + (pair + m % 2) % 5), an.number, 1,
                  static_cast<std::int64_t>(1 + pair % 5), an.serial},
                 cd, an, sliding);
    if (cohesive) {
      c.internal_comment = comment;
      c.internal_lines.push_back({Real{cd.radius * random.uniform(0.4, 0.6)},
                                  Real{random.uniform(-1.0e-4, 1.0e-4)},
                                  Real{random.uniform(-1.0e-8, 1.0e-8)},
                                  Real{random.uniform() < 0.8 ? 1.0 : random.uniform()}, Real{-99.0}});
    }
    file.interactions.push_back(std::move(c));
  }
  return grammar::write_vloc_rloc(file);
}

}  // namespace lmgc::bench
