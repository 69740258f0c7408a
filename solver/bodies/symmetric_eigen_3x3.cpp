#include "solver/bodies/symmetric_eigen_3x3.hpp"

// LMGC90 takes its principal frames from LAPACK's dsyevd, whose eigenvector signs depend on every
// rounding of its algorithm: to give LMGC90's frames, this follows the reference LAPACK/BLAS 3.11.0
// algorithm (BSD-3-Clause, netlib.org/lapack) that
// DSYEVD('V', 'L', N = 3) executes. Each function names the routine (and branch) it follows;
// the arithmetic keeps the Fortran operation order (left to right, same parentheses), so every
// rounding is the same. Arrays are 1-based like the Fortran ones (index 0 unused) to keep the
// loops recognisable. Fortran SIGN(A, B) is std::copysign(|A|, B) (gfortran honours the sign of a
// negative zero B).

// No contraction of a*b+c into an FMA (the Fortran library is built for baseline x86-64, which has
// none): Clang contracts by default when the target has FMA, GCC does so in the GNU dialects.
#if defined(__clang__)
#pragma clang fp contract(off)
#elif defined(__GNUC__)
#pragma GCC optimize("fp-contract=off")
#endif

#include <cmath>
#include <limits>
#include <stdexcept>

namespace lmgc::solver {
namespace {

constexpr int n = 3;

// DLAMCH (INSTALL/dlamch.f) for IEEE double.
constexpr double safe_minimum = std::numeric_limits<double>::min();     // 'S': TINY = 2^-1022
constexpr double epsilon = std::numeric_limits<double>::epsilon() / 2;  // 'E': 2^-53
constexpr double precision = std::numeric_limits<double>::epsilon();    // 'P': eps * base = 2^-52
constexpr double overflow = std::numeric_limits<double>::max();         // 'O': HUGE

double fsign(double a, double b) {
  return std::copysign(std::abs(a), b);
}

// The "IF (VALUE .LT. SUM .OR. DISNAN(SUM)) VALUE = SUM" of DLANSY / DLANST.
void keep_max(double& value, double sum) {
  if (value < sum || std::isnan(sum)) value = sum;
}

// Fortran column-major n x n array, 1-based: A(i, j).
struct FArray {
  double v[n * n] = {};
  double& operator()(int i, int j) { return v[(i - 1) + n * (j - 1)]; }
};

// DLAPY2 (3.11): sqrt(x^2 + y^2) avoiding overflow.
double dlapy2(double x, double y) {
  const bool x_is_nan = std::isnan(x), y_is_nan = std::isnan(y);
  double result = 0.0;
  if (x_is_nan) result = x;
  if (y_is_nan) result = y;
  if (!(x_is_nan || y_is_nan)) {
    const double xabs = std::abs(x), yabs = std::abs(y);
    const double w = xabs > yabs ? xabs : yabs;  // MAX
    const double z = xabs < yabs ? xabs : yabs;  // MIN
    if (z == 0.0 || w > overflow) {
      result = w;
    } else {
      const double q = z / w;
      result = w * std::sqrt(1.0 + q * q);
    }
  }
  return result;
}

// BLAS DNRM2 (3.10+ dnrm2.f90, Blue's scaled sums) of x(1..count), INCX = 1.
double dnrm2(int count, const double* x) {
  if (count <= 0) return 0.0;
  constexpr double tsml = 0x1p-511, tbig = 0x1p486, ssml = 0x1p537, sbig = 0x1p-538;
  constexpr double max_n = overflow;
  bool notbig = true;
  double asml = 0.0, amed = 0.0, abig = 0.0;
  for (int i = 0; i < count; ++i) {
    const double ax = std::abs(x[i]);
    if (ax > tbig) {
      const double t = ax * sbig;
      abig = abig + t * t;
      notbig = false;
    } else if (ax < tsml) {
      if (notbig) {
        const double t = ax * ssml;
        asml = asml + t * t;
      }
    } else {
      amed = amed + ax * ax;
    }
  }
  double scl = 1.0, sumsq = 0.0;
  if (abig > 0.0) {
    if (amed > 0.0 || amed > max_n || amed != amed) abig = abig + (amed * sbig) * sbig;
    scl = 1.0 / sbig;
    sumsq = abig;
  } else if (asml > 0.0) {
    if (amed > 0.0 || amed > max_n || amed != amed) {
      amed = std::sqrt(amed);
      asml = std::sqrt(asml) / ssml;
      double ymin, ymax;
      if (asml > amed) {
        ymin = amed;
        ymax = asml;
      } else {
        ymin = asml;
        ymax = amed;
      }
      scl = 1.0;
      const double q = ymin / ymax;
      sumsq = ymax * ymax * (1.0 + q * q);
    } else {
      scl = 1.0 / ssml;
      sumsq = asml;
    }
  } else {
    scl = 1.0;
    sumsq = amed;
  }
  return scl * std::sqrt(sumsq);
}

// DLARFG with N = 2 (the only call with N > 1 here): alpha, x(1) = A(2,1), A(3,1). Returns TAU;
// alpha becomes BETA, x the reflector's second component.
double dlarfg2(double& alpha, double& x) {
  double xnorm = dnrm2(1, &x);
  if (xnorm == 0.0) return 0.0;
  double beta = -fsign(dlapy2(alpha, xnorm), alpha);
  const double safmin = safe_minimum / epsilon;
  int knt = 0;
  if (std::abs(beta) < safmin) {
    const double rsafmn = 1.0 / safmin;
    do {
      ++knt;
      x = rsafmn * x;  // DSCAL
      beta = beta * rsafmn;
      alpha = alpha * rsafmn;
    } while (std::abs(beta) < safmin && knt < 20);
    xnorm = dnrm2(1, &x);
    beta = -fsign(dlapy2(alpha, xnorm), alpha);
  }
  const double tau = (beta - alpha) / beta;
  x = (1.0 / (alpha - beta)) * x;  // DSCAL
  for (int j = 1; j <= knt; ++j) beta = beta * safmin;
  alpha = beta;
  return tau;
}

// DLASCL multiplies by CTO/CFROM in one or several steps that cannot over/underflow; the steps
// are the same for every entry, so they are computed once (returns their count).
int dlascl_steps(double cfrom, double cto, double mul[8]) {
  const double smlnum = safe_minimum, bignum = 1.0 / smlnum;
  double cfromc = cfrom, ctoc = cto;
  int count = 0;
  bool done = false;
  while (!done && count < 8) {
    const double cfrom1 = cfromc * smlnum;
    double m;
    if (cfrom1 == cfromc) {  // CFROMC is an inf
      m = ctoc / cfromc;
      done = true;
    } else {
      const double cto1 = ctoc / bignum;
      if (cto1 == ctoc) {  // CTOC is 0 or an inf
        m = ctoc;
        done = true;
        cfromc = 1.0;
      } else if (std::abs(cfrom1) > std::abs(ctoc) && ctoc != 0.0) {
        m = smlnum;
        cfromc = cfrom1;
      } else if (std::abs(cto1) > std::abs(cfromc)) {
        m = bignum;
        ctoc = cto1;
      } else {
        m = ctoc / cfromc;
        done = true;
        if (m == 1.0) return count;
      }
    }
    mul[count++] = m;
  }
  return count;
}
void dlascl_apply(int steps, const double mul[8], double& x) {
  for (int k = 0; k < steps; ++k) x = x * mul[k];
}

// DLAEV2: eigen-decomposition of [[a, b], [b, c]]: rt1 (larger |.|), rt2, and (cs1, sn1) the
// unit right eigenvector of rt1.
void dlaev2(double a, double b, double c, double& rt1, double& rt2, double& cs1, double& sn1) {
  const double sm = a + c, df = a - c, adf = std::abs(df), tb = b + b, ab = std::abs(tb);
  double acmx, acmn;
  if (std::abs(a) > std::abs(c)) {
    acmx = a;
    acmn = c;
  } else {
    acmx = c;
    acmn = a;
  }
  double rt;
  if (adf > ab) {
    const double q = ab / adf;
    rt = adf * std::sqrt(1.0 + q * q);
  } else if (adf < ab) {
    const double q = adf / ab;
    rt = ab * std::sqrt(1.0 + q * q);
  } else {
    rt = ab * std::sqrt(2.0);
  }
  int sgn1;
  if (sm < 0.0) {
    rt1 = 0.5 * (sm - rt);
    sgn1 = -1;
    rt2 = (acmx / rt1) * acmn - (b / rt1) * b;
  } else if (sm > 0.0) {
    rt1 = 0.5 * (sm + rt);
    sgn1 = 1;
    rt2 = (acmx / rt1) * acmn - (b / rt1) * b;
  } else {
    rt1 = 0.5 * rt;
    rt2 = -0.5 * rt;
    sgn1 = 1;
  }
  int sgn2;
  double cs;
  if (df >= 0.0) {
    cs = df + rt;
    sgn2 = 1;
  } else {
    cs = df - rt;
    sgn2 = -1;
  }
  const double acs = std::abs(cs);
  if (acs > ab) {
    const double ct = -tb / cs;
    sn1 = 1.0 / std::sqrt(1.0 + ct * ct);
    cs1 = ct * sn1;
  } else if (ab == 0.0) {
    cs1 = 1.0;
    sn1 = 0.0;
  } else {
    const double tn = -cs / tb;
    cs1 = 1.0 / std::sqrt(1.0 + tn * tn);
    sn1 = tn * cs1;
  }
  if (sgn1 == sgn2) {
    const double tn = cs1;
    cs1 = -sn1;
    sn1 = tn;
  }
}

// DLARTG (3.10+ dlartg.f90): plane rotation with c*f + s*g = r, -s*f + c*g = 0.
void dlartg(double f, double g, double& c, double& s, double& r) {
  const double safmin = safe_minimum, safmax = 1.0 / safmin;  // la_constants dsafmin, dsafmax
  const double rtmin = std::sqrt(safmin), rtmax = std::sqrt(safmax / 2);
  const double f1 = std::abs(f), g1 = std::abs(g);
  if (g == 0.0) {
    c = 1.0;
    s = 0.0;
    r = f;
  } else if (f == 0.0) {
    c = 0.0;
    s = fsign(1.0, g);
    r = g1;
  } else if (f1 > rtmin && f1 < rtmax && g1 > rtmin && g1 < rtmax) {
    const double d = std::sqrt(f * f + g * g);
    c = f1 / d;
    r = fsign(d, f);
    s = g / r;
  } else {
    double u = safmin > f1 ? safmin : f1;  // MAX(safmin, f1, g1)
    u = u > g1 ? u : g1;
    u = safmax < u ? safmax : u;  // MIN(safmax, .)
    const double fs = f / u, gs = g / u;
    const double d = std::sqrt(fs * fs + gs * gs);
    c = std::abs(fs) / d;
    r = fsign(d, f);
    s = gs / r;
    r = r * u;
  }
}

// DLASR('R', 'V', direct, N, ncols, c, s, Z(1, first), LDZ): rotations of columns first-1+j and
// first+j, j = ncols-1 .. 1 ('B') or 1 .. ncols-1 ('F').
void dlasr_right(bool backward, int ncols, const double* c, const double* s, FArray& z, int first) {
  for (int k = 1; k <= ncols - 1; ++k) {
    const int j = backward ? ncols - k : k;
    const double ctemp = c[j - 1], stemp = s[j - 1];
    if (ctemp != 1.0 || stemp != 0.0) {
      for (int i = 1; i <= n; ++i) {
        const double temp = z(i, first + j);
        z(i, first + j) = ctemp * temp - stemp * z(i, first + j - 1);
        z(i, first + j - 1) = stemp * temp + ctemp * z(i, first + j - 1);
      }
    }
  }
}

// DLANST('M', count, d(l..), e(l..)).
double dlanst_max(int count, const double* d, const double* e) {
  if (count <= 0) return 0.0;
  double anorm = std::abs(d[count - 1]);
  for (int i = 0; i < count - 1; ++i) {
    keep_max(anorm, std::abs(d[i]));
    keep_max(anorm, std::abs(e[i]));
  }
  return anorm;
}

// DSTEQR('I', 3, D, E, Z, 3, WORK, INFO): implicit QL/QR on the tridiagonal (d, e), Z starting
// from the identity; eigenvalues sorted ascending (with the columns of Z) on success.
int dsteqr(double d[n + 1], double e[n + 1], FArray& z) {
  constexpr int maxit = 30;
  const double eps = epsilon, eps2 = eps * eps;
  const double safmin = safe_minimum, safmax = 1.0 / safmin;
  const double ssfmax = std::sqrt(safmax) / 3.0, ssfmin = std::sqrt(safmin) / eps2;
  double work[2 * n - 1] = {};  // WORK(1..N-1) cosines, WORK(N..2N-2) sines
  double* const wc = work;      // wc[i-1] = WORK(i)
  double* const ws = work + n - 1;

  for (int j = 1; j <= n; ++j)  // DLASET('Full', N, N, 0, 1, Z)
    for (int i = 1; i <= n; ++i) z(i, j) = i == j ? 1.0 : 0.0;

  const int nmaxit = n * maxit;
  int jtot = 0, l1 = 1;
  const int nm1 = n - 1;
  for (;;) {  // label 10: look for a small subdiagonal element to split the matrix
    if (l1 > n) break;
    if (l1 > 1) e[l1 - 1] = 0.0;
    int m = n;
    for (int mm = l1; mm <= nm1; ++mm) {
      const double tst = std::abs(e[mm]);
      if (tst == 0.0) {
        m = mm;
        break;
      }
      if (tst <= (std::sqrt(std::abs(d[mm])) * std::sqrt(std::abs(d[mm + 1]))) * eps) {
        e[mm] = 0.0;
        m = mm;
        break;
      }
    }
    int l = l1;
    const int lsv = l;
    int lend = m;
    const int lendsv = lend;
    l1 = m + 1;
    if (lend == l) continue;

    // Scale the submatrix in rows and columns l to lend.
    const double anorm = dlanst_max(lend - l + 1, d + l, e + l);
    int iscale = 0;
    if (anorm == 0.0) continue;
    double mul[8];
    if (anorm > ssfmax || anorm < ssfmin) {
      iscale = anorm > ssfmax ? 1 : 2;
      const int steps = dlascl_steps(anorm, iscale == 1 ? ssfmax : ssfmin, mul);
      for (int i = l; i <= lend; ++i) dlascl_apply(steps, mul, d[i]);
      for (int i = l; i <= lend - 1; ++i) dlascl_apply(steps, mul, e[i]);
    }

    // Choose between QL and QR iteration.
    if (std::abs(d[lend]) < std::abs(d[l])) {
      lend = lsv;
      l = lendsv;
    }

    if (lend > l) {
      for (;;) {  // label 40: QL iteration, look for a small subdiagonal element
        m = lend;
        if (l != lend) {
          for (int mm = l; mm <= lend - 1; ++mm) {
            const double tst = std::abs(e[mm]) * std::abs(e[mm]);
            if (tst <= (eps2 * std::abs(d[mm])) * std::abs(d[mm + 1]) + safmin) {
              m = mm;
              break;
            }
          }
        }
        if (m < lend) e[m] = 0.0;
        double p = d[l];
        if (m == l) {  // label 80: eigenvalue found
          d[l] = p;
          ++l;
          if (l <= lend) continue;
          break;
        }
        if (m == l + 1) {  // 2x2 block: DLAEV2 and its rotation ('B')
          double rt1, rt2, c, s;
          dlaev2(d[l], e[l], d[l + 1], rt1, rt2, c, s);
          wc[l - 1] = c;
          ws[l - 1] = s;
          dlasr_right(true, 2, wc + l - 1, ws + l - 1, z, l);
          d[l] = rt1;
          d[l + 1] = rt2;
          e[l] = 0.0;
          l += 2;
          if (l <= lend) continue;
          break;
        }
        if (jtot == nmaxit) break;
        ++jtot;
        // Form shift.
        double g = (d[l + 1] - p) / (2.0 * e[l]);
        double r = dlapy2(g, 1.0);
        g = d[m] - p + (e[l] / (g + fsign(r, g)));
        double s = 1.0, c = 1.0;
        p = 0.0;
        for (int i = m - 1; i >= l; --i) {  // inner loop
          const double f = s * e[i], b = c * e[i];
          dlartg(g, f, c, s, r);
          if (i != m - 1) e[i + 1] = r;
          g = d[i + 1] - p;
          r = (d[i] - g) * s + 2.0 * c * b;
          p = s * r;
          d[i + 1] = g + p;
          g = c * r - b;
          wc[i - 1] = c;  // save rotations
          ws[i - 1] = -s;
        }
        dlasr_right(true, m - l + 1, wc + l - 1, ws + l - 1, z, l);
        d[l] = d[l] - p;
        e[l] = g;
      }
    } else {
      for (;;) {  // label 90: QR iteration, look for a small superdiagonal element
        m = lend;
        if (l != lend) {
          for (int mm = l; mm >= lend + 1; --mm) {
            const double tst = std::abs(e[mm - 1]) * std::abs(e[mm - 1]);
            if (tst <= (eps2 * std::abs(d[mm])) * std::abs(d[mm - 1]) + safmin) {
              m = mm;
              break;
            }
          }
        }
        if (m > lend) e[m - 1] = 0.0;
        double p = d[l];
        if (m == l) {  // label 130: eigenvalue found
          d[l] = p;
          --l;
          if (l >= lend) continue;
          break;
        }
        if (m == l - 1) {  // 2x2 block: DLAEV2 and its rotation ('F')
          double rt1, rt2, c, s;
          dlaev2(d[l - 1], e[l - 1], d[l], rt1, rt2, c, s);
          wc[m - 1] = c;
          ws[m - 1] = s;
          dlasr_right(false, 2, wc + m - 1, ws + m - 1, z, l - 1);
          d[l - 1] = rt1;
          d[l] = rt2;
          e[l - 1] = 0.0;
          l -= 2;
          if (l >= lend) continue;
          break;
        }
        if (jtot == nmaxit) break;
        ++jtot;
        // Form shift.
        double g = (d[l - 1] - p) / (2.0 * e[l - 1]);
        double r = dlapy2(g, 1.0);
        g = d[m] - p + (e[l - 1] / (g + fsign(r, g)));
        double s = 1.0, c = 1.0;
        p = 0.0;
        for (int i = m; i <= l - 1; ++i) {  // inner loop
          const double f = s * e[i], b = c * e[i];
          dlartg(g, f, c, s, r);
          if (i != m) e[i - 1] = r;
          g = d[i] - p;
          r = (d[i + 1] - g) * s + 2.0 * c * b;
          p = s * r;
          d[i] = g + p;
          g = c * r - b;
          wc[i - 1] = c;  // save rotations
          ws[i - 1] = s;
        }
        dlasr_right(false, l - m + 1, wc + m - 1, ws + m - 1, z, m);
        d[l] = d[l] - p;
        e[l - 1] = g;
      }
    }

    // label 140: undo scaling.
    if (iscale != 0) {
      const int steps = dlascl_steps(iscale == 1 ? ssfmax : ssfmin, anorm, mul);
      for (int i = lsv; i <= lendsv; ++i) dlascl_apply(steps, mul, d[i]);
      for (int i = lsv; i <= lendsv - 1; ++i) dlascl_apply(steps, mul, e[i]);
    }
    if (jtot < nmaxit) continue;
    int info = 0;  // failed: count the unconverged off-diagonal elements (no sort)
    for (int i = 1; i <= n - 1; ++i)
      if (e[i] != 0.0) ++info;
    return info;
  }

  // label 160: selection sort of the eigenvalues, increasing, swapping the columns of Z (DSWAP).
  for (int ii = 2; ii <= n; ++ii) {
    const int i = ii - 1;
    int k = i;
    double p = d[i];
    for (int j = ii; j <= n; ++j) {
      if (d[j] < p) {
        k = j;
        p = d[j];
      }
    }
    if (k != i) {
      d[k] = d[i];
      d[i] = p;
      for (int r = 1; r <= n; ++r) {
        const double t = z(r, i);
        z(r, i) = z(r, k);
        z(r, k) = t;
      }
    }
  }
  return 0;
}

}  // namespace

int lapack_symmetric_eigen_3x3(const double a_in[3][3], double values[3], double vectors[3][3]) {
  // DSYEVD('V', 'L', 3, A, 3, W, WORK, 37, IWORK, 18, INFO). Only the lower triangle matters.
  FArray a;
  for (int j = 1; j <= n; ++j)
    for (int i = j; i <= n; ++i) a(i, j) = a_in[i - 1][j - 1];

  // Scale the matrix to the allowable range if necessary: DLANSY('M', 'L') and DLASCL('L').
  const double safmin = safe_minimum, eps = precision;
  const double smlnum = safmin / eps, bignum = 1.0 / smlnum;
  const double rmin = std::sqrt(smlnum), rmax = std::sqrt(bignum);
  double anrm = 0.0;
  for (int j = 1; j <= n; ++j)
    for (int i = j; i <= n; ++i) keep_max(anrm, std::abs(a(i, j)));
  int iscale = 0;
  double sigma = 0.0;
  if (anrm > 0.0 && anrm < rmin) {
    iscale = 1;
    sigma = rmin / anrm;
  } else if (anrm > rmax) {
    iscale = 1;
    sigma = rmax / anrm;
  }
  if (iscale == 1) {
    double mul[8];
    const int steps = dlascl_steps(1.0, sigma, mul);
    for (int j = 1; j <= n; ++j)
      for (int i = j; i <= n; ++i) dlascl_apply(steps, mul, a(i, j));
  }

  // DSYTRD('L') -> DSYTD2('L', 3): one Householder reflector H(1) = I - tau v v^T, v = (0, 1, v3),
  // reduces A to tridiagonal (d, e). (The reflector of step I = 2 has N-I = 1: TAU(2) = 0.)
  double d[n + 1] = {}, e[n + 1] = {}, tau[n] = {};
  {
    const double taui = dlarfg2(a(2, 1), a(3, 1));  // DLARFG(2, A(2,1), A(3,1), 1, TAUI)
    e[1] = a(2, 1);
    if (taui != 0.0) {
      a(2, 1) = 1.0;
      const double v[3] = {0.0, a(2, 1), a(3, 1)};  // v(1..2) = A(2:3, 1)
      // DSYMV('L', 2, TAUI, A(2,2), 3, v, 1, ZERO, y, 1): y = tau * A(2:3, 2:3) v (into TAU(1:2)).
      double y[3] = {0.0, 0.0, 0.0};
      auto s = [&](int i, int j) -> double& { return a(i + 1, j + 1); };  // A(2,2) as (1,1)
      for (int j = 1; j <= 2; ++j) {
        const double temp1 = taui * v[j];
        double temp2 = 0.0;
        y[j] = y[j] + temp1 * s(j, j);
        for (int i = j + 1; i <= 2; ++i) {
          y[i] = y[i] + temp1 * s(i, j);
          temp2 = temp2 + s(i, j) * v[i];
        }
        y[j] = y[j] + taui * temp2;
      }
      // ALPHA = -HALF*TAUI*DDOT(2, y, 1, v, 1)
      double dot = 0.0;
      for (int i = 1; i <= 2; ++i) dot = dot + y[i] * v[i];
      const double alpha = -(0.5 * taui * dot);
      if (alpha != 0.0)  // DAXPY(2, ALPHA, v, 1, y, 1)
        for (int i = 1; i <= 2; ++i) y[i] = y[i] + alpha * v[i];
      // DSYR2('L', 2, -ONE, v, 1, y, 1, A(2,2), 3): A := A - v y^T - y v^T (lower triangle).
      for (int j = 1; j <= 2; ++j) {
        if (v[j] != 0.0 || y[j] != 0.0) {
          const double temp1 = -1.0 * y[j], temp2 = -1.0 * v[j];
          for (int i = j; i <= 2; ++i) s(i, j) = s(i, j) + v[i] * temp1 + y[i] * temp2;
        }
      }
      a(2, 1) = e[1];
    }
    d[1] = a(1, 1);
    tau[1] = taui;
    e[2] = a(3, 2);
    d[2] = a(2, 2);
    tau[2] = 0.0;
    d[3] = a(3, 3);
  }

  // DSTEDC('I', 3, ...) -> DSTEQR('I', 3, W, E, Z = WORK(INDWRK), 3, ...) since N <= SMLSIZ = 25.
  FArray z;
  const int info = dsteqr(d, e, z);

  // DORMTR('L', 'L', 'N', 3, 3, A, 3, TAU, Z, 3, ...) -> DORMQR('L', 'N', 2, 3, 2, A(2,1), 3, TAU,
  // Z(2,1), 3, ...) -> DORM2R (NB >= K): H(2) then H(1) applied to rows 2..3 of Z; H(2) has
  // TAU(2) = 0 (DLARF does nothing); H(1) = DLARF('L', 2, 3, v = (1, A(3,1)), 1, TAU(1), Z(2,1)).
  if (tau[1] != 0.0) {
    const double v[3] = {0.0, 1.0, a(3, 1)};
    auto c = [&](int i, int j) -> double& { return z(i + 1, j); };  // C = Z(2:3, 1:3)
    int lastv = 2;
    while (lastv > 0 && v[lastv] == 0.0) --lastv;
    int lastc = n;  // ILADLC(lastv, 3, C, 3): last non-zero column of C(1:lastv, :)
    if (!(c(1, n) != 0.0 || c(lastv, n) != 0.0)) {
      for (lastc = n; lastc >= 1; --lastc) {
        bool nonzero = false;
        for (int i = 1; i <= lastv; ++i)
          if (c(i, lastc) != 0.0) nonzero = true;
        if (nonzero) break;
      }
    }
    if (lastc > 0) {
      // DGEMV('T', lastv, lastc, ONE, C, 3, v, 1, ZERO, WORK, 1): w = C^T v.
      double w[n + 1] = {};
      for (int j = 1; j <= lastc; ++j) w[j] = 0.0;
      for (int j = 1; j <= lastc; ++j) {
        double temp = 0.0;
        for (int i = 1; i <= lastv; ++i) temp = temp + c(i, j) * v[i];
        w[j] = w[j] + 1.0 * temp;
      }
      // DGER(lastv, lastc, -TAU, v, 1, WORK, 1, C, 3): C := C - tau v w^T.
      const double alpha = -tau[1];
      for (int j = 1; j <= lastc; ++j) {
        if (w[j] != 0.0) {
          const double temp = alpha * w[j];
          for (int i = 1; i <= lastv; ++i) c(i, j) = c(i, j) + v[i] * temp;
        }
      }
    }
  }

  // DLACPY Z into A; DSCAL(3, ONE/SIGMA, W, 1) if the matrix was scaled.
  if (iscale == 1) {
    const double rsigma = 1.0 / sigma;
    for (int i = 1; i <= n; ++i) d[i] = rsigma * d[i];
  }
  for (int j = 1; j <= n; ++j) {
    values[j - 1] = d[j];
    for (int i = 1; i <= n; ++i) vectors[i - 1][j - 1] = z(i, j);
  }
  return info;
}

int lapack_symmetric_eigen_3x3(const Eigen::Matrix3d& a, Eigen::Vector3d& values, Eigen::Matrix3d& vectors) {
  double in[3][3], w[3], v[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) in[i][j] = a(i, j);
  const int info = lapack_symmetric_eigen_3x3(in, w, v);
  for (int j = 0; j < 3; ++j) {
    values[j] = w[j];
    for (int i = 0; i < 3; ++i) vectors(i, j) = v[i][j];
  }
  return info;
}

void lmgc90_diagonalise33(Eigen::Matrix3d m, Eigen::Vector3d& moments, Eigen::Matrix3d& frame) {
  // mod_algebra.f90:364-388: zero the negligible terms row by row, count the zero off-diagonal ones.
  int nb = 0;
  for (int j = 0; j < 3; ++j) {
    const bool large_diagonal = std::abs(m(j, j)) > 1.0e-10;
    for (int k = 0; k < 3; ++k) {
      if (large_diagonal) {
        if (std::abs(m(j, k)) < 1.0e-14 * std::abs(m(j, j))) m(j, k) = 0.0;
      } else if (std::abs(m(j, k)) < 1.0e-17) {
        m(j, k) = 0.0;
      }
      if (j != k && m(j, k) == 0.0) ++nb;
    }
  }
  if (nb == 6) {  // :392-403: already diagonal, kept in place
    moments = m.diagonal();
    frame.setIdentity();
    return;
  }
  // :411-414: Fp = I; dsyevd('V', 'L', 3, Fp, 3, Ip, work, 37, iwork, 18, ierror).
  Eigen::Vector3d ip;
  Eigen::Matrix3d fp;
  if (lapack_symmetric_eigen_3x3(m, ip, fp) != 0)
    throw std::runtime_error("diagonalise33: diagonalisation not possible");
  // :436-440: columns 1 and 2 normalised, their moments multiplied by the squared norms.
  for (int j = 0; j < 2; ++j) {
    double norm = 0.0;  // dot_product
    for (int i = 0; i < 3; ++i) norm = norm + fp(i, j) * fp(i, j);
    const double root = std::sqrt(norm);
    for (int i = 0; i < 3; ++i) fp(i, j) = fp(i, j) / root;
    ip[j] = ip[j] * norm;
  }
  // :442-443: moment 3 multiplied by the squared norm of column 3.
  double norm = 0.0;
  for (int i = 0; i < 3; ++i) norm = norm + fp(i, 2) * fp(i, 2);
  ip[2] = ip[2] * norm;
  // :445-446: column 3 = cross_product(column 1, column 2) (mod_algebra.f90:157-159).
  const double a1 = fp(0, 0), a2 = fp(1, 0), a3 = fp(2, 0);
  const double b1 = fp(0, 1), b2 = fp(1, 1), b3 = fp(2, 1);
  fp(0, 2) = (a2 * b3) - (a3 * b2);
  fp(1, 2) = (a3 * b1) - (a1 * b3);
  fp(2, 2) = (a1 * b2) - (a2 * b1);
  moments = ip;
  frame = fp;
}

}  // namespace lmgc::solver
