// The template part of golden/certify.hpp: recording a field on a tape of balls.
#pragma once

#include "oracle/taylor.hpp"

namespace gm::golden {

// The validated Taylor method on a recorded field (golden/certify.cpp).
Enclosure enclose_tape(const oracle::Tape<Ball>& tape, const std::vector<int>& out, int dim,
                       const std::vector<Rational>& x0, const std::vector<Rational>& times, const EnclosureOptions& o);

template <class Field>
Enclosure enclose_field(const Field& field, int dim, const std::vector<Rational>& x0,
                        const std::vector<Rational>& times, const EnclosureOptions& o) {
  const Ball::Precision precision(o.precision_bits);
  oracle::Tape<Ball> tape;
  std::vector<oracle::Recorder<Ball>> x(dim), dx(dim);
  for (int i = 0; i < dim; ++i) x[i] = oracle::Recorder<Ball>{&tape, tape.push(oracle::Tape<Ball>::Op::Var)};
  field(x.data(), dx.data());
  std::vector<int> out;
  for (int i = 0; i < dim; ++i) {
    if (dx[i].tape != &tape)
      dx[i] = oracle::Recorder<Ball>{&tape, tape.push(oracle::Tape<Ball>::Op::Const, -1, -1, Ball(0L))};
    out.push_back(dx[i].id);
  }
  return enclose_tape(tape, out, dim, x0, times, o);
}

}  // namespace gm::golden
