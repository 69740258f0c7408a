#include "solver/bodies/surface_integrals_t3.hpp"

// Every sum and product below keeps the Fortran operation order (left to right, same parentheses,
// DOT_PRODUCT as a running sum from zero) so that each rounding is LMGC90's. Line numbers are those
// of src/Core/shared/mod_DiscreteGeometry.f90 unless another file is named.

// No contraction of a*b+c into an FMA (LMGC90 is built for baseline x86-64, which has none): Clang
// contracts by default when the target has FMA, GCC does so in the GNU dialects.
#if defined(__clang__)
#pragma clang fp contract(off)
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif

#include <cmath>
#include <stdexcept>
#include <utility>

#include "solver/bodies/polyhedron.hpp"

namespace lmgc::solver {
namespace {

using Face = std::array<std::int32_t, 3>;

// The three corners of a face in its connectivity order: x[k][id] is the Fortran X(id, k+1).
struct Triangle {
  double x[3][3];
};

Triangle triangle_of(const std::vector<Eigen::Vector3d>& vertices, const Face& f) {
  Triangle t;
  for (std::size_t k = 0; k < 3; ++k)
    for (int id = 0; id < 3; ++id) t.x[k][id] = vertices[static_cast<std::size_t>(f[k])][id];
  return t;
}

// DOT_PRODUCT of two 3-vectors as gfortran evaluates it: a running sum from zero, in index order.
double dot3(const double a[3], const double b[3]) {
  double s = 0.0;
  s = s + a[0] * b[0];
  s = s + a[1] * b[1];
  s = s + a[2] * b[2];
  return s;
}

// length3 (mod_algebra.f90:165-171): sqrt of that dot product.
double length3(const double v[3]) {
  return std::sqrt(dot3(v, v));
}

// cross_product (mod_algebra.f90:153-161).
void cross_product(const double a[3], const double b[3], double c[3]) {
  c[0] = (a[1] * b[2]) - (a[2] * b[1]);
  c[1] = (a[2] * b[0]) - (a[0] * b[2]);
  c[2] = (a[0] * b[1]) - (a[1] * b[0]);
}

// A triangle quadrature rule of pos_gauss (mod_a_EF.f90:313-332): reference coordinates (ksi, eta)
// and weights, all double-precision literals or quotients of them.
struct Rule {
  int n;
  double ksi[4], eta[4], weight[4];
};

// TR01: the centroid, weight 1/2 (UN/TROIS, US2).
constexpr Rule tr01{1, {1.0 / 3.0}, {1.0 / 3.0}, {0.5}};
// TR03: (1/6, 1/6), (2/3, 1/6), (1/6, 2/3), weights 1/6 (UN/SIX, DEUX/TROIS).
constexpr Rule tr03{3,
                    {1.0 / 6.0, 2.0 / 3.0, 1.0 / 6.0},
                    {1.0 / 6.0, 1.0 / 6.0, 2.0 / 3.0},
                    {1.0 / 6.0, 1.0 / 6.0, 1.0 / 6.0}};
// TR04: the centroid with weight -27/96, then (0.2, 0.2), (0.6, 0.2), (0.2, 0.6) with 25/96.
constexpr Rule tr04{4,
                    {1.0 / 3.0, 0.2, 0.6, 0.2},
                    {1.0 / 3.0, 0.2, 0.2, 0.6},
                    {-27.0 / 96.0, 25.0 / 96.0, 25.0 / 96.0, 25.0 / 96.0}};

// get_gp_coor (mod_a_EF.f90:1556-1568): the Gauss point's real coordinates, N(1:3) . X(id, 1:3)
// with the T_P1 shape functions N = (1 - ksi - eta, ksi, eta) of fonct_forme (mod_a_EF.f90:629-633).
void gauss_point(const Triangle& t, const Rule& rule, int ig, double gp[3]) {
  const double ksi = rule.ksi[ig], eta = rule.eta[ig];
  const double n[3] = {1.0 - ksi - eta, ksi, eta};
  for (int id = 0; id < 3; ++id) {
    const double column[3] = {t.x[0][id], t.x[1][id], t.x[2][id]};
    gp[id] = dot3(n, column);
  }
}

// The Jacobian of integrate_field for a T_P1 element in 3D (mod_a_EF.f90:1874-1908): the rows
// (-1, 1, 0) and (-1, 0, 1) of the TEP1 shape-function derivatives (derive_forme,
// mod_a_EF.f90:999-1004) dotted with X(id, 1:3) give the two edge vectors from corner 1, and
// detJ = length3 of their cross product (twice the area). It does not depend on the Gauss point.
double jacobian(const Triangle& t) {
  const double d_ksi[3] = {-1.0, 1.0, 0.0}, d_eta[3] = {-1.0, 0.0, 1.0};
  double v1[3], v2[3], c[3];
  for (int id = 0; id < 3; ++id) {
    const double column[3] = {t.x[0][id], t.x[1][id], t.x[2][id]};
    v1[id] = dot3(d_ksi, column);
    v2[id] = dot3(d_eta, column);
  }
  cross_product(v1, v2, c);
  return length3(c);
}

// integrate_field's sum (mod_a_EF.f90:1888-1911): res = 0, then res + (detJ * weight) * field, in
// Gauss-point order.
double integrate(const double field[4], const Rule& rule, double det_j) {
  double res = 0.0;
  for (int ig = 0; ig < rule.n; ++ig) {
    const double coefint = det_j * rule.weight[ig];
    res = res + coefint * field[ig];
  }
  return res;
}

// compute_info_triangle's normal (:6917-6997): sides v1 = s2 - s3, v2 = s1 - s3, v3 = s2 - s1 and
// Heron's area; merged (half-perimeter < 1e-12) or aligned corners (area < 1e-24) give a zero
// normal and `false`; otherwise the normalised v1 × v3 (component by component division).
bool face_normal(const Triangle& t, double normal[3]) {
  const double tol = 1e-12;
  double v1[3], v2[3], v3[3];
  for (int id = 0; id < 3; ++id) {
    v1[id] = t.x[1][id] - t.x[2][id];
    v2[id] = t.x[0][id] - t.x[2][id];
    v3[id] = t.x[1][id] - t.x[0][id];
  }
  const double l1 = length3(v1), l2 = length3(v2), l3 = length3(v3);
  const double hp = 0.5 * (l1 + l2 + l3);
  const double surf = std::sqrt(hp * (hp - l1) * (hp - l2) * (hp - l3));
  if ((hp < tol && surf < tol * tol) || (hp > tol && surf < tol * tol)) {
    normal[0] = normal[1] = normal[2] = 0.0;
    return false;
  }
  cross_product(v1, v3, normal);
  const double length = length3(normal);
  for (int id = 0; id < 3; ++id) normal[id] = normal[id] / length;
  return true;
}

// The integrands (:7624-7774) at a Gauss point p, or its offset d = p - G from the centre, for a
// face of normal n.
double f_vol(const double p[3], const double n[3]) {
  return p[0] * n[0];
}
double f_half_square(const double p[3], const double n[3], int k) {  // f_xG, f_yG, f_zG
  return 0.5 * p[k] * p[k] * n[k];
}
double f_cube_pair(const double d[3], const double n[3], int a, int b) {  // f_I11 (a, b = y, z) ..
  const double untiers = 1.0 / 3.0;
  return (d[a] * d[a] * d[a] * n[a] + d[b] * d[b] * d[b] * n[b]) * untiers;
}
double f_product(const double d[3], const double n[3], int a, int b) {  // f_I32 (a = y, b = z) ..
  return -(0.5 * d[a] * d[a] * d[b] * n[a]);
}

}  // namespace

SurfaceT3Integrals lmgc90_surface_t3_integrals(const std::vector<Eigen::Vector3d>& vertices,
                                               const std::vector<std::array<std::int32_t, 3>>& faces,
                                               bool compute_inertia) {
  const auto nv = static_cast<std::int32_t>(vertices.size());
  for (const Face& f : faces)
    for (std::int32_t k : f)
      if (k < 0 || k >= nv)
        throw std::invalid_argument("lmgc90_surface_t3_integrals: face names a missing vertex");

  SurfaceT3Integrals out;
  out.faces = faces;
  const std::size_t nf = faces.size();

  // Normals of the faces as given (:6322-6344).
  std::vector<std::array<double, 3>> normals(nf);
  for (std::size_t ie = 0; ie < nf; ++ie)
    if (!face_normal(triangle_of(vertices, faces[ie]), normals[ie].data())) ++out.degenerate_faces;

  // Volume (compute_volume_surface_T3 :6055-6084): faces with n_x exactly 0 are skipped.
  double vol = 0.0;
  for (std::size_t ie = 0; ie < nf; ++ie) {
    const double* n = normals[ie].data();
    if (n[0] != 0.0) {
      const Triangle t = triangle_of(vertices, faces[ie]);
      double gp[3], field[4];
      gauss_point(t, tr01, 0, gp);
      field[0] = f_vol(gp, n);
      vol = vol + integrate(field, tr01, jacobian(t));
    }
  }

  // A negative volume turns everything over (:6352-6361): |V|, negated normals (not recomputed),
  // 2nd and 3rd vertices swapped.
  if (vol < 0.0) {
    vol = std::abs(vol);
    for (auto& n : normals)
      for (double& c : n) c = -c;
    for (Face& f : out.faces) std::swap(f[1], f[2]);
    out.flipped = true;
  }
  out.volume = vol;

  // Centre of inertia (compute_mass_center_surface_T3 :6125-6166), on the possibly swapped faces.
  double x_g[3] = {0.0, 0.0, 0.0};
  for (std::size_t ie = 0; ie < nf; ++ie) {
    const Triangle t = triangle_of(vertices, out.faces[ie]);
    const double* n = normals[ie].data();
    const double det_j = jacobian(t);
    double gp[3][3];
    for (int ig = 0; ig < tr03.n; ++ig) gauss_point(t, tr03, ig, gp[ig]);
    double value[3];
    for (int k = 0; k < 3; ++k) {
      double field[4];
      for (int ig = 0; ig < tr03.n; ++ig) field[ig] = f_half_square(gp[ig], n, k);
      value[k] = integrate(field, tr03, det_j);
    }
    for (int k = 0; k < 3; ++k) x_g[k] = x_g[k] + value[k];
  }
  for (int k = 0; k < 3; ++k) x_g[k] = x_g[k] / vol;
  out.centre = Eigen::Vector3d(x_g[0], x_g[1], x_g[2]);

  if (!compute_inertia) return out;  // I = 0 (:6376-6381)

  // Inertia tensor about x_G (compute_inertia_surface_T3 :6206-6267): Voigt components in the
  // order I11, I22, I33, I32, I31, I21, each integrated over the face on its own.
  double i_vect[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  for (std::size_t ie = 0; ie < nf; ++ie) {
    const Triangle t = triangle_of(vertices, out.faces[ie]);
    const double* n = normals[ie].data();
    const double det_j = jacobian(t);
    double d[4][3];  // Gauss points about x_G (coor_bary of the f_I* functions)
    for (int ig = 0; ig < tr04.n; ++ig) {
      double gp[3];
      gauss_point(t, tr04, ig, gp);
      for (int id = 0; id < 3; ++id) d[ig][id] = gp[id] - x_g[id];
    }
    double value[6];
    for (int c = 0; c < 6; ++c) {
      double field[4];
      for (int ig = 0; ig < tr04.n; ++ig) {
        switch (c) {
          case 0:
            field[ig] = f_cube_pair(d[ig], n, 1, 2);
            break;  // f_I11
          case 1:
            field[ig] = f_cube_pair(d[ig], n, 0, 2);
            break;  // f_I22
          case 2:
            field[ig] = f_cube_pair(d[ig], n, 0, 1);
            break;  // f_I33
          case 3:
            field[ig] = f_product(d[ig], n, 1, 2);
            break;  // f_I32
          case 4:
            field[ig] = f_product(d[ig], n, 0, 2);
            break;  // f_I31
          default:
            field[ig] = f_product(d[ig], n, 0, 1);
            break;  // f_I21
        }
      }
      value[c] = integrate(field, tr04, det_j);
    }
    for (int c = 0; c < 6; ++c) i_vect[c] = i_vect[c] + value[c];
  }
  // Full symmetric matrix (:6262-6267).
  Eigen::Matrix3d& m = out.inertia;
  m(0, 0) = i_vect[0];
  m(1, 1) = i_vect[1];
  m(2, 2) = i_vect[2];
  m(2, 1) = m(1, 2) = i_vect[3];
  m(2, 0) = m(0, 2) = i_vect[4];
  m(1, 0) = m(0, 1) = i_vect[5];
  return out;
}

SurfaceT3Integrals lmgc90_polyr_integrals(const std::vector<Eigen::Vector3d>& vertices,
                                          const std::vector<std::array<std::int32_t, 3>>& faces_as_read,
                                          bool compute_inertia) {
  std::vector<Face> faces = faces_as_read;
  orient_faces(vertices, faces);
  // Undo orient_faces' turn-over on its own volume: LMGC90 turns the faces over after integrating
  // the volume on the unturned ones, which lmgc90_surface_t3_integrals redoes.
  if (!faces.empty()) {
    const Face& read = faces_as_read.front();
    const Face& oriented = faces.front();
    if (read[1] != read[2] && oriented[0] == read[0] && oriented[1] == read[2] && oriented[2] == read[1])
      for (Face& f : faces) std::swap(f[1], f[2]);
  }
  return lmgc90_surface_t3_integrals(vertices, faces, compute_inertia);
}

}  // namespace lmgc::solver
