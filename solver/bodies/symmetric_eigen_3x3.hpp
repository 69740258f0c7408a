#pragma once
// Eigen-decomposition of a symmetric 3x3 matrix exactly as LMGC90 gets it from LAPACK: a bit-exact
// C++ translation of the code path that reference LAPACK 3.11 (Debian 12's liblapack3/libblas3,
// v3.11.0 sources) runs in DSYEVD('V', 'L', 3, ...), so that the signs of the eigenvectors, hence
// the principal frames written in BODIES.OUT and DOF.OUT, are LMGC90's. No LAPACK is linked.
//
// LMGC90 (src/Core/shared/mod_algebra.f90) diagonalise33 (:338-453) calls
//   dsyevd('V', 'L', 3, Fp, 3, Ip, work, lwork = 37, iwork, liwork = 18, ierror)   (:411)
// on a copy of its (cleaned) tensor: JOBZ = 'V' (vectors), UPLO = 'L' (only the lower triangle
// is read), ascending eigenvalues, orthonormal eigenvectors in columns.
//
// The path for n = 3 (see the .cpp): DLANSY('M') and DLASCL scaling when the largest entry is
// outside [2^-485, 2^485]; DSYTRD -> DSYTD2 (unblocked, n < NB); DSTEDC('I') -> DSTEQR('I')
// (n <= SMLSIZ = 25) with DLAEV2, DLARTG, DLAPY2, DLASR, DLANST, DLASCL, and the final selection
// sort; DORMTR -> DORMQR -> DORM2R -> DLARF; the reference BLAS DNRM2, DSYMV, DDOT, DAXPY,
// DSYR2, DGEMV, DGER, DSCAL as they are called there.
//
// Bit-exactness needs IEEE double arithmetic without contraction into FMA (the .cpp disables it
// for GCC and Clang) and without -ffast-math style reassociation.
#include <Eigen/Core>

namespace lmgc::solver {

// DSYEVD('V', 'L', 3, A, 3, W, ...): a[i][j] is row i, column j; only the lower triangle
// (i >= j) is read, as LAPACK does with UPLO = 'L'. values: the eigenvalues in ascending order
// (W); vectors[i][j]: component i of the eigenvector of values[j] (the columns of A on exit).
// Returns LAPACK's INFO: 0 on success, > 0 if DSTEQR did not converge in 90 sweeps (then the
// outputs are what DSYEVD leaves, unsorted).
int lapack_symmetric_eigen_3x3(const double a[3][3], double values[3], double vectors[3][3]);

// The same with Eigen types: a(i, j) row i, column j (lower triangle read), vectors' columns are
// the eigenvectors (an Eigen::Matrix3d is column-major like the Fortran array).
int lapack_symmetric_eigen_3x3(const Eigen::Matrix3d& a, Eigen::Vector3d& values, Eigen::Matrix3d& vectors);

// LMGC90's diagonalise33 (shared/mod_algebra.f90:338-453), operation for operation:
//  - :364-388: row by row (j), an entry I(j,k) with |I(j,k)| < 1e-14 |I(j,j)| is set to 0 when
//    |I(j,j)| > 1e-10, else when |I(j,k)| < 1e-17; the off-diagonal zeros are counted;
//  - :392-403: if all six off-diagonal entries are zero, moments = the diagonal (unsorted) and
//    frame = identity;
//  - :411-414: otherwise DSYEVD('V', 'L') on the lower triangle (a failure is LMGC90's faterr,
//    here std::runtime_error);
//  - :436-446: columns 1 and 2 divided by sqrt(dot_product(c, c)) and moments 1, 2 multiplied by
//    that dot product, moment 3 multiplied by the dot product of column 3, then column 3 replaced
//    by cross_product(column 1, column 2) (mod_algebra.f90:153-161).
// tensor is taken by value: LMGC90 zeroes the negligible entries of its caller's array in place.
void lmgc90_diagonalise33(Eigen::Matrix3d tensor, Eigen::Vector3d& moments, Eigen::Matrix3d& frame);

}  // namespace lmgc::solver
