#include "solver/nlgs/nlgs_check.hpp"

#include <cmath>

namespace lmgc::solver {

NlgsNorms nlgs_norms(const NlgsCheckSums& s, double tol) {
  NlgsNorms q;
  if (s.active >= 1.0 && s.wrr > 1e-18 && s.wrwr > 1e-18) {
    q.quad_wr = std::sqrt(s.wrwr / s.active);
    const double mean_wrr = s.wrr / s.active;
    q.quad_dv = std::sqrt(s.dvdv / s.active) / (q.quad_wr * tol);
    q.maxm_dv = std::sqrt(s.max_dvdv) / (q.quad_wr * tol);
    q.quad_dvr = std::sqrt(s.dvdvrr / s.active) / (mean_wrr * tol);
    q.maxm_dvr = std::sqrt(s.max_dvdvrr) / (mean_wrr * tol);
    q.mean_dvor = s.dvor / (s.wrr * tol);
  } else {
    q = NlgsNorms{0.111e-11, 0.111e-11, 0.111e-11, 0.111e-11, 0.111e-11, 0.0};
  }
  return q;
}

bool nlgs_check_passes(NlgsNorm norm, const NlgsNorms& q) {
  const bool quad = std::fabs(q.mean_dvor) < 1.0 && std::fabs(q.quad_dv) < 1.0 && std::fabs(q.quad_dvr) < 1.0;
  const bool maxm = std::fabs(q.mean_dvor) < 1.0 && std::fabs(q.maxm_dv) < 1.0 && std::fabs(q.maxm_dvr) < 1.0;
  switch (norm) {
    case NlgsNorm::quad:
    case NlgsNorm::quad_normal:
      return quad;
    case NlgsNorm::maxm:
      return maxm;
    case NlgsNorm::qm16:
      return quad && std::fabs(q.maxm_dv) < 16.666 && std::fabs(q.maxm_dvr) < 16.666;
  }
  return quad;
}

}  // namespace lmgc::solver
