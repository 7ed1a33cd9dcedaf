// The bundled reference implementation as a subject: the first implementation every property
// is run against, and the base from which negative controls are made.
#pragma once

#include "core/subject.hpp"

namespace gm {

template <class T>
Subject<T> make_reference_subject();

extern template Subject<double> make_reference_subject<double>();
extern template Subject<Real50> make_reference_subject<Real50>();
extern template Subject<Rational> make_reference_subject<Rational>();

// What the reference implementation claims about its integrators (impl/reference_integrators.cpp).
std::vector<IntegratorClaims> reference_integrator_claims();

// The reference implementation in double, Real50 and Rational, with its integrators' claims.
const SubjectSet& reference_subject();

}  // namespace gm
