#include "solver/io/mesh_gauss_values.hpp"

#include "solver/fem/large_strain.hpp"

namespace lmgc::solver {

namespace {

using fem::Hypothesis;

// stress and strain of one Gauss point in the written order.
void point_values(const fem::MeshBody& body, bool matlib, const Eigen::VectorXd& strain_voigt, double poisson,
                  const Eigen::MatrixXd& d, std::vector<std::vector<grammar::Real>>& lines) {
  const Eigen::VectorXd stress_voigt = d * strain_voigt;
  std::vector<double> stress, strain;
  if (body.dimension == 2) {
    // Voigt (xx, yy, xy[, θθ]) → the 4-component vectors.
    double szz = 0.0, ezz = 0.0;
    if (body.hypothesis == Hypothesis::axisymmetric) {
      szz = stress_voigt(3);
      ezz = strain_voigt(3);
    } else if (body.hypothesis == Hypothesis::plane_strain) {
      szz = poisson * (stress_voigt(0) + stress_voigt(1));
    }
    if (matlib) {
      stress = {stress_voigt(0), stress_voigt(2), stress_voigt(1), szz};
      strain = {strain_voigt(0), strain_voigt(2), strain_voigt(1), ezz};
    } else {
      stress = {stress_voigt(0), stress_voigt(1), stress_voigt(2), szz};
      strain = {strain_voigt(0), strain_voigt(1), strain_voigt(2), ezz};
    }
  } else {
    // Voigt (xx, yy, zz, xy, yz, zx).
    const auto order = matlib ? std::array<int, 6>{0, 3, 1, 5, 4, 2} : std::array<int, 6>{0, 1, 2, 3, 4, 5};
    for (int k : order) {
      stress.push_back(stress_voigt(k));
      strain.push_back(strain_voigt(k));
    }
  }
  const auto line = [](const std::vector<double>& v) {
    return std::vector<grammar::Real>(v.begin(), v.end());
  };
  lines.push_back(line(stress));
  lines.push_back(line(strain));
  if (matlib) lines.push_back({grammar::Real{0.5 * stress_voigt.dot(strain_voigt)}});
}

}  // namespace

namespace {

// The written value lines (stress, strain[, energy] per Gauss point) of one element.
std::vector<std::vector<grammar::Real>> element_lines(const fem::MeshBody& body, bool matlib,
                                                      const Eigen::VectorXd& displacement, std::size_t e) {
  std::vector<std::vector<grammar::Real>> lines;
  const fem::MeshElement& element = body.elements[e];
  const fem::ElementEntry& entry = fem::element_entry(element.kind);
  const fem::Material& material = body.materials[static_cast<std::size_t>(element.material)];
  const Eigen::MatrixXd d = fem::elasticity_matrix(body.hypothesis, material.young, material.poisson);
  fem::with_element(element.kind, [&](auto shape) {
    using E = decltype(shape);
    constexpr int D = E::kDimension;
    if (D != body.dimension) return;
    fem::NodeCoordinates<E> x;
    Eigen::Matrix<double, E::kNodes * D, 1> u;
    for (int k = 0; k < E::kNodes; ++k) {
      const auto node = static_cast<Eigen::Index>(element.nodes[static_cast<std::size_t>(k)]);
      for (int c = 0; c < D; ++c) {
        x(k, c) = body.coordinates[static_cast<std::size_t>(node * D + c)];
        u(k * D + c) = displacement(node * D + c);
      }
    }
    const fem::QuadratureRule<D> rule = fem::quadrature<D>(entry.stiffness_rule);
    for (int p = 0; p < rule.size(); ++p) {
      const auto g = fem::point_geometry<E>(x, rule.points[static_cast<std::size_t>(p)],
                                            rule.weights[static_cast<std::size_t>(p)], body.hypothesis);
      if (!g) continue;  // refused when the body was assembled
      const Eigen::VectorXd strain = fem::strain_matrix<E>(*g, body.hypothesis) * u;
      point_values(body, matlib, strain, material.poisson, d, lines);
    }
  });
  return lines;
}

}  // namespace

namespace {

// A large-strain body's points: P and F (11, 12, 21, 22, 33), then the material's internal variables
// (mailx-2d-large-strain.md §5).
std::vector<std::vector<grammar::Real>> large_strain_lines(const fem::MeshBody& body,
                                                           const Eigen::VectorXd& displacement,
                                                           std::size_t e) {
  std::vector<std::vector<grammar::Real>> lines;
  const auto values = [](const auto& v) {
    std::vector<grammar::Real> line;
    for (auto x : v) line.push_back(grammar::Real{x});
    return line;
  };
  for (const fem::LargeStrainPoint& p : fem::large_strain_points(body, displacement, e)) {
    lines.push_back(values(p.stress));
    lines.push_back(values(p.gradient));
    if (!p.internal.empty()) lines.push_back(values(p.internal));
  }
  return lines;
}

}  // namespace

grammar::GpvBody gauss_point_values(const fem::MeshBody& body, bool matlib,
                                    const Eigen::VectorXd& displacement, int body_number) {
  grammar::GpvBody out;
  out.number = body_number;
  for (std::size_t e = 0; e < body.elements.size(); ++e) {
    grammar::GpvElement written;
    written.type = grammar::Word{std::string(fem::element_entry(body.elements[e].kind).body_name)};
    written.number = static_cast<std::int64_t>(e + 1);
    grammar::GpvModelBlock block;
    block.model = grammar::Word{std::string("MECAx")};
    block.lines = body.kinematics == fem::Kinematics::total_lagrangian
                      ? large_strain_lines(body, displacement, e)
                      : element_lines(body, matlib, displacement, e);
    written.models.push_back(std::move(block));
    out.elements.push_back(std::move(written));
  }
  return out;
}

void element_mean_strain_stress(const fem::MeshBody& body, const Eigen::VectorXd& displacement,
                                std::size_t element, Eigen::Vector4d& strain, Eigen::Vector4d& stress) {
  strain.setZero();
  stress.setZero();
  if (body.kinematics == fem::Kinematics::total_lagrangian) {
    // Large strain: the Green–Lagrange strain E = ½(FᵀF − I) (γxy = 2E12) and the Cauchy stress
    // σ = P Fᵀ / det F, averaged over the Gauss points.
    const auto points = fem::large_strain_points(body, displacement, element);
    for (const fem::LargeStrainPoint& p : points) {
      Eigen::Matrix3d f = Eigen::Matrix3d::Zero(), pk = Eigen::Matrix3d::Zero();
      f << p.gradient(0), p.gradient(1), 0, p.gradient(2), p.gradient(3), 0, 0, 0, p.gradient(4);
      pk << p.stress(0), p.stress(1), 0, p.stress(2), p.stress(3), 0, 0, 0, p.stress(4);
      const Eigen::Matrix3d e = 0.5 * (f.transpose() * f - Eigen::Matrix3d::Identity());
      const Eigen::Matrix3d sigma = pk * f.transpose() / f.determinant();
      const double w = 1.0 / static_cast<double>(points.size());
      strain += w * Eigen::Vector4d(e(0, 0), e(1, 1), 2.0 * e(0, 1), e(2, 2));
      stress += w * Eigen::Vector4d(sigma(0, 0), sigma(1, 1), sigma(0, 1), sigma(2, 2));
    }
    return;
  }
  const auto lines = element_lines(body, false, displacement, element);
  const std::size_t points = lines.size() / 2;
  for (std::size_t p = 0; p < points; ++p)
    for (int k = 0; k < 4 && static_cast<std::size_t>(k) < lines[2 * p].size(); ++k) {
      stress(k) += lines[2 * p][static_cast<std::size_t>(k)].value / static_cast<double>(points);
      strain(k) += lines[2 * p + 1][static_cast<std::size_t>(k)].value / static_cast<double>(points);
    }
}

namespace {

// A body with J2 plasticity (LMGC90's own large-strain material): per point its stored Cauchy stress
// (xx, yy, xy, zz), a strain line LMGC90 never fills (zeros), the 6 internal variables.
grammar::GpvBody plastic_point_values(const fem::MeshBody& body, const MeshBodyState& s, int body_number) {
  grammar::GpvBody out;
  out.number = body_number;
  for (std::size_t e = 0; e < body.elements.size(); ++e) {
    grammar::GpvElement written;
    written.type = grammar::Word{std::string(fem::element_entry(body.elements[e].kind).body_name)};
    written.number = static_cast<std::int64_t>(e + 1);
    grammar::GpvModelBlock block;
    block.model = grammar::Word{std::string("MECAx")};
    for (std::size_t p = e * 4; p < e * 4 + 4; ++p) {
      block.lines.emplace_back();
      for (std::size_t k = 0; k < 4; ++k)
        block.lines.back().push_back(grammar::Real{s.point_stress[p * 4 + k]});
      block.lines.emplace_back(4, grammar::Real{0.0});
      block.lines.emplace_back();
      for (std::size_t k = 0; k < static_cast<std::size_t>(fem::kJ2Internal); ++k)
        block.lines.back().push_back(grammar::Real{s.history[p * fem::kJ2Internal + k]});
    }
    written.models.push_back(std::move(block));
    out.elements.push_back(std::move(written));
  }
  return out;
}

}  // namespace

grammar::GpvFile gauss_point_values_file(const DeformableBodies& bodies, long step, double time) {
  grammar::GpvFile file;
  file.step = grammar::Integer{step};
  file.time = grammar::Real{time};
  for (std::size_t b = 0; b < bodies.states.size(); ++b) {
    const MeshBodyState& s = bodies.states[b];
    const fem::MeshBody& mesh = bodies.meshes.bodies[b];
    const int number = static_cast<int>(b + 1);
    file.bodies.push_back(s.history.empty() ? gauss_point_values(mesh, bodies.meshes.matlib[b], s.x, number)
                                            : plastic_point_values(mesh, s, number));
  }
  return file;
}

}  // namespace lmgc::solver
