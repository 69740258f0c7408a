#include "bench/scenes/generated_files.hpp"

#include <cmath>

#include "grammar/bodies/writer.hpp"

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
    node.coordinates = {Real{0.0025 * static_cast<double>(i % side)}, Real{0.0025 * static_cast<double>(i / side)},
                        Real{0.0}};
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
        c.vertices.push_back({Real{bulk.avrd.value * std::cos(angle)}, Real{bulk.avrd.value * std::sin(angle)}, Real{0.0}});
      }
    }
    b.contactors.push_back(c);
    file.bodies.push_back(std::move(b));
  }
  return write_bodies(file);
}

}  // namespace lmgc::bench
