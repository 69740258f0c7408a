// Four plain 2D updates at once (sweep_group_2d.hpp). Each line names the scalar formula of
// nlgs_2d.cpp it repeats lane by lane; the operands keep their order, so that every lane rounds as
// the scalar update does.
#include "solver/nlgs/sweep_group_2d.hpp"

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#define LMGC_SWEEP_GROUPS_X86 1
#endif

namespace lmgc::solver {

#ifdef LMGC_SWEEP_GROUPS_X86

bool sweep_groups_available() {
  return __builtin_cpu_supports("avx2");
}

namespace {

#define LMGC_AVX2 __attribute__((target("avx2"), always_inline)) inline

LMGC_AVX2 __m256d load(const double (&lanes)[4]) {
  return _mm256_load_pd(lanes);
}
LMGC_AVX2 __m256d negate(__m256d x) {
  return _mm256_xor_pd(x, _mm256_set1_pd(-0.0));
}

// Two doubles per lane (x, y at p[k]) into one vector per component.
LMGC_AVX2 void load_pairs(const double* p0, const double* p1, const double* p2, const double* p3, __m256d& x,
                          __m256d& y) {
  const __m256d even = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p0)), _mm_loadu_pd(p2), 1);
  const __m256d odd = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(p1)), _mm_loadu_pd(p3), 1);
  x = _mm256_unpacklo_pd(even, odd);  // (x0, x1, x2, x3)
  y = _mm256_unpackhi_pd(even, odd);  // (y0, y1, y2, y3)
}

LMGC_AVX2 void store_pairs(__m256d x, __m256d y, double* p0, double* p1, double* p2, double* p3) {
  const __m256d even = _mm256_unpacklo_pd(x, y);  // (x0, y0, x2, y2)
  const __m256d odd = _mm256_unpackhi_pd(x, y);   // (x1, y1, x3, y3)
  _mm_storeu_pd(p0, _mm256_castpd256_pd128(even));
  _mm_storeu_pd(p1, _mm256_castpd256_pd128(odd));
  _mm_storeu_pd(p2, _mm256_extractf128_pd(even, 1));
  _mm_storeu_pd(p3, _mm256_extractf128_pd(odd, 1));
}

LMGC_AVX2 __m256d load_singles(const double* p0, const double* p1, const double* p2, const double* p3) {
  const __m128d low = _mm_loadh_pd(_mm_load_sd(p0), p1), high = _mm_loadh_pd(_mm_load_sd(p2), p3);
  return _mm256_insertf128_pd(_mm256_castpd128_pd256(low), high, 1);
}

LMGC_AVX2 void store_singles(__m256d x, double* p0, double* p1, double* p2, double* p3) {
  const __m128d low = _mm256_castpd256_pd128(x), high = _mm256_extractf128_pd(x, 1);
  _mm_store_sd(p0, low);
  _mm_storeh_pd(p1, low);
  _mm_store_sd(p2, high);
  _mm_storeh_pd(p3, high);
}

// One side's body of each lane (the candidates, or the antagonists): where its velocity is, and the
// velocity (x, y, ω), one vector per component.
struct LaneBodies {
  double* velocity[4];
  __m256d x, y, w;
};

LMGC_AVX2 LaneBodies load_bodies(double* v, const std::int32_t (&body)[4]) {
  LaneBodies b{{v + 3 * body[0], v + 3 * body[1], v + 3 * body[2], v + 3 * body[3]}, {}, {}, {}};
  load_pairs(b.velocity[0], b.velocity[1], b.velocity[2], b.velocity[3], b.x, b.y);
  b.w = load_singles(b.velocity[0] + 2, b.velocity[1] + 2, b.velocity[2] + 2, b.velocity[3] + 2);
  return b;
}

// The candidate gains the impulse, the antagonist loses it.
template <bool candidate>
LMGC_AVX2 __m256d with_impulse(__m256d v, __m256d impulse) {
  return candidate ? _mm256_add_pd(v, impulse) : _mm256_sub_pd(v, impulse);
}

// inject's v[i] += M_i⁻¹ (f, dt ℓ_t + dn ℓ_n) (candidate) or v[j] −= ... (antagonist), on the lanes
// taken: the others inject r_old − r_old = 0, which would turn a −0 velocity into +0.
template <bool candidate>
LMGC_AVX2 void inject_lanes(LaneBodies& b, const double (&inverse_mass)[4],
                            const double (&inverse_inertia)[4], __m256d fx, __m256d fy, __m256d dt,
                            __m256d dn, __m256d lever_t, __m256d lever_n, __m256d taken) {
  const __m256d turn = _mm256_add_pd(_mm256_mul_pd(dt, lever_t), _mm256_mul_pd(dn, lever_n));
  const __m256d m = load(inverse_mass);
  b.x = _mm256_blendv_pd(b.x, with_impulse<candidate>(b.x, _mm256_mul_pd(m, fx)), taken);
  b.y = _mm256_blendv_pd(b.y, with_impulse<candidate>(b.y, _mm256_mul_pd(m, fy)), taken);
  b.w =
      _mm256_blendv_pd(b.w, with_impulse<candidate>(b.w, _mm256_mul_pd(load(inverse_inertia), turn)), taken);
}

