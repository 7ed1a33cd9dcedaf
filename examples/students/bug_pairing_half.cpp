// Buggy: the trace pairing without the factor 1/2 of (2.15), <A, B> = tr(A^T B), and the
// Lagrangian (2.13) computed with it. Caught by trace_pairing_is_dot_product and
// lagrangian_2_13_is_kinetic_energy: with the 1/2, <hat(a), hat(b)> = a . b.
#include <geomech/student.hpp>

using namespace gm;

struct PairingWithoutHalf {
  template <class T>
  static T pairing(const MatX<T>& A, const MatX<T>& B) {
    return (A.transpose() * B).trace();
  }
  // l = (1/2) <I Omega_hat, Omega_hat> with I Omega_hat the hat of (I1 W1, I2 W2, I3 W3).
  template <class T>
  static T lagrangian_2_13(const Vec3<T>& I, const Mat3<T>& W) {
    Mat3<T> IW = Mat3<T>::Zero();
    IW(2, 1) = I(0) * W(2, 1);
    IW(1, 2) = -IW(2, 1);
    IW(0, 2) = I(1) * W(0, 2);
    IW(2, 0) = -IW(0, 2);
    IW(1, 0) = I(2) * W(1, 0);
    IW(0, 1) = -IW(1, 0);
    return pairing<T>(IW, W) / T(2);
  }
};

GEOMECH_STUDENT(PairingWithoutHalf);
