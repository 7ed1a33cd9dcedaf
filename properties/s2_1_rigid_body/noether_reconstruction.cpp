// Noether's theorem, reconstruction and coadjoint motion (Remarks 2.1, 2.2, 2.6, 2.7, Theorem 2.2,
// (2.10), (2.28)-(2.33)), and the Clebsch form of the same motion ((3.20), (3.21)).
//
// Which flow where (support/dynamics.hpp):
//   - statements about a subject's *functions* along the motion (its spatial momentum, its
//     I_space) use the Taylor oracle's flow of (2.20), so that only the function is under test;
//   - statements about a subject's *equations* (reconstruction (2.10), Clebsch (3.21)) use the
//     flow of its slots (GBS).
#include "properties/registry.hpp"
#include "properties/support/derivatives.hpp"
#include "properties/support/dynamics.hpp"
#include "properties/support/figures.hpp"
#include "properties/support/generators.hpp"
#include "properties/support/lie_groups.hpp"
#include "properties/support/tolerance.hpp"
#include "properties/support/truth.hpp"

#include <cstdio>

namespace gm {
namespace properties_noether_reconstruction {
namespace {

// Subject flows of the 12-dimensional (Pi, O) system cost ~4x the 3-dimensional one.
template <class T>
T attitude_horizon() {
  return std::is_same_v<T, double> ? T(20) : T(5);
}

// ---------------------------------------------------------------------------------------------
// s2.noether: Theorem 2.2, (2.29)-(2.30). The subject's spatial_momentum slot, evaluated along the
// exact motion, must be constant. pi = O Pi (= Ad*_{O^-1} Pi) is; the formula printed in (2.30),
// pi = O^-1 Pi O, i.e. O^T Pi, is not (the literal variant fails this property).
// Constancy alone would pass a function returning a constant, so the value is also compared with
// the conserved quantity of the notes, pi = Ad*_{O^-1} Pi = O Pi ((2.29), corrected (2.30)), at
// t = 0: pi(t) = O(0) Pi(0) along the oracle's motion (the slot on its own, off the flow, is
// checked by definition_spatial_momentum).
template <class T>
void noether_spatial_momentum_conserved(const Subject<T>& s) {
  const Vec3<T> I = dyn::draw_inertia<T>();
  const RigidBodyState<T> x0{dyn::draw_momentum<T>(), dyn::draw_rotation<T>()};
  const auto times = dyn::times_to(dyn::rigid_body_horizon<T>(), 10);
  const auto xs = dyn::oracle_rigid_body(I, x0, times);
  const Vec3<T> pi0 = s.spatial_momentum(x0.O, x0.Pi);
  const Vec3<T> pi_notes = x0.O * x0.Pi;  // Ad*_{O^-1} Pi = O Pi at t = 0 (2.29)-(2.30)
  const T lambda = dyn::rigid_body_rate(I, x0.Pi);
  const T size = dyn::at_least_one(norm_inf(x0.Pi));
  Series ser{"Noether: spatial momentum",
             std::string("|pi(t) - pi(0)| (") + ScalarInfo<T>::name + ")",
             "t",
             "residual",
             false,
             true,
             {},
             0};
  for (std::size_t i = 0; i < times.size(); ++i) {
    const Vec3<T> pi = s.spatial_momentum(xs[i].O, xs[i].Pi);
    // O Pi is an invariant of degree 2 of the oracle's flow: k = 128 (support/dynamics.hpp).
    require_close("spatial_momentum(O(t), Pi(t)) = spatial_momentum(O(0), Pi(0)) along (2.20)", pi, pi0,
                  T(size * dyn::growth(lambda, times[i])), 128);
    // The same drift bound: O(t) Pi(t) - O(0) Pi(0) is the drift of the same degree-2 invariant,
    // plus the slot's own rounding of a 3-term product (far below it): k = 128.
    require_close("spatial_momentum(O(t), Pi(t)) = O(0) Pi(0), the conserved pi = Ad*_{O^-1} Pi of (2.29)-(2.30)", pi,
                  pi_notes, T(size * dyn::growth(lambda, times[i])), 128);
    ser.points.emplace_back(to_double(times[i]), to_double(max_abs((pi - pi0).eval())));
  }
  record_series(ser);
}

// s2.noether, (2.28): the end-point term in body and in space. For a constant spatial variation
// xi_hat = delta O O^-1 the body variation is Xi_hat = O^-1 delta O = O^-1 xi_hat O, and then
// <Pi, Xi_hat> = <pi, xi_hat> with the subject's pairing (2.15) and spatial momentum: exactly, in
// rationals, for rational rotations.
template <class T>
void noether_endpoint_term_2_28(const Subject<T>& s) {
  const Mat3<T> O = *gen::rotation3<T>().as("O");
  const Vec3<T> Pi = *gen::vec3<T>().as("Pi");
  const Vec3<T> xi = *gen::vec3<T>().as("xi");
  const Mat3<T> xi_hat = truth::skew_of(xi);
  const Mat3<T> Xi_hat = O.transpose() * xi_hat * O;
  const Vec3<T> pi = s.spatial_momentum(O, Pi);
  const T body = s.pairing(MatX<T>(truth::skew_of(Pi)), MatX<T>(Xi_hat));
  const T space = s.pairing(MatX<T>(truth::skew_of(pi)), MatX<T>(xi_hat));
  require_close("(2.28): <Pi, Xi> = <pi, xi> with Xi = O^-1 xi O and pi = spatial_momentum(O, Pi)", body, space,
                T(norm_inf(Pi) * norm_inf(xi)), 32);
  // As printed, (2.28) also writes <Pi, Xi> = trace(Pi^T Xi), which is 2 <Pi, Xi> under (2.15).
  const T trace = (truth::skew_of(Pi).transpose() * Xi_hat).trace();
  if (body != T(0)) {
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "(2.28) as printed equates <Pi, Xi> with trace(Pi^T Xi); with (2.15) the trace is %.17g = %.6g x "
                  "<Pi, Xi> (the factor 1/2 of (2.15) is dropped)",
                  to_double(trace), to_double(T(trace / body)));
    record_note(buf);
  }
}

// s2.space-momentum, the exercise after Remark 2.1: pi = I_space(t) omega(t), omega = O Omega, is
// conserved (along the exact motion; the subject provides I_space).
template <class T>
void space_momentum_is_conserved(const Subject<T>& s) {
  const Vec3<T> I = dyn::draw_inertia<T>();
  const RigidBodyState<T> x0{dyn::draw_momentum<T>(), dyn::draw_rotation<T>()};
  const auto times = dyn::times_to(dyn::rigid_body_horizon<T>(), 10);
  const auto xs = dyn::oracle_rigid_body(I, x0, times);
  auto pi_of = [&](const RigidBodyState<T>& x) {
    const Vec3<T> omega = x.O * x.Pi.cwiseQuotient(I);  // Remark 2.1: Omega = O^-1 omega
    return Vec3<T>(s.inertia_space(x.O, I) * omega);
  };
  const Vec3<T> pi0 = pi_of(x0);
  const T lambda = dyn::rigid_body_rate(I, x0.Pi);
  // I_space omega rounds a 3 x 3 product of size |I| |omega| <= |I| |Pi| / min I: k = 128 (degree 2)
  // on scale |Pi| * (max I / min I).
  const T size = dyn::at_least_one(norm_inf(x0.Pi)) * I.maxCoeff() / I.minCoeff();
  for (std::size_t i = 0; i < times.size(); ++i)
    require_close("I_space(t) omega(t) = I_space(0) omega(0) along (2.20)", pi_of(xs[i]), pi0,
                  T(size * dyn::growth(lambda, times[i])), 128);
}

// s2.reconstruction, Remark 2.2: integrating the subject's (2.10) along its Euler flow keeps O in
// SO(3).
template <class T>
void reconstruction_stays_in_so3(const Subject<T>& s) {
  const Vec3<T> I = dyn::draw_inertia<T>();
  const RigidBodyState<T> x0{dyn::draw_momentum<T>(), dyn::draw_rotation<T>()};
  const auto times = dyn::times_to(attitude_horizon<T>(), 10);
  const auto xs = dyn::subject_rigid_body(s, I, x0, times);
  const T lambda = dyn::rigid_body_rate(I, x0.Pi);
  Series ser{"reconstruction: orthogonality",
             std::string("|O^T O - Id| (") + ScalarInfo<T>::name + ")",
             "t",
             "residual",
             false,
             true,
             {},
             0};
  for (std::size_t i = 0; i < times.size(); ++i) {
    const Mat3<T>& O = xs[i].O;
    const T g = dyn::growth(lambda, times[i]);
    // O^T O (degree 2) and det O (degree 3) of a flow accurate to round-off per step.
    require_close("O(t)^T O(t) = Id along the subject's (2.10)", (O.transpose() * O).eval(), Mat3<T>::Identity().eval(),
                  g, 128);
    require_close("det O(t) = 1 along the subject's (2.10)", O.determinant(), T(1), g, 192);
    ser.points.emplace_back(to_double(times[i]), to_double(max_abs((O.transpose() * O - Mat3<T>::Identity()).eval())));
  }
  record_series(ser);
}

// s2.coadjoint-motion, (2.33): along the subject's (3.8) + (2.10), Pi(t) = Ad*_{O(t)} pi with
// pi = Ad*_{O(0)^-1} Pi(0) = O(0) Pi(0) constant; Ad*_O pi = O^-1 pi.
template <class T>
void coadjoint_motion_2_33(const Subject<T>& s) {
  const Vec3<T> I = dyn::draw_inertia<T>();
  const RigidBodyState<T> x0{dyn::draw_momentum<T>(), dyn::draw_rotation<T>()};
  const auto times = dyn::times_to(attitude_horizon<T>(), 10);
  const auto xs = dyn::subject_rigid_body(s, I, x0, times);
  const Vec3<T> pi = x0.O * x0.Pi;
  const T lambda = dyn::rigid_body_rate(I, x0.Pi);
  const T size = dyn::at_least_one(norm_inf(x0.Pi));
  for (std::size_t i = 0; i < times.size(); ++i)
    // O^T pi - Pi = O^T (pi - O Pi): the drift of the degree-2 invariant O Pi, k = 128.
    require_close("Pi(t) = O(t)^-1 pi, pi = O(0) Pi(0), along the subject's (3.8) and (2.10)", xs[i].Pi,
                  (xs[i].O.transpose() * pi).eval(), T(size * dyn::growth(lambda, times[i])), 128);
}

// s2.ad-star-identity, (2.32): for any curve g(t) in a matrix group and any mu(t),
//   d/dt (Ad*_{g^-1} mu) = Ad*_{g^-1} (dmu/dt - ad*_Omega mu),   Omega = g^-1 dg/dt,
// on so(3), sl(2, R) and so(4), in the subject's coordinates (lie_hat / lie_vee) with the
// subject's ad*. Ad* is the truth: the transpose of the matrix of Ad in the subject's basis (the
// coordinate pairing of a basis with its dual). The left side is differentiated by the order-8
// central difference of support/derivatives.hpp along g(t) = exp(t A) exp(t B) (|A|, |B| <= 3/4,
// so the curve's time scale is ~1 and the difference is accurate to ~eps^(8/9)).
template <class T>
void ad_star_identity_for(const Subject<T>& s, LieAlgebraId g) {
  const int d = g == LieAlgebraId::so4 ? 6 : 3;
  const VecX<T> a = *gen::vec<T>(d, 16, 6).as("a"), b = *gen::vec<T>(d, 16, 6).as("b");
  const VecX<T> mu0 = *gen::vec<T>(d, 64, 6).as("mu0"), mu1 = *gen::vec<T>(d, 64, 6).as("mu1"),
                mu2 = *gen::vec<T>(d, 64, 6).as("mu2");
  const T t0 = *gen::scalar<T>(64, 6).as("t0");
  const MatX<T> A = s.lie_hat(g, a), B = s.lie_hat(g, b);
  std::vector<MatX<T>> E;
  for (int k = 0; k < d; ++k) {
    VecX<T> e = VecX<T>::Zero(d);
    e(k) = T(1);
    E.push_back(s.lie_hat(g, e));
  }
  auto ad_star_inverse = [&](const MatX<T>& G, const MatX<T>& Ginv, const VecX<T>& mu) {  // Ad*_{G^-1} mu
    VecX<T> out(d);
    for (int k = 0; k < d; ++k) out(k) = s.lie_vee(g, (Ginv * E[k] * G).eval()).dot(mu);
    return out;
  };
  auto f = [&](const T& dt) {
    const T t = t0 + dt;
    const MatX<T> G = lie::expm<T>((t * A).eval()) * lie::expm<T>((t * B).eval());
    const MatX<T> Ginv = lie::expm<T>((-t * B).eval()) * lie::expm<T>((-t * A).eval());
    return ad_star_inverse(G, Ginv, (mu0 + t * mu1 + t * t * mu2).eval());
  };
  const VecX<T> lhs = deriv::central8<T>(f, deriv::step8<T>());
  const MatX<T> G = lie::expm<T>((t0 * A).eval()) * lie::expm<T>((t0 * B).eval());
  const MatX<T> Ginv = lie::expm<T>((-t0 * B).eval()) * lie::expm<T>((-t0 * A).eval());
  const MatX<T> Omega = lie::expm<T>((-t0 * B).eval()) * A * lie::expm<T>((t0 * B).eval()) + B;
  const VecX<T> mu = mu0 + t0 * mu1 + t0 * t0 * mu2, dmu = mu1 + T(2) * t0 * mu2;
  const VecX<T> rhs = ad_star_inverse(G, Ginv, (dmu - s.ad_star(g, s.lie_vee(g, Omega), mu)).eval());
  // Round-off of the difference quotient: roundoff_factor8 eps |f|; truncation is below it.
  const T scale = dyn::at_least_one(norm_inf(f(T(0)))) * deriv::roundoff_factor8<T>();
  require_close(
      std::string("(2.32) on ") + lie_algebra_name(g) + ": d/dt Ad*_{g^-1} mu = Ad*_{g^-1}(dmu/dt - ad*_Omega mu)", lhs,
      rhs, scale, 16);
}

template <class T>
void ad_star_identity_2_32(const Subject<T>& s) {
  for (LieAlgebraId g : {LieAlgebraId::so3, LieAlgebraId::sl2, LieAlgebraId::so4}) ad_star_identity_for(s, g);
}

// s3.clebsch-reconstruction, (3.20)-(3.21): from Pi(0) = P(0) x Q(0), O(0) = Id, the flow of the
// subject's Clebsch equations and that of its (3.8) + (2.10) are the same motion:
// P x Q = Pi, Q(t) = O(t)^-1 Q(0), P(t) = O(t)^-1 P(0).
template <class T>
void hamilton_pontryagin_and_clebsch_are_one_motion(const Subject<T>& s) {
  const Vec3<T> I = dyn::draw_inertia<T>();
  const Vec3<T> Q0 = dyn::draw_momentum<T>(), P0 = dyn::draw_momentum<T>();
  const Vec3<T> Pi0 = truth::cross(P0, Q0);
  const T t_end = attitude_horizon<T>();
  const auto times = dyn::times_to(t_end, 10);
  flow::Gbs<T> clebsch([&](const T&, const VecX<T>& v) {
    const auto d = s.clebsch_3_21(I, Vec3<T>(v.head(3)), Vec3<T>(v.tail(3)));
    VecX<T> out(6);
    out << d.first, d.second;
    return out;
  });
  VecX<T> qp0(6);
  qp0 << Q0, P0;
  const auto qp = clebsch.sample(qp0, T(0), times);
  const auto hp = dyn::subject_rigid_body(s, I, RigidBodyState<T>{Pi0, Mat3<T>::Identity()}, times);
  // The suite's own motion (the Taylor oracle of the notes' (3.8) and (2.10), oracle/fields.hpp):
  // each of the two systems is also compared with it, so an error shared by the subject's
  // (2.20) and (3.21) (e.g. both built on a wrong Omega) is caught.
  const auto ref = dyn::oracle_rigid_body(I, RigidBodyState<T>{Pi0, Mat3<T>::Identity()}, times);
  const T lambda = dyn::rigid_body_rate(I, Pi0);
  const T kappa = dyn::rigid_body_conditioning(I, Pi0, t_end);
  const T size = dyn::at_least_one(T(norm_inf(Q0) * norm_inf(P0)));
  for (std::size_t i = 0; i < times.size(); ++i) {
    const Vec3<T> Q = qp[i].head(3), P = qp[i].tail(3);
    const T g = dyn::growth(lambda, times[i]);
    // Two flows compared: k = 64 with (1 + lambda t) kappa, and one more (1 + lambda t) for the
    // attitude (support/dynamics.hpp).
    require_close("P(t) x Q(t) of the subject's (3.21) = Pi(t) of its (2.20)", truth::cross(P, Q), hp[i].Pi,
                  T(size * g * kappa), 64);
    require_close("Q(t) = O(t)^-1 Q(0) (3.20)", Q, (hp[i].O.transpose() * Q0).eval(),
                  T(dyn::at_least_one(norm_inf(Q0)) * g * g * kappa), 64);
    require_close("P(t) = O(t)^-1 P(0)", P, (hp[i].O.transpose() * P0).eval(),
                  T(dyn::at_least_one(norm_inf(P0)) * g * g * kappa), 64);
    // Against the oracle, the same two-flow bounds.
    require_close("Pi(t) of the subject's (2.20) = Pi(t) of the oracle's (3.8)", hp[i].Pi, ref[i].Pi,
                  T(size * g * kappa), 64);
    require_close("O(t) of the subject's (2.20) = O(t) of the oracle's (2.10)", hp[i].O, ref[i].O, T(g * g * kappa),
                  64);
    require_close("P(t) x Q(t) of the subject's (3.21) = Pi(t) of the oracle's (3.8)", truth::cross(P, Q), ref[i].Pi,
                  T(size * g * kappa), 64);
    require_close("Q(t) of the subject's (3.21) = O(t)^-1 Q(0) with the oracle's O (3.20)", Q,
                  (ref[i].O.transpose() * Q0).eval(), T(dyn::at_least_one(norm_inf(Q0)) * g * g * kappa), 64);
  }
}

}  // namespace

GM_PROPERTY(
    noether_spatial_momentum_conserved, float_scalars,
    {.spec = "s2.noether",
     .title = "Theorem 2.2: the subject's spatial momentum is constant along the motion (2.20) and equals pi = O Pi",
     .tolerance = ToleranceClass::Roundoff,
     .needs = {"spatial_momentum"},
     .negative_controls = {"spatial_momentum_as_printed_2_30", "spatial_momentum_constant"},
     .cases = {.d = 20, .mp = 2, .q = 0}});

GM_PROPERTY(noether_endpoint_term_2_28, all_scalars,
            {.spec = "s2.noether",
             .title = "(2.28): <Pi, Xi> = <pi, xi> for Xi = O^-1 xi O (xi = delta O O^-1) and pi the spatial momentum",
             .tolerance = ToleranceClass::Exact,
             .needs = {"spatial_momentum", "pairing"},
             .negative_controls = {"spatial_momentum_as_printed_2_30"}});

GM_PROPERTY(space_momentum_is_conserved, float_scalars,
            {.spec = "s2.space-momentum",
             .title = "exercise after Remark 2.1: pi = I_space(t) omega(t) is constant along the motion",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {"inertia_space"},
             .negative_controls = {"inertia_space_inverted"},
             .cases = {.d = 20, .mp = 2, .q = 0}});

GM_PROPERTY(reconstruction_stays_in_so3, float_scalars,
            {.spec = "s2.reconstruction",
             .title = "Remark 2.2: integrating the subject's (2.10) along its Euler flow keeps O^T O = Id, det O = 1",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {"euler_3_8", "reconstruction_2_10"},
             .negative_controls = {"reconstruction_hat_not_skew"},
             .cases = {.d = 10, .mp = 2, .q = 0}});

GM_PROPERTY(coadjoint_motion_2_33, float_scalars,
            {.spec = "s2.coadjoint-motion",
             .title = "(2.33): along the subject's (3.8) and (2.10), Pi(t) = Ad*_{O(t)} pi with pi constant",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {"euler_3_8", "reconstruction_2_10"},
             .negative_controls = {"reconstruction_right_multiplied", "euler_3_8_cross_reversed"},
             .cases = {.d = 10, .mp = 2, .q = 0}});

GM_PROPERTY(ad_star_identity_2_32, float_scalars,
            {.spec = "s2.ad-star-identity",
             .title = "(2.32): d/dt Ad*_{g^-1} mu = Ad*_{g^-1}(dmu/dt - ad*_Omega mu) on so(3), sl(2,R), so(4)",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {"lie_hat", "lie_vee", "ad_star"},
             .negative_controls = {"ad_star_sign_flipped", "ad_star_sl2_transpose_pairing"},
             .cases = {.d = 50, .mp = 5, .q = 0}});

GM_PROPERTY(hamilton_pontryagin_and_clebsch_are_one_motion, float_scalars,
            {.spec = "s3.clebsch-reconstruction",
             .title = "(3.20)-(3.21): from Pi(0) = P(0) x Q(0), the subject's Clebsch flow and (2.20) flow agree: "
                      "P x Q = Pi, Q = O^-1 Q(0), P = O^-1 P(0), and both agree with the oracle's motion",
             .tolerance = ToleranceClass::Roundoff,
             .needs = {"clebsch_3_21", "euler_3_8", "reconstruction_2_10"},
             .negative_controls = {"clebsch_3_21_Q_sign", "rigid_body_and_clebsch_time_reversed"},
             .cases = {.d = 10, .mp = 2, .q = 0}});

}  // namespace properties_noether_reconstruction
}  // namespace gm