LMGC_AVX2 void store_bodies(const LaneBodies& b) {
  store_pairs(b.x, b.y, b.velocity[0], b.velocity[1], b.velocity[2], b.velocity[3]);
  store_singles(b.w, b.velocity[0] + 2, b.velocity[1] + 2, b.velocity[2] + 2, b.velocity[3] + 2);
}

}  // namespace

__attribute__((target("avx2"))) int sweep_group_2d(const SweepGroup2D& g, ContactReaction2D* reaction,
                                                   Eigen::Vector3d* velocity, bool relaxed, double relax,
                                                   double keep) {
  ContactReaction2D* const s0 = reaction + g.position[0];
  ContactReaction2D* const s1 = reaction + g.position[1];
  ContactReaction2D* const s2 = reaction + g.position[2];
  ContactReaction2D* const s3 = reaction + g.position[3];
  __m256d rt_old, rn_old;
  load_pairs(&s0->rt, &s1->rt, &s2->rt, &s3->rt, rt_old, rn_old);
  const __m256d zero = _mm256_setzero_pd();
  // A lane without reaction: its visit is the open-contact schedule's to decide (scalar update).
  const __m256d without_reaction =
      _mm256_and_pd(_mm256_cmp_pd(rt_old, zero, _CMP_EQ_OQ), _mm256_cmp_pd(rn_old, zero, _CMP_EQ_OQ));
  if (_mm256_movemask_pd(without_reaction) == 0xF) return 0;

  LaneBodies a = load_bodies(velocity->data(), g.cd), b = load_bodies(velocity->data(), g.an);

  const __m256d nx = load(g.nx), ny = load(g.ny), minus_nx = negate(nx);
  const __m256d lcd_t = load(g.lever_cd_t), lcd_n = load(g.lever_cd_n);
  const __m256d lan_t = load(g.lever_an_t), lan_n = load(g.lever_an_n);
  const __m256d wtt = load(g.wtt), wtn = load(g.wtn), wnn = load(g.wnn), mu = load(g.mu);

  // relative_velocity: ((across dx + across dy) + ℓ_cd a_ω) − ℓ_an b_ω, across = (ny, nx), (−nx, ny).
  const __m256d dx = _mm256_sub_pd(a.x, b.x), dy = _mm256_sub_pd(a.y, b.y);
  const __m256d ut =
      _mm256_sub_pd(_mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(ny, dx), _mm256_mul_pd(minus_nx, dy)),
                                  _mm256_mul_pd(lcd_t, a.w)),
                    _mm256_mul_pd(lan_t, b.w));
  const __m256d un = _mm256_sub_pd(
      _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(nx, dx), _mm256_mul_pd(ny, dy)), _mm256_mul_pd(lcd_n, a.w)),
      _mm256_mul_pd(lan_n, b.w));
  // minus_w_r: u − (W_t r_t + W_n r_n); then the plain path's normal shift. Its tangential shift, +0
  // or -0, is left out: it only decides the sign of a zero q_t, which reaches nothing. q_t enters
  // d_t = -(W_nn q_t - W_tn q_n), which is a zero only when W_tn q_n is one; the case tests compare
  // with zero, where the sign does not count; and a sticking r_t = d_t / det that is zero is flushed
  // to +0 below. Sliding lanes' reactions do not read q_t.
  const __m256d qt = _mm256_sub_pd(ut, _mm256_add_pd(_mm256_mul_pd(wtt, rt_old), _mm256_mul_pd(wtn, rn_old)));
  const __m256d qn =
      _mm256_add_pd(_mm256_sub_pd(un, _mm256_add_pd(_mm256_mul_pd(wtn, rt_old), _mm256_mul_pd(wnn, rn_old))),
                    load(g.cov_n));

  // solve_signorini_coulomb_2d with the reciprocals (local_solver_2d.hpp).
  const __m256d open = _mm256_cmp_pd(qn, zero, _CMP_GE_OQ);
  const __m256d dft = negate(_mm256_sub_pd(_mm256_mul_pd(wnn, qt), _mm256_mul_pd(wtn, qn)));
  const __m256d dfn = negate(_mm256_add_pd(_mm256_mul_pd(negate(wtn), qt), _mm256_mul_pd(wtt, qn)));
  const __m256d mu_dfn = _mm256_mul_pd(mu, dfn);
  const __m256d cf = _mm256_add_pd(dft, mu_dfn), cb = _mm256_sub_pd(dft, mu_dfn);
  const __m256d forward = load(g.inverse_forward), backward = load(g.inverse_backward);
  const __m256d det = load(g.inverse_det);
  const __m256d cf_forward = _mm256_cmp_pd(cf, zero, _CMP_GE_OQ);  // cf >= 0 (false on NaN)
  const __m256d slide_forward = _mm256_andnot_pd(
      open, _mm256_and_pd(_mm256_cmp_pd(cf, zero, _CMP_LT_OQ), _mm256_cmp_pd(forward, zero, _CMP_NEQ_UQ)));
  const __m256d slide_backward =
      _mm256_andnot_pd(open, _mm256_and_pd(_mm256_and_pd(cf_forward, _mm256_cmp_pd(cb, zero, _CMP_GT_OQ)),
                                           _mm256_cmp_pd(backward, zero, _CMP_NEQ_UQ)));
  const __m256d stick =
      _mm256_andnot_pd(open, _mm256_and_pd(_mm256_and_pd(cf_forward, _mm256_cmp_pd(cb, zero, _CMP_LE_OQ)),
                                           _mm256_cmp_pd(det, zero, _CMP_NEQ_UQ)));
  // The lanes taken here: with a reaction, and in one of the plain cases (not the dividing fallback's).
  const __m256d taken = _mm256_andnot_pd(
      without_reaction, _mm256_or_pd(_mm256_or_pd(open, slide_forward), _mm256_or_pd(slide_backward, stick)));
  const int lanes = _mm256_movemask_pd(taken);
  if (lanes == 0) return 0;
  const __m256d minus_qn = negate(qn);
  const __m256d rn_forward = _mm256_mul_pd(minus_qn, forward);
  const __m256d rn_backward = _mm256_mul_pd(minus_qn, backward);
  __m256d rn = _mm256_or_pd(
      _mm256_or_pd(_mm256_and_pd(slide_forward, rn_forward), _mm256_and_pd(slide_backward, rn_backward)),
      _mm256_and_pd(stick, _mm256_mul_pd(dfn, det)));
  __m256d rt = _mm256_or_pd(_mm256_or_pd(_mm256_and_pd(slide_forward, _mm256_mul_pd(negate(mu), rn_forward)),
                                         _mm256_and_pd(slide_backward, _mm256_mul_pd(mu, rn_backward))),
                            _mm256_and_pd(stick, _mm256_mul_pd(dft, det)));
  if (relaxed) {
    const __m256d r = _mm256_set1_pd(relax), k = _mm256_set1_pd(keep);
    rt = _mm256_add_pd(_mm256_mul_pd(r, rt), _mm256_mul_pd(k, rt_old));
    rn = _mm256_add_pd(_mm256_mul_pd(r, rn), _mm256_mul_pd(k, rn_old));
  }
  // |r| < 1e-24 -> +0.
  const __m256d magnitude = _mm256_set1_pd(-0.0), tiny = _mm256_set1_pd(1e-24);
  rt = _mm256_andnot_pd(_mm256_cmp_pd(_mm256_andnot_pd(magnitude, rt), tiny, _CMP_LT_OQ), rt);
  rn = _mm256_andnot_pd(_mm256_cmp_pd(_mm256_andnot_pd(magnitude, rn), tiny, _CMP_LT_OQ), rn);
  // The lanes left to the scalar update keep their reaction and their bodies' velocities, bit for bit.
  rt = _mm256_blendv_pd(rt_old, rt, taken);
  rn = _mm256_blendv_pd(rn_old, rn, taken);

  // inject(c, rt − s.rt, rn − s.rn): f = t dt + n dn, t = (ny, −nx).
  const __m256d dt = _mm256_sub_pd(rt, rt_old), dn = _mm256_sub_pd(rn, rn_old);
  const __m256d fx = _mm256_add_pd(_mm256_mul_pd(ny, dt), _mm256_mul_pd(nx, dn));
  const __m256d fy = _mm256_add_pd(_mm256_mul_pd(minus_nx, dt), _mm256_mul_pd(ny, dn));
  inject_lanes<true>(a, g.inverse_mass_cd, g.inverse_inertia_cd, fx, fy, dt, dn, lcd_t, lcd_n, taken);
  inject_lanes<false>(b, g.inverse_mass_an, g.inverse_inertia_an, fx, fy, dt, dn, lan_t, lan_n, taken);
  // Candidates first, as the scalar update writes its candidate before its antagonist: a body that
  // no update moves (inverse mass 0) may be an antagonist of several lanes, each writing it unchanged.
  store_bodies(a);
  store_bodies(b);

  store_pairs(rt, rn, &s0->rt, &s1->rt, &s2->rt, &s3->rt);
  // restart_if(r != 0), -0 counting as zero; the lanes not taken have their reaction, and restart
  // in their scalar update if they keep one.
  const int restart = lanes & _mm256_movemask_pd(_mm256_or_pd(_mm256_cmp_pd(rt, zero, _CMP_NEQ_UQ),
                                                              _mm256_cmp_pd(rn, zero, _CMP_NEQ_UQ)));
  s0->visits.restart_if((restart & 1) != 0);
  s1->visits.restart_if((restart & 2) != 0);
  s2->visits.restart_if((restart & 4) != 0);
  s3->visits.restart_if((restart & 8) != 0);
  return lanes;
}

#undef LMGC_AVX2

#else

bool sweep_groups_available() {
  return false;
}

int sweep_group_2d(const SweepGroup2D&, ContactReaction2D*, Eigen::Vector3d*, bool, double, double) {
  return 0;
}

#endif

}  // namespace lmgc::solver
