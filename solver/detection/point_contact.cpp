#include "solver/detection/point_contact.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <utility>

namespace lmgc::solver {

using Eigen::Vector3d;

namespace {

// Where contactor k is for reference lengths: the reference configuration, or the current one.
Vector3d link_position(const Scene3D& scene, std::size_t k, LinkLength length) {
  const Contactor3D& c = scene.contactors[k];
  const RigidBodies3D& b = scene.bodies;
  const auto body = static_cast<std::size_t>(c.body);
  if (length == LinkLength::current)
    return b.reference[body] + b.displacement_begin[body].head<3>() + b.frame[body] * c.shift;
  return b.reference[body] + b.frame_initial[body] * c.shift;
}

// The scene's PT3Dx contactors in contactor order: LMGC90's PT3Dx numbering, from 1.
std::vector<std::size_t> point_contactors(const Scene3D& scene) {
  std::vector<std::size_t> points;
  for (std::size_t k = 0; k < scene.contactors.size(); ++k)
    if (scene.contactors[k].shape == ContactorShape3D::point) points.push_back(k);
  return points;
}

// The first PTPT3 visibility row for two colours, read in either order as get_isee reads rows; -1
// when none.
std::int32_t ptpt3_row(const Scene3D& scene, const std::string& a, const std::string& b) {
  for (std::size_t r = 0; r < scene.visibility.size(); ++r) {
    const Visibility3D& v = scene.visibility[r];
    if (v.family == PairFamily3D::PTPT3 && ((v.candidate_color == a && v.antagonist_color == b) ||
                                            (v.candidate_color == b && v.antagonist_color == a)))
      return static_cast<std::int32_t>(r);
  }
  return -1;
}

// pair_rank: the links of one pair numbered 0, 1, ... in list order.
void rank_pairs(std::vector<PointLink3D>& links) {
  std::map<std::pair<std::int32_t, std::int32_t>, std::int32_t> seen;
  for (PointLink3D& link : links) link.pair_rank = seen[{link.candidate, link.antagonist}]++;
}

}  // namespace

Vector3d period_shift(const Scene3D& scene, const std::array<std::int32_t, 2>& periods) {
  return Vector3d(periods[0] * scene.x_period, periods[1] * scene.y_period, 0.0);
}

std::vector<PointLink3D> link_points_3d(const Scene3D& scene, LinkLength length) {
  std::vector<PointLink3D> links;
  const std::vector<std::size_t> points = point_contactors(scene);
  // The images tried besides the direct pair: those within one period of the candidate along each
  // periodic axis, counted in the periodic cell (points wrapped into it) and kept as the shift
  // between the points where they are, so that points outside the cell link as inside.
  const int x_reach = scene.x_period > 0.0 ? 1 : 0, y_reach = scene.y_period > 0.0 ? 1 : 0;
  const auto cell = [&](const Vector3d& x) {
    return std::array<std::int32_t, 2>{
        scene.x_period > 0.0 ? static_cast<std::int32_t>(std::floor(x.x() / scene.x_period)) : 0,
        scene.y_period > 0.0 ? static_cast<std::int32_t>(std::floor(x.y() / scene.y_period)) : 0};
  };
  std::vector<std::array<std::int32_t, 2>> tried;
  for (std::size_t p = 0; p < points.size(); ++p) {
    const Contactor3D& cd = scene.contactors[points[p]];
    const Vector3d cd_at = link_position(scene, points[p], length);
    const std::array<std::int32_t, 2> cd_cell = cell(cd_at);
    for (std::size_t q = p + 1; q < points.size(); ++q) {
      const Contactor3D& an = scene.contactors[points[q]];
      if (cd.body == an.body) continue;
      const std::int32_t row = ptpt3_row(scene, cd.color, an.color);
      if (row < 0) continue;
      const double alert = scene.visibility[static_cast<std::size_t>(row)].alert;
      const Vector3d an_at = link_position(scene, points[q], length);
      const std::array<std::int32_t, 2> an_cell = cell(an_at);
      tried.assign(1, {0, 0});
      for (int iy = -y_reach; iy <= y_reach; ++iy)
        for (int ix = -x_reach; ix <= x_reach; ++ix) {
          const std::array<std::int32_t, 2> periods = {ix + cd_cell[0] - an_cell[0],
                                                       iy + cd_cell[1] - an_cell[1]};
          if (std::find(tried.begin(), tried.end(), periods) == tried.end()) tried.push_back(periods);
        }
      for (const std::array<std::int32_t, 2>& periods : tried) {
        const double distance = (cd_at - an_at - period_shift(scene, periods)).norm();
        if (distance <= alert)
          links.push_back({static_cast<std::int32_t>(points[p]), static_cast<std::int32_t>(points[q]), row,
                           distance, periods, false, 0});
      }
    }
  }
  rank_pairs(links);
  return links;
}

bool network_links_3d(const Scene3D& scene, const grammar::Ptpt3NetworkFile& network, LinkLength length,
                      std::vector<PointLink3D>& links, std::string& error) {
  links.clear();
  const std::vector<std::size_t> points = point_contactors(scene);
  for (std::size_t l = 0; l < network.links.size(); ++l) {
    const grammar::Ptpt3Link& link = network.links[l];
    const std::string where = "PTPT3_NETWORK.DAT link " + std::to_string(l + 1) + ": ";
    const std::int64_t count = static_cast<std::int64_t>(points.size());
    if (link.candidate.value < 1 || link.candidate.value > count || link.antagonist.value < 1 ||
        link.antagonist.value > count) {
      error =
          where + "point " +
          std::to_string(link.candidate.value < 1 || link.candidate.value > count ? link.candidate.value
                                                                                  : link.antagonist.value) +
          " does not exist (the case has " + std::to_string(count) + " PT3Dx)";
      return false;
    }
    const std::size_t i = points[static_cast<std::size_t>(link.candidate.value - 1)];
    const std::size_t j = points[static_cast<std::size_t>(link.antagonist.value - 1)];
    const Contactor3D &cd = scene.contactors[i], &an = scene.contactors[j];
    if (cd.body == an.body) {
      error = where + "both points are on body " + std::to_string(cd.body + 1);
      return false;
    }
    const std::int32_t row = ptpt3_row(scene, cd.color, an.color);
    if (row < 0) {
      error = where + "no PTPT3 visibility row reads PT3Dx " + cd.color + " against PT3Dx " + an.color;
      return false;
    }
    // iloop = 1 shifts the candidate by the periods, which is the antagonist shifted the other way.
    const auto sign = link.loop.value == 1 ? -1 : 1;
    const std::array<std::int32_t, 2> periods = {sign * static_cast<std::int32_t>(link.x_periods.value),
                                                 sign * static_cast<std::int32_t>(link.y_periods.value)};
    const double reference_length = length == LinkLength::current
                                        ? link.reference_length.value
                                        : (link_position(scene, i, length) - link_position(scene, j, length) -
                                           period_shift(scene, periods))
                                              .norm();
    links.push_back({static_cast<std::int32_t>(i), static_cast<std::int32_t>(j), row, reference_length,
                     periods, sign < 0, 0});
  }
  rank_pairs(links);
  return true;
}

ContactGeometry3D point_point_geometry(const Vector3d& candidate, const Vector3d& antagonist) {
  ContactGeometry3D g;
  g.point = 0.5 * (candidate + antagonist);
  const double distance = (candidate - antagonist).norm();
  if (distance < 1e-20) {
    g.tangent = Vector3d::UnitX();
    g.normal = Vector3d::UnitY();
    g.second_tangent = Vector3d::UnitZ();
    return g;
  }
  Vector3d n = (candidate - antagonist) / distance;
  for (int k = 0; k < 3; ++k)
    if (std::abs(n(k)) < 1e-18) n(k) = 0.0;
  Vector3d t;
  if (n.x() * n.y() == 0.0 && n.y() * n.z() == 0.0 && n.z() * n.x() == 0.0) {
    t = n.x() != 0.0 ? Vector3d::UnitZ() : n.y() != 0.0 ? Vector3d::UnitX() : Vector3d::UnitY();
  } else if (n.x() == 0.0) {
    const double f = -n.y() / n.z();
    t = Vector3d(1.0, 1.0, f) / std::sqrt(f * f + 2.0);
  } else {
    const double f = -(n.y() + n.z()) / n.x();
    t = Vector3d(f, 1.0, 1.0) / std::sqrt(f * f + 2.0);
  }
  g.normal = n;
  g.tangent = t;
  g.second_tangent = t.cross(n);
  g.gap = distance;
  return g;
}

}  // namespace lmgc::solver
