// Buggy: Manakov's Omega recovered from M = A Omega + Omega A as if A and Omega commuted,
// Omega = A^-1 M / 2. True only for A a multiple of the identity. Caught by
// manakov_omega_solves_2_34 (A Omega + Omega A must give M back).
#include <geomech/student.hpp>

using namespace gm;

struct ManakovOmegaWrong {
  template <class T>
  static MatX<T> manakov_Omega(const MatX<T>& A, const MatX<T>& M) {
    return A.partialPivLu().solve(M) / T(2);
  }
  template <class T>
  static MatX<T> manakov_M(const MatX<T>& A, const MatX<T>& Omega) {
    return A * Omega + Omega * A;
  }
};

GEOMECH_STUDENT(ManakovOmegaWrong);
