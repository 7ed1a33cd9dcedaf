// Buggy, and alone: a student who writes only the energy (3.4) and forgets its 1/2. No other
// slot is provided, so only a property that needs hamiltonian_3_4 alone can catch it:
// definition_hamiltonian_3_4 (every slot is checked on its own).
#include <geomech/student.hpp>

using namespace gm;

struct EnergyOnly {
  template <class T>
  static T hamiltonian_3_4(const Vec3<T>& I, const Vec3<T>& Pi) {
    return Pi.dot(Pi.cwiseQuotient(I));  // h = Pi . I^-1 Pi: the 1/2 of (3.4) is missing
  }
};

GEOMECH_STUDENT(EnergyOnly);
